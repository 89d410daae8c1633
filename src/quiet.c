/* quiet.c — proofs that a pair inside the envelope has nothing to do
 * for a while, so that it is not looked at until then (heap = 1 only;
 * heap = 0 looks and finds nothing, so the bits are the same):
 *   box_face_axis, over_face   a level face of a static box, a ball's centre over it
 *   quiet_slide                a ball sliding on or grazing such a face
 *   vrPair_QuietHorizon        how far ahead the proofs hold
 *   stays_within, stays_by_bounds, vrPair_ApproachHorizon   a pair in the envelope, not touching */
#include "owner_state.h"
#include "schedule.h"

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

/* ball S's centre stays over the face of static box Y whose normal is
 * axis k, inside it by margin, until `until` */
static int over_face(const vrBody *S, const vrBody *Y, int k, double t, double until, double margin)
{
    vec3 lo, hi;
    int j;
    vrBody_PathBox(S, t, until, &lo, &hi);
    for (j = 0; j < 3; j++) {
        double at = vec3_get(Y->m.x0, j), half = vec3_get(Y->shape.half, j) - margin;
        if (j != k && !(vec3_get(lo, j) - at > -half && vec3_get(hi, j) - at < half)) return 0;
    }
    return 1;
}

/* A ball sliding on a level table, or grazing a wall: a sphere in the
 * envelope of a static box with no rotation, the contact normal an axis, no velocity or acceleration along it,
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
    if (!vrBody_IsSphere(S) || !vrBody_IsFree(S)) return 0;
    if ((k = box_face_axis(B, c->n)) < 0) return 0;
    if (vec3_get(S->m.v0, k) != 0 || vec3_get(S->m.a, k) != 0) return 0;
    return over_face(S, B, k, t, until, 1e-9);
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
/* how far inside the envelope a pair proved to stay in it stays: far above
 * the rounding of positions (1e-13 m a minute into a run) */
#define STAY_MARGIN 1e-9

double vrPair_QuietHorizon(vrOwner *o, const vrPair *p, double t, const vrContact *c)
{
    double T = o->bp.T;
    if (!quiet_slide(o, p, t, T, c)) return -INFINITY;
    return quiet_slide(o, p, t, T + QUIET_AHEAD, c) ? T + QUIET_AHEAD : T;
}

/* the first tau with dist + s tau + acc tau^2 / 2 = level (dist < level) */
static double reach_level(double dist, double s, double acc, double level)
{
    double room = level - dist;
    if (acc == 0) return s > 0 ? room / s : INFINITY;
    return 2.0 * room / (s + sqrt(s * s + 2.0 * acc * room));
}

/* How long the pair surely stays within level (its distance dist at t).
 * Two points of the bodies that are dist apart at t move apart no faster
 * than the centres' relative velocity, which changes by at most |a_b -
 * a_a| a second until a speed cap and |a_a| + |a_b| after, plus each
 * body's |omega| R (vrSchedule_SpinReach: a true sphere's surface does not
 * matter, its distance is its centre's less the radius); the distance is
 * at most theirs.  dist is canonical:
 * the true distance may be VR_QUICK_CLEAR above it (contact.h). */
static double stays_within(vrBody *A, vrBody *B, double t, double dist, double level)
{
    vec3 va, vb;
    double s, tau;
    vrBody_Velocity(A, t, &va);
    vrBody_Velocity(B, t, &vb);
    s = vec3_len(vec3_sub(vb, va)) + vrSchedule_SpinReach(A) + vrSchedule_SpinReach(B);
    dist += VR_QUICK_CLEAR;
    if (!(dist < level)) return t;
    tau = reach_level(dist, s, vec3_len(vec3_sub(B->m.a, A->m.a)), level);
    if (tau > vr_min(vrSchedule_CapLeft(A, t), vrSchedule_CapLeft(B, t)))
        tau = reach_level(dist, s, vec3_len(A->m.a) + vec3_len(B->m.a), level);
    return t + tau;
}

/* the point of box b nearest p: a point of the body whatever p is */
static vec3 onto_box(const vrBody *b, const vrPose *pose, vec3 p)
{
    vec3 q = mat33_tmulv(&pose->R, vec3_sub(p, pose->p)), h = b->shape.half;
    q = vec3_make(vr_min(vr_max(q.x, -h.x), h.x), vr_min(vr_max(q.y, -h.y), h.y), vr_min(vr_max(q.z, -h.z), h.z));
    return vec3_add(pose->p, mat33_mulv(&pose->R, q));
}

/* The same from distbound.h's upper bounds, which follow the motion: the
 * distance is at most that of two points of the bodies carried along (a
 * sphere's contact points are its own; a box's canonical point, which need
 * not be, is moved onto it, which only makes the start farther), and with
 * a frozen box (a wall, a table top) at most the other body's lowest point
 * over its face while it stays over it.  A ball leaving a wall at a slant
 * leaves the envelope as fast as it rises from the face, not as fast as it
 * moves.  t when there are no such bounds. */
static double stays_by_bounds(vrOwner *o, const vrPair *p, double t, const vrPose *pa, const vrPose *pb,
                              const vrContact *c, double level)
{
    vrBody *A = o->body[p->a], *B = o->body[p->b];
    vrDistBound db;
    double hi = vr_min(o->bp.T + QUIET_AHEAD, t + vr_min(vrSchedule_CapLeft(A, t), vrSchedule_CapLeft(B, t)));
    int boxes = A->shape.kind == VR_SHAPE_BOX && B->shape.kind == VR_SHAPE_BOX;
    int on_bodies = vrBody_IsSphere(A) || vrBody_IsSphere(B) || boxes;
    vec3 wa = c->pa, wb = c->pb;
    if (vrBody_IsFree(A) && vrBody_IsFree(B) && !on_bodies) return t;
    if (boxes) wa = onto_box(A, pa, wa), wb = onto_box(B, pb, wb);
    vrDistBound_Make(&db, A, pa, B, pb, t, wa, wb, on_bodies, t, hi);
    return vrDistBound_StaysWithin(&db, level, hi);
}

/* A pair in the envelope and not touching has an event only once it comes
 * within g_c (an impact) or touches; until it leaves the envelope, heap =
 * 0 would find it there at every grid point and do nothing.  So it is
 * quiet until the earlier of: the key toward the touching level (its
 * distance cannot come down to it before), and the time it surely stays
 * in the envelope (its state, inside and not near, is then what every
 * look would find).  A pair after an impact flies out of the envelope,
 * and one coming in flies through it to g_c: a look every grid step was
 * most of a crowded room's looks.  -INFINITY when not quiet past t. */
double vrPair_ApproachHorizon(vrOwner *o, const vrPair *p, double t, const vrPose *pa, const vrPose *pb,
                              const vrContact *c)
{
    vrBody *A = o->body[p->a], *B = o->body[p->b];
    double near = o->gc + VR_PENETRATION_TOL + VR_QUICK_CLEAR, level = o->p.d - STAY_MARGIN, stay, until;
    if (!(c->dist > near)) return -INFINITY;
    /* the bounds on leaving first: a horizon short of the next grid point
     * skips nothing, and the key need not be followed past it */
    stay = vr_max(stays_within(A, B, t, c->dist, level), stays_by_bounds(o, p, t, pa, pb, c, level));
    if (!(stay >= t + o->step_h)) return -INFINITY;
    until = vr_min(stay, vrSchedule_KeyUpTo(A, B, t, c->dist, c->n, near, &o->p.flight, stay));
    return until >= t + o->step_h ? until : -INFINITY;
}
