/* rest.c — the rest state (thesis 3.3.3, generalised as SPEC 3.5 and 7).
 *
 * Bodies rest and wake as islands: the bodies that touched one another at
 * the last island step (island_step.c) carry the island's id, its lowest
 * body id.  At a frame end an island rests when every body of it is in an
 * island's contact step, hit by no impulse, and still or slow, not
 * speeding up (the window, below): no force, no motion,
 * its poses frozen as they are (never snapped), its pairs among themselves
 * and with static bodies unscheduled.  When anything changes a body of a
 * resting island (a response, an edit, a moving body touching it at an
 * island step), the whole island wakes.
 *   state_once         a body's state in an update, added if not there
 *   wake_islands       every resting body of the given islands, woken
 *   qualifies, rests   one body's part of the rest test
 *   vrRest_*           the coordinator's calls (rest.h)
 */
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include "rest.h"
#include "contact_set.h"
#include "config.h"

#define REST_DISPLACEMENT 1e-4   /* m per frame */
#define REST_ROTATION 1e-3       /* rad per frame */
#define REST_FRAMES 2            /* frames in a row: a body rocking on an edge, turning back
                                    within one frame, must not be caught there */

/* vrUpdate_Body for bodies met once each: only the n states up held
 * before are searched (the bodies added since are others), so that
 * 10,000 bodies put to rest or woken at once are not quadratic */
static vrBodyState *state_once(vrUpdate *up, int n, vrBody *b, double t)
{
    vrBodyState *st = vrUpdate_Find(up, n, b->id);
    return st ? st : vrUpdate_Append(up, b, t);
}

/* the live resting bodies whose island has mark[island] set wake: their
 * states join up (at t), resting no more */
