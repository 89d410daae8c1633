/* closest_exhaustive.h — what the closest-feature walk does past its step
 * cap, or when the plane between its closest points does not separate the
 * bodies (closest.c): every feature pair searched (closest_exhaustive.c). */
#ifndef VROC_CLOSEST_EXHAUSTIVE_H
#define VROC_CLOSEST_EXHAUSTIVE_H

#include "closest_walk.h"

/* the walk w ended by search, O(E F) over the features that can matter:
 * VR_WALK_DONE with w->c the closest points, or VR_WALK_PENETRATING with
 * w->pen_point; w->f the features */
int vrWalk_Exhaustive(vrWalk *w);
/* the same over every feature (the definition, for the tests) */
int vrWalk_ExhaustiveAll(vrWalk *w);

#endif
