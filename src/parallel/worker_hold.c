/* worker_hold.c — the objects and pairs a worker holds (SPEC 5): copies
 * of the objects of its pairs in a table of its own, built from their
 * definitions by the same code as the SGP's (build.h), so every copy moves
 * the same bits, and one vrOwner over its pairs.
 *
 *   held                  whether an object is held
 *   vrWorker_ApplyStates  the SGP's states onto the bodies held here
 *   vrWorker_SetUp        a setup's objects and pairs
 */
#include <stdlib.h>
#include "build.h"
#include "worker_hold.h"
#include "worker_reply.h"
#include "wire.h"

/* A setup's object ids index the worker's table: a malformed one of 2^30
 * grew it for minutes (make fuzz).  Ids at or past this are refused. */
#define MAX_ID (1 << 20)

static int held(const vrWorker *k, int id)
{
    vrObject *o = vrTable_Get(&k->objects, id);
    return o && o->built;
}

int vrWorker_ApplyStates(vrWorker *k, const vroc_body_state_t *states, int n)
{
    int i, nid = 0;
    k->scratch.n = 0;
    if (vrWire_GetStates(states, n, 1 << 30, &k->scratch) != 0) return -1;
    if (n > k->idcap) {
        int *ni = realloc(k->ids, (size_t)n * sizeof *ni);
        if (!ni) return -1;
        k->ids = ni;
        k->idcap = n;
    }
    for (i = 0; i < k->scratch.n; i++) {
        const vrBodyState *st = &k->scratch.body[i];
        if (!held(k, st->id)) continue;
        vrBody_Apply(&vrTable_Get(&k->objects, st->id)->body, st, &k->params.flight);
        k->ids[nid++] = st->id;
    }
    vrOwner_BodiesChanged(k->owner, k->ids, nid);
    return 0;
}

int vrWorker_SetUp(vrWorker *k, const vroc_setup_t *m, char *err, size_t n)
{
    int i;
    if (vrWire_GetParams(&m->params, &k->params) != 0) return snprintf(err, n, "bad settings"), -1;
    vrTable_Clear(&k->objects);
    vrOwner_Free(k->owner);
    k->owner = NULL;
    for (i = 0; i < m->nbodies; i++) {
        vrObjectDef d;
        if (vrWire_GetDef(&m->defs[i], &d) != 0 || m->defs[i].id < 0 || m->defs[i].id >= MAX_ID)
            return snprintf(err, n, "bad object definition"), -1;
        if (vrTable_Put(&k->objects, m->defs[i].id, &d, m->defs[i].off, err, n) != 0) return -1;
    }
    for (i = 0; i < k->objects.n; i++)   /* placed: their states follow */
        if (k->objects.obj[i] && vrObject_Ready(k->objects.obj[i], m->t, &k->params.flight, NULL, err, n) != 0) return -1;
    k->owner = vrOwner_Create();
    if (!k->owner) return snprintf(err, n, "out of memory"), -1;
    vrOwner_SetParams(k->owner, &k->params);
    vrOwner_SetProgress(k->owner, vrWorker_Beat, k);
    for (i = 0; i < m->nbodies; i++) {
        vrObject *o = vrTable_Get(&k->objects, m->defs[i].id);
        if (vrOwner_HoldBody(k->owner, o->body.id, &o->body) != 0) return snprintf(err, n, "out of memory"), -1;
    }
    if (vrWorker_ApplyStates(k, m->states, m->nbodies) != 0) return snprintf(err, n, "bad body state"), -1;
    for (i = 0; i < m->npairs; i++) {
        if (!held(k, m->a[i]) || !held(k, m->b[i]) || m->a[i] >= m->b[i]) return snprintf(err, n, "bad pair"), -1;
        if (vrOwner_AddPairAt(k->owner, m->a[i], m->b[i], m->t, m->flagged[i]) != 0) return snprintf(err, n, "out of memory"), -1;
    }
    return 0;
}
