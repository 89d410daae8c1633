/* distbound.c — Taylor bounds on a pair's distance near a measurement
 * (see distbound.h for what they are and why they hold). */
#include "distbound.h"

/* the side's constant angular velocity in free flight, or 0 when it does
 * not turn (or, as a true sphere, turns without moving its surface);
 * returns 0 when its spin is not constant */
static int constant_spin(const vrBody *b, vec3 *w)
{
    *w = vec3_zero();
    if (b->shape.kind == VR_SHAPE_SPHERE || b->rot == VR_ROT_NONE) return 1;
    if (b->rot == VR_ROT_KINEMATIC) {   /* held: the world omega itself (body.h) */
        *w = b->m.L;
        return 1;
    }
    if (b->rot != VR_ROT_ISOTROPIC) return 0;
    *w = vec3_scale(b->m.L, 1.0 / b->moments.x);
    return 1;
}

/* A box's highest vertex along body direction ob: each term of the dot
 * product at its largest, and since rounding is monotone the sum of the
 * largest terms is the largest sum: the same bits as the loop over its
 * eight vertices (+-half, never recentred). */
static double box_top(vec3 half, vec3 ob)
{
    return fabs(ob.x) * half.x + fabs(ob.y) * half.y + fabs(ob.z) * half.z;
}

/* How far the side reaches along out at te (its support), and when it
 * turns, the vertices that could be the highest within |tau| <= span: one
 * below the top by more than 2 |omega| R span cannot overtake the top,
 * which falls by at most |omega| R span while it rises by as much. */
static double reach(vrBoundSide *s, const vrBody *b, const vrPose *pose, vec3 out, vec3 w, double span)
{
    const vrPolyhedron *poly = b->shape.poly;
    vec3 ob, rate;
    double top, slack = 2.0 * s->w_len * s->r_out * span + 1e-12;
    int i;
    if (b->shape.kind == VR_SHAPE_SPHERE) return vec3_dot(out, pose->p) + b->shape.radius;
    ob = mat33_tmulv(&pose->R, out);   /* in the body frame: one rotation, not one per vertex */
    if (b->shape.kind == VR_SHAPE_BOX) {
        top = box_top(b->shape.half, ob);
    } else {
        top = -INFINITY;
        for (i = 0; i < poly->nv; i++) {
            double x = vec3_dot(ob, poly->vert[i]);
            if (x > top) top = x;
        }
    }
    if (s->w_len == 0) return vec3_dot(out, pose->p) + top;
    rate = vec3_cross(ob, mat33_tmulv(&pose->R, w));
    for (i = 0; i < poly->nv && s->nv >= 0; i++) {
        double g = vec3_dot(ob, poly->vert[i]) - top;
        if (g < -slack) continue;
        if (s->nv == VR_DISTBOUND_VERTS) {
            s->nv = -1;
            break;
        }
        s->g[s->nv] = g;
        s->s[s->nv] = vec3_dot(poly->vert[i], rate);   /* out . (omega x r) */
        s->nv++;
    }
    return vec3_dot(out, pose->p) + top;
}

/* one side seen from te along its outward direction: its support there in
 * *top; 0 when it gives no bounds */
static int side_make(vrBoundSide *s, vrBody *b, const vrPose *pose, vec3 out, const vec3 *witness,
                     double te, double lo, double hi, double *top)
{
    vec3 w = vec3_zero();
    s->v = s->a = s->u = s->acc = vec3_zero();
    s->w_len = s->jerk = 0;
    s->r_out = b->r_out;
    s->nv = 0;
    if (b->shape.kind != VR_SHAPE_SPHERE && !b->shape.poly) return 0;   /* nothing to bound */
    if (vrBody_IsFree(b)) {                              /* else static or resting: frozen */
        double cap = b->m.t0 + b->m.tcap;
        /* the speed cap must not bend the path inside the window: it comes
         * after it, or came before (the path is then a line) */
        if (lo < b->m.t0 || (lo < cap && hi > cap)) return 0;
        if (!constant_spin(b, &w)) return 0;
        vrBody_Velocity(b, te, &s->v);
        s->a = lo < cap ? b->m.a : vec3_zero();
        s->w_len = vec3_len(w);
        if (witness) {   /* for the upper bound */
            vec3 r = vec3_sub(*witness, pose->p);
            s->u = vec3_add(s->v, vec3_cross(w, r));
            s->acc = vec3_add(s->a, vec3_cross(w, vec3_cross(w, r)));
            s->jerk = s->w_len * s->w_len * s->w_len * vec3_len(r);
        }
    }
    *top = reach(s, b, pose, out, w, hi - lo);
    /* no surface point gets farther than R from the centre */
    s->headroom = b->r_out - (*top - vec3_dot(out, pose->p));
    return 1;
}

