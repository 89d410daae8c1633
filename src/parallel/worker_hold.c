/* worker_hold.c — the objects and pairs a worker holds (SPEC 5): copies
 * of the objects of its pairs in a table of its own, built from their
 * definitions by the same code as the SGP's (build.h), so every copy moves
 * the same bits, and one lazy vrOwner over its pairs (SPEC 10): the serial
 * owner's code, with the deal as its filter, so a pair's record exists
 * only while its bodies' boxes meet and the deal gives it to this worker.
 *
 *   held                  whether an object is held
 *   vrWorker_ApplyStates  the SGP's states onto the bodies held here
 *   get_deal, mine        a setup's deal; the owner's filter
 *   build_objects         a setup's objects, built and placed
 *   make_pairs            their pairs as of the poses, flagged for the pending bodies
 *   vrWorker_SetUp        a setup's objects and pairs
 */
#include <stdlib.h>
#include <string.h>
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

/* the deal a setup carries, whole (vrDeal_Check), or -1 */
static int get_deal(const vroc_setup_t *m, vrDeal *d)
{
    memset(d, 0, sizeof *d);
    if (m->ngps < 1 || m->ngps > VR_MAX_GPS || m->gp < 0 || m->gp >= m->ngps) return -1;
    if (m->nalive < 1 || m->nalive > VR_MAX_GPS || m->groups < 1 || m->groups > VR_DEAL_GROUPS) return -1;
    d->improved = m->improved != 0;
    d->nalive = m->nalive;
    memcpy(d->alive, m->alive, (size_t)m->nalive * sizeof *d->alive);
    d->per = m->per;
    d->groups = m->groups;
    if (m->nblocks != (d->improved ? d->groups * (d->groups + 1) / 2 : 0)) return -1;
    memcpy(d->block_gp, m->block_gp, (size_t)m->nblocks * sizeof *d->block_gp);
    return vrDeal_Check(d, m->ngps);
}

static int mine(const void *ctx, int a, int b)
{
    const vrWorker *k = ctx;
    return vrDeal_Owner(&k->deal, a, b) == k->gp;
}

/* built from their definitions and placed (their states follow); the
 * SGP hears heartbeats meanwhile: 10,000 objects take seconds to build */
static int build_objects(vrWorker *k, const vroc_setup_t *m, char *err, size_t n)
{
    int i;
    vrTable_Clear(&k->objects);
    for (i = 0; i < m->nbodies; i++) {
        vrObjectDef d;
        vrWorker_Beat(k);
        if (vrWire_GetDef(&m->defs[i], &d) != 0 || m->defs[i].id < 0 || m->defs[i].id >= MAX_ID)
            return snprintf(err, n, "bad object definition"), -1;
        if (vrTable_Put(&k->objects, m->defs[i].id, &d, m->defs[i].off, err, n) != 0) return -1;
    }
    for (i = 0; i < k->objects.n; i++) {
        vrWorker_Beat(k);
        if (k->objects.obj[i] && vrObject_Ready(k->objects.obj[i], m->t, &k->params.flight, NULL, err, n) != 0) return -1;
    }
    return 0;
}

/* the pairs whose boxes meet at t, settled from the poses there, or
 * flagged when a body of theirs is one of the pending (as the serial
 * owner's, owners.c) */
static int make_pairs(vrWorker *k, const vroc_setup_t *m, char *err, size_t n)
{
    unsigned char *marks = calloc((size_t)k->objects.n + 1, 1);
    int i, r;
    if (!marks) return snprintf(err, n, "out of memory"), -1;
    for (i = 0; i < m->npending; i++) {
        if (!held(k, m->pending[i])) {
            free(marks);
            return snprintf(err, n, "bad pending body"), -1;
        }
        marks[m->pending[i]] = 1;
    }
    r = vrOwner_MakePairsAt(k->owner, m->t, marks);
    free(marks);
    return r == 0 ? 0 : (snprintf(err, n, "out of memory"), -1);
}

int vrWorker_SetUp(vrWorker *k, const vroc_setup_t *m, char *err, size_t n)
{
    int i;
    if (vrWire_GetParams(&m->params, &k->params) != 0) return snprintf(err, n, "bad settings"), -1;
    if (get_deal(m, &k->deal) != 0) return snprintf(err, n, "bad deal"), -1;
    vrOwner_Free(k->owner);
    k->owner = NULL;
    if (build_objects(k, m, err, n) != 0) return -1;
    k->owner = vrOwner_Create();
    if (!k->owner) return snprintf(err, n, "out of memory"), -1;
    vrOwner_SetLazy(k->owner, 1);
    vrOwner_SetFilter(k->owner, mine, k);
    vrOwner_SetParams(k->owner, &k->params);
    vrOwner_SetProgress(k->owner, vrWorker_Beat, k);
    for (i = 0; i < m->nbodies; i++) {
        vrObject *o = vrTable_Get(&k->objects, m->defs[i].id);
        if (vrOwner_HoldBody(k->owner, o->body.id, &o->body) != 0) return snprintf(err, n, "out of memory"), -1;
    }
    if (vrWorker_ApplyStates(k, m->states, m->nbodies) != 0) return snprintf(err, n, "bad body state"), -1;
    return make_pairs(k, m, err, n);
}
