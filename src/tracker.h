/* tracker.h — the world's trackers, as the world's life cycle sees them
 * (tracker.c; the rest is include/vroc.h's vrWorld_PushSample and kin). */
#ifndef VROC_TRACKER_H
#define VROC_TRACKER_H
#include "vroc.h"
void vrWorld_FreeTrackers(vrWorld *w);
#endif
