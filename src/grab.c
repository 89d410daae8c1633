/* grab.c — the hand's select mode (SPEC 8; see grab.h).
 *
 *   filtered_segment, hand_at, hand_motion   the hand's pose and its motion's
 *                                  velocity (raw, or through hand_filter.h)
 *   surface_distance, nearest      what the trigger grabs
 *   take, aim, let_go              grab, follow (re-anchor), release (throw)
 *   trigger_down, edge, dispatch   the buttons' changes, in the precedence of SPEC 8
 *   fly_to                         the viewpoint flown up to a time
 *   next_cut                       where the frame's contact step is cut next
 *   vrGrab_Cut                     the frame loop's call
 */
#include <string.h>
#include "grab.h"
#include "config.h"
#include "owners.h"
#include "panel.h"
#include "sphere.h"

#define SNAP_TOL 1e-9    /* m and rad: a held body this near its target is on it (rounding) */

void vrGrab_Init(vrGrab *g)
{
    memset(g, 0, sizeof *g);
    g->t_done = -INFINITY;
    g->held = g->last = -1;
    g->off_q = quat_identity();
}

static vrPose sample_pose(const vrTrackerSample *s)
{
    return vrPose_make(vrVec3_Of(s->position),
                       quat_make(s->orientation[0], s->orientation[1], s->orientation[2], s->orientation[3]));
}

