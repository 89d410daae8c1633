/* contact_set.h — the bodies that may be in an island's contact step, and
 * the island step's scratch by object id (contact_set.c). */
#ifndef VROC_CONTACT_SET_H
#define VROC_CONTACT_SET_H

#include "world_state.h"

/* object ids in ascending order */
void vrIds_Sort(int *ids, int n);
/* body id's state was applied with contact set: it joins the set */
int vrContactSet_Note(vrWorld *w, int id);
/* states were applied behind the set's back (a frame undone): the next
 * prune finds it again from every object */
void vrContactSet_Lost(vrWorld *w);
/* the set sorted by id, each id once, only live bodies in contact and not
 * resting: every such body of the table (found from all of them when
 * w->structure moved) */
int vrContactSet_Prune(vrWorld *w);
/* w's isl_* arrays hold every object id (isl_slot's new entries -1) */
int vrIslandScratch_Reserve(vrWorld *w);

#endif
