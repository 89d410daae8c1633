/* balance.h — whether a body lying on its supports is balanced on them
 * (balance.c): the statics the rest test (rest.c) asks of a body before
 * it may rest, from the touches of an island step. */
#ifndef VROC_BALANCE_H
#define VROC_BALANCE_H

#include "world_state.h"

/* Each moving body in w's touches at t (gathered by the island step, the
 * leaving ones too) gets its tipping flag (table.h): 1 when it lies only
 * on supports along one normal and the force's line through its centre of
 * mass misses them, so that it must turn however still it is; else 0.
 * Needs vrIslandScratch_Reserve.  0, or -1 when out of memory. */
int vrBalance_Mark(vrWorld *w, double t);

#endif
