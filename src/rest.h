/* rest.h — the rest state (thesis 3.3.3, SPEC 3.5, 7): what the coordinator
 * decides at frame ends and when states change.  Bodies rest and wake as
 * islands (rest.c). */
#ifndef VROC_REST_H
#define VROC_REST_H

#include "world_state.h"
#include "ownerset.h"

/* the resting bodies of the islands of the bodies up changes wake */
int vrRest_WakeDependents(vrWorld *w, vrUpdate *up, double t);
/* the resting bodies of island (an island id, -1: none, VR_EVERY_ISLAND:
 * all of them; what rests on a static body edited or deleted is not
 * recorded) wake into up */
#define VR_EVERY_ISLAND (-2)
int vrRest_WakeIsland(vrWorld *w, int island, vrUpdate *up, double t);
/* frame end: puts to rest the islands that qualify; fills up with the new states */
int vrRest_FrameEnd(vrWorld *w, vrUpdate *up);
/* frame end: the poses the next frame end's rest test compares with are
 * those of now (taken lazily: vrRest_KeepFramePose) */
void vrRest_RememberFramePoses(vrWorld *w);
/* o's pose at the last frame end, from its anchor, if not yet taken:
 * before its anchor changes, and wherever o->frame_pose is read */
void vrRest_KeepFramePose(const vrWorld *w, vrObject *o);

#endif
