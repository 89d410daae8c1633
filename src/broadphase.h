/* broadphase.h — which bodies could meet in the rest of a frame, so that a
 * pair owner (owner.c, dormancy.c) looks only at those pairs.
 *
 * Each held body has a box for the rest of the current frame: a moving
 * body's is the box its centre sweeps (exact path extremes), padded by its
 * outer radius; a static body's is its surface's bounding box; both are
 * padded by half the envelope d.  Two bodies whose boxes are apart cannot
 * come within d before the frame ends.  At a frame start the boxes are
 * sorted along x and swept, so the pairs that overlap come out without a
 * look at the (many more) pairs that stay apart; a pair map turns two
 * bodies into their pair.  Within a frame the moving bodies stay sorted
 * as events rebox them, so that the bodies an event's box meets are found
 * by a search, not by a look at every pair of the changed body.
 */
#ifndef VROC_BROADPHASE_H
#define VROC_BROADPHASE_H

#include <limits.h>
#include "body.h"
#include "aabb_tree.h"

typedef struct vrBox { vec3 lo, hi; int valid; long long frame; } vrBox;

/* a pair's order: (a << 32) | b for its bodies a < b (in either order here) */
static inline long long vrPair_Order(int x, int y)
{
    return x < y ? ((long long)x << 32) | (long long)y : ((long long)y << 32) | (long long)x;
}

/* pair index by the pair's order (vrPair_Order): open addressing */
typedef struct vrPairMap { long long *key; int *val; int cap, n; } vrPairMap;

/* which structure finds the pairs (the same pairs either way) */
typedef enum vrBroadKind { VR_BROAD_SWEEP, VR_BROAD_TREE } vrBroadKind;

typedef struct vrBroadphase {
    vrBroadKind kind;
    double t0, T, d;          /* the span looked through, the frame's end, the envelope */
    long long frame;          /* counts frames: a box is made when first needed in one */
    vrBox *box;               /* by body id */
    int cap;
    int *sweep;               /* the held bodies by their boxes' lower x, as of the last frame */
    int nsweep, sweepcap;
    int stale;                /* bodies came or went: the sweep list is made anew */
    /* for vrBroad_Meeting, made at each frame start */
    long long near_frame;     /* the frame they are for (-1: none, e.g. no memory) */
    int *near, nnear, nearcap;/* moving bodies with a box, by their box's lower x */
    int *pos, poscap;         /* by body id: its index in near, or -1 */
    int *odd, nodd, oddcap;   /* the others: static (wide boxes) or boxless */
    double widest;            /* no box in near is wider along x (within the frame) */
    /* VR_BROAD_TREE (broad_tree.c): near is unused, odd holds the boxless */
    vrTree moving, fixed;     /* the moving bodies' boxes, the static ones' */
    struct vrLeafRef { int node; int in; } *leaf;   /* by body id: its leaf and tree (0: none) */
    int leafcap;
    int *late, latecap;       /* bodies whose leaves go in after the frame's refit */
    double built;             /* the moving tree's cost when last made anew */
    vrPairMap map;
} vrBroadphase;

void vrBroad_Init(vrBroadphase *bp);
/* the structure: a change makes the next frame start afresh */
void vrBroad_SetKind(vrBroadphase *bp, vrBroadKind kind);
void vrBroad_Free(vrBroadphase *bp);
/* box slots for body ids below n */
int vrBroad_Reserve(vrBroadphase *bp, int n);
/* body id was placed, replaced or dropped: its box and the sweep list are
 * made anew */
void vrBroad_BodyChanged(vrBroadphase *bp, int id);
/* a new envelope: every box is made anew, and none is valid until the
 * next frame */
void vrBroad_SetEnvelope(vrBroadphase *bp, double d);
/* the box of body id made again now (its motion changed) */
void vrBroad_Rebox(vrBroadphase *bp, vrBody *const *body, int id);

/* vrBox.frame of a static body's box: kept until the body or d changes */
#define VR_BOX_FOR_GOOD LLONG_MAX

/* the box of body id (body[id] may be NULL: no box); inline, as an event
 * asks it for every pair of the bodies it changed */
static inline const vrBox *vrBroad_Box(vrBroadphase *bp, vrBody *const *body, int id)
{
    vrBox *x = &bp->box[id];
    if (x->frame != bp->frame && x->frame != VR_BOX_FOR_GOOD) vrBroad_Rebox(bp, body, id);
    return x;
}

static inline int vrBox_Disjoint(const vrBox *a, const vrBox *b)
{
    return a->hi.x < b->lo.x || b->hi.x < a->lo.x || a->hi.y < b->lo.y || b->hi.y < a->lo.y
        || a->hi.z < b->lo.z || b->hi.z < a->lo.z;
}

/* both boxes valid and apart */
static inline int vrBroad_Apart(const vrBox *a, const vrBox *b) { return a->valid && b->valid && vrBox_Disjoint(a, b); }
/* A new frame [t0, T]: new boxes, sorted and swept.  Calls meet(ctx, x, y)
 * for every two held bodies (x < y), not both static, whose boxes overlap
 * and boxless(ctx,
 * id) for every held body without a valid box.  Returns -1 (and calls
 * nothing) when out of memory: the caller must then assume every pair
 * could meet. */
int vrBroad_NewFrame(vrBroadphase *bp, vrBody *const *body, int nbody, double t0, double T,
                     void (*meet)(void *ctx, int x, int y), void (*boxless)(void *ctx, int id), void *ctx);

/* Calls meet(ctx, y) for every held body y != id whose box may overlap
 * id's (a superset: boxless bodies, and a few that do not, come too).
 * Returns -1, calling nothing, when the current frame has no sorted list
 * (bodies came or went since its start, or no memory): the caller must
 * then look at every pair. */
int vrBroad_Meeting(const vrBroadphase *bp, int id, void (*meet)(void *ctx, int y), void *ctx);
static inline int vrBroad_CanMeet(const vrBroadphase *bp) { return bp->near_frame == bp->frame; }

/* The pairs that could be within d at the one instant t (a new owner's
 * pairs, new bodies'): boxes of the bodies where they are at t (a moving
 * body's bounding sphere, a static body's surface box), padded by d/2,
 * sorted and swept as at a frame start.  Calls meet(ctx, x, y), x < y, for
 * every two held bodies, not both static, whose boxes overlap and of which
 * one is marked in want (want NULL: every body).  -1 on no memory, nothing
 * called then.  The frame's boxes and lists are not touched. */
int vrBroad_MeetAt(const vrBroadphase *bp, vrBody *const *body, int nbody, double t, const unsigned char *want,
                   void (*meet)(void *ctx, int x, int y), void *ctx);

/* an empty map for at least n pairs (-1 and no map when out of memory) */
int vrPairMap_Reset(vrPairMap *m, int n);
void vrPairMap_Put(vrPairMap *m, long long key, int val);
int vrPairMap_Find(const vrPairMap *m, long long key);   /* -1: none */
void vrPairMap_Remove(vrPairMap *m, long long key);
void vrPairMap_Free(vrPairMap *m);

#endif
