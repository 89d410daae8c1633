/* aabb_tree.h — a dynamic bounding-volume tree of axis-aligned boxes (the
 * structure of Box2D's b2DynamicTree and Bullet's btDbvt): leaves hold a
 * box and an id, an inner node the smallest box around its two children.
 * A leaf goes in where the surface-area cost grows least and the tree is
 * kept balanced by rotations on the way back up; a leaf's box may instead
 * be changed in place (refit), and the whole tree rebuilt top-down when
 * many refits have let it grow loose.  No fat boxes: the broadphase's boxes
 * are already the whole rest of a frame (broadphase.h).
 *
 * Overlap is closed (boxes that touch overlap), as vrBox_Disjoint's; an
 * inner box is the exact fmin/fmax of its children's, so a query prunes
 * nothing that a look at every leaf would find. */
#ifndef VROC_AABB_TREE_H
#define VROC_AABB_TREE_H

#include "vec.h"

typedef struct vrAabb { vec3 lo, hi; } vrAabb;

typedef struct vrTreeNode {
    vrAabb box;
    int parent;            /* -1 at the root; the next free node while free */
    int child1, child2;    /* -1 at a leaf */
    int height;            /* 0 at a leaf, -1 while free */
    int id;                /* a leaf's: the caller's */
} vrTreeNode;

typedef struct vrTree {
    vrTreeNode *node;
    int cap, root, free_list, nleaf;
} vrTree;

void vrTree_Init(vrTree *t);
void vrTree_Free(vrTree *t);
/* a new leaf of box b and id: its node, or -1 (tree unchanged) when out of
 * memory */
int vrTree_Insert(vrTree *t, const vrAabb *b, int id);
void vrTree_Remove(vrTree *t, int leaf);
/* the leaf's box becomes b and its ancestors' boxes follow (no change of
 * shape: cheap, but the tree grows loose if boxes travel far) */
void vrTree_Refit(vrTree *t, int leaf, const vrAabb *b);
/* only the leaf's box: many of them, then one vrTree_RefitAll */
static inline void vrTree_SetLeaf(vrTree *t, int leaf, const vrAabb *b) { t->node[leaf].box = *b; }
void vrTree_RefitAll(vrTree *t);
/* the same leaves in a tree made anew top-down (median splits along the
 * longest axis of the centres); -1, the tree as it was, on no memory */
int vrTree_Rebuild(vrTree *t);
/* the sum of the inner nodes' surface areas: what a query pays, roughly */
double vrTree_Cost(const vrTree *t);

/* hit(ctx, id) for every leaf whose box overlaps b */
void vrTree_Query(const vrTree *t, const vrAabb *b, void (*hit)(void *ctx, int id), void *ctx);
/* pair(ctx, a, b) once for every two leaves of t whose boxes overlap */
void vrTree_SelfPairs(const vrTree *t, void (*pair)(void *ctx, int a, int b), void *ctx);
/* pair(ctx, a, b) for every leaf a of t and leaf b of u that overlap */
void vrTree_CrossPairs(const vrTree *t, const vrTree *u, void (*pair)(void *ctx, int a, int b), void *ctx);

/* the invariants (parents, heights, balance within `slack`, exact inner
 * boxes, leaf count): 0, or -1 for a broken tree (for the tests) */
int vrTree_Check(const vrTree *t, int slack);

static inline int vrAabb_Disjoint(const vrAabb *a, const vrAabb *b)
{
    return a->hi.x < b->lo.x || b->hi.x < a->lo.x || a->hi.y < b->lo.y || b->hi.y < a->lo.y
        || a->hi.z < b->lo.z || b->hi.z < a->lo.z;
}

#endif
