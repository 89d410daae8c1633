/* spawn.h — the SGP's workers come and go: forked here, hand-started ones
 * claimed (ttl >= 1), or run in this process (memq://, for tests). */
#ifndef VROC_SPAWN_H
#define VROC_SPAWN_H

#include "sgp_state.h"

/* an SGP with s->gps workers on s->lcm_url, every one announced; NULL (err) if not */
vrSgp *vrSgp_Open(const vrSettings *s, char *err, size_t n);
/* tells the workers the run is over, waits for the forked ones, frees */
void vrSgp_Free(vrSgp *s);

#endif
