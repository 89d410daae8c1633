/* rest.h — the rest state (thesis 3.3.3, SPEC 3.5): what the coordinator
 * decides at frame ends and when states change. */
#ifndef VROC_REST_H
#define VROC_REST_H

#include "world_state.h"
#include "ownerset.h"

/* bodies resting on a changed body wake, transitively (SPEC 3.5) */
int vrRest_WakeDependents(vrWorld *w, vrUpdate *up, double t);
/* frame end: puts to rest what qualifies; fills up with the new states */
int vrRest_FrameEnd(vrWorld *w, vrUpdate *up);
/* frame end T: bodies carried by several contacts together become
 * supported by all of them; -1 (err) or VR_RESTART_FRAME from the owners */
int vrRest_SeveralSupports(vrWorld *w, double T, const vrOwnerSet *owners, vrUpdate *up, char *err, size_t n);
void vrRest_RememberFramePoses(vrWorld *w);

#endif
