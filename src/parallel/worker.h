/* worker.h — a GP (thesis 3.5): a pair owner behind LCM.
 *
 * A worker answers the SGP's requests: setup (its objects and pairs),
 * frame_start and forwarded updates (look ahead through the span: its
 * `earliest`), advance (when it is the responder: the `update`), shutdown.
 * Every request carries the run id and a sequence number; a repeated request
 * is answered from the cache, a stale or foreign one is ignored.  The same
 * code runs in forked processes, in `vroc-gp URL`, and in the SGP's own
 * process over memq:// for tests.
 */
#ifndef VROC_WORKER_H
#define VROC_WORKER_H

#include "link.h"

typedef struct vrWorker vrWorker;

/* a worker on an open link (not owned); nonce identifies it to the SGP */
vrWorker *vrWorker_Create(vrLink *link, long long nonce, int forked);
void vrWorker_Free(vrWorker *k);
/* announces itself while free; returns 1 once told to shut down */
int vrWorker_Tick(vrWorker *k);
/* the process loop of a forked or hand-started worker */
int vrWorker_Main(const char *url, long long nonce, int forked, char *err, size_t n);

#endif
