/* owner_state.h — what a pair owner keeps, shared by the files that make
 * it up (owner.h is what the coordinator sees):
 *   owner.c       life cycle, bodies and pairs held, where a pair waits
 *   dormancy.c    pairs that cannot meet before the frame ends (broadphase)
 *   lookahead.c   the grid points of a span, due pairs, evaluation, undo log
 *   pair_query.c  a pair's contact at t (with the region memo)
 *   bisect.c      the moment of an impact or a touch (thesis 3.2.3)
 *   pair_events.c which event an evaluated pair has (SPEC 3.1)
 *   cheap_look.c  looks that prove a pair clear without its region
 *   quiet.c       proofs that an inside pair has nothing to do for a while
 */
#ifndef VROC_OWNER_STATE_H
#define VROC_OWNER_STATE_H

#include "owner.h"
#include "broadphase.h"
#include "distbound.h"
#include "heap.h"

#define VR_TIE_SPEED 1e-9      /* m/s: points this close to the most approaching one share the impulse */
#define VR_CONTAIN_TOL 1e-9    /* m: support containment in the contact plane */

typedef struct vrPair {
    int a, b;                 /* object ids, a < b */
    long long order;
    int inside;               /* distance <= d at t_check: in the envelope */
    int near;                 /* distance <= g_c at t_check: touching (vrParams_Gap) */
    int overlap;              /* distance < -VR_PENETRATION_TOL at t_check */
    int scheduled;            /* 0 when both bodies are frozen (static or resting) */
    int flagged;              /* to be evaluated at the next span start */
    double t_check;
    double looked;            /* the grid point of its last look (kept looks are not made again) */
    double key;               /* expected earliest event (in the heap when scheduled and finite) */
    double quiet_until;       /* inside, but nothing can happen until then (quiet_slide) */
    double touch_t;           /* the last island step it touched at (vrOwner_Touching) */
    int active;               /* index in the active list, or -1 */
    vrWalkCache cache;
} vrPair;

/* per pair, in a byte array an event can sweep without touching the pairs
 * themselves (a thousand bodies make half a million pairs) */
enum { HOT_DORMANT = 1, HOT_INSIDE = 2, HOT_LISTED_A = 4, HOT_LISTED_B = 8 };

/* what an evaluation changed, so Advance can take it back */
typedef struct vrUndo {
    int pair;
    double at;                /* the evaluation time */
    int inside, near, overlap;
    double t_check, looked;
    double key, quiet_until;
    vrWalkCache cache;        /* where its walks start: in a tie (parallel faces) the distance's
                                 last bits depend on it, so a look made again starts where it did */
} vrUndo;

typedef struct vrIntList { int n, cap; int *v; } vrIntList;

/* A pair's last contacts with their regions (see vrPair_Query), in
 * 2^REGION_MEMO_BITS slots */
#define REGION_MEMO_BITS 12
#define REGION_MEMO (1 << REGION_MEMO_BITS)
typedef struct vrRegionMemo {
    long long order;          /* the pair; 0 with nothing kept (a pair's order is never 0: a < b) */
    unsigned long shape_a, shape_b;   /* the shapes' serials */
    double d;
    vec3 pa, pb;              /* the poses it was made at */
    quat qa, qb;
    vrContact c;
} vrRegionMemo;

