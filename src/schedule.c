/* schedule.c — the internal-step grid (thesis 3.2.3) and the expected
 * earliest collision time of a pair (thesis 3.3.1.1), SPEC 3.2–3.3. */
#include <float.h>
#include "schedule.h"
#include "distbound.h"

/* what the key leaves on the table for rounding in distances and poses */
#define KEY_MARGIN 1e-9

double vrSchedule_Reach(const vrBody *b, double ts, double T, const vrFlight *f)
{
    if (!b || !vrBody_IsFree(b)) return 0;
    return vrBody_SpeedBound(b, ts, T - ts, vec3_len(f->accel), f->max_linear) + vrSchedule_SpinReach(b);
}

void vrSchedule_GridFor(double fastest, double ts, double T, double d, double internal_step, vrGrid *g)
{
    double span = T - ts;
    g->t0 = ts;
    g->T = T;
    g->frame_T = T;
    g->a = ts;
    g->k0 = 0;
    if (span <= 0) {          /* an event at the frame end: nothing left to step */
        g->n = 0;
        g->h = 0;
        return;
    }
    if (internal_step > 0) {
        g->n = (long)ceil(span / internal_step);
        if (g->n < 1) g->n = 1;
        g->h = internal_step;
        return;
    }
    g->n = 1;
    if (fastest > 0) {
        /* never finer than the clock can tell apart */
        double steps = ceil(span * 2.0 * fastest / d), finest = span / (8.0 * DBL_EPSILON * vr_max(1.0, fabs(T)));
        g->n = steps > 1 ? (long)vr_min(steps, finest) : 1;
    }
    g->h = span / (double)g->n;
}

void vrSchedule_AnchoredGrid(double fastest, double a, double ts, double T, double d, double internal_step,
                             long *steps, vrGrid *g)
{
    vrGrid whole;
    long N, j;
    vrSchedule_GridFor(fastest, a, T, d, internal_step, &whole);   /* the whole step's at this reach */
    if (!(ts > a)) {                    /* the step's first span */
        *steps = whole.n;
        *g = whole;
        return;
    }
    if (!(T > ts)) {                    /* nothing left */
        vrSchedule_GridFor(0, ts, T, d, internal_step, g);
        return;
    }
    N = *steps < 1 ? whole.n : *steps;
    while (N < whole.n) N *= 2;         /* a response raised the fastest reach */
    *steps = N;
    g->t0 = ts;
    g->T = T;
    g->frame_T = T;
    g->a = a;
    g->h = internal_step > 0 ? internal_step : (T - a) / (double)N;
    j = (long)floor((ts - a) / g->h);
    j = j < 0 ? 0 : j > N - 1 ? N - 1 : j;
    while (j < N - 1 && a + (double)(j + 1) * g->h <= ts) j++;
    while (j > 0 && a + (double)j * g->h > ts) j--;
    g->k0 = j;
    g->n = N - j;
}

double vrSchedule_Fastest(vrBody *const *bodies, int nbodies, double ts, double T, double internal_step,
                          const vrFlight *f)
{
    double fastest = 0;
    int i;
    for (i = 0; i < nbodies && vrSchedule_NeedsReach(ts, T, internal_step); i++) fastest = vr_max(fastest, vrSchedule_Reach(bodies[i], ts, T, f));
    return fastest;
}

void vrSchedule_Grid(vrBody *const *bodies, int nbodies, double ts, double T, double d,
                     double internal_step, const vrFlight *f, vrGrid *g)
{
    vrSchedule_GridFor(vrSchedule_Fastest(bodies, nbodies, ts, T, internal_step, f), ts, T, d, internal_step, g);
}

long vrSchedule_FirstPointAtOrAfter(const vrGrid *g, double t)
{
    long k;
    if (t <= g->t0) return 1;
    if (t > g->T) return g->n + 1;
    k = (long)ceil((t - g->a) / g->h) - g->k0;
    if (k < 1) k = 1;
    if (k > g->n) k = g->n;
    while (k > 1 && vrGrid_Point(g, k - 1) >= t) k--;
    while (k <= g->n && vrGrid_Point(g, k) < t) k++;
    return k;
}

/* a body that can turn in free flight may bring a surface point (R - r)
 * closer than its centre does (thesis fig. 3.5); spheres, and bodies whose
 * orientation is frozen until their next event, cannot */
static double spin_margin(const vrBody *b)
{
    if (b->shape.kind == VR_SHAPE_SPHERE || b->rot == VR_ROT_NONE || !vrBody_IsFree(b)) return 0.0;
    return b->r_out - b->r_in;
}

/* ...and not faster than |omega| R: the same margin as a rate */
static double spin_rate(const vrBody *b)
{
    return spin_margin(b) > 0 ? vrBody_SpinBound(b) * b->r_out : 0.0;
}

static int moves(const vrBody *b) { return vrBody_IsFree(b); }

/* distance covered in time L at speed c growing at slope k */
static double covered(double c, double k, double L)
{
    if (L == INFINITY) return c > 0 || k > 0 ? INFINITY : 0.0;
    return c * L + 0.5 * k * L * L;
}

