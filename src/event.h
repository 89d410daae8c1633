/* event.h — what changes a body's motion (SPEC 3.1), and the state a holder
 * needs to follow the change (the thesis's `update` message, 3.5.2). */
#ifndef VROC_EVENT_H
#define VROC_EVENT_H

#include "body.h"

typedef enum vrEventKind {
    VR_EV_NONE,
    VR_EV_IMPACT,        /* distance came down to g_c while approaching */
    VR_EV_CONTACT,       /* within g_c, approaching faster than v_eps */
    VR_EV_PUSHOUT        /* interpenetrating: pushed apart along the normal */
} vrEventKind;

typedef struct vrEvent {
    int kind;
    double t;
    long long order;     /* the pair's order: (lower id, higher id) */
    int a, b;            /* object ids, a < b */
    vec3 n;              /* contact normal, from a toward b */
    vec3 c;              /* where the impulse acts (centroid of the most approaching points) */
    double approach;     /* n.u at c, < 0 when approaching */
    double e;            /* restitution to use */
    double mu;           /* friction to use: sqrt(mu_a mu_b) (SPEC 7) */
    double depth;        /* push-out */
} vrEvent;

/* (time, pair order): the order events are taken in */
static inline int vrEvent_Before(const vrEvent *x, const vrEvent *y)
{
    return x->t < y->t || (x->t == y->t && x->order < y->order);
}

/* A body's new state after an event: everything a holder needs to
 * re-anchor.  raw = 1: x, v, q, L are the body's anchor itself at t = t0,
 * to be restored bit for bit (setups, snapshots); raw = 0: the state at an
 * event, re-anchored there (clamped, normalised) by every holder alike. */
typedef struct vrBodyState {
    int id;
    double t;
    vec3 x, v, L;
    quat q;
    int raw;
    int resting, hit;
    int contact, island;     /* vrBody's */
    int kinematic;           /* vrBody's: held by the hand (grab.h); x, v, q, L (= omega) its motion */
    int clamped;             /* the responder's max_angular cut this state's spin (stats clamps) */
} vrBodyState;

typedef struct vrUpdate { int n, cap; vrBodyState *body; } vrUpdate;

/* A pair touching at an island step (SPEC 7): within twice the contact
 * gap, with at most VR_TOUCH_POINTS points of its region and their gaps.
 * Reported by the owners at each island step (island_step.c). */
#define VR_TOUCH_POINTS 8
typedef struct vrTouch {
    int a, b;                  /* a < b */
    vec3 n;                    /* from a toward b */
    double dist;
    int npoints;
    vec3 point[VR_TOUCH_POINTS];
    double gap[VR_TOUCH_POINTS];
    int leaving;               /* 1: every point separates, in no island; -1: the island step's
                                * solve turned it back (island_step.c) */
} vrTouch;

typedef struct vrTouches { int n, cap; vrTouch *t; } vrTouches;

vrTouch *vrTouches_Add(vrTouches *l);
void vrTouches_Free(vrTouches *l);

void vrUpdate_Init(vrUpdate *u);
void vrUpdate_Free(vrUpdate *u);
/* the slot of body id in u, added as a capture of b at time t if absent */
vrBodyState *vrUpdate_Body(vrUpdate *u, vrBody *b, double t);
/* body id's first state among u's first n, or NULL (a caller that adds
 * each body once searches only the states u held before it began) */
vrBodyState *vrUpdate_Find(const vrUpdate *u, int n, int id);
/* ...added without the search, for a caller that knows b is not in u (a
 * body at a time into an update of many: the search made it quadratic) */
vrBodyState *vrUpdate_Append(vrUpdate *u, vrBody *b, double t);
/* each state of `from` into `to`, in order: replacing to's state of its
 * body (the first, as vrUpdate_Body finds it) or added; ids below nid
 * (a whole world's update is merged by a table of ids, not searched
 * state by state); -1 when out of memory */
int vrUpdate_Merge(vrUpdate *to, const vrUpdate *from, int nid);
/* every state of `from` added to the end of `to`, in order (no merge: a
 * body in both is then in `to` twice); -1 when out of memory */
int vrUpdate_AppendStates(vrUpdate *to, const vrUpdate *from);
/* x's state and, when y is not NULL, y's (else *sy = NULL), both in the
 * update: both are added before either pointer is taken, since adding one
 * may move the array; -1 when out of memory */
int vrUpdate_Bodies(vrUpdate *u, vrBody *x, vrBody *y, double t, vrBodyState **sx, vrBodyState **sy);
/* st, its velocity v new, after an impulse that jolted the body
 * (vrBody_Jolted): a hit; and a body in an island's contact step (flying
 * straight, the step's gravity paid in at its start) sent up against the
 * force accel flies under it from st->t.  Flown straight, it climbed
 * without slowing to the next island step, and the world gained m |g| v t
 * (0.1 J for a box knocked up at 4 m/s off the floor of the peers' 100
 * room) */
void vrBodyState_Jolt(vrBodyState *st, vec3 accel);
void vrBody_Capture(vrBody *b, double t, vrBodyState *st);
/* the body's anchor as it is (raw = 1) */
void vrBody_CaptureAnchor(const vrBody *b, vrBodyState *st);
/* the number of speed clamps it took (stats clamps): the responder's, and
 * the caps' at the anchor */
int vrBody_Apply(vrBody *b, const vrBodyState *st, const vrFlight *f);

#endif
