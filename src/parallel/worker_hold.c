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
 *   build_part, place_part  a setup part's objects, built, placed, given their states
 *   hold_all, make_owner  the owner on the last part: the pairs as of the poses
 *   start_setup, vrWorker_SetUp   a setup, part by part (setup_t.lcm)
 */
#include <stdlib.h>
#include <string.h>
#include "build.h"
#include "grow.h"
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

/* A part's objects built from their definitions and placed (their states
 * follow); the SGP hears heartbeats meanwhile */
static int build_part(vrWorker *k, const vroc_setup_t *m, char *err, size_t n)
{
    int i;
    for (i = 0; i < m->nbodies; i++) {
        vrObjectDef d;
        vrWorker_Beat(k);
        if (vrWire_GetDef(&m->defs[i], &d) != 0 || m->defs[i].id < 0 || m->defs[i].id >= MAX_ID)
            return snprintf(err, n, "bad object definition"), -1;
        if (vrTable_Put(&k->objects, m->defs[i].id, &d, m->defs[i].off, err, n) != 0) return -1;
    }
    for (i = 0; i < m->nbodies; i++) {
        vrObject *o = vrTable_Get(&k->objects, m->defs[i].id);
        if (o && !o->built && vrObject_Ready(o, m->t, &k->params.flight, NULL, err, n) != 0) return -1;
    }
    return 0;
}

/* a part's states onto its objects, and its pending bodies noted */
static int place_part(vrWorker *k, const vroc_setup_t *m, char *err, size_t n)
{
    int i;
    k->scratch.n = 0;
    if (vrWire_GetStates(m->states, m->nbodies, 1 << 30, &k->scratch) != 0)
        return snprintf(err, n, "bad body state"), -1;
    for (i = 0; i < k->scratch.n; i++) {
        const vrBodyState *st = &k->scratch.body[i];
        if (held(k, st->id)) vrBody_Apply(&vrTable_Get(&k->objects, st->id)->body, st, &k->params.flight);
    }
    for (i = 0; i < m->npending; i++) {
        if (!held(k, m->pending[i])) return snprintf(err, n, "bad pending body"), -1;
        if (vrGrow((void **)&k->setup_pending, &k->setup_pending_cap, k->nsetup_pending + 1,
                   sizeof *k->setup_pending) != 0)
            return snprintf(err, n, "out of memory"), -1;
        k->setup_pending[k->nsetup_pending++] = m->pending[i];
    }
    return 0;
}

/* every object built, held by a new lazy owner whose filter is the deal;
 * told their states, as vrWorker_ApplyStates tells a held body's */
static int hold_all(vrWorker *k)
{
    int i, nid = 0;
    if (!(k->owner = vrOwner_Create())
        || vrGrow((void **)&k->ids, &k->idcap, k->objects.n + 1, sizeof *k->ids) != 0) return -1;
    vrOwner_SetLazy(k->owner, 1);
    vrOwner_SetFilter(k->owner, mine, k);
    vrOwner_SetParams(k->owner, &k->params);
    vrOwner_SetProgress(k->owner, vrWorker_Beat, k);
    for (i = 0; i < k->objects.n; i++)
        if (held(k, i)) {
            if (vrOwner_HoldBody(k->owner, i, &k->objects.obj[i]->body) != 0) return -1;
            k->ids[nid++] = i;
        }
    vrOwner_BodiesChanged(k->owner, k->ids, nid);
    return 0;
}

/* after the last part: the pairs whose boxes meet at t, settled from the
 * poses there, or flagged when a body of theirs is pending (as the
 * serial owner's, owners.c) */
static int make_owner(vrWorker *k, double t, char *err, size_t n)
{
    unsigned char *marks = calloc((size_t)k->objects.n + 1, 1);
    int i, r = -1;
    if (marks && hold_all(k) == 0) {
        for (i = 0; i < k->nsetup_pending; i++) marks[k->setup_pending[i]] = 1;
        r = vrOwner_MakePairsAt(k->owner, t, marks);
    }
    free(marks);
    return r == 0 ? 0 : (snprintf(err, n, "out of memory"), -1);
}

/* part 0: the settings and the deal, and nothing held from before */
static int start_setup(vrWorker *k, const vroc_setup_t *m, char *err, size_t n)
{
    vrOwner_Free(k->owner);
    k->owner = NULL;
    vrTable_Clear(&k->objects);
    k->nsetup_pending = 0;
    k->setup_next = 0;
    if (vrWire_GetParams(&m->params, &k->params) != 0) return snprintf(err, n, "bad settings"), -1;
    if (get_deal(m, &k->deal) != 0) return snprintf(err, n, "bad deal"), -1;
    return 0;
}

int vrWorker_SetUp(vrWorker *k, const vroc_setup_t *m, char *err, size_t n)
{
    int r;
    if (m->part == 0 && start_setup(k, m, err, n) != 0) return k->setup_next = -1, -1;
    if (m->part != k->setup_next || m->part < 0 || m->part >= m->parts)
        return k->setup_next = -1, snprintf(err, n, "setup part out of order"), -1;
    if (build_part(k, m, err, n) != 0 || place_part(k, m, err, n) != 0) return k->setup_next = -1, -1;
    k->setup_next++;
    if (m->part + 1 < m->parts) return 0;
    r = make_owner(k, m->t, err, n);
    k->setup_next = -1;
    return r;
}