/* The time to cover `room` with a speed starting at c, growing at slope k
 * but never above cmax, within a segment of length len (thesis eq. 5 split
 * at the speed cap).  Returns that time, or INFINITY when the segment ends
 * first, having taken off `room` what it covered and left c at its end. */
static double cover(double *room, double *c, double k, double len, double cmax)
{
    double ramp = len, dist;
    if (k > 0 && (cmax - *c) / k < ramp) ramp = vr_max(0.0, (cmax - *c) / k);
    dist = covered(*c, k, ramp);
    if (*room <= dist) return 2.0 * *room / (*c + sqrt(*c * *c + 2.0 * k * *room));
    *room -= dist;
    *c += k * ramp;
    if (ramp < len) {        /* the rest of the segment at the cap */
        *c = cmax;
        dist = covered(cmax, 0, len - ramp);
        if (*room <= dist) return ramp + *room / cmax;
        *room -= dist;
    }
    return INFINITY;
}

/* the first tau > 0 with A tau^2 + B tau + C <= 0, given C > 0 (INFINITY if none) */
static double first_root(double A, double B, double C)
{
    double disc, q, r1, r2;
    if (A == 0) return B < 0 ? -C / B : INFINITY;
    disc = B * B - 4 * A * C;
    if (disc < 0) return INFINITY;               /* stays positive */
    q = -0.5 * (B + (B < 0 ? -sqrt(disc) : sqrt(disc)));
    r1 = q / A;
    r2 = q != 0 ? C / q : INFINITY;
    if (r1 > r2) { double x = r1; r1 = r2; r2 = x; }
    return r1 > 0 ? r1 : r2 > 0 && A < 0 ? r2 : INFINITY;
}

typedef struct vrClosing {
    double room;       /* distance to cover before the pair can be within d */
    double spin;       /* closing speed that turning adds (counted as a rate) */
    double cmax;       /* the closing speed never exceeds this */
    double t1;         /* until then both accelerations are exact (no speed cap) */
    vec3 dv, da;       /* relative velocity and acceleration, b's minus a's */
} vrClosing;

/* thesis eq. (5) generalised: any direction, closing speed |dv| growing at
 * most |da| until t1, at most the larger acceleration after */
static double key_any_direction(const vrClosing *k, const vrBody *a, const vrBody *b)
{
    double cmax = k->cmax + k->spin, room = k->room, c = vr_min(vec3_len(k->dv) + k->spin, cmax), tau;
    tau = cover(&room, &c, vec3_len(k->da), k->t1, cmax);
    if (tau == INFINITY && k->t1 < INFINITY) {
        tau = cover(&room, &c, vr_max(vec3_len(a->m.a), vec3_len(b->m.a)), INFINITY, cmax);
        if (tau < INFINITY) tau += k->t1;
    }
    return tau;
}

/* Along the separating direction n: for convex bodies
 * dist(tau) >= dist - (R - r) margins + n.dv tau + n.da tau^2 / 2
 * exactly until t1; from t1 on, the bound above from what is left. */
static double key_along_normal(const vrClosing *k, vec3 n, const vrBody *a, const vrBody *b)
{
    double B = vec3_dot(n, k->dv) - k->spin, A = 0.5 * vec3_dot(n, k->da), tau = first_root(A, B, k->room), left;
    vrClosing after;
    if (tau <= k->t1) return tau;
    if (k->t1 == INFINITY) return INFINITY;
    left = k->room + B * k->t1 + A * k->t1 * k->t1;
    if (left <= 0) return k->t1;
    after = *k;
    after.room = left;
    after.dv = vec3_madd(k->dv, k->t1, k->da);
    after.t1 = 0;
    return k->t1 + key_any_direction(&after, a, b);
}

/* the later of the two bounds: moving in any direction, and along n */
static double key_for(const vrClosing *k, vec3 n, const vrBody *a, const vrBody *b)
{
    if (k->room <= 0) return 0;
    return vr_max(key_any_direction(k, a, b), key_along_normal(k, n, a, b));
}

/* when b's speed cap could bend its path after t (INFINITY: never) */
static double cap_time(const vrBody *b, double t)
{
    double cap = b->m.t0 + b->m.tcap;
    return moves(b) && t < cap ? cap : INFINITY;
}

/* Turning bodies close together: the support of each along n followed
 * vertex by vertex (distbound.h), which sees how fast the near vertices
 * really come, not only that some point could come at |omega| R.  Looks
 * at most KEY_HORIZON ahead, from `known`, the key the speed bounds gave
 * (it cannot come earlier). */
#define KEY_HORIZON 1.0
static double key_by_vertices(vrBody *a, vrBody *b, double t, vec3 n, double d, double known, double enough)
{
    vrPose pa, pb;
    vrDistBound db;
    double until = vr_min(vr_min(t + KEY_HORIZON, enough), vr_min(cap_time(a, t), cap_time(b, t)));
    if (known >= until) return known;   /* it could say no more */
    vrBody_ShapePose(a, t, &pa);
    vrBody_ShapePose(b, t, &pb);
    vrDistBound_MakeAlong(&db, a, &pa, b, &pb, t, n, t, until);
    return vrDistBound_Clear(&db, d + KEY_MARGIN, known, until);
}

