/* exchange.h — one round of the SGP's star protocol (ARCHITECTURE
 * "reliability over UDP multicast"): the request in s->req goes out, the
 * workers' answers come in, and a missing one is asked for again. */
#ifndef VROC_EXCHANGE_H
#define VROC_EXCHANGE_H

#include "sgp_state.h"

/* the SGP's LCM subscriptions for the workers' answers */
void vrSgp_Subscribe(vrSgp *s);
void vrSgp_Unsubscribe(vrSgp *s);
/* Sends the current request and waits until every target answered (all
 * live workers, or only `target`), resending with back-off.  Returns 0, or
 * 1 when a worker died on the way (it is marked dead). */
int vrSgp_Exchange(vrSgp *s, int waiting, int target);
int vrSgp_AliveCount(const vrSgp *s);

#endif
