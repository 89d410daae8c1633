/* schedule.c — the internal-step grid (thesis 3.2.3) and the expected
 * earliest collision time of a pair (thesis 3.3.1.1), SPEC 3.2–3.3. */
#include <float.h>
#include "schedule.h"

/* what the key leaves on the table for rounding in distances and poses */
#define KEY_MARGIN 1e-9

void vrSchedule_Grid(vrBody *const *bodies, int nbodies, double ts, double T, double d,
                     double internal_step, const vrFlight *f, vrGrid *g)
{
    double span = T - ts, fastest = 0, accel = vec3_len(f->accel);
    int i;
    g->t0 = ts;
    g->T = T;
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
    for (i = 0; i < nbodies; i++) {
        const vrBody *b = bodies[i];
        double reach;
        if (!b || !vrBody_IsFree(b)) continue;
        reach = vrBody_SpeedBound(b, ts, span, accel, f->max_linear)
              + vrBody_SpinBound(b) * (b->shape.kind == VR_SHAPE_SPHERE ? 0.0 : b->r_out);
        if (reach > fastest) fastest = reach;
    }
    g->n = 1;
    if (fastest > 0) {
        /* never finer than the clock can tell apart */
        double steps = ceil(span * 2.0 * fastest / d), finest = span / (8.0 * DBL_EPSILON * fmax(1.0, fabs(T)));
        g->n = steps > 1 ? (long)fmin(steps, finest) : 1;
    }
    g->h = span / (double)g->n;
}

long vrSchedule_FirstPointAtOrAfter(const vrGrid *g, double t)
{
    long k;
    if (t <= g->t0) return 1;
    if (t > g->T) return g->n + 1;
    k = (long)ceil((t - g->t0) / g->h);
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

static int moves(const vrBody *b) { return vrBody_IsFree(b); }

/* time left before b's speed stops growing */
static double cap_left(const vrBody *b, double t)
{
    double left = b->m.tcap - (t - b->m.t0);
    return moves(b) ? (left > 0 ? left : 0) : INFINITY;
}

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
    if (k > 0 && (cmax - *c) / k < ramp) ramp = fmax(0.0, (cmax - *c) / k);
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

double vrSchedule_Key(vrBody *a, vrBody *b, double t, double dist, double d, const vrFlight *f)
{
    double room = dist - d - spin_margin(a) - spin_margin(b) - KEY_MARGIN;
    double cmax = (moves(a) ? f->max_linear : 0) + (moves(b) ? f->max_linear : 0);
    double t1, k1, k2, c, tau;
    vec3 va, vb;
    if (room <= 0) return t;
    if (cmax <= 0) return INFINITY;
    vrBody_Velocity(a, t, &va);
    vrBody_Velocity(b, t, &vb);
    c = fmin(vec3_len(vec3_sub(va, vb)), cmax);
    /* until either body reaches the speed cap the relative acceleration is
     * exactly a_a - a_b (0 between two free bodies under the same force);
     * after that at most the larger of the two */
    t1 = fmin(cap_left(a, t), cap_left(b, t));
    k1 = vec3_len(vec3_sub(a->m.a, b->m.a));
    k2 = fmax(vec3_len(a->m.a), vec3_len(b->m.a));
    tau = cover(&room, &c, k1, t1, cmax);
    if (tau == INFINITY && t1 < INFINITY) {
        tau = cover(&room, &c, k2, INFINITY, cmax);
        if (tau < INFINITY) tau += t1;
    }
    return t + tau;
}