static int wake_islands(vrWorld *w, const unsigned char *mark, vrUpdate *up, double t)
{
    int i, n = up->n;
    for (i = 0; i < w->table.n; i++) {
        vrObject *x = w->table.obj[i];
        vrBodyState *st;
        if (!x || !x->live || !x->body.resting || x->body.island < 0 || !mark[x->body.island]) continue;
        st = state_once(up, n, &x->body, t);
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

/* The rest test's window (SPEC 7 wins over 3.5 here; man vroc, REST).
 * A body is still (SPEC 3.5) when it moved under 1e-4 m and turned under
 * 1e-3 rad over each of the last REST_FRAMES frames.  A body with friction
 * is slow when its motion over each frame of the last REST_TIME stayed
 * under rest_speed times the frame (Box2D's sleep threshold and time): a
 * ball rolling into a pile at 1 cm/s, as fast as it would roll for ever,
 * kept the pile's island of fifty awake for 13 s (pile seed 6).  Either
 * rests it, but only while it is not speeding up: a frame whose motion is
 * more than REST_ACCEL dt^2 over the window's first frame's starts the
 * window again, so a box setting off down a slope, or a body starting to
 * tip off an edge, is not frozen as it sets off (SPEC 3.5's rule alone
 * froze a box on a slope that gains 2e-6 m a frame: still, two frames).
 * A body's motion is the larger of its centre's displacement and its turn
 * times its outer radius (how far its surface moves).  Frictionless
 * sliding never rests (SPEC 1), only friction brings a body to a stop. */
#define REST_TIME 0.5            /* s */
#define REST_ACCEL 1e-2          /* m/s^2: motion growing faster than this is speeding up */

/* Without a global force nothing lies on anything (SPEC 3.1: support is
 * along the force), and a body touching another that moves at all is
 * drifting: frozen as still (under 1e-4 m a frame), it lost its energy
 * (the physics fuzzer's seed 12384: e = 1, no force, the bottom box of a
 * struck stack, leaving the floor at 4 mm/s, rested with 2.4e-5 J of
 * 0.95 J).  Then only a body that does not move rests. */
static int drifting(const vrBody *b, int forceless)
{
    return forceless && (vec3_len2(b->m.v0) > 0 || vec3_len2(b->m.L) > 0);
}

/* the body's own part: in a contact step, not hit, still or slow over
 * the window (its counts, o->quiet_frames and o->slow_frames, move on);
 * forceless: the world has no global force */
static void qualifies(vrWorld *w, const vrUpdate *up, vrObject *o, int forceless)
{
    vrBody *b = &o->body;
    double dt = w->s.time_step, dx, turn, motion;
    int rise, still, slow;
    vrPose p;
    if (!b->contact || b->hit || o->tipping || b->island < 0 || !o->have_frame_pose || vrUpdate_Find(up, up->n, b->id)
        || drifting(b, forceless)) {
        o->quiet_frames = o->slow_frames = 0;
        return;
    }
    vrRest_KeepFramePose(w, o);
    vrBody_Pose(b, w->t, &p);
    dx = vec3_dist(p.p, o->frame_pose.p), turn = quat_angle_between(o->frame_pose.q, p.q);
    motion = vr_max(dx, turn * b->r_out);
    rise = motion > o->slow_start + REST_ACCEL * dt * dt;
    if (rise || (o->quiet_frames == 0 && o->slow_frames == 0)) o->slow_start = motion;
    still = dx < REST_DISPLACEMENT && turn < REST_ROTATION;
    slow = b->friction > 0 && motion < w->s.rest_speed * dt;
    o->quiet_frames = !still ? 0 : rise ? 1 : o->quiet_frames + 1;
    o->slow_frames = !slow ? 0 : rise ? 1 : o->slow_frames + 1;
}

/* still for REST_FRAMES, or slow for REST_TIME (and REST_FRAMES at least) */
static int rests(const vrWorld *w, const vrObject *o)
{
    double need = ceil(REST_TIME / w->s.time_step - 1e-9);
    return o->quiet_frames >= REST_FRAMES || (o->slow_frames >= REST_FRAMES && o->slow_frames >= need);
}

/* An island rests when each of its moving bodies qualifies (fails[i]:
 * some body of island i does not). */
int vrRest_FrameEnd(vrWorld *w, vrUpdate *up)
{
    unsigned char *fails;
    int k, n = up->n, forceless = vec3_len2(vrSettings_Flight(&w->s).accel) == 0;
    /* SPEC 8: while the hand holds a body nothing starts to rest: a body
     * lying on the held one, frozen, would hang in the air when the hand
     * moves it away (a kinematic body wakes what it meets, not what it
     * leaves) */
    if (w->grab.held >= 0) return 0;
    /* a body in an island is in contact: the contact set, in id order,
     * holds them all (a pass over the table was 14 % of a frame of 10,000
     * flying objects) */
    if (vrContactSet_Prune(w) != 0 || !(fails = calloc((size_t)w->table.n + 1, 1))) return -1;
    for (k = 0; k < w->ncontact_ids; k++) {
        vrObject *o = w->table.obj[w->contact_ids[k]];
        if (!o || !o->live || o->body.is_static || o->body.resting) continue;
        if (o->body.island < 0) continue;
        qualifies(w, up, o, forceless);
        if (!rests(w, o)) fails[o->body.island] = 1;
    }
    for (k = 0; k < w->ncontact_ids; k++) {
        int i = w->contact_ids[k];
        vrObject *o = w->table.obj[i];
        vrBodyState *st;
        if (!o || !o->live || o->body.is_static || o->body.resting || o->body.island < 0) continue;
        if (fails[o->body.island] || vrUpdate_Find(up, n, i)) continue;
        st = vrUpdate_Append(up, &o->body, w->t);   /* each id once in the set, not in up's first n */
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

/* The frame end's poses are taken when first needed: a body's pose at
 * w->frame_pose_t is a pure function of its anchor, so it is found from
 * the anchor it still has when the rest test or a save asks, or when its
 * anchor is about to change (vrRest_KeepFramePose, before an update is
 * applied).  Taken for every body at every frame end, it was 29 % of a
 * frame of 10,000 flying objects that never rest. */
void vrRest_RememberFramePoses(vrWorld *w)
{
    int i;
    w->may_rest = 0;
    w->frame_pose_t = w->t;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o || !o->live || o->body.is_static) continue;
        w->may_rest += o->body.resting;
        o->frame_pose_lazy = 1;
        o->have_frame_pose = 1;
        o->body.hit = 0;
        o->tipping = 0;
    }
}

void vrRest_KeepFramePose(const vrWorld *w, vrObject *o)
{
    if (!o->frame_pose_lazy) return;
    vrBody_Pose(&o->body, w->frame_pose_t, &o->frame_pose);
    o->frame_pose_lazy = 0;
}