/* the index of the first hand sample after t */
static int first_after(const vrTrack *tr, double t)
{
    int lo = 0, hi = tr->n;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (tr->s[mid].t <= t) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

/* the filtered samples that hold t: the segment that ends at t when the
 * last filtered sample is at t (0: none, a filtered pose held) */
static int filtered_segment(const vrWorld *w, double t, vrHandFiltered *a, vrHandFiltered *b)
{
    const vrHandFilter *f = &w->grab.filter;
    const vrTrack *tr = &w->track[VR_DEVICE_HAND];
    int k = first_after(tr, f->last.t);
    if (t <= f->last.t && f->n >= 2 && t >= f->prev.t) {
        *a = f->prev, *b = f->last;
        return 1;
    }
    *a = *b = f->last;
    if (t <= f->last.t || k >= tr->n) return 0;
    *b = vrHandFilter_Next(f, &tr->s[k], w->s.hand_min_cutoff, w->s.hand_beta);
    return 1;
}

/* the hand at t (interpolated; with hand_filter, the filtered motion);
 * 0 when there is no hand */
static int hand_at(const vrWorld *w, double t, vrTrackerSample *s)
{
    vrHandFiltered a, b;
    if (vrTrack_At(&w->track[VR_DEVICE_HAND], t, s) != 0) return 0;
    if (!w->s.hand_filter || w->grab.filter.n == 0) return 1;
    filtered_segment(w, t, &a, &b);
    vrHandFilter_Between(&a, &b, t, s);
    return 1;
}

/* the filtered motion's velocity and spin at t */
static void filtered_motion(const vrWorld *w, double t, vec3 *v, vec3 *om)
{
    vrHandFiltered a, b;
    *v = *om = vec3_zero();
    if (!filtered_segment(w, t, &a, &b) || !(b.t > a.t)) return;
    *v = vec3_scale(vec3_sub(b.x, a.x), 1 / (b.t - a.t));
    *om = vec3_scale(vrTrack_Turn(a.q, b.q), 1 / (b.t - a.t));
}

/* The velocity and spin of the hand's interpolated motion at t.  At a
 * sample's time, where two segments meet, the one that ends there: the
 * motion that brought the object to its release (a file's last sample
 * may let go). */
static void hand_motion(const vrWorld *w, double t, vec3 *v, vec3 *om)
{
    const vrTrack *tr = &w->track[VR_DEVICE_HAND];
    int k = first_after(tr, t) - 1;
    double dv[3], dw[3], at = t;
    if (w->s.hand_filter && w->grab.filter.n > 0) {
        filtered_motion(w, t, v, om);
        return;
    }
    if (k >= 1 && tr->s[k].t == t && tr->s[k - 1].t < t) at = 0.5 * (tr->s[k - 1].t + t);
    vrTrack_Velocity(tr, at, dv, dw);
    *v = vrVec3_Of(dv);
    *om = vrVec3_Of(dw);
}

/* ---- what the trigger grabs --------------------------------------------------------- */

/* p's distance to b's surface at t (negative inside) */
static double surface_distance(vrBody *b, double t, vec3 p)
{
    vrPose pose;
    vrWalkCache cache;
    vrNear nr;
    int steps = 0;
    vrBody_Pose(b, t, &pose);
    if (b->shape.kind == VR_SHAPE_SPHERE) return vrNear_Sphere(pose.p, b->shape.radius, p).dist;
    if (b->shape.kind == VR_SHAPE_BOX) return vrNear_Box(&b->shape, &pose, p).dist;
    memset(&cache, 0, sizeof cache);
    if (!b->shape.poly || vrNear_Poly(b->shape.poly, &pose, p, &cache, &steps, &nr) != 0) return INFINITY;
    return nr.dist;
}

static vrBody *grabbable(const vrWorld *w, int id)
{
    vrObject *o = id >= 0 && id < w->table.n ? w->table.obj[id] : NULL;
    return o && o->live && !o->body.is_static ? &o->body : NULL;
}

/* the dynamic object whose surface is nearest p, within grab_reach (the
 * lower id of equals), or -1 */
static int nearest(const vrWorld *w, double t, vec3 p)
{
    double best = w->s.grab_reach;
    int id, found = -1;
    for (id = 0; id < w->table.n; id++) {
        vrBody *b = grabbable(w, id);
        double d;
        if (!b) continue;
        d = surface_distance(b, t, p);
        if (d <= best && (found < 0 || d < best)) best = d, found = id;
    }
    return found;
}

/* ---- grab, follow, release ------------------------------------------------------------ */

/* the held body's pose the hand at h gives it */
static vrPose target(const vrGrab *g, const vrTrackerSample *h)
{
    vrPose hp = sample_pose(h);
    return vrPose_make(vrPose_apply(&hp, g->off_p), quat_normalize(quat_mul(hp.q, g->off_q)));
}

/* b's state at t in w->update, on its target when it is there to
 * rounding (so that an unobstructed release is exactly where the hand
 * let go), else where it is (a static held it back); its anchor from t */
static vrBodyState *held_state(vrWorld *w, vrBody *b, const vrTrackerSample *h, double t)
{
    vrBodyState *st = vrUpdate_Body(&w->update, b, t);
    vrPose aim;
    if (!st) return NULL;
    aim = target(&w->grab, h);
    if (vec3_dist(st->x, aim.p) <= SNAP_TOL * vr_max(1, vec3_len(aim.p)) && quat_angle_between(st->q, aim.q) <= SNAP_TOL)
        st->x = aim.p, st->q = aim.q;
    /* anchored as given, not clamped: the speed caps cut neither the
     * rigid follow nor the throw (SPEC 8; motion.c flies an anchor above
     * max_linear uncapped to its next event) */
    st->raw = 1;
    st->resting = st->contact = st->hit = 0;
    st->island = -1;
    return st;
}

/* the hand takes body id where it is: its pose in the hand's frame kept */
static void take(vrWorld *w, int id, const vrTrackerSample *h, double t)
{
    vrGrab *g = &w->grab;
    vrPose hp = sample_pose(h), bp;
    vrBody_Pose(&w->table.obj[id]->body, t, &bp);
    g->held = id;
    g->off_p = vrPose_invapply(&hp, bp.p);
    g->off_q = quat_normalize(quat_mul(quat_conj(hp.q), bp.q));
}

/* The held body re-anchored at t to reach its target at `cut` (the
 * chord: a straight line and a constant turn), kinematic (body.h). */
static int aim(vrWorld *w, double t, double cut)
{
    vrBody *b = &w->table.obj[w->grab.held]->body;
    vrTrackerSample h, hn;
    vrBodyState *st;
    vrPose next;
    double dt = cut - t;
    hand_at(w, t, &h);
    hand_at(w, cut, &hn);
    if (!(st = held_state(w, b, &h, t))) return -1;
    st->kinematic = 1;
    next = target(&w->grab, &hn);
    if (dt > 0) {
        st->v = vec3_scale(vec3_sub(next.p, st->x), 1 / dt);
        st->L = vec3_scale(vrTrack_Turn(st->q, next.q), 1 / dt);
    } else {
        st->v = st->L = vec3_zero();
    }
    return 0;
}

/* SPEC 8's throw: the body leaves from where the hand let go with the
 * velocity of its own point of the hand's motion, v + w x r, and the
 * hand's spin */
static int let_go(vrWorld *w, double t)
{
    vrGrab *g = &w->grab;
    vrBody *b = grabbable(w, g->held);
    vrTrackerSample h;
    vrBodyState *st;
    vec3 v, om;
    mat33 inertia;
    vrPose pose;
    if (b && hand_at(w, t, &h)) {
        if (!(st = held_state(w, b, &h, t))) return -1;
        hand_motion(w, t, &v, &om);
        pose = vrPose_make(st->x, st->q);
        inertia = vrBody_InertiaWorld(b, &pose);
        st->kinematic = 0;
        st->v = vec3_add(v, vec3_cross(om, vec3_sub(st->x, vrVec3_Of(h.position))));
        st->L = mat33_mulv(&inertia, om);
    }
    g->last = g->held;
    g->held = -1;
    return 0;
}

/* ---- the buttons ---------------------------------------------------------------------- */

/* the hand points along its +y (vroc.h) */
static vec3 pointing(const vrTrackerSample *h) { return quat_rotate(sample_pose(h).q, vec3_make(0, 1, 0)); }

/* the viewpoint flown up to t along the hand's +y as it was at the last step */
static void fly_to(vrWorld *w, double t)
{
    vrGrab *g = &w->grab;
    vrTrackerSample h;
    if (g->flying && t > g->fly_t) g->fly = vec3_madd(g->fly, w->s.fly_speed * (t - g->fly_t), g->fly_dir);
    g->fly_t = t;
    if (hand_at(w, t, &h)) g->fly_dir = pointing(&h);
}

/* SPEC 8's precedence at trigger down: a panel control, then the panel
 * itself (both the panel's to say), then an object (select mode), then
 * flying */
static void trigger_down(vrWorld *w, const vrTrackerSample *s, const vrTrackerSample *now, double at)
{
    vrGrab *g = &w->grab;
    int id;
    if (vrPanel_TriggerDown(w, s)) return;
    if (w->s.select && g->held >= 0) return;
    id = w->s.select ? nearest(w, at, vrVec3_Of(now->position)) : -1;
    if (id >= 0) {
        take(w, id, now, at);
        return;
    }
    fly_to(w, s->t);
    g->flying = 1;
}

/* one sample's button change: s is the sample, now the hand at `at` */
static int edge(vrWorld *w, const vrTrackerSample *s, const vrTrackerSample *now, double at)
{
    vrGrab *g = &w->grab;
    unsigned down = s->buttons & ~g->buttons, up = g->buttons & ~s->buttons;
    g->buttons = s->buttons;
    if (up & VR_BUTTON_TRIGGER) {
        if (vrPanel_Holds(w)) vrPanel_TriggerUp(w, s);
        fly_to(w, s->t);
        g->flying = 0;
    }
    /* a held object goes when no button holds it any more */
    if (g->held >= 0 && !(s->buttons & (VR_BUTTON_TRIGGER | VR_BUTTON_RESELECT)) && let_go(w, at) != 0) return -1;
    if (down & VR_BUTTON_TRIGGER) trigger_down(w, s, now, at);
    if ((down & VR_BUTTON_RESELECT) && w->s.select && g->held < 0 && grabbable(w, g->last)) take(w, g->last, now, at);
    return 0;
}

/* the hand's samples in (t_done, at], their button changes dispatched */
static int dispatch(vrWorld *w, double at)
{
    vrGrab *g = &w->grab;
    const vrTrack *tr = &w->track[VR_DEVICE_HAND];
    vrTrackerSample now;
    int k;
    if (!hand_at(w, at, &now)) return 0;
    for (k = first_after(tr, g->t_done); k < tr->n && tr->s[k].t <= at; k++)
        vrHandFilter_Take(&g->filter, &tr->s[k], w->s.hand_min_cutoff, w->s.hand_beta);
    hand_at(w, at, &now);   /* with hand_filter, the filtered hand after those samples */
    for (k = first_after(tr, g->t_done); k < tr->n && tr->s[k].t <= at; k++)
        if (tr->s[k].buttons != g->buttons && edge(w, &tr->s[k], &now, at) != 0) return -1;
    g->t_done = at;
    if (g->held >= 0 && (!grabbable(w, g->held) || !w->s.select) && let_go(w, at) != 0) return -1;
    if (vrPanel_Holds(w)) vrPanel_HandMoved(w, &now);
    fly_to(w, at);
    return 0;
}

/* the next hand sample in (at, end) that matters: any while something is
 * held, else one whose buttons change; end when none (select mode only:
 * elsewhere nothing the hand does moves a body) */
static double next_cut(const vrWorld *w, double at, double end)
{
    const vrTrack *tr = &w->track[VR_DEVICE_HAND];
    int k, holding = w->grab.held >= 0 || vrPanel_Holds(w);
    if (!w->s.select) return end;
    for (k = first_after(tr, at); k < tr->n && tr->s[k].t < end; k++) {
        unsigned before = k > 0 ? tr->s[k - 1].buttons : w->grab.buttons;
        if (holding || tr->s[k].buttons != before) return tr->s[k].t;
    }
    return end;
}

int vrGrab_Cut(vrWorld *w, double at, double end, double *cut, char *err, size_t n)
{
    w->update.n = 0;
    *cut = end;
    if (w->track[VR_DEVICE_HAND].n == 0) return 0;
    if (dispatch(w, at) != 0) return vrGeom_Fail(err, n, "out of memory");
    *cut = next_cut(w, at, end);
    if (w->grab.held >= 0 && aim(w, at, *cut) != 0) return vrGeom_Fail(err, n, "out of memory");
    if (vrWorld_ApplyUpdate(w, &w->update) != 0) return vrGeom_Fail(err, n, "out of memory");
    return 0;
}

void vrGrab_FlyOffset(const vrWorld *w, double out[3])
{
    const vrGrab *g = &w->grab;
    vec3 f = g->fly;
    if (g->flying && w->t > g->fly_t) f = vec3_madd(f, w->s.fly_speed * (w->t - g->fly_t), g->fly_dir);
    out[0] = f.x, out[1] = f.y, out[2] = f.z;
}
