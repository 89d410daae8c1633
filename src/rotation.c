/* rotation.c — torque-free rotation between events (thesis 3.2.3, SPEC
 * 3.2): the orientation at tau after a body's anchor, for each kind of
 * body (body.h's vrRotKind).
 *
 *   subflow, open_flows, rot_step   the splitting of an asymmetric body's
 *                                   free rotation into exact principal turns
 *   open_step, rot_state_at         its fixed sub-steps from the anchor, with
 *                                   the cache of checkpoints (body.h)
 *   general_orientation             an asymmetric body
 *   symmetric_orientation           a symmetric top: regular precession
 *   vrRotation_Orientation          each kind, isotropic and kinematic too
 *
 * The splitting (McLachlan 1993; Dullweber, Leimkuhler, McLachlan 1997)
 * keeps L to rounding and does not drift in energy; it runs on a fixed
 * grid from t0, so the orientation is a pure function of the anchor and
 * tau in every process that holds the body.
 */
#include "rotation.h"

#define CHECKPOINT_EVERY 64

static double moment(const vrBody *b, int k) { return vec3_get(b->moments, k); }

/* one exact sub-flow of H_k = Pi_k^2 / 2 I_k for time s: Pi turns about
 * e_k by -theta, the principal frame by +theta about its own axis k */
static void subflow(const vrBody *b, int k, double s, vrRotState *st)
{
    double pk = k == 0 ? st->Pi.x : k == 1 ? st->Pi.y : st->Pi.z;
    double th = pk * s / moment(b, k), hc = cos(0.5 * th), hs = sin(0.5 * th);
    double c = 1.0 - 2.0 * hs * hs, sn = 2.0 * hs * hc;     /* of th, from the half angle's */
    vec3 p = st->Pi;
    quat r = quat_make(hc, k == 0 ? hs : 0, k == 1 ? hs : 0, k == 2 ? hs : 0);
    if (k == 0) st->Pi = vec3_make(p.x, c * p.y + sn * p.z, -sn * p.y + c * p.z);
    if (k == 1) st->Pi = vec3_make(c * p.x - sn * p.z, p.y, sn * p.x + c * p.z);
    if (k == 2) st->Pi = vec3_make(c * p.x + sn * p.y, -sn * p.x + c * p.y, p.z);
    st->Q = quat_mul(st->Q, r);
}

/* the flows of x for s, y for h/2, z for h, y for h/2: a step of h whose
 * closing x flow is left open */
static void open_flows(const vrBody *b, double s, double h, vrRotState *st)
{
    subflow(b, 0, s, st);
    subflow(b, 1, 0.5 * h, st);
    subflow(b, 2, h, st);
    subflow(b, 1, 0.5 * h, st);
}

/* Strang splitting, symmetric in time (second order, symplectic): the
 * flows of x for h/2, y for h/2, z for h, y for h/2, x for h/2 */
static void rot_step(const vrBody *b, double h, vrRotState *st)
{
    open_flows(b, 0.5 * h, h, st);
    subflow(b, 0, 0.5 * h, st);
}

/* The cache keeps whole steps n >= 1 "open": without their closing x flow
 * for h/2, which the next step's opening one joins (two flows about one
 * axis add exactly), so a step costs four flows, not five.  Step 0 (the
 * anchor) is whole.  One step on from st: */
static void open_step(const vrBody *b, double h, vrRotState *st)
{
    open_flows(b, st->step == 0 ? 0.5 * h : h, h, st);
    st->step++;
}

static void push_checkpoint(vrRotCache *rc, const vrRotState *st)
{
    if (rc->nring == VR_ROT_CHECKPOINTS) {
        int i;
        for (i = 1; i < VR_ROT_CHECKPOINTS; i++) rc->ring[i - 1] = rc->ring[i];
        rc->nring--;
    }
    rc->ring[rc->nring++] = *st;
}

/* integrator state at whole step n (open, but step 0), from the nearest
 * cached state before it */
static vrRotState rot_state_at(vrBody *b, long n)
{
    vrRotCache *rc = &b->rc;
    vrRotState st = rc->anchor;
    int i;
    if (n >= rc->last.step) {
        st = rc->last;
    } else {
        for (i = rc->nring - 1; i >= 0 && rc->ring[i].step > n; i--)
            ;
        if (i >= 0) st = rc->ring[i];
    }
    while (st.step < n) {
        open_step(b, rc->h, &st);
        if (st.step % CHECKPOINT_EVERY == 0 && (rc->nring == 0 || st.step > rc->ring[rc->nring - 1].step))
            push_checkpoint(rc, &st);
    }
    rc->last = st;
    return st;
}

static quat general_orientation(vrBody *b, double tau)
{
    long n = (long)floor(tau / b->rc.h);
    vrRotState st = rot_state_at(b, n);
    double rest = tau - (double)n * b->rc.h;
    if (n == 0) {
        if (rest > 0) rot_step(b, rest, &st);
    } else if (rest > 0) {        /* step n's closing x flow joins the rest's opening one */
        open_flows(b, 0.5 * (b->rc.h + rest), rest, &st);
        subflow(b, 0, 0.5 * rest, &st);
    } else {
        subflow(b, 0, 0.5 * b->rc.h, &st);
    }
    return quat_mul(quat_normalize(st.Q), quat_conj(b->principal));
}

/* regular precession of a symmetric top: about L at |L|/I_t, and about the
 * symmetry axis at Pi_s (1/I_s - 1/I_t) */
static quat symmetric_orientation(const vrBody *b, double tau)
{
    int s = b->sym_axis;
    double it = moment(b, s == 0 ? 1 : 0), is = moment(b, s);
    const vrRotState *a = &b->rc.anchor;
    double ps = s == 0 ? a->Pi.x : s == 1 ? a->Pi.y : a->Pi.z;
    vec3 axis = vec3_make(s == 0, s == 1, s == 2);
    quat spin = quat_from_rotvec(vec3_scale(axis, ps * (1.0 / is - 1.0 / it) * tau));
    quat prec = quat_from_rotvec(vec3_scale(b->m.L, tau / it));
    quat Q = quat_mul(quat_mul(prec, a->Q), spin);
    return quat_mul(quat_normalize(Q), quat_conj(b->principal));
}

quat vrRotation_Orientation(vrBody *b, double tau)
{
    switch (b->rot) {
    case VR_ROT_ISOTROPIC:
        return quat_normalize(quat_mul(quat_from_rotvec(vec3_scale(b->m.L, tau / b->moments.x)), b->m.q0));
    case VR_ROT_SYMMETRIC:
        return symmetric_orientation(b, tau);
    case VR_ROT_GENERAL:
        return general_orientation(b, tau);
    case VR_ROT_KINEMATIC:   /* the hand's slerp: a constant world omega */
        return quat_normalize(quat_mul(quat_from_rotvec(vec3_scale(b->m.L, tau)), b->m.q0));
    default:
        return b->m.q0;
    }
}
