/* owner.h — a pair owner: the thesis's Graphics Processor (3.4.2, 3.5).
 *
 * An owner holds some object pairs, the bodies those pairs need, a
 * collision heap over its pairs, and the walk caches.  It answers the one
 * question the coordinator asks (ARCHITECTURE "the loop, once"): running
 * its pairs through the internal steps of a span, what is its first event?
 * Serial VROC is one owner holding every pair; with workers each forked
 * process runs the same code on a subset.
 *
 * Look-ahead is speculative: an owner checks its pairs past the moment
 * where some other owner's event will turn out to come first.  Advance(t)
 * keeps what it learnt up to t and rolls back the rest, so that what every
 * owner knows at an event time depends on nothing but the event times —
 * not on how far each owner had looked, nor on how pairs are spread over
 * owners.  That is what makes runs reproducible bit for bit.
 */
#ifndef VROC_OWNER_H
#define VROC_OWNER_H

#include <float.h>
#include <math.h>
#include "effect.h"
#include "schedule.h"

#define VR_INSTANT_MAX 64      /* responses at one instant before moving on (SPEC 3.1) */
/* Events that creep (each this close after the last, not at it) count
 * against a VR_INSTANT_MAX of their own, and then close everything to the
 * next grid point: a light table between the floor and a ball, each
 * answer (and its take-back) leaving the other pair coming in, had its
 * next event one rounding of t later, each a new instant, and the frame
 * never ended (edit fuzzer seed 531).  1e-12 s (a body at 10 m/s moves
 * 1e-11 m), or 16 roundings of t when those are more. */
static inline double vrInstant_Span(double t) { return fmax(1e-12, 16 * DBL_EPSILON * fabs(t)); }
#define VR_PENETRATION_TOL 1e-9
#define VR_START_OVERLAP 1e-4  /* m: deeper overlaps refuse to start (SPEC 1.4, 7: a saved pile starts again) */
#define VR_OVERLAP_SLOP VR_SHALLOW_OVERLAP  /* shallower overlaps of touching bodies are left as they
                                  are (SPEC 7: overlap is prevented, not pushed out); deeper ones are pushed out */
#define VR_CONTACT_GAP 1e-3    /* m: impacts and rest act this far apart at most (SPEC 7) */

typedef struct vrParams {
    double d;            /* collision distance: the envelope the schedule keeps (thesis 3.2.3) */
    vrFlight flight;
    int use_heap;
    int use_tree;        /* 1: box trees find the boxes that meet; 0: the sorted sweep */
    int keep_looks;      /* 1: looks past an event at pairs it did not change are kept */
} vrParams;

/* SPEC 7's contact gap g_c = min(d, 1 mm): where impacts and rest act,
 * whatever the envelope d is, so that with the thesis's d = 0.25 nothing
 * floats.  Inside the envelope the approach to g_c is found by bisection. */
static inline double vrParams_Gap(const vrParams *p) { return p->d < VR_CONTACT_GAP ? p->d : VR_CONTACT_GAP; }
/* the points of a contact region are those within twice that (at most d)
 * of the other body's face: a body resting a little tilted keeps them all */
static inline double vrParams_RegionLevel(const vrParams *p)
{
    return 2 * vrParams_Gap(p) < p->d ? 2 * vrParams_Gap(p) : p->d;
}
/* v_rest = sqrt(2 |a| g_c), what the force adds across the gap (SPEC 3.1,
 * 7): slower impacts do not bounce, and smaller impulses are no hit */
static inline double vrParams_RestSpeed(const vrParams *p)
{
    return sqrt(2.0 * vec3_len(p->flight.accel) * vrParams_Gap(p));
}

typedef struct vrOwnerStats {
    long long checks, heap_pops;
    vrResponseStats response;
} vrOwnerStats;

typedef struct vrOwner vrOwner;

vrOwner *vrOwner_Create(void);
void vrOwner_Free(vrOwner *o);
/* new settings: every pair is re-evaluated at the next span start */
void vrOwner_SetParams(vrOwner *o, const vrParams *p);
/* makes body id known to the owner (it is the caller's memory) */
int vrOwner_HoldBody(vrOwner *o, int id, vrBody *b);
/* forgets body id and removes its pairs */
void vrOwner_DropBody(vrOwner *o, int id);
/* a new pair (a < b, both held); it is evaluated at the next span start */
int vrOwner_AddPair(vrOwner *o, int a, int b);
/* a pair joining at a frame boundary t: settled from the poses at t (inside
 * when within d), or flagged for evaluation at the next span start */