struct vrOwner {
    vrParams p;
    double gc, region;        /* vrParams_Gap, vrParams_RegionLevel */
    double gather_t, gather_h; /* the last island step's time and length (vrOwner_Touching) */
    double span_end;          /* the end of the span being looked through: the next island step */
    double step_h;            /* the grid step of the span being looked through */
    double closed_t;          /* an instant that had its VR_INSTANT_MAX: no event there (NAN: none) */
    double closed_end;        /* nor before this (the next grid point, when events crept) */
    double v_rest;            /* sqrt(2 |a| g_c), SPEC 3.1, 7 */
    vrBody **body;            /* by id, NULL when not held */
    vrIntList *body_pairs;    /* by id: indices of its pairs */
    vrIntList *body_partners; /* by id: the other body of each of those pairs */
    vrIntList *body_awake;    /* by id: its pairs that may not be dormant (each listed once,
                                 HOT_LISTED_A or _B; a dormant one may linger) */
    unsigned char *was_frozen; /* by id: frozen when its pairs were last scheduled (2: not yet) */
    unsigned char *hot;       /* by pair: HOT_* */
    vrBroadphase bp;          /* which pairs could meet in the rest of the frame; its t0 and T
                                 are the span being looked through and the frame's end */
    int hotcap;
    int bodycap, nheld;
    vrPair *pair;
    int npair, paircap;
    vrHeap heap;
    vrIntList active;         /* inside pairs: due at every grid point, kept out of the heap */
    vrIntList flagged, due, due_inside;  /* due at a grid point: outside the envelope, inside */
    /* keys of pairs found outside at the grid point being looked at (by the
     * walk or a full look), made once it is known whether an impact before
     * it rolls them back */
    int defer_keys, nlater, latercap;
    struct vrLaterKey { int pair; double dist; vec3 n; } *later;
    vrUndo *undo;
    int nundo, undocap;
    vrEvent *pending;         /* events found at pending_t not yet taken */
    int npending, pendcap;
    double pending_t;
    vrEvent *found;           /* scratch: the events of one grid point */
    int nfound, foundcap;
    /* with p.keep_looks, a walk's looks past the event answered are kept
     * for the pairs whose bodies it did not change (lookahead.c) */
    struct vrKept { vrEvent ev; double point; } *kept;   /* their events, by the grid point found at */
    int nkept, keptcap;
    double kept_a, kept_h;    /* the grid the kept looks are on */
    int keep_lost;            /* no memory to keep an event: the next answer takes every look back */
    vrIntList redo;           /* pairs whose last look stopped short (a bisection past an event) */
    vrIntList again;          /* kept pairs the heap gave at their own grid point: back into it */
    vrIntList marked;         /* pairs whose looks are to be taken back, marked in mark[] */
    unsigned char *mark;
    int markcap;
    vrIntList reach;          /* an instant's islands, body by body (vrOwner_TouchingFrom) */
    unsigned char *reached;   /* by body id: 1 queued, 2 its pairs looked at */
    int reachedcap;
    vrResponder *responder;
    vrRegionMemo memo[REGION_MEMO];
    long long checks, heap_pops;
    int awake_lost;           /* no memory to list a pair awake: events look at every pair */
    /* lazy pairs (pair_life.c): with lazy = 1 the owner holds a pair of any
     * two of its bodies (not both static), but keeps its record only while
     * their boxes meet; a slot of o->pair with a = -1 is free */
    int lazy;
    int (*mine)(const void *ctx, int a, int b);   /* which pairs are this owner's (NULL: all) */
    const void *mine_ctx;
    vrIntList free_pairs;     /* free slots, to be used again */
    unsigned char *fresh;     /* by body id: its pairs are still to be made (at the next look at the poses) */
    int any_fresh;
    void (*progress)(void *ctx);
    void *progress_ctx;
};

static inline int vrBody_Frozen(const vrBody *b) { return b->is_static || b->resting; }
static inline int vrBody_IsSphere(const vrBody *b) { return b->shape.kind == VR_SHAPE_SPHERE; }

/* touching at the last island step: its approach is the island's to stop,
 * until the next (pair_events.c's too_fast) */
static inline int vrPair_InIsland(const vrOwner *o, const vrPair *p) { return p->touch_t == o->gather_t; }

/* touching: within g_c, and a rounding's width more (VR_PENETRATION_TOL),
 * so that a pair resting at g_c does not cross it back and forth by
 * rounding and make an impact of each crossing */
static inline int vrPair_Near(const vrOwner *o, double dist) { return dist <= o->gc + VR_PENETRATION_TOL; }