/* The plane bound of frozen box fz (pose pf) under body o (pose po, side
 * so made with its motion): fz's face that best faces out (from fz toward
 * o), and o's point lowest over its plane at te.  0 when fz is no box or
 * the point is not over the face. */
static int plane_make(vrPlaneBound *pl, const vrBody *fz, const vrPose *pf, vec3 out, const vrBody *o,
                      const vrPose *po, const vrBoundSide *so)
{
    vec3 ob = mat33_tmulv(&pf->R, out), half = fz->shape.half, nrm, x, r, w, u, acc, xb;
    double room;
    int k = 0, i;
    if (fz->shape.kind != VR_SHAPE_BOX) return 0;
    for (i = 1; i < 3; i++)   /* the face: the body axis nearest out */
        if (fabs(vec3_get(ob, i)) > fabs(vec3_get(ob, k))) k = i;
    nrm = vec3_scale(mat33_col(&pf->R, k), vec3_get(ob, k) < 0 ? -1 : 1);
    pl->floor = 0;
    if (o->shape.kind == VR_SHAPE_SPHERE) {
        x = po->p;
        pl->floor = -o->shape.radius;
    } else if (o->shape.kind == VR_SHAPE_BOX) {
        vec3 down = mat33_tmulv(&po->R, nrm), v = o->shape.half;
        x = vrPose_apply(po, vec3_make(down.x > 0 ? -v.x : v.x, down.y > 0 ? -v.y : v.y, down.z > 0 ? -v.z : v.z));
    } else {
        return 0;
    }
    w = vec3_zero();
    if (vrBody_IsFree(o) && !constant_spin(o, &w)) return 0;
    r = vec3_sub(x, po->p);
    u = vec3_add(so->v, vec3_cross(w, r));
    acc = vec3_add(so->a, vec3_cross(w, vec3_cross(w, r)));
    /* the face is the plane n.x = half_k + n.p */
    pl->h0 = vec3_dot(nrm, vec3_sub(x, pf->p)) - vec3_get(half, k) + pl->floor;
    pl->h1 = vec3_dot(nrm, u);
    pl->h2 = 0.5 * vec3_dot(nrm, acc);
    pl->cubic = vec3_len2(w) * vec3_len(w) * vec3_len(r) / 6.0;
    pl->move1 = vec3_len(u);
    pl->move2 = 0.5 * vec3_len(acc);
    /* how far inside the face's edges the point is, seen along the normal */
    xb = mat33_tmulv(&pf->R, vec3_sub(x, pf->p));
    room = INFINITY;
    for (i = 0; i < 3; i++)
        if (i != k) room = vr_min(room, vec3_get(half, i) - fabs(vec3_get(xb, i)));
    pl->room = room - 1e-9;
    return pl->room > 0;
}

void vrDistBound_MakeAlong(vrDistBound *db, vrBody *A, const vrPose *pose_a, vrBody *B, const vrPose *pose_b,
                           double te, vec3 n, double lo, double hi)
{
    double top_a, top_b;
    db->valid = 0;
    if (!(lo <= te && te <= hi)) return;
    db->te = te;
    db->gap0 = vec3_zero();
    db->shrink = 0;
    db->has_upper = db->has_plane = 0;
    db->n = n;
    if (!side_make(&db->a, A, pose_a, n, NULL, te, lo, hi, &top_a)
        || !side_make(&db->b, B, pose_b, vec3_neg(n), NULL, te, lo, hi, &top_b))
        return;
    db->gap_n = -top_b - top_a;
    db->valid = 1;
}

/* the point whose motion the upper bound carries: p, or a sphere's centre
 * (its radius added to *shrink) */
static vec3 witness(const vrBody *b, const vrPose *pose, vec3 p, double *shrink)
{
    if (b->shape.kind != VR_SHAPE_SPHERE) return p;
    *shrink += b->shape.radius;
    return pose->p;
}