int vrOwner_AddPairAt(vrOwner *o, int a, int b, double t, int flagged);
/* the pairs with a record (lazy: those whose bodies' boxes meet) */
long vrOwner_PairCount(const vrOwner *o);
/* SPEC 10: lazy = 1 makes the owner hold a pair of every two of its
 * bodies, not both static, without vrOwner_AddPair: a pair's record is made
 * when the bodies' boxes meet and dropped when they are apart and the pair
 * has nothing in hand, so memory grows with n and the close pairs.  Set it
 * before the first body. */
void vrOwner_SetLazy(vrOwner *o, int lazy);
/* lazy: only the pairs (a < b) mine(ctx, a, b) accepts are this owner's
 * (a worker's share of the deal, parallel/distribution.h); NULL, as the
 * serial owner has it: every pair.  Set it before the first body. */
void vrOwner_SetFilter(vrOwner *o, int (*mine)(const void *ctx, int a, int b), const void *ctx);
/* lazy: the pairs of the held bodies, as of the poses at t, settled from
 * them (as vrOwner_AddPairAt) or flagged when a body is marked in pending
 * (by id; NULL: none).  -1 on no memory. */
int vrOwner_MakePairsAt(vrOwner *o, double t, const unsigned char *pending);
/* lazy: body id joins with its pairs, to be evaluated at the next span
 * start (as vrOwner_AddPair) */
int vrOwner_AddBody(vrOwner *o, int id, vrBody *b);
/* these bodies were re-anchored: their pairs are re-evaluated at the next
 * span start, and any pending event of theirs is dropped */
void vrOwner_BodiesChanged(vrOwner *o, const int *ids, int n);
/* the pairs to be evaluated with a body among ids[0..nids) that overlap
 * deeper than tol at time t: fills up to max (a, b) id pairs, returns how
 * many overlap, -1 on no memory.  Ids this owner holds no body for are
 * ignored. */
int vrOwner_Overlapping(vrOwner *o, double t, double tol, const int *ids, int nids, int (*out)[2], int max);
/* the first event in the span the grid covers: 1 (with *ev), 0 for none,
 * -1 on no memory.  allow_instant = 0 suppresses events at the span start
 * (after VR_INSTANT_MAX of them at one instant). */
int vrOwner_FirstEvent(vrOwner *o, const vrGrid *g, int allow_instant, vrEvent *ev);
/* every clock moves to t: keep what was learnt up to t, undo the rest */
void vrOwner_Advance(vrOwner *o, double t);
/* every clock moves to the event ev, to be answered next: the same, but
 * with keep_looks the looks past it at pairs it does not change stand
 * (those of the bodies its answer changes go at vrOwner_BodiesChanged) */
void vrOwner_AdvanceTo(vrOwner *o, const vrEvent *ev);
/* the new states of the bodies an event changes; -1 if the solve fails */
int vrOwner_Respond(vrOwner *o, const vrEvent *ev, vrUpdate *up);
void vrOwner_Stats(const vrOwner *o, vrOwnerStats *s);
/* An island step at t for a contact step of h (SPEC 7): appends to out
 * every pair of this owner's that touches at t (within twice the contact
 * gap), with its region's points and their gaps; those pairs' approach is
 * the island's to stop until the next island step.  h = 0: the contacts
 * of an instant, to be solved at once (follow-ups of a response), every
 * touching pair that does not leave, and nothing marked.  Every clock must
 * be at t.  -1 on no memory. */
int vrOwner_Touching(vrOwner *o, double t, double h, vrTouches *out);
/* vrOwner_Touching at an instant (h = 0) for the islands of a and b only:
 * the touches of each body reached from a or b through touches between
 * bodies that can move (leaving or not: a solve may turn a leaving pair
 * back, and island_group.c then joins it); the same touches of those
 * bodies as vrOwner_Touching finds, none of the others.  -1 on no memory. */
int vrOwner_TouchingFrom(vrOwner *o, double t, int a, int b, vrTouches *out);
/* 1 when an island step (vrOwner_Touching, h > 0) would find no pair
 * here: none in the envelope, none flagged, none still to be made */
int vrOwner_Quiet(const vrOwner *o);
/* fn(ctx) is called every few hundred pair evaluations during a look-ahead
 * (a worker sends heartbeats from it while it cannot answer) */
void vrOwner_SetProgress(vrOwner *o, void (*fn)(void *ctx), void *ctx);
/* the bodies whose pairs this owner holds (copies, thesis 3.5.1) */
int vrOwner_BodyCount(const vrOwner *o);

#endif