/* owner.c: containers, and where a pair waits */
int vrIntList_Push(vrIntList *l, int v);
int vrEvents_Push(vrEvent **arr, int *n, int *cap, const vrEvent *ev);
void vrPair_Flag(vrOwner *o, int pi);                /* evaluated at the next span start */
void vrPair_ListAwake(vrOwner *o, int pi);           /* in both its bodies' awake lists */
void vrPair_Place(vrOwner *o, int pi);               /* into the heap or the active list */
void vrPair_UpdateSchedule(vrOwner *o, int pi);      /* unscheduled when both bodies are frozen */
double vrPair_Key(const vrOwner *o, const vrPair *p, double t, double dist, vec3 n);
void vrPair_Settle(vrOwner *o, int pi, int inside, double key);   /* after an evaluation */

/* pair_life.c */
int vrPair_Meet(vrOwner *o, int x, int y);          /* the pair of x and y (made when lazy), -1: none */
int vrOwner_MakeFresh(vrOwner *o, double t);        /* the pairs of fresh bodies, from the poses at t */
int vrOwner_MeetAll(vrOwner *o, int id);            /* lazy: every pair of id made (it meets everything) */
void vrOwner_DropApart(vrOwner *o);                 /* lazy: records of pairs apart and quiet go */
static inline int vrPair_Free(const vrPair *p) { return p->a < 0; }

/* look_log.c: a look at pair pi at time `at` logged; its looks past the
 * next answer taken back (it stopped short); the looks of the pairs of
 * the bodies ids[0..n) taken back */
void vrLook_Remember(vrOwner *o, int pi, double at);
void vrLook_Redo(vrOwner *o, int pi);
void vrOwner_TakeBackChanged(vrOwner *o, const int *ids, int n);

/* dormancy.c */
int vrPair_Apart(vrOwner *o, int pi);               /* cannot meet before the frame ends */
void vrPair_MakeDormant(vrOwner *o, int pi);
int vrOwner_NewFrame(vrOwner *o, const vrGrid *g);   /* -1: no memory */

/* pair_query.c: region = 0, the distance only; 1, the contact region too */
void vrPair_Query(vrOwner *o, vrPair *p, double t, int region, vrPose *pa, vrPose *pb, vrContact *c);
/* the spheres' real poses and the flush-surface normal, after a query with the region */
void vrPair_ForEvents(vrOwner *o, const vrPair *p, double t, vrPose *pa, vrPose *pb, vrContact *c);
void vrPair_EventQuery(vrOwner *o, vrPair *p, double t, vrPose *pa, vrPose *pb, vrContact *c);

/* bisect.c: is the distance at t at most level (with its bounds over [lo, hi] in *near)? */
int vrPair_Within(vrOwner *o, vrPair *p, double t, double level, double lo, double hi, vrDistBound *near);
/* the first time in (lo, hi] with distance <= level; NAN once past wanted */
double vrPair_Bisect(vrOwner *o, vrPair *p, double lo, double hi, const vrContact *at_hi, double level,
                     double wanted);

/* pair_events.c: 1 with *ev when the pair has that event */
int vrPair_InsideEvents(vrOwner *o, vrEvent *ev, double t, const vrPair *p, const vrPose *pa,
                        const vrPose *pb, const vrContact *c);
int vrPair_Impact(vrOwner *o, vrEvent *ev, vrPair *p, double tau);
int vrPair_Touch(vrOwner *o, vrEvent *ev, vrPair *p, double tau);

/* cheap_look.c: 1 when the pair was proved clear and keyed */
int vrPair_ClearBySpheres(vrOwner *o, int pi, double t);
int vrPair_ClearByWalk(vrOwner *o, int pi, double t);
/* the bounding spheres' gap at t, and the direction between the centres */
double vrPair_SphereGap(const vrOwner *o, const vrPair *p, double t, vec3 *dir);

/* lookahead.c: a key to be made once no earlier impact drops it; 0 when made at once */
int vrOwner_PutOffKey(vrOwner *o, int pi, double dist, vec3 n);

/* quiet.c: how far ahead the pair is proved quiet (-INFINITY: not) */
double vrPair_QuietHorizon(vrOwner *o, const vrPair *p, double t, const vrContact *c);
/* a pair in the envelope, not touching: quiet until it may touch or leave */
double vrPair_ApproachHorizon(vrOwner *o, const vrPair *p, double t, const vrPose *pa, const vrPose *pb,
                              const vrContact *c);

#endif
