/* reach.h — the largest reach of the free bodies (SPEC 3.2's max over i
 * of s_i + w_i R_i, which sets the internal step) without a look at every
 * body at every event.
 *
 * Each body keeps a bound on its reach for any span start later in the
 * frame: its speed can grow by at most max(|a|, |a_i|) per second, which
 * the span's own |a| (T - t_s) already counts, so |v| + |a| (T - t_s) at a
 * later t_s is never above that at the body's last change.  The bounds sit
 * in a max-tree; the exact reach is computed only for bodies whose bound
 * beats the best found so far, so the result is the same number the look
 * at every body gives, in O(log n) for an event that changes two bodies.
 */
#ifndef VROC_REACH_H
#define VROC_REACH_H

#include "body.h"

typedef struct vrReach {
    double *bound;        /* max-tree: node k's children are 2k and 2k + 1, leaves from `leaves` */
    int leaves, cap;
    int n;                /* bodies, by their index in the caller's list */
    double T;             /* the frame the bounds are for */
    int valid;            /* 0: no tree (no memory): the caller looks at every body */
} vrReach;

void vrReach_Init(vrReach *r);
void vrReach_Free(vrReach *r);
/* the bounds of the n bodies for a frame [t0, T] */
void vrReach_Frame(vrReach *r, vrBody *const *bodies, int n, double t0, double T, const vrFlight *f);
/* body i was re-anchored at t (an event) */
void vrReach_Changed(vrReach *r, vrBody *const *bodies, int i, double t, const vrFlight *f);
/* max over the bodies of vrSchedule_Reach(b, ts, T, f), 0 if none is free */
double vrReach_Fastest(const vrReach *r, vrBody *const *bodies, double ts, const vrFlight *f);

#endif
