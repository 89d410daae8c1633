/* loop.c — the frame loop: the coordinator of ARCHITECTURE "the loop,
 * once" (thesis 3.4.2 and 3.5.2).
 *
 * Per frame [t, T], a contact step at a time (SPEC 7): the island step at
 * its start (island_step.c); then the owners run their pairs through the
 * span to the step's end on the grid computed here from the global state;
 * the earliest event by (time, pair order) is taken; every clock advances
 * to it; its owner responds; the new states go to every holder; the next
 * span starts at the event.  At the frame end, rest is decided.
 *
 *   span_grid      the internal steps of a span (SPEC 3.2)
 *   too_many_steps a frame's work is bounded (SPEC 11)
 *   reach_changed  the grid's reach bounds follow the bodies an event changed
 *   contact_steps, contact_point   the frame's contact steps
 *   contact_step, hand_steps   one contact step; the steps the hand cuts it into
 *   run_span       the events of a span
 *   caps_reached   the flights the force sped up to the cap, counted
 *   run_frame      one frame: the loop
 */
#include <time.h>
#include <stdio.h>
#include <stdlib.h>
#include "config.h"
#include "owners.h"
#include "rest.h"
#include "island_step.h"

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* the grid of the span [ts, end] of the frame ending at T (SPEC 3.2): the
 * reach bounds kept for the rest of the frame hold for the span too.  With
 * steps, on the anchored points of the contact step starting at a
 * (vrSchedule_AnchoredGrid); without, its own. */
static void span_grid(const vrWorld *w, double a, long *steps, double ts, double end, double T, const vrParams *p,
                      vrGrid *g)
{
    double fastest = 0;
    if (!w->reach.valid || !(w->reach.T == T) || w->reach.n != w->ndyn)
        fastest = vrSchedule_Fastest(w->dyn, w->ndyn, ts, end, w->s.internal_step, &p->flight);
    else if (vrSchedule_NeedsReach(ts, end, w->s.internal_step))
        fastest = vrReach_Fastest(&w->reach, w->dyn, ts, &p->flight);
    if (steps) vrSchedule_AnchoredGrid(fastest, a, ts, end, p->d, w->s.internal_step, steps, g);
    else vrSchedule_GridFor(fastest, ts, end, p->d, w->s.internal_step, g);
    g->frame_T = T;
}

/* SPEC 11: a frame's work is bounded.  The grid's step is d / (2 v) for
 * the fastest reach v (thesis 3.2.3), so a frame's internal steps grow as
 * time_step v / d: a 1e20 kg ball at 1e9 m/s with d = 0.25 needed 8e8 of
 * them, and the look-ahead's undo log grew with every one.  A grid of more
 * than `most` steps is refused, naming what to change. */
static int too_many_steps(const vrWorld *w, const vrGrid *g, double before, double most, char *err, size_t n)
{
    double steps = before + (double)g->n, span = g->T - g->t0;
    if (steps <= most) return 0;
    return vrGeom_Fail(err, n, "frame %ld would need %.3g internal steps (at most %d): a body may reach %.3g m/s "
                               "against collision_dist %g m in time_step %g s; lower max_linear, max_angular or "
                               "time_step, or raise collision_dist",
                       w->frames + 1, steps, VR_FRAME_STEPS_MAX, span > 0 ? (double)g->n * w->s.collision_dist / (2 * span) : 0,
                       w->s.collision_dist, w->s.time_step);
}

/* the bodies an event changed have new reach bounds */
static void reach_changed(vrWorld *w, const vrUpdate *up, const vrParams *p)
{
    int k;
    for (k = 0; k < up->n; k++)
        if (up->body[k].id < w->ndyn_slot) vrReach_Changed(&w->reach, w->dyn, w->dyn_slot[up->body[k].id], up->body[k].t, &p->flight);
}

/* the contact steps of a frame: the frame cut into equal steps no longer
 * than contact_step (SPEC 7), so that island steps fall at the same times
 * whatever happens in between */
