/* quiet.c — proofs that a pair inside the envelope has nothing to do
 * for a while, so that it is not looked at until then (heap = 1 only;
 * heap = 0 looks and finds nothing, so the bits are the same):
 *   box_face_axis, over_face   a level face of a static box, a footprint over it
 *   quiet_slide                a ball sliding on or grazing such a face
 *   quiet_support              a body supported by such a face alone
 *   vrPair_QuietHorizon        how far ahead the proofs hold */
#include "owner_state.h"

/* The axis (0..2) the unit normal n lies exactly along, when B is a
 * static unrotated box, so that n can be the normal of one of its faces;
 * -1 otherwise */
static int box_face_axis(const vrBody *B, vec3 n)
{
    int k;
    if (!B->is_static || B->shape.kind != VR_SHAPE_BOX) return -1;
    if (B->m.q0.w != 1 || B->m.q0.x != 0 || B->m.q0.y != 0 || B->m.q0.z != 0) return -1;
    for (k = 0; k < 3 && fabs(vec3_get(n, k)) != 1; k++)
        ;
    if (k == 3 || vec3_get(n, (k + 1) % 3) != 0 || vec3_get(n, (k + 2) % 3) != 0) return -1;
    return k;
}

/* x's footprint (a ball's centre) stays over the face of static box Y
 * whose normal is axis k, inside it by margin, until `until`.  px is x's
 * pose at t (a ball's is not needed). */
static int over_face(const vrBody *X, const vrPose *px, const vrBody *Y, int k, double t, double until,
                     double margin)
{
    vec3 lo, hi;
    double turn = 0;
    int j;
    vrBody_PathBox(X, t, until, &lo, &hi);
    if (!vrBody_IsSphere(X)) {   /* its vertices now, carried along the path, and how far turning can carry them */
        vec3 vlo = px->p, vhi = px->p;
        for (j = 0; j < X->shape.poly->nv; j++) {
            vec3 w = vrPose_apply(px, X->shape.poly->vert[j]);
            vlo = vec3_min(vlo, w);
            vhi = vec3_max(vhi, w);
        }
        lo = vec3_add(vlo, vec3_sub(lo, px->p));
        hi = vec3_add(vhi, vec3_sub(hi, px->p));
        turn = X->m.spin * X->r_out * (until - t);
    }
    for (j = 0; j < 3; j++) {
        double at = vec3_get(Y->m.x0, j), half = vec3_get(Y->shape.half, j) - turn - margin;
        if (j != k && !(vec3_get(lo, j) - at > -half && vec3_get(hi, j) - at < half)) return 0;
    }
    return 1;
}

/* A ball sliding on a level table, or grazing a wall: a sphere in the
 * envelope of a static box with no rotation (its only support, if it has
 * one), the contact normal an axis, no velocity or acceleration along it,
 * and its centre over the face's inside (by 1e-9 m) until `until`.
 * Its distance then stays the same bits, its contact point lies exactly
 * beside its centre, and that point's normal velocity is exactly 0 however
 * it spins: every evaluation until then would find what this one found,
 * and none is made (with the heap; heap = 0 looks at every pair at every
 * step).  Anything that changes either body flags the pair, and its
 * evaluation starts afresh. */
static int quiet_slide(vrOwner *o, const vrPair *p, double t, double until, const vrContact *c)
{
    const vrBody *S = o->body[p->b], *B = o->body[p->a];
    int k;
    if (!vrBody_IsSphere(S)) S = o->body[p->a], B = o->body[p->b];
    if (!vrBody_IsSphere(S) || !vrBody_IsFree(S) || S->nsupport > 1 || (S->nsupport == 1 && S->support[0].partner != B->id))
        return 0;
    if ((k = box_face_axis(B, c->n)) < 0) return 0;
    if (vec3_get(S->m.v0, k) != 0 || vec3_get(S->m.a, k) != 0) return 0;
    return over_face(S, NULL, B, k, t, until, 1e-9);
}

/* A box, superquadric or ball sliding on a level static box (the table,
 * the floor), supported by it alone: every evaluation until `until` would
 * find it inside, supported, with no event, unless something changes
 * either body (which flags the pair) or its own motion brings a change.
 * This proves, from the query at t, that its motion cannot, and then no
 * evaluation is made until then (heap = 1 only; heap = 0 looks at every
 * pair at every step and finds nothing, so the runs keep the same bits).
 * Over [t, until] (length span), with the normal n along one of the box's
 * axes and x's footprint staying over the box's face:
 *  - x's spin changes at most |omega x L| / I_min a second, growing at
 *    most by e^(spin span) (torque-free: d omega/dt = -R I^-1 R^T (omega
 *    x L)); 4x for the integrator of asymmetric bodies;
 *  - so every point of x moves along n at most U = |n.v| + |n.a| span +
 *    w_perp R a second (w_perp: the spin's part off n; turning about n
 *    moves nothing along it), and at most H = U span in all: the contact
 *    points never approach or separate by v_eps / 2, the distance stays
 *    inside (0, d], and no vertex crosses the region's slab edge;
 *  - the region is x's near vertices turned about n and carried along,
 *    tilted at most w_perp span: the centre of mass stays inside it. */
