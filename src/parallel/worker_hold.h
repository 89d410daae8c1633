/* worker_hold.h — the objects and pairs a worker holds (worker_hold.c):
 * a setup's, and the SGP's states applied to them. */
#ifndef VROC_WORKER_HOLD_H
#define VROC_WORKER_HOLD_H

#include "worker_state.h"
#include "vroc_body_state_t.h"
#include "vroc_setup_t.h"

/* the SGP's states onto the bodies held here (their pairs are evaluated
 * at the next span start); -1 when one is malformed */
int vrWorker_ApplyStates(vrWorker *k, const vroc_body_state_t *states, int n);
/* a setup part (in order from part 0): its objects built from their
 * definitions and placed at their states; after the last, the owner of
 * the pairs the setup's deal gives this worker, made lazily (settled from
 * the poses or flagged); -1 and err */
int vrWorker_SetUp(vrWorker *k, const vroc_setup_t *m, char *err, size_t n);

#endif