static long contact_steps(const vrWorld *w)
{
    double k = ceil(w->s.time_step / w->s.contact_step);
    return k < 1 ? 1 : k > 1e6 ? 1000000 : (long)k;
}

/* the start of contact step k of the frame [ts, T] (k = steps: T itself) */
static double contact_point(double ts, double T, long k, long steps)
{
    return k >= steps ? T : ts + (T - ts) * (double)k / (double)steps;
}

/* An island step is needed while some dynamic body can move.  "None" is
 * kept until a state is applied or the structure moves: a look at 10,000
 * bodies at rest at every contact step was a cache miss each. */
static int moving_bodies(vrWorld *w)
{
    int i;
    if (w->still_structure == w->structure && w->still_applied == w->applied) return 0;
    for (i = 0; i < w->ndyn; i++)
        if (!w->dyn[i]->resting) return 1;
    w->still_structure = w->structure, w->still_applied = w->applied;
    return 0;
}

/* pairwise answers to the follow-ups of a response at one instant, when
 * bounces are in play, before the rest are answered together */
#define VR_PAIRWISE_MAX 16

typedef struct Frame {
    double T;                /* the frame's end */
    double ts;               /* where the owners look from */
    double step_at;          /* the contact step's start: its grid's anchor */
    long step_grid;          /* the steps its grid is cut into (0: none yet) */
    double instant_t;        /* the responses at the last instant so far: a frame ending */
    int instant;             /* at an instant that had its VR_INSTANT_MAX does not give it more */
    int creep;               /* answers since the last one not a vrInstant_Span after the one before */
} Frame;

/* SPEC 7: an impulse that follows a response at its instant (a box
 * coming down on a stack, a ball on a board on a ball), or that meets a
 * body touching others (a box landing on four balls on the floor), is
 * answered with every contact of its islands together (island_step.c),
 * not one corner at a time: at once when the pair cannot bounce (e = 0);
 * when it can, follow-ups only, after VR_PAIRWISE_MAX pairwise answers (a
 * Newton's cradle's impulses go down the row one by one, as they must to
 * send out one ball); and the first impact again of an instant taken
 * back because its answers drove a body into the floor it lies on
 * (instant_undo.h).  (Every slow follow-up answered together cost a
 * pile twice the time: each solves whole islands.)  The decision reads
 * only the bodies, as every owner set can. */
static int answered_together(const vrWorld *w, const Frame *f, const vrEvent *ev)
{
    const vrBody *A = &w->table.obj[ev->a]->body, *B = &w->table.obj[ev->b]->body;
    int follow_up = ev->kind == VR_EV_CONTACT && ev->t == f->instant_t;
    if (ev->kind != VR_EV_CONTACT && ev->kind != VR_EV_IMPACT) return 0;
    if (vrInstantLog_Held(&w->instant_log, ev)) return 1;   /* instant_undo.h */
    if (fmin(A->elasticity, B->elasticity) == 0) return follow_up || A->contact || B->contact;
    return follow_up && f->instant >= VR_PAIRWISE_MAX;
}

/* the owners' allow_instant: 1, 0 when the instant had its
 * VR_INSTANT_MAX (none there), -1 when as many answers crept (none until
 * the next grid point, owner.h vrInstant_Span) */
static int allow_instant(const Frame *f)
{
    return f->creep >= VR_INSTANT_MAX ? -1 : f->instant < VR_INSTANT_MAX;
}

/* the events of [f->ts, end]: the owners' first event of all, answered,
 * until there is none before end.  0, -1, or VR_RESTART_FRAME. */
