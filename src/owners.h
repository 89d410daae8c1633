/* owners.h — who owns the pairs: serial VROC's one owner of every pair
 * (ARCHITECTURE), or the workers (parallel/sgp.h), as the settings say;
 * and how the owners hear of changed states. */
#ifndef VROC_OWNERS_H
#define VROC_OWNERS_H

#include "world_state.h"
#include "ownerset.h"

/* serial or parallel, as the settings say: the owners made or re-set */
int vrOwners_Choose(vrWorld *w, char *err, size_t n);
/* the owners go (their counts stay in the stats); the next start makes
 * them anew from the world's state, as a change of gps does (save.h) */
void vrOwners_Retire(vrWorld *w);
/* the owner set the settings choose */
const vrOwnerSet *vrOwners_Of(const vrWorld *w);
/* a new object's body and its pairs join the serial owner, if there is one */
int vrOwners_AddObject(vrWorld *w, int id);
/* the owners are to be made anew (a change of gps, heap, broadphase:
 * structure moves on, which sets the workers up again) while the physics
 * stays as it was: the contacts' warm starts stand, as in a run that made
 * no such change (serial = workers = heap off to the bit through switches) */
void vrOwners_Renew(vrWorld *w);
/* applies an update: wakes what rests on changed bodies, re-anchors, tells the owners */
int vrWorld_ApplyUpdate(vrWorld *w, vrUpdate *up);

#endif