/* the speed a body never exceeds in its flight: the cap, but a throw's
 * (motion.c: uncapped to its next event) */
static double speed_cap(const vrBody *b, const vrFlight *f)
{
    return !moves(b) ? 0 : b->m.over_cap ? INFINITY : f->max_linear;
}

/* the key from the velocities va, vb at t (key_with's caller may have them) */
static double key_with(vrBody *a, vrBody *b, double t, vec3 va, vec3 vb, double dist, vec3 n, double d,
                       const vrFlight *f, int turning, double enough)
{
    vrClosing whole, rate;
    double known;
    whole.room = dist - d - KEY_MARGIN;
    whole.cmax = speed_cap(a, f) + speed_cap(b, f);
    if (whole.room <= 0) return t;
    if (whole.cmax <= 0) return INFINITY;
    whole.dv = vec3_sub(vb, va);
    /* until either body reaches the speed cap the relative acceleration is
     * exactly a_b - a_a (0 between two free bodies under the same force) */
    whole.da = vec3_sub(b->m.a, a->m.a);
    whole.t1 = vr_min(vrSchedule_CapLeft(a, t), vrSchedule_CapLeft(b, t));
    /* turning bodies: the thesis takes (R - r) off the distance at once;
     * turning at omega also cannot close faster than omega R.  Each bound
     * holds, so the later time does. */
    whole.spin = 0;
    if (!turning || (spin_margin(a) == 0 && spin_margin(b) == 0)) return t + key_for(&whole, n, a, b);
    rate = whole;
    whole.room -= spin_margin(a) + spin_margin(b);
    rate.spin = spin_rate(a) + spin_rate(b);
    known = t + vr_max(key_for(&whole, n, a, b), key_for(&rate, n, a, b));
    return vr_max(known, key_by_vertices(a, b, t, n, d, known, enough));
}

static double key(vrBody *a, vrBody *b, double t, double dist, vec3 n, double d, const vrFlight *f, int turning,
                  double enough)
{
    vec3 va, vb;
    vrBody_Velocity(a, t, &va);
    vrBody_Velocity(b, t, &vb);
    return key_with(a, b, t, va, vb, dist, n, d, f, turning, enough);
}

double vrSchedule_Key(vrBody *a, vrBody *b, double t, double dist, vec3 n, double d, const vrFlight *f)
{
    return key(a, b, t, dist, n, d, f, 1, INFINITY);
}

double vrSchedule_KeyUpTo(vrBody *a, vrBody *b, double t, double dist, vec3 n, double d, const vrFlight *f,
                          double enough)
{
    return key(a, b, t, dist, n, d, f, 1, enough);
}

/* Two bodies flying free under the same force move in straight lines
 * relative to each other until either reaches the speed cap, so their
 * centres come within D of each other exactly at the first root of
 * |dx + dv tau|^2 = D^2; the bounds above only see the closing speed
 * along the line between them now, and a pair flying past each other was
 * looked at again and again.
 * D keeps the KEY_MARGIN (rounding of a minute-long run's positions is
 * below 1e-13 m): a path that enters the envelope goes 1e-9 m deep into
 * D's sphere, far above the root's rounding unless the centres are
 * kilometres apart.  No root before t1: no contact before t1. */
static double linear_key(const vrBody *a, const vrBody *b, double t, const vrCentres *c, vec3 va, vec3 vb,
                         double room)
{
    vec3 dx, dv;
    double len = c->len, D, tau, t1;
    if (!moves(a) || !moves(b) || a->m.a.x != b->m.a.x || a->m.a.y != b->m.a.y || a->m.a.z != b->m.a.z) return t;
    dx = vec3_sub(c->xb, c->xa);
    dv = vec3_sub(vb, va);
    D = len - room;
    if (!(D > 0)) return t;
    tau = first_root(vec3_dot(dv, dv), 2 * vec3_dot(dx, dv), room * (len + D));
    t1 = vr_min(vrSchedule_CapLeft(a, t), vrSchedule_CapLeft(b, t));
    return t + vr_min(tau, t1);
}

void vrCentres_At(const vrBody *a, const vrBody *b, double t, vrCentres *c)
{
    vrBody_Position(a, t, &c->xa);
    vrBody_Position(b, t, &c->xb);
    c->len = vec3_len(vec3_sub(c->xb, c->xa));
}

double vrSchedule_SphereKey(vrBody *a, vrBody *b, double t, const vrCentres *c, double dist, vec3 n, double d,
                            const vrFlight *f)
{
    vec3 va, vb;
    double bound, room = dist - d - KEY_MARGIN;
    vrBody_Velocity(a, t, &va);   /* once for both bounds */
    vrBody_Velocity(b, t, &vb);
    bound = key_with(a, b, t, va, vb, dist, n, d, f, 0, INFINITY);
    if (!(room > 0)) return bound;
    return vr_max(bound, linear_key(a, b, t, c, va, vb, room));
}