static int run_span(vrWorld *w, Frame *f, double end, const vrParams *p, char *err, size_t n)
{
    for (;;) {
        vrGrid g;
        vrEvent ev;
        int r;
        span_grid(w, f->step_at, &f->step_grid, f->ts, end, f->T, p, &g);
        if (too_many_steps(w, &g, (double)w->subframes, VR_FRAME_STEPS_HARD_MAX, err, n) != 0) return -1;
        r = vrOwners_Of(w)->first_event(w, &g, allow_instant(f), &ev, err, n);
        if (r != 1) {
            if (r == 0) w->subframes += g.n;
            return r;
        }
        w->subframes += ev.t > f->ts ? vrSchedule_FirstPointAtOrAfter(&g, ev.t) : 0;
        if (vrInstantLog_Drives(w, &ev, p->flight.accel)) {   /* the instant again, with islands (instant_undo.h) */
            if ((r = vrInstantLog_Undo(w, &w->update)) < 0 || vrWorld_ApplyUpdate(w, &w->update) != 0)
                return vrGeom_Fail(err, n, "out of memory");
            f->instant = r < f->instant ? f->instant - r : 0;
            reach_changed(w, &w->update, p);
            continue;
        }
        if (vrSounds_Note(&w->sounds, &ev, &w->s) != 0) return vrGeom_Fail(err, n, "out of memory");
        if (answered_together(w, f, &ev) && (r = vrIsland_Instant(w, ev.t, ev.a, ev.b, err, n)) != 1) {
            if (r != 0) return r;
            if (vrInstantLog_Note(w, &ev, &w->update, 1) != 0) return vrGeom_Fail(err, n, "out of memory");
            reach_changed(w, &w->update, p);
            f->instant++;
            f->ts = ev.t;
            continue;
        }
        w->update.n = 0;
        r = vrOwners_Of(w)->respond(w, &ev, &w->update, err, n);
        if (r != 0) return r;
        if (vrInstantLog_Note(w, &ev, &w->update, 0) != 0) return vrGeom_Fail(err, n, "out of memory");
        if (ev.kind == VR_EV_IMPACT || ev.kind == VR_EV_CONTACT) w->collisions++;
        if (vrWorld_ApplyUpdate(w, &w->update) != 0) return vrGeom_Fail(err, n, "out of memory");
        reach_changed(w, &w->update, p);
        if (ev.t != f->instant_t) f->creep = ev.t - f->instant_t <= vrInstant_Span(ev.t) ? f->creep + 1 : 0;
        f->instant = ev.t == f->instant_t ? f->instant + 1 : 1;
        f->instant_t = ev.t;
        f->ts = ev.t;
    }
}

/* the look-ahead the contact step [at, end] starts with if its island
 * step changes nothing: run_span's first grid, when it is not refused */
static void expect_look_ahead(vrWorld *w, const Frame *f, double at, double end, const vrParams *p)
{
    long steps = 0;
    span_grid(w, at, &steps, at, end, f->T, p, &w->ahead.g);
    w->ahead.allow = allow_instant(f);
    w->ahead.valid = (double)w->subframes + (double)w->ahead.g.n <= VR_FRAME_STEPS_HARD_MAX;
}

/* the contact step [at, end]: its island step at `at`, then its events */
static int contact_step(vrWorld *w, Frame *f, double at, double end, const vrParams *p, char *err, size_t n)
{
    int r = 0;
    if (f->T > w->t && moving_bodies(w)) {
        if (w->s.gps > 0) expect_look_ahead(w, f, at, end, p);   /* only the workers' island step sends it */
        r = vrIsland_Step(w, at, end - at, err, n);
        w->ahead.valid = 0;
    }
    if (r != 0) return r;
    reach_changed(w, &w->update, p);
    f->ts = f->step_at = at;
    f->step_grid = 0;
    return run_span(w, f, end, p, err, n);
}

/* SPEC 8: the contact step [at, end] cut also where the hand's samples
 * act (grab.h), the hand dispatched at each cut before its island step.
 * No hand, or outside select mode: one cut, the step as it was. */
