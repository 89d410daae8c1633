/* rest.c — the rest state (thesis 3.3.3, generalised as SPEC 3.5 and 7).
 *
 * Bodies rest and wake as islands: the bodies that touched one another at
 * the last island step (island_step.c) carry the island's id, its lowest
 * body id.  At a frame end an island rests when every body of it is in an
 * island's contact step, moved less than 1e-4 m and turned less than
 * 1e-3 rad over each of the last two frames, and was hit by no impulse: no force, no motion,
 * its poses frozen as they are (never snapped), its pairs among themselves
 * and with static bodies unscheduled.  When anything changes a body of a
 * resting island (a response, an edit, a moving body touching it at an
 * island step), the whole island wakes.
 *   in_update          a body's state in an update, if there
 *   wake_islands       every resting body of the given islands, woken
 *   qualifies          one body's part of the rest test
 *   vrRest_*           the coordinator's calls (rest.h)
 */
#include <stdlib.h>
#include <string.h>
#include "rest.h"

#define REST_DISPLACEMENT 1e-4   /* m per frame */
#define REST_ROTATION 1e-3       /* rad per frame */
#define REST_FRAMES 2            /* frames in a row: a body rocking on an edge, turning back
                                    within one frame, must not be caught there */

static const vrBodyState *in_update(const vrUpdate *up, int id)
{
    int i;
    for (i = 0; i < up->n; i++)
        if (up->body[i].id == id) return &up->body[i];
    return NULL;
}

/* the live resting bodies whose island has mark[island] set wake: their
 * states join up (at t), resting no more */
static int wake_islands(vrWorld *w, const unsigned char *mark, vrUpdate *up, double t)
{
    int i;
    for (i = 0; i < w->table.n; i++) {
        vrObject *x = w->table.obj[i];
        vrBodyState *st;
        if (!x || !x->live || !x->body.resting || x->body.island < 0 || !mark[x->body.island]) continue;
        st = vrUpdate_Body(up, &x->body, t);
        if (!st) return -1;
        st->resting = 0;
    }
    return 0;
}

int vrRest_WakeDependents(vrWorld *w, vrUpdate *up, double t)
{
    unsigned char *mark;
    int k, any = 0, rc;
    if (w->may_rest == 0) return 0;     /* nothing rests: no look at every object */
    if (!(mark = calloc((size_t)w->table.n + 1, 1))) return -1;
    for (k = 0; k < up->n; k++) {
        const vrObject *o = w->table.obj[up->body[k].id];
        int island = o ? o->body.island : -1;
        if (island >= 0 && island < w->table.n && !up->body[k].resting) mark[island] = 1, any = 1;
    }
    rc = any ? wake_islands(w, mark, up, t) : 0;
    free(mark);
    return rc;
}

int vrRest_WakeIsland(vrWorld *w, int island, vrUpdate *up, double t)
{
    unsigned char *mark;
    int rc;
    if (island < VR_EVERY_ISLAND || island >= w->table.n || w->may_rest == 0) return 0;
    if (!(mark = calloc((size_t)w->table.n + 1, 1))) return -1;
    if (island == VR_EVERY_ISLAND) memset(mark, 1, (size_t)w->table.n);
    else if (island >= 0) mark[island] = 1;
    rc = wake_islands(w, mark, up, t);
    free(mark);
    return rc;
}

/* the body's own part: in a contact step, not hit, still over the frame */
static int qualifies(vrWorld *w, const vrUpdate *up, vrObject *o)
{
    vrBody *b = &o->body;
    vrPose p;
    if (!b->contact || b->hit || b->island < 0 || !o->have_frame_pose || in_update(up, b->id)) return 0;
    vrBody_Pose(b, w->t, &p);
    return vec3_dist(p.p, o->frame_pose.p) < REST_DISPLACEMENT
        && quat_angle_between(o->frame_pose.q, p.q) < REST_ROTATION;
}

/* An island rests when each of its moving bodies qualifies (fails[i]:
 * some body of island i does not). */
int vrRest_FrameEnd(vrWorld *w, vrUpdate *up)
{
    unsigned char *fails;
    int i;
    /* SPEC 8: while the hand holds a body nothing starts to rest: a body
     * lying on the held one, frozen, would hang in the air when the hand
     * moves it away (a kinematic body wakes what it meets, not what it
     * leaves) */
    if (w->grab.held >= 0) return 0;
    if (!(fails = calloc((size_t)w->table.n + 1, 1))) return -1;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o || !o->live || o->body.is_static || o->body.resting) continue;
        if (o->body.island < 0) continue;
        o->quiet_frames = qualifies(w, up, o) ? o->quiet_frames + 1 : 0;
        if (o->quiet_frames < REST_FRAMES) fails[o->body.island] = 1;
    }
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        vrBodyState *st;
        if (!o || !o->live || o->body.is_static || o->body.resting || o->body.island < 0) continue;
        if (fails[o->body.island] || in_update(up, i)) continue;
        st = vrUpdate_Body(up, &o->body, w->t);
        if (!st) {
            free(fails);
            return -1;
        }
        st->resting = 1;
        w->may_rest = w->table.n;      /* counted again once applied */
    }
    free(fails);
    return 0;
}

void vrRest_RememberFramePoses(vrWorld *w)
{
    int i;
    w->may_rest = 0;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o || !o->live || o->body.is_static) continue;
        w->may_rest += o->body.resting;
        vrBody_Pose(&o->body, w->t, &o->frame_pose);
        o->have_frame_pose = 1;
        o->body.hit = 0;
    }
}
