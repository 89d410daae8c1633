/* sgp.h — the workers as the coordinator sees them (thesis 3.5.2, SPEC 5):
 * an owner set (ownerset.h) whose owners are worker processes. */
#ifndef VROC_SGP_H
#define VROC_SGP_H

#include "world_state.h"
#include "ownerset.h"

extern const vrOwnerSet vrSgp_Owners;
/* starts or re-sets the workers as the settings and objects require */
int vrSgp_Sync(vrWorld *w, char *err, size_t n);
/* frees the SGP and its workers, their counts kept in the stats */
void vrSgp_Retire(vrWorld *w);
/* adds the workers' counts to st */
void vrSgp_Stats(const vrSgp *s, vrStats *st);

#endif