static int hand_steps(vrWorld *w, Frame *f, double at, double end, const vrParams *p, char *err, size_t n)
{
    for (;;) {
        double cut;
        int r = vrGrab_Cut(w, at, end, &cut, err, n);
        if (r != 0) return r;
        reach_changed(w, &w->update, p);
        if ((r = contact_step(w, f, at, cut, p, err, n)) != 0 || !(cut < end)) return r;
        at = cut;
    }
}

/* SPEC 3.2: a body the force speeds up to max_linear flies on at it, and
 * that cut counts in stats clamps as an event's does (the shell notes the
 * first): a ball dropped 5 m onto a floor with e = 1 came back to 3.4 m,
 * clamps = 0.  Counted in the frame whose end the flight reaches, or
 * when its anchor moves (vrWorld_ApplyUpdate), whichever comes first. */
static void caps_reached(vrWorld *w, double T)
{
    int i;
    for (i = 0; i < w->ndyn; i++) w->clamps += vrBody_CapReached(w->dyn[i], w->t, T);
}

/* the whole frame's grid from its start, before anything moves: a frame
 * too long is refused with the world unchanged */
static int frame_bounded(const vrWorld *w, const Frame *f, const vrParams *p, char *err, size_t n)
{
    vrGrid g;
    span_grid(w, f->ts, NULL, f->ts, f->T, f->T, p, &g);
    return too_many_steps(w, &g, 0, VR_FRAME_STEPS_MAX, err, n);
}

/* Runs [t, t + time_step]: ARCHITECTURE "the loop, once", a contact step
 * at a time (SPEC 7): the island step at its start, then its events. */
static int run_frame(vrWorld *w, char *err, size_t n)
{
    vrParams p = vrSettings_Params(&w->s);
    long steps = contact_steps(w), k;
    vrGrab grab = w->grab;   /* the hand as it was, for a frame run again */
    Frame f;
    f.T = w->t_base + (double)(w->frames + 1 - w->frames_base) * w->s.time_step;
    f.ts = w->t;
    f.instant_t = w->instant_t;
    f.instant = w->instant;
    f.creep = 0;
    w->subframes = 0;
    vrInstantLog_Frame(&w->instant_log);
    vrSounds_Frame(&w->sounds);
    vrReach_Frame(&w->reach, w->dyn, w->ndyn, f.ts, f.T, &p.flight);
    if (frame_bounded(w, &f, &p, err, n) != 0) return -1;
    for (k = 0; k < steps; k++) {
        double at = contact_point(w->t, f.T, k, steps), end = contact_point(w->t, f.T, k + 1, steps);
        int r = hand_steps(w, &f, at, end, &p, err, n);
        if (r == VR_RESTART_FRAME) {   /* a worker died: the frame again from its start */
            w->grab = grab;
            f.ts = w->t;
            vrReach_Frame(&w->reach, w->dyn, w->ndyn, f.ts, f.T, &p.flight);
            f.instant = w->instant;
            f.instant_t = w->instant_t;
            f.creep = 0;
            w->subframes = 0;
            vrInstantLog_Frame(&w->instant_log);
            k = -1;
            continue;
        }
        if (r != 0) return -1;
    }
    vrOwners_Of(w)->end_frame(w, f.T);
    caps_reached(w, f.T);
    w->t = f.T;
    w->frames++;
    w->instant = f.instant;
    w->instant_t = f.instant_t;
    w->update.n = 0;
    if (vrRest_FrameEnd(w, &w->update) != 0 || vrWorld_ApplyUpdate(w, &w->update) != 0)
        return vrGeom_Fail(err, n, "out of memory");
    vrRest_RememberFramePoses(w);
    return 0;
}

int vrWorld_Step(vrWorld *w, long frames, char *err, size_t n)
{
    long f;
    for (f = 0; f < frames; f++) {
        double t0;
        if (vrWorld_Start(w, err, n) != 0) return -1;
        t0 = now_ms();
        if (run_frame(w, err, n) != 0) return -1;
        w->frame_ms = now_ms() - t0;
        w->sim_ms += w->frame_ms;
    }
    return 0;
}
