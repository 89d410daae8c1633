/* cheap_look.c — looks that prove a pair clear of the envelope without
 * its contact region, and give it a key from what they measured: the
 * bounding spheres about the centres, then the closest-feature walk.
 * Only with the heap, and never for a pair inside or supporting (heap = 0
 * makes the full look, and the two must agree). */
#include "owner_state.h"

/* heap = 0 is the thesis's ablation: every pair looked at fully, every
 * step; a pair in the envelope always is (its events need the contact) */
static int cheap_look_allowed(const vrOwner *o, const vrPair *p)
{
    return o->p.use_heap && !p->inside;
}

/* the walk's distance when it is clear of the envelope: outside, no event,
 * and a key from that distance (VR_QUICK_CLEAR below it: the canonical
 * distance a full look measures may be that much less; heap = 0 makes the
 * full look, and the two must agree) */
int vrPair_ClearByWalk(vrOwner *o, int pi, double t)
{
    vrPair *p = &o->pair[pi];
    vrBody *A = o->body[p->a], *B = o->body[p->b];
    vrPose pa, pb;
    double dist;
    vec3 n;
    if (!cheap_look_allowed(o, p) || vrBody_IsSphere(A) || vrBody_IsSphere(B)) return 0;
    vrBody_Pose(A, t, &pa);
    vrBody_Pose(B, t, &pb);
    if (vrContact_Quick(&A->shape, &pa, &B->shape, &pb, &p->cache, &dist, &n) != 0) return 0;
    o->checks++;
    if (dist <= o->p.d + VR_QUICK_CLEAR) return 0;
    p->t_check = t;
    if (!vrOwner_PutOffKey(o, pi, dist - VR_QUICK_CLEAR, n))
        vrPair_Settle(o, pi, 0, vrPair_Key(o, p, t, dist - VR_QUICK_CLEAR, n));
    return 1;
}

/* the gap between the bodies' bounding spheres about their centres at t (a
 * lower bound on their distance) and the unit direction from a's centre to
 * b's (zero when the centres meet) */
static double sphere_gap(const vrOwner *o, const vrPair *p, double t, vrCentres *c, vec3 *dir)
{
    const vrBody *A = o->body[p->a], *B = o->body[p->b];
    vrCentres_At(A, B, t, c);
    *dir = c->len > 0 ? vec3_scale(vec3_sub(c->xb, c->xa), 1.0 / c->len) : vec3_zero();
    return c->len - A->r_out - B->r_out;
}

double vrPair_SphereGap(const vrOwner *o, const vrPair *p, double t, vec3 *dir)
{
    vrCentres c;
    return sphere_gap(o, p, t, &c, dir);
}

/* A cheap look first: the bounding spheres about the centres are a lower
 * bound on the distance.  When they are clear of the envelope, the full
 * query could only find the pair outside with nothing to do, and the
 * spheres' key (they do not change as the bodies turn) is as valid as the
 * full one, if earlier: the pair is looked at again then, unless a change
 * of either body comes first (in a crowded room, bodies are hit many
 * times a second, so an earlier key rarely costs a look, and taking it
 * only when it passed the frame's end costs more).  A support pair always
 * gets the full look (its support may have to end). */
int vrPair_ClearBySpheres(vrOwner *o, int pi, double t)
{
    vrPair *p = &o->pair[pi];
    vrCentres c;
    vec3 dir;
    double gap, key;
    if (!cheap_look_allowed(o, p)) return 0;
    gap = sphere_gap(o, p, t, &c, &dir);
    if (gap <= o->p.d || vec3_len2(dir) == 0) return 0;
    key = vrSchedule_SphereKey(o->body[p->a], o->body[p->b], t, &c, gap, dir, o->p.d, &o->p.flight);
    if (!(key > t)) return 0;
    p->t_check = t;
    vrPair_Settle(o, pi, 0, key);
    return 1;
}