void vrDistBound_Make(vrDistBound *db, vrBody *A, const vrPose *pose_a, vrBody *B, const vrPose *pose_b,
                      double te, vec3 pa, vec3 pb, int on_bodies, double lo, double hi)
{
    vec3 gap = vec3_sub(pb, pa), wa, wb;
    double len = vec3_len(gap), top_a, top_b;
    db->valid = 0;
    if (!(len > 0) || !(lo <= te && te <= hi)) return;
    db->te = te;
    db->n = vec3_scale(gap, 1.0 / len);
    /* a sphere is as far from anything as its centre, less its radius:
     * carrying the centre, the bound does not grow as the sphere slides */
    db->shrink = 0;
    wa = witness(A, pose_a, pa, &db->shrink);
    wb = witness(B, pose_b, pb, &db->shrink);
    db->gap0 = vec3_sub(wb, wa);
    db->has_upper = on_bodies || (A->shape.kind == VR_SHAPE_SPHERE && B->shape.kind == VR_SHAPE_SPHERE);
    if (!side_make(&db->a, A, pose_a, db->n, &wa, te, lo, hi, &top_a)
        || !side_make(&db->b, B, pose_b, vec3_neg(db->n), &wb, te, lo, hi, &top_b))
        return;
    db->gap_n = -top_b - top_a;
    db->has_plane = !vrBody_IsFree(A) ? plane_make(&db->plane, A, pose_a, db->n, B, pose_b, &db->b)
                  : !vrBody_IsFree(B) ? plane_make(&db->plane, B, pose_b, vec3_neg(db->n), A, pose_a, &db->a) : 0;
    db->valid = 1;
}

/* the highest of n lines g + s tau at tau */
static double highest_line(const double *g, const double *s, int n, double tau)
{
    double top = -INFINITY;
    int i;
    for (i = 0; i < n; i++) {
        double h = g[i] + s[i] * tau;
        if (h > top) top = h;
    }
    return top;
}

/* how much higher the side's support along its outward direction can be at tau */
static double rise(const vrBoundSide *s, double tau)
{
    double turn = 0.5 * s->w_len * s->w_len * s->r_out * tau * tau;
    if (s->w_len == 0) return 0;
    if (s->nv < 0) return vr_min(s->w_len * s->r_out * fabs(tau) + turn, s->headroom);
    return vr_min(highest_line(s->g, s->s, s->nv, tau) + turn, s->headroom);
}

static double lower_at(const vrDistBound *db, double tau)
{
    vec3 dv = vec3_madd(vec3_scale(vec3_sub(db->b.v, db->a.v), tau), 0.5 * tau * tau, vec3_sub(db->b.a, db->a.a));
    return db->gap_n + vec3_dot(db->n, dv) - rise(&db->a, tau) - rise(&db->b, tau);
}

/* A side looking forward only (tau >= 0): the lines that can be the
 * highest there (none: it does not turn; too many vertices: the one line
 * |omega| R tau), the turn term's coefficient, and the cap. */
typedef struct vrAhead {
    int n;
    double g[VR_DISTBOUND_VERTS], s[VR_DISTBOUND_VERTS];
    double turn, headroom;
} vrAhead;

static void ahead_of(const vrBoundSide *side, vrAhead *f)
{
    int i, top;
    f->n = 0;
    f->turn = 0.5 * side->w_len * side->w_len * side->r_out;
    f->headroom = side->headroom;
    if (side->w_len == 0) return;
    if (side->nv < 0) {
        f->n = 1;
        f->g[0] = 0;
        f->s[0] = side->w_len * side->r_out;
        return;
    }
    /* the top line at 0 (of those, the steepest) stays on the envelope until
     * a steeper one overtakes it; no line as slow as it ever does */
    for (i = top = 0; i < side->nv; i++)
        if (side->g[i] > side->g[top] || (side->g[i] == side->g[top] && side->s[i] > side->s[top])) top = i;
    for (i = 0; i < side->nv; i++) {
        if (i != top && side->s[i] <= side->s[top]) continue;
        f->g[f->n] = side->g[i];
        f->s[f->n] = side->s[i];
        f->n++;
    }
}

/* The first tau >= from at which c + b tau + a tau^2 <= 0: from when it
 * is not above 0 there, INFINITY when never.  The roots come from the
 * stable form, so the polynomial is within rounding of 0 at them, far
 * inside the margin a key adds to d, however ill-conditioned they are. */
static double first_down(double a, double b, double c, double from)
{
    double q, r1, r2, disc;
    if (!(c + (b + a * from) * from > 0)) return from;
    if (a == 0) return b < 0 ? vr_max(from, -c / b) : INFINITY;
    disc = b * b - 4 * a * c;
    if (disc < 0) return a > 0 ? INFINITY : from;
    q = -0.5 * (b + (b < 0 ? -sqrt(disc) : sqrt(disc)));
    r1 = q / a;
    r2 = q != 0 ? c / q : r1;
    if (r1 > r2) q = r1, r1 = r2, r2 = q;
    if (a > 0) return from < r1 ? r1 : from > r2 ? INFINITY : from;  /* above 0 outside the roots */
    return from < r2 ? r2 : from;                                     /* above 0 between them */
}

