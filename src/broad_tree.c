/* broad_tree.c — the broadphase on box trees (broad_tree.h).  At a frame
 * start every held body's box for the frame is made (broadphase.c's
 * make_box, through vrBroad_Box) and its leaf follows: a moving body's leaf
 * box is set and the moving tree refitted once, bottom-up; bodies new to a
 * tree (or to their kind: a body made static) go in after the refit;
 * bodies gone or boxless come out.  When the refits have let the moving
 * tree grow loose (its cost LOOSE times what it was when last made), it is
 * made anew top-down.  The pairs are then the moving tree's with itself and
 * with the static tree: two static bodies make none, as in the sweep.
 *   drop, place, insert_late, keep_tight   the leaves at a frame start
 *   vrBroadTree_NewFrame, vrBroadTree_Meeting, vrBroadTree_Moved */
#include <stdlib.h>
#include "broad_tree.h"
#include "grow.h"

enum { IN_NONE, IN_MOVING, IN_FIXED };

/* rebuild when refits raised the tree's cost by half: a rebuild of 10,000
 * leaves costs about as much as a few frames' loss to a loose tree */
#define LOOSE 1.5

/* the tree of a box: a static or resting body's, kept for good, is fixed */
static int in_of(const vrBox *x) { return x->frame == VR_BOX_FOR_GOOD ? IN_FIXED : IN_MOVING; }

static vrTree *tree_of(vrBroadphase *bp, int id) { return bp->leaf[id].in == IN_FIXED ? &bp->fixed : &bp->moving; }

static vrAabb aabb_of(const vrBox *x)
{
    vrAabb a;
    a.lo = x->lo, a.hi = x->hi;
    return a;
}

void vrBroadTree_Free(vrBroadphase *bp)
{
    vrTree_Free(&bp->moving);
    vrTree_Free(&bp->fixed);
    free(bp->leaf);
    free(bp->late);
    bp->leaf = NULL, bp->late = NULL;
    bp->leafcap = bp->latecap = 0;
    bp->built = 0;
}

static int reserve(vrBroadphase *bp, int n)
{
    int i, old = bp->leafcap;
    if (vrGrow((void **)&bp->leaf, &bp->leafcap, n, sizeof *bp->leaf) != 0) return -1;
    for (i = old; i < bp->leafcap; i++) bp->leaf[i].node = -1, bp->leaf[i].in = IN_NONE;
    return 0;
}

static void drop(vrBroadphase *bp, int id)
{
    if (!bp->leaf[id].in) return;
    vrTree_Remove(tree_of(bp, id), bp->leaf[id].node);
    bp->leaf[id].node = -1;
    bp->leaf[id].in = IN_NONE;
}

static int same_aabb(const vrAabb *a, const vrAabb *b)
{
    return a->lo.x == b->lo.x && a->lo.y == b->lo.y && a->lo.z == b->lo.z && a->hi.x == b->hi.x
        && a->hi.y == b->hi.y && a->hi.z == b->hi.z;
}

/* body id's new box x in its leaf; 1 when it has none yet (it goes in
 * after the refit, which needs the old inner boxes around the old leaves) */
static int place(vrBroadphase *bp, int id, const vrBox *x)
{
    struct vrLeafRef *r = &bp->leaf[id];
    vrAabb a = aabb_of(x);
    if (r->in != IN_NONE && r->in != in_of(x)) drop(bp, id);
    if (r->in == IN_NONE) return 1;
    if (r->in == IN_MOVING) vrTree_SetLeaf(&bp->moving, r->node, &a);
    else if (!same_aabb(&bp->fixed.node[r->node].box, &a))   /* d changed, or a resting body boxed again */
        vrTree_Refit(&bp->fixed, r->node, &a);
    return 0;
}

static int insert_late(vrBroadphase *bp, int nlate)
{
    int i;
    for (i = 0; i < nlate; i++) {
        int id = bp->late[i], in = in_of(&bp->box[id]);
        vrAabb a = aabb_of(&bp->box[id]);
        int node = vrTree_Insert(in == IN_FIXED ? &bp->fixed : &bp->moving, &a, id);
        if (node < 0) return -1;    /* the others are late again next frame */
        bp->leaf[id].node = node;
        bp->leaf[id].in = in;
    }
    return 0;
}