#define QUIET_FACE_MARGIN 1e-6   /* m: x's footprint inside the box's face */

static int quiet_support(vrOwner *o, const vrPair *p, double t, double until, const vrPose *pa, const vrPose *pb,
                         const vrContact *c)
{
    int x_is_a = !vrBody_Frozen(o->body[p->a]);
    const vrBody *X = o->body[x_is_a ? p->a : p->b], *Y = o->body[x_is_a ? p->b : p->a];
    const vrPose *px = x_is_a ? pa : pb;
    vec3 n = x_is_a ? vec3_neg(c->n) : c->n, v, w, q;  /* n: from Y toward X */
    double span = until - t, top, w_perp, drift, U, H;
    int k, j;
    if (vrBody_Frozen(X) || X->nsupport != 1 || X->support[0].partner != Y->id || X->support[0].joint
        || c->npoints >= VR_REGION_MAX || (k = box_face_axis(Y, n)) < 0)
        return 0;
    if (2 * vec3_get(Y->shape.half, k) <= o->region + QUIET_FACE_MARGIN) return 0;  /* its far face stays out of the slab */
    vrBody_Velocity(X, t, &v);
    w = vrBody_Omega(X, px);
    drift = X->i_min > 0 ? vec3_len(vec3_cross(w, X->m.L)) / X->i_min * span * exp(X->m.spin * span) : 0;
    w_perp = vec3_len(vec3_madd(w, -vec3_dot(w, n), n)) + 4 * drift + 1e-12;
    U = fabs(vec3_dot(n, v)) + fabs(vec3_dot(n, X->m.a)) * span + w_perp * X->r_out;
    H = U * span + 1e-12;
    if (!(U <= 0.5 * VR_V_EPS) || !(c->dist - H > VR_PENETRATION_TOL) || !(c->dist + H < o->gc - 1e-9)) return 0;
    if (!over_face(X, px, Y, k, t, until, QUIET_FACE_MARGIN)) return 0;
    if (vrBody_IsSphere(X)) return 1;   /* its region is the point below its centre */
    top = vec3_dot(n, Y->m.x0) + vec3_get(Y->shape.half, k);
    for (j = 0; j < X->shape.poly->nv; j++) {
        double gap = vec3_dot(n, vrPose_apply(px, X->shape.poly->vert[j])) - top;
        if (fabs(gap - o->region) <= H + 1e-8) return 0;   /* it might enter or leave the region's slab */
    }
    q = vec3_madd(px->p, vec3_dot(vec3_sub(c->point[0], px->p), n), n);
    return vrRegion_Margin(c->point, c->npoints, n, q) > 2 * X->r_out * w_perp * span + 1e-8;
}

/* How far ahead of t an inside pair with no event at t is proved quiet:
 * to the frame's end, and then QUIET_AHEAD seconds past it when the proof
 * holds that far (a box or a ball sliding across a table would otherwise
 * be looked at again at the start of every frame; longer or shorter
 * horizons, or tries at a part of the frame when the whole fails, cost
 * more than they saved in the thesis's scenes).
 * -INFINITY when not quiet.  Nothing at a frame's end needs the pair
 * looked at: rest and support are decided from the bodies' states, and
 * whatever changes either body flags the pair. */
#define QUIET_AHEAD 0.1   /* s */

static int quiet_to(vrOwner *o, const vrPair *p, double t, double until, const vrPose *pa, const vrPose *pb,
                    const vrContact *c)
{
    return quiet_slide(o, p, t, until, c) || quiet_support(o, p, t, until, pa, pb, c);
}

double vrPair_QuietHorizon(vrOwner *o, const vrPair *p, double t, const vrPose *pa, const vrPose *pb,
                            const vrContact *c)
{
    double T = o->bp.T;
    if (!quiet_to(o, p, t, T, pa, pb, c)) return -INFINITY;
    return quiet_to(o, p, t, T + QUIET_AHEAD, pa, pb, c) ? T + QUIET_AHEAD : T;
}