/* line k of a side looking ahead, g + s tau + turn tau^2 (0 for a side
 * that does not turn), or (at = 1) its headroom, the most it can ever rise */
static void ahead_line(const vrAhead *f, int at, int k, double *g, double *s, double *turn)
{
    *g = *s = *turn = 0;
    if (at) *g = f->headroom;
    else if (f->n > 0) *g = f->g[k], *s = f->s[k], *turn = f->turn;
}

/* how long the gap (base + closing tau + half_accel tau^2) stays above the
 * rises of a and b, each taken as its lines or (ha, hb) as its headroom:
 * the first time any line of one plus any of the other reaches it (or
 * any time not after `known`, once it is clear it will be no later) */
static double clear_of(const vrAhead *a, int ha, const vrAhead *b, int hb, double base, double closing,
                       double half_accel, double from, double known)
{
    int na = ha || a->n == 0 ? 1 : a->n, nb = hb || b->n == 0 ? 1 : b->n, i, j;
    double t = INFINITY;
    for (i = 0; i < na; i++)
        for (j = 0; j < nb && t > known; j++) {
            double ga, sa, qa, gb, sb, qb;
            ahead_line(a, ha, i, &ga, &sa, &qa);
            ahead_line(b, hb, j, &gb, &sb, &qb);
            t = vr_min(t, first_down(half_accel - qa - qb, closing - sa - sb, base - ga - gb, from));
        }
    return t;
}

/* How long the lower bound stays above d, from `from` on (the caller
 * knows the pair clear before it), in closed form: a side rises as the
 * lower of its highest line (plus the turn term) and its headroom, so the
 * bound is above d while, for one of the four choices of line or headroom
 * on each side, every pair of lines leaves the gap above d; each pair
 * gives a quadratic, and its first root.  A side that does not turn has
 * one line, 0, and no headroom to choose.  (Conservative advancement in
 * a fixed number of steps stops short of where the bound goes.) */
double vrDistBound_Clear(const vrDistBound *db, double d, double from, double until)
{
    double tau = from > db->te ? from - db->te : 0, span = until - db->te, closing, half_accel, base, t;
    vrAhead fa, fb;
    int ha, hb, it;
    if (!db->valid) return db->te;
    closing = vec3_dot(db->n, vec3_sub(db->b.v, db->a.v));
    half_accel = 0.5 * vec3_dot(db->n, vec3_sub(db->b.a, db->a.a));
    base = db->gap_n - d;
    ahead_of(&db->a, &fa);
    ahead_of(&db->b, &fb);
    for (it = 0; it < 4; it++) {
        t = tau;
        for (ha = fa.n != 0; ha >= 0; ha--)   /* the headrooms first: one root, often the latest */
            for (hb = fb.n != 0; hb >= 0; hb--)
                t = vr_max(t, clear_of(&fa, ha, &fb, hb, base, closing, half_accel, tau, t));
        if (t >= span) return until;
        /* a pair of lines that dipped to d and rose again ended it early:
         * on from there while the bound is clearly above d */
        if (!(t > tau && lower_at(db, t) - d > 1e-12)) break;
        tau = t;
    }
    return db->te + t;
}

/* Is the point's height over the face plane surely below level at tau,
 * with the point surely over the face (so the bodies are no farther apart
 * than that)? */
static int under_level(const vrPlaneBound *pl, double tau, double level)
{
    double at = fabs(tau), cube = pl->cubic * at * at * at, h = pl->h0 + (pl->h1 + pl->h2 * tau) * tau;
    return h + cube < level && h - cube >= pl->floor && (pl->move1 + pl->move2 * at) * at + cube <= pl->room;
}

int vrDistBound_Decide(const vrDistBound *db, double t, double d, double tol)
{
    double tau = t - db->te, lower, upper;
    vec3 rel;
    if (!db->valid) return -1;
    /* the gap along n: the centres move exactly, the turning supports at most rise() */
    lower = lower_at(db, tau);
    if (lower > d + tol) return 0;
    if (db->has_plane && under_level(&db->plane, tau, d - tol)) return 1;
    if (!db->has_upper) return -1;
    /* the witness points carried along: their distance is at least the bodies' */
    rel = vec3_madd(vec3_madd(db->gap0, tau, vec3_sub(db->b.u, db->a.u)), 0.5 * tau * tau,
                    vec3_sub(db->b.acc, db->a.acc));
    upper = vec3_len(rel) - db->shrink + (db->a.jerk + db->b.jerk) * fabs(tau * tau * tau) / 6.0;
    if (upper < d - tol) return 1;
    return -1;
}

