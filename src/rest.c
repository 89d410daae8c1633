/* rest.c — the rest state (thesis 3.3.3, generalised as SPEC 3.5).
 *
 * At a frame end a supported body that moved less than 1e-4 m and turned
 * less than 1e-3 rad over the frame, and that no impulse hit, rests: no
 * force, no motion, its pose frozen as it is (never snapped), its pairs with
 * its supports unscheduled.  Its supports must themselves be frozen (static
 * or resting): a frictionless body does not ride on a sliding one.  A
 * resting body wakes when a response involves it or a support changes;
 * waking anything wakes what rests on it.
 */
#include "world.h"

#define REST_DISPLACEMENT 1e-4   /* m per frame */
#define REST_ROTATION 1e-3       /* rad per frame */

static const vrBodyState *in_update(const vrUpdate *up, int id)
{
    int i;
    for (i = 0; i < up->n; i++)
        if (up->body[i].id == id) return &up->body[i];
    return NULL;
}

static int rests_on(const vrBody *b, int partner)
{
    int i;
    for (i = 0; i < b->nsupport; i++)
        if (b->support[i].partner == partner) return 1;
    return 0;
}

int vrRest_WakeDependents(vrWorld *w, vrUpdate *up, double t)
{
    int k, i;
    for (k = 0; k < up->n; k++) {
        int id = up->body[k].id;
        for (i = 0; i < w->nobj; i++) {
            vrObject *x = w->obj[i];
            vrBodyState *st;
            if (!x || !x->live || !x->body.resting || !rests_on(&x->body, id) || in_update(up, i)) continue;
            st = vrUpdate_Body(up, &x->body, t);
            if (!st) return -1;
            st->resting = 0;
        }
    }
    return 0;
}

/* frozen now, or about to rest in this same update */
static int frozen_support(const vrWorld *w, const vrUpdate *up, int id)
{
    const vrObject *o = w->obj[id];
    const vrBodyState *st = in_update(up, id);
    return o && (o->body.is_static || o->body.resting || (st && st->resting));
}

static int qualifies(vrWorld *w, const vrUpdate *up, vrObject *o)
{
    vrBody *b = &o->body;
    vrPose p;
    int i;
    if (!o->live || b->is_static || b->resting || b->hit || b->nsupport == 0 || !o->have_frame_pose) return 0;
    if (in_update(up, b->id)) return 0;
    for (i = 0; i < b->nsupport; i++)
        if (!frozen_support(w, up, b->support[i].partner)) return 0;
    vrBody_Pose(b, w->t, &p);
    return vec3_dist(p.p, o->frame_pose.p) < REST_DISPLACEMENT
        && quat_angle_between(o->frame_pose.q, p.q) < REST_ROTATION;
}

int vrRest_FrameEnd(vrWorld *w, vrUpdate *up)
{
    int more = 1, i;
    while (more) {              /* a stack comes to rest from the bottom up */
        more = 0;
        for (i = 0; i < w->nobj; i++) {
            vrObject *o = w->obj[i];
            vrBodyState *st;
            if (!o || !qualifies(w, up, o)) continue;
            st = vrUpdate_Body(up, &o->body, w->t);
            if (!st) return -1;
            st->resting = 1;
            more = 1;
        }
    }
    return 0;
}

void vrRest_RememberFramePoses(vrWorld *w)
{
    int i;
    for (i = 0; i < w->nobj; i++) {
        vrObject *o = w->obj[i];
        if (!o || !o->live || o->body.is_static) continue;
        vrBody_Pose(&o->body, w->t, &o->frame_pose);
        o->have_frame_pose = 1;
        o->body.hit = 0;
    }
}
