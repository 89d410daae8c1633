/* broad_tree.h — the broadphase of broadphase.h on box trees (kind
 * VR_BROAD_TREE): the moving bodies' boxes in one dynamic tree, refitted
 * at each frame start and made anew when refits have let it grow loose,
 * the static bodies' in another that changes only when they do.  The
 * entry points of broadphase.h call these for that kind; the pairs met are
 * the sweep's, in another order. */
#ifndef VROC_BROAD_TREE_H
#define VROC_BROAD_TREE_H

#include "broadphase.h"

/* vrBroad_NewFrame's pairs, the boxes made already for the frame */
int vrBroadTree_NewFrame(vrBroadphase *bp, vrBody *const *body, int nbody, void (*meet)(void *ctx, int x, int y),
                         void (*boxless)(void *ctx, int id), void *ctx);
/* vrBroad_Meeting's bodies in the trees (the frame's trees made; vrBroad_Meeting met the odd ones) */
void vrBroadTree_Meeting(const vrBroadphase *bp, int id, void (*meet)(void *ctx, int y), void *ctx);
/* body id's box was made again within the frame */
void vrBroadTree_Moved(vrBroadphase *bp, int id);
void vrBroadTree_Free(vrBroadphase *bp);

#endif