static double cubic_at(double c0, double c1, double c2, double c3, double tau)
{
    return c0 + tau * (c1 + tau * (c2 + tau * c3));
}

/* A tau >= 0 no later than the first at which c0 + c1 tau + c2 tau^2 +
 * c3 tau^3 (every ci >= 0, c0 < level) reaches level, and close to it.
 * Each term alone up to a third of the room is below it.  The curve is
 * convex and rising: a Newton step from below lands past the crossing,
 * and the chord between the two lies above the curve, so where the chord
 * reaches level is still before the crossing.  INFINITY when it never
 * rises. */
static double rise_to(double c0, double c1, double c2, double c3, double level)
{
    double third = (level - c0) / 3.0, lo = INFINITY;
    int i;
    if (c1 > 0) lo = third / c1;
    if (c2 > 0) lo = vr_min(lo, sqrt(third / c2));
    if (c3 > 0) lo = vr_min(lo, cbrt(third / c3));
    for (i = 0; i < 3 && lo < INFINITY; i++) {
        double f = cubic_at(c0, c1, c2, c3, lo) - level, slope = c1 + lo * (2 * c2 + 3 * lo * c3), hi, g;
        if (!(f < 0 && slope > 0)) break;
        hi = lo - f / slope;
        g = cubic_at(c0, c1, c2, c3, hi) - level;
        if (!(g > f)) break;
        lo = vr_max(lo, lo - f * (hi - lo) / (g - f));
    }
    return lo;
}

/* the plane bound's time: its height rising at most as its rising terms,
 * and the point staying over the face */
static double plane_stays(const vrPlaneBound *pl, double level)
{
    if (!(pl->h0 < level)) return 0;
    return vr_min(rise_to(pl->h0, vr_max(pl->h1, 0), vr_max(pl->h2, 0), pl->cubic, level),
                  rise_to(0, pl->move1, pl->move2, pl->cubic, pl->room));
}

/* the first tau > 0 with |g + u tau| = L, given |g| < L */
static double line_leaves(vec3 g, vec3 u, double L)
{
    double a = vec3_dot(u, u), b = vec3_dot(g, u), c = vec3_dot(g, g) - L * L;
    if (a == 0) return INFINITY;
    /* the positive root of a tau^2 + 2 b tau + c (c < 0), in the stable form */
    return b > 0 ? -c / (b + sqrt(b * b - a * c)) : (-b + sqrt(b * b - a * c)) / a;
}

/* The witness points' bound: their gap g + u tau + acc tau^2 / 2 within
 * jerk |tau|^3 / 6 is at most |g + u tau| (convex: above L only past its
 * root) plus the rest, which only grows.  So, for any tau_x, the root of
 * |g + u tau| = L less the rest at tau_x, if no later than tau_x, is a
 * time before which the bound holds; tau_x starts where the line alone
 * leaves and shrinks while the rest there leaves no room.  Or, at the
 * least, what the triangle inequality gives. */
static double witness_stays(const vrDistBound *db, double level)
{
    vec3 u = vec3_sub(db->b.u, db->a.u);
    double acc = vec3_len(vec3_sub(db->b.acc, db->a.acc)), jerk = db->a.jerk + db->b.jerk;
    double L = level + db->shrink, g = vec3_len(db->gap0), tri, x;
    int i;
    if (!(g < L)) return 0;
    tri = rise_to(g, vec3_len(u), 0.5 * acc, jerk / 6.0, L);
    x = line_leaves(db->gap0, u, L);
    for (i = 0; i < 4 && x < INFINITY; i++) {
        double rest = (0.5 * acc + jerk / 6.0 * x) * x * x;
        if (g < L - rest) return vr_max(tri, vr_min(x, line_leaves(db->gap0, u, L - rest)));
        x *= 0.25;
    }
    return tri;
}

double vrDistBound_StaysWithin(const vrDistBound *db, double level, double until)
{
    double tau = 0;
    if (!db->valid) return db->te;
    if (db->has_plane) tau = plane_stays(&db->plane, level);
    if (db->has_upper) tau = vr_max(tau, witness_stays(db, level));
    return vr_min(db->te + tau, until);
}