static void keep_tight(vrBroadphase *bp)
{
    double cost = vrTree_Cost(&bp->moving);
    if (cost <= LOOSE * bp->built) {
        bp->built = fmin(bp->built, cost);   /* boxes that shrink together leave it as tight */
        return;
    }
    if (vrTree_Rebuild(&bp->moving) == 0) bp->built = vrTree_Cost(&bp->moving);
}

typedef struct vrSink { void (*meet)(void *ctx, int x, int y); void *ctx; } vrSink;

static void meet_ordered(void *ctx, int x, int y)
{
    const vrSink *s = ctx;
    s->meet(s->ctx, x < y ? x : y, x < y ? y : x);
}

/* every held body's leaf as its box for the frame says */
static int make_leaves(vrBroadphase *bp, vrBody *const *body, int nbody)
{
    int i, nlate = 0;
    if (reserve(bp, nbody) != 0 || vrGrow((void **)&bp->odd, &bp->oddcap, nbody, sizeof *bp->odd) != 0
        || vrGrow((void **)&bp->late, &bp->latecap, nbody, sizeof *bp->late) != 0)
        return -1;
    bp->nodd = 0;
    for (i = 0; i < bp->leafcap; i++) {
        const vrBox *x;
        if (i >= nbody || !body[i]) {
            drop(bp, i);
            continue;
        }
        x = vrBroad_Box(bp, body, i);
        if (!x->valid) {
            drop(bp, i);
            bp->odd[bp->nodd++] = i;
        } else if (place(bp, i, x)) {
            bp->late[nlate++] = i;
        }
    }
    vrTree_RefitAll(&bp->moving);
    if (insert_late(bp, nlate) != 0) return -1;
    keep_tight(bp);
    return 0;
}

int vrBroadTree_NewFrame(vrBroadphase *bp, vrBody *const *body, int nbody, void (*meet)(void *ctx, int x, int y),
                         void (*boxless)(void *ctx, int id), void *ctx)
{
    vrSink s;
    int i;
    if (make_leaves(bp, body, nbody) != 0) return -1;
    for (i = 0; i < bp->nodd; i++) boxless(ctx, bp->odd[i]);
    s.meet = meet, s.ctx = ctx;
    vrTree_SelfPairs(&bp->moving, meet_ordered, &s);
    vrTree_CrossPairs(&bp->fixed, &bp->moving, meet_ordered, &s);
    return 0;
}

typedef struct vrAsked { void (*meet)(void *ctx, int y); void *ctx; int id; } vrAsked;

static void meet_other(void *ctx, int y)
{
    const vrAsked *a = ctx;
    if (y != a->id) a->meet(a->ctx, y);
}

void vrBroadTree_Meeting(const vrBroadphase *bp, int id, void (*meet)(void *ctx, int y), void *ctx)
{
    const vrBox *x = &bp->box[id];
    vrAsked a;
    vrAabb q;
    int i;
    if (!x->valid) {         /* meets everything */
        for (i = 0; i < bp->leafcap; i++)
            if (i != id && bp->leaf[i].in) meet(ctx, i);
        return;
    }
    a.meet = meet, a.ctx = ctx, a.id = id;
    q = aabb_of(x);
    vrTree_Query(&bp->moving, &q, meet_other, &a);
    vrTree_Query(&bp->fixed, &q, meet_other, &a);
}

/* refitted in place: within a frame an event changes a path a little, and
 * the next frame start refits or remakes the tree anyway */
void vrBroadTree_Moved(vrBroadphase *bp, int id)
{
    const vrBox *x = &bp->box[id];
    vrAabb a;
    if (id >= bp->leafcap || !bp->leaf[id].in) return;
    if (x->valid) {
        a = aabb_of(x);
        vrTree_Refit(tree_of(bp, id), bp->leaf[id].node, &a);
        return;
    }
    drop(bp, id);
    if (vrGrow((void **)&bp->odd, &bp->oddcap, bp->nodd + 1, sizeof *bp->odd) != 0) bp->near_frame = -1;
    else bp->odd[bp->nodd++] = id;
}
