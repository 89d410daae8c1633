/* worker_reply.h — a worker's answers (worker_reply.c): each kept for the
 * request's repeats, and the heartbeat of a busy worker. */
#ifndef VROC_WORKER_REPLY_H
#define VROC_WORKER_REPLY_H

#include "worker_state.h"
#include "wire.h"
#include "vroc_earliest_t.h"

/* k->reply (encoded) published on channel as the answer to seq */
void vrWorker_Answer(vrWorker *k, const char *channel, int64_t seq);
/* Is this request new?  A repeat is answered from the cache (the SGP lost
 * our answer or we lost its request), a stale or foreign one ignored. */
int vrWorker_Fresh(vrWorker *k, int64_t run, int64_t seq);
/* the response counts of the answers the SGP took (SPEC 1.3's klu_*) */
vrResponseStats vrWorker_Counts(const vrWorker *k);
/* the answer sent with the last earliest was taken (1) or not (0) */
void vrWorker_Settle(vrWorker *k, int taken);
/* the time since the current request's start counts as busy */
void vrWorker_NoteBusy(vrWorker *k);
/* the earliest message: found = 1 with ev (its time, pair, kind, the
 * approach and point its sound is made of, and k's answer to it when
 * k->answered), the overlaps of a check, an error (NULL: none) */
void vrWorker_SendEarliest(vrWorker *k, int64_t seq, int found, const vrEvent *ev, int noverlap, int32_t *a,
                           int32_t *b, const char *error);
/* the same message made in *m (its answer's states in *ws, to be freed
 * with vrWire_FreeStates once m is encoded), not sent */
void vrWorker_PutEarliest(vrWorker *k, int64_t seq, int found, const vrEvent *ev, int noverlap, int32_t *a,
                          int32_t *b, const char *error, vroc_earliest_t *m, vrWireStates *ws);
/* a heartbeat (the owner's progress callback; ctx is the worker) at most
 * every HELLO_MS, while a long look-ahead keeps it from answering */
void vrWorker_Beat(void *ctx);

#endif
