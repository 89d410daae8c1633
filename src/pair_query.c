/* pair_query.c — what a look at a pair measures: the canonical distance
 * and contact region at t (contact.c) from the poses at t, a region
 * remembered for the same poses, and the normal that events and islands
 * are decided from (flush surfaces, flush_normal).
 *   real_poses       a sphere's turning pose where events need its spin
 *   memo_*           the region memo (a pair asked again at the same poses)
 *   vrPair_Query     distance, or the whole contact with its region
 *   flush_normal     straight up across a seam between flush bodies
 *   vrPair_EventQuery the query events are decided from */
#include <string.h>
#include "owner_state.h"

/* what needs a sphere's spin (approach speeds, responses): its real pose,
 * where distances took vrBody_ShapePose's */
static void real_poses(vrOwner *o, const vrPair *p, double t, vrPose *pa, vrPose *pb)
{
    if (vrBody_IsSphere(o->body[p->a])) vrBody_Pose(o->body[p->a], t, pa);
    if (vrBody_IsSphere(o->body[p->b])) vrBody_Pose(o->body[p->b], t, pb);
}

static int same_bits(const void *x, const void *y, size_t n) { return memcmp(x, y, n) == 0; }

/* a contact and its region's points, not the unused room after them */
static void copy_contact(vrContact *to, const vrContact *from)
{
    int i;
    to->dist = from->dist, to->n = from->n, to->pa = from->pa, to->pb = from->pb;
    to->npoints = from->npoints, to->walk_steps = from->walk_steps;
    for (i = 0; i < from->npoints; i++) to->point[i] = from->point[i], to->gap[i] = from->gap[i];
}

/* A contact is a function of the two shapes, their poses and d alone
 * (SPEC 3.2's determinism rule), and a pair is asked again at the same
 * poses: after an event at a grid point the pairs of its bodies are
 * evaluated anew there, the responding one among them (a body's pose at
 * its own event is the same bits from its new anchor), and an instant's
 * touches are gathered again after each answer there.  The last region of
 * each of up to REGION_MEMO pairs is kept, with the serials of the shapes
 * it was made for (an edit remakes a shape in place, a body put anew has a
 * new one), in a slot found by hashing the pair: with 64 slots taken by
 * order modulo 64, a landing pile's 600 touching pairs missed nearly
 * every time (its first busy second: 16.7 G instructions, 12.5 G now). */
static vrRegionMemo *memo_slot(vrOwner *o, const vrPair *p)
{
    return &o->memo[((unsigned long long)p->order * 0x9E3779B97F4A7C15ULL) >> (64 - REGION_MEMO_BITS)];
}

static int memo_holds(const vrOwner *o, const vrRegionMemo *m, const vrPair *p, const vrPose *pa, const vrPose *pb)
{
    return m->order == p->order && m->shape_a == o->body[p->a]->shape.serial
        && m->shape_b == o->body[p->b]->shape.serial && m->d == o->region && same_bits(&m->pa, &pa->p, sizeof m->pa)
        && same_bits(&m->qa, &pa->q, sizeof m->qa) && same_bits(&m->pb, &pb->p, sizeof m->pb)
        && same_bits(&m->qb, &pb->q, sizeof m->qb);
}

void vrPair_Query(vrOwner *o, vrPair *p, double t, int region, vrPose *pa, vrPose *pb, vrContact *c)
{
    vrBody *A = o->body[p->a], *B = o->body[p->b];
    vrRegionMemo *m;
    vrBody_ShapePose(A, t, pa);
    vrBody_ShapePose(B, t, pb);
    if (!region) {
        o->checks++;
        vrContact_Distance(&A->shape, pa, &B->shape, pb, &p->cache, c);
        return;
    }
    m = memo_slot(o, p);
    if (memo_holds(o, m, p, pa, pb)) {
        copy_contact(c, &m->c);
        return;
    }
    o->checks++;
    if (vrContact_Region(&A->shape, pa, &B->shape, pb, o->region, &p->cache, c) != 0) return;
    m->order = p->order, m->d = o->region, m->pa = pa->p, m->qa = pa->q, m->pb = pb->p, m->qb = pb->q;
    m->shape_a = A->shape.serial, m->shape_b = B->shape.serial;
    copy_contact(&m->c, c);
}

/* Flush surfaces (a table top made of two boxes side by side): a body
 * sliding on one meets the next one's edge at a slant inside the envelope,
 * and the slanted normal would kick it back (Box2D's ghost collisions,
 * Bullet's internal edges).  When x lies on something (in an island's
 * contact step) and frozen y reaches no higher up (against the global
 * force, m) than x's lowest point, y cannot stop x sliding over it: the
 * pair's normal for events, responses and the island is m, as if y were
 * part of what x lies on.  Distances, and so the schedule, are untouched.
 * A step up higher than x's gap over it is a real obstacle and keeps its
 * normal. */
static void flush_normal(const vrOwner *o, const vrPair *p, const vrPose *pa, const vrPose *pb, vrContact *c)
{
    vec3 g = o->p.flight.accel, m;
    int side;
    if (c->dist <= 0 || vec3_len2(g) == 0) return;
    m = vec3_normalize(vec3_neg(g));
    for (side = 0; side < 2; side++) {
        const vrBody *x = o->body[side ? p->b : p->a], *y = o->body[side ? p->a : p->b];
        const vrPose *px = side ? pb : pa, *py = side ? pa : pb;
        vec3 n_yx = side ? c->n : vec3_neg(c->n);
        double y_top, x_bottom;
        if (vrBody_Frozen(x) || !x->contact || !vrBody_Frozen(y) || vec3_dot(n_yx, m) >= 1 - 1e-12) continue;
        y_top = vec3_dot(m, vrShape_Support(&y->shape, py, m));
        x_bottom = vec3_dot(m, vrShape_Support(&x->shape, px, vec3_neg(m)));
        if (y_top > x_bottom + VR_CONTAIN_TOL) continue;
        c->n = side ? m : vec3_neg(m);
        if (vrBody_IsSphere(x) && c->npoints == 1) c->point[0] = vec3_madd(px->p, -x->shape.radius, m);   /* below it */
        return;
    }
}

/* what events are decided from, besides a query with the region: the
 * spheres' real poses (their spin) and the flush-surface normal */
void vrPair_ForEvents(vrOwner *o, const vrPair *p, double t, vrPose *pa, vrPose *pb, vrContact *c)
{
    real_poses(o, p, t, pa, pb);
    flush_normal(o, p, pa, pb, c);
}

/* the query that events are decided from */
void vrPair_EventQuery(vrOwner *o, vrPair *p, double t, vrPose *pa, vrPose *pb, vrContact *c)
{
    vrPair_Query(o, p, t, 1, pa, pb, c);
    vrPair_ForEvents(o, p, t, pa, pb, c);
}
