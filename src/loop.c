/* loop.c — the frame loop: the coordinator of ARCHITECTURE "the loop,
 * once" (thesis 3.4.2 and 3.5.2).
 *
 * Per frame [t, T]: the owners run their pairs through the span on the
 * grid computed here from the global state; the earliest event by (time,
 * pair order) is taken; every clock advances to it; its owner responds;
 * the new states go to every holder; the next span starts at the event.
 * At the frame end, rest is decided from the bodies' states.
 *
 *   span_grid      the internal steps of a span (SPEC 3.2)
 *   reach_changed  the grid's reach bounds follow the bodies an event changed
 *   run_frame      one frame: the loop
 */
#include <time.h>
#include "config.h"
#include "owners.h"
#include "rest.h"

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* the grid of the span [ts, T] (SPEC 3.2) */
static void span_grid(const vrWorld *w, double ts, double T, const vrParams *p, vrGrid *g)
{
    if (!w->reach.valid || !(w->reach.T == T) || w->reach.n != w->ndyn) {
        vrSchedule_Grid(w->dyn, w->ndyn, ts, T, p->d, w->s.internal_step, &p->flight, g);
        return;
    }
    vrSchedule_GridFor(vrSchedule_NeedsReach(ts, T, w->s.internal_step) ? vrReach_Fastest(&w->reach, w->dyn, ts, &p->flight) : 0,
                       ts, T, p->d, w->s.internal_step, g);
}

/* the bodies an event changed have new reach bounds */
static void reach_changed(vrWorld *w, const vrUpdate *up, const vrParams *p)
{
    int k;
    for (k = 0; k < up->n; k++)
        if (up->body[k].id < w->ndyn_slot) vrReach_Changed(&w->reach, w->dyn, w->dyn_slot[up->body[k].id], up->body[k].t, &p->flight);
}

/* Runs [t, t + time_step]: ARCHITECTURE "the loop, once". */
static int run_frame(vrWorld *w, char *err, size_t n)
{
    double T = w->t_base + (double)(w->frames + 1 - w->frames_base) * w->s.time_step, ts = w->t;
    vrParams p = vrSettings_Params(&w->s);
    /* the responses at the last instant so far: a frame ending at an
     * instant that had its VR_INSTANT_MAX does not give it more */
    double instant_t = w->instant_t;
    int instant = w->instant;
    w->subframes = 0;
    vrReach_Frame(&w->reach, w->dyn, w->ndyn, ts, T, &p.flight);
    for (;;) {
        vrGrid g;
        vrEvent ev;
        int r;
        span_grid(w, ts, T, &p, &g);
        r = vrOwners_Of(w)->first_event(w, &g, instant < VR_INSTANT_MAX, &ev, err, n);
        if (r == VR_RESTART_FRAME) goto restart;
        if (r < 0) return -1;
        if (r == 0) {
            w->update.n = 0;
            r = vrRest_SeveralSupports(w, T, vrOwners_Of(w), &w->update, err, n);
            if (r == VR_RESTART_FRAME) goto restart;
            if (r != 0 || vrWorld_ApplyUpdate(w, &w->update) != 0) return -1;
            vrOwners_Of(w)->end_frame(w, T);
            w->subframes += g.n;
            break;
        }
        w->subframes += ev.t > ts ? vrSchedule_FirstPointAtOrAfter(&g, ev.t) : 0;
        w->update.n = 0;
        r = vrOwners_Of(w)->respond(w, &ev, &w->update, err, n);
        if (r == VR_RESTART_FRAME) goto restart;
        if (r != 0) return -1;
        if (ev.kind == VR_EV_IMPACT || ev.kind == VR_EV_CONTACT) w->collisions++;
        if (vrWorld_ApplyUpdate(w, &w->update) != 0) return vrGeom_Fail(err, n, "out of memory");
        reach_changed(w, &w->update, &p);
        instant = ev.t == instant_t ? instant + 1 : 1;
        instant_t = ev.t;
        ts = ev.t;
        continue;
    restart:                 /* a worker died: the frame again from its start */
        ts = w->t;
        vrReach_Frame(&w->reach, w->dyn, w->ndyn, ts, T, &p.flight);
        instant = w->instant;
        instant_t = w->instant_t;
        w->subframes = 0;
    }
    w->t = T;
    w->frames++;
    w->instant = instant;
    w->instant_t = instant_t;
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
