/* island_group.h — which touching pairs make which island (SPEC 7,
 * island_step.c): the union-find over the moving bodies of the touches,
 * and the touches grouped by island. */
#ifndef VROC_ISLAND_GROUP_H
#define VROC_ISLAND_GROUP_H

#include "world_state.h"

/* a touch not leaving (its index k in w->touches) and its island's root */
typedef struct vrRooted { int root, k; } vrRooted;

/* a held body (kinematic) is a boundary, as a static one, with a velocity */
static inline int vrIsland_Moves(const vrWorld *w, int id) { return !vrBody_Immovable(&w->table.obj[id]->body); }

/* body i's island: its root, the lowest body id in it (parent as
 * vrIsland_Union set it; compresses the path) */
int vrIsland_Root(int *parent, int i);
/* The union-find of the touching pairs (those not leaving) over moving
 * bodies: parent[] and in_island[] set for every id of a touch and of the
 * contact set (the rest of those arrays is not read).  The moving ids of
 * the touches, each once in id order, into ids (NULL: not wanted); their
 * count. */
int vrIsland_Union(vrWorld *w, int *parent, int *in_island, int *ids);
/* The touches not leaving, by their island's root and in the touches'
 * order within one (malloc'ed, *m of them), so that an island finds its
 * own without a pass over all of them.  NULL when out of memory. */
vrRooted *vrIsland_Group(vrWorld *w, int *parent, int *m);
/* island r's touches in g (vrIsland_Group): the first, their count in *len */
const vrRooted *vrIsland_Run(const vrRooted *g, int m, int r, int *len);

#endif
