/* setup.c — a setup round (SPEC 5): the pairs dealt among the live workers
 * (distribution.c: a function of the two ids, no list of pairs), and each
 * worker sent its setup — the definitions and anchors of the objects of
 * its pairs, the deal, the bodies changed since the owners last heard, the
 * parameters — which it answers like a frame start.  A worker's pairs are
 * settled from the poses at the setup time as their boxes meet there
 * (vrOwner_MakePairsAt), or flagged when a body of theirs changed since,
 * so a setup at a frame start changes no result.
 *
 *   deal, put_deal  the live pairs to the live workers; the deal in a setup
 *   plan_share      a worker's objects, cut into parts of about 60 kB
 *   encode_part     part k of a worker's setup
 *   send_parts      the parts, an exchange each; set_up_all, the round
 *   retire_counts a setup gives every worker a new owner: its counts kept
 */
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "distribution.h"
#include "exchange.h"
#include "setup.h"
#include "wire.h"
#include "vroc_setup_t.h"

/* appended, not looked for (vrUpdate_Body's search made a snapshot of
 * 10,000 bodies 50 M comparisons): each caller adds a body once */
int vrSgp_AddAnchor(vrUpdate *up, vrBody *b)
{
    vrBodyState *st;
    if (vrGrow((void **)&up->body, &up->cap, up->n + 1, sizeof *up->body) != 0) return -1;
    st = &up->body[up->n++];
    vrBody_Capture(b, b->m.t0, st);
    vrBody_CaptureAnchor(b, st);
    return 0;
}

int vrSgp_Delivered(vrWorld *w, vrSgp *s)
{
    int r = vrUpdate_AppendStates(&s->snap_pending, &w->pending);
    w->pending.n = 0;
    return r;
}

vrGpCounts vrSgp_Counts(const vrSgp *s, int g)
{
    const vrGpCounts *b = &s->gp[g].before, *c = &s->gp[g].now;
    vrGpCounts t;
    t.checks = b->checks + c->checks, t.heap_pops = b->heap_pops + c->heap_pops;
    t.solves = b->solves + c->solves, t.refactors = b->refactors + c->refactors;
    t.factors = b->factors + c->factors;
    return t;
}

static void retire_counts(vrSgp *s)
{
    int g;
    for (g = 0; g < s->n; g++) {
        s->gp[g].before = vrSgp_Counts(s, g);
        memset(&s->gp[g].now, 0, sizeof s->gp[g].now);
    }
}

static void deal(const vrWorld *w, const vrSgp *s, vrDeal *d)
{
    int alive[VR_MAX_GPS], nalive = 0, i;
    for (i = 0; i < s->n; i++)
        if (s->gp[i].alive) alive[nalive++] = i;
    vrDistribution_Deal(d, &w->table, w->s.distribution, alive, nalive);
}

/* the deal into the message (its arrays stay d's) */
static void put_deal(vroc_setup_t *m, vrDeal *d)
{
    m->improved = (int8_t)d->improved;
    m->nalive = d->nalive;
    m->alive = d->alive;
    m->per = d->per;
    m->groups = d->groups;
    m->nblocks = d->improved ? d->groups * (d->groups + 1) / 2 : 0;
    m->block_gp = d->block_gp;
}

/* A setup part's budget: bursts of UDP multicast much past the kernel's
 * default receive buffer (208 kB) are lost whole, and a lost part is sent
 * again, so parts stay near one LCM fragment.  A body's definition and
 * anchor encode to about 250 bytes, plus its OFF text. */
#define PART_BYTES 60000
#define BODY_BYTES 260

/* worker g's objects in id order (its share of the deal), cut into parts
 * starting at start[0..nparts), start[nparts] = n */
typedef struct vrShare { int *ids, n, *start, nparts; } vrShare;

static int plan_share(const vrWorld *w, vrSgp *s, const vrDeal *d, int g, unsigned char *need, vrShare *sh)
{
    int i, bytes = 0;
    int *ids = malloc(((size_t)w->table.n + 1) * sizeof *ids), *start = malloc(((size_t)w->table.n + 2) * sizeof *start);
    if (!ids || !start) {   /* nothing held on failure */
        free(ids);
        free(start);
        return -1;
    }
    sh->ids = ids;
    sh->start = start;
    s->gp[g].pairs = (int)vrDeal_Share(d, &w->table, g, need);
    sh->start[0] = 0;
    for (i = 0; i < w->table.n; i++) {
        const char *off = w->table.obj[i] ? w->table.obj[i]->off_text : NULL;
        int size = BODY_BYTES + (off ? (int)strlen(off) : 0);
        if (!need[i]) continue;
        if (sh->n > 0 && bytes + size > PART_BYTES) sh->start[++sh->nparts] = sh->n, bytes = 0;
        bytes += size;
        sh->ids[sh->n++] = i;
    }
    sh->start[++sh->nparts] = sh->n;   /* a worker with no objects still has a part, empty */
    return 0;
}

/* Part k of worker g's setup: its objects' definitions and anchors, those
 * of them marked in pending (their pairs start flagged, as
 * vrOwner_MakePairsAt's pending), the deal and the settings */
static int encode_part(vrWorld *w, vrSgp *s, int g, vrDeal *d, const unsigned char *pending, const vrShare *sh,
                       int k, int parts)
{
    int lo = k < sh->nparts ? sh->start[k] : sh->n, hi = k < sh->nparts ? sh->start[k + 1] : sh->n, j, r = -1;
    vroc_setup_t m;
    vrWireStates ws;
    vrUpdate states;
    vroc_body_def_t *defs = calloc((size_t)(hi - lo) + 1, sizeof *defs);
    vrParams p = vrSettings_Params(&w->s);
    memset(&m, 0, sizeof m);
    memset(&ws, 0, sizeof ws);
    vrUpdate_Init(&states);
    m.pending = malloc(((size_t)(hi - lo) + 1) * sizeof *m.pending);
    for (j = lo; defs && m.pending && j < hi; j++) {
        int i = sh->ids[j];
        vrWire_PutDef(&defs[m.nbodies++], i, &w->table.obj[i]->def, w->table.obj[i]->off_text);
        if (pending[i]) m.pending[m.npending++] = i;
        if (vrSgp_AddAnchor(&states, &w->table.obj[i]->body) != 0) break;
    }
    if (defs && m.pending && j == hi && vrWire_PutStates(&ws, &states) == 0) {
        m.run = s->run;
        m.seq = s->seq;
        m.nonce = s->gp[g].nonce;
        m.gp = g;
        m.ngps = s->n;
        m.part = k;
        m.parts = parts;
        vrWire_PutParams(&m.params, &p);
        m.t = w->t;
        m.defs = defs;
        m.states = ws.m;
        put_deal(&m, d);
        r = VR_ENCODE(&s->gp[g].setup, vroc_setup_t, &m);
    }
    free(m.pending);
    free(defs);
    vrWire_FreeStates(&ws);
    vrUpdate_Free(&states);
    return r;
}

/* the parts, one exchange each, to every live worker: 0 when all are set
 * up (or one answered an error, in s->error), 1 when a worker died, -1
 * on no memory */
static int send_parts(vrWorld *w, vrSgp *s, vrDeal *d, const unsigned char *pending, const vrShare *sh, int parts)
{
    int g, k;
    for (k = 0; k < parts; k++) {
        int died;
        s->seq++;
        s->error[0] = 0;
        for (g = 0; g < s->n; g++)
            if (s->gp[g].alive && encode_part(w, s, g, d, pending, &sh[g], k, parts) != 0) return -1;
        s->setup_round = 1;
        died = vrSgp_Exchange(s, WAIT_EARLIEST, -1);
        s->setup_round = 0;
        if (died) return 1;
        if (s->error[0]) return 0;
    }
    return 0;
}

/* every live worker set up from one deal.  gcc 12's analyzer loses the
 * shares' arrays stored at sh[g] (a symbolic index) and reports them leaked
 * on return from plan_share; every sh[] is freed below (a false positive). */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wanalyzer-malloc-leak"
#endif
static int set_up_all(vrWorld *w, vrSgp *s)
{
    vrDeal d;
    vrShare sh[VR_MAX_GPS];
    unsigned char *pending = vrTable_PendingMarks(&w->table, &w->pending);
    unsigned char *need = calloc((size_t)w->table.n + 1, 1);
    int g, parts = 1, r = -1;
    memset(sh, 0, sizeof sh);
    deal(w, s, &d);
    for (g = 0; pending && need && g < s->n && g < VR_MAX_GPS; g++) {
        if (!s->gp[g].alive) continue;
        if (plan_share(w, s, &d, g, need, &sh[g]) != 0) break;
        if (sh[g].nparts > parts) parts = sh[g].nparts;
    }
    if (g == s->n) r = send_parts(w, s, &d, pending, sh, parts);
    for (g = 0; g < VR_MAX_GPS; g++) {   /* all: those not planned are NULL */
        free(sh[g].ids);
        free(sh[g].start);
    }
    free(pending);
    free(need);
    return r;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

int vrSgp_Setup(vrWorld *w, vrSgp *s, char *err, size_t n)
{
    for (;;) {
        int r;
        retire_counts(s);
        if (vrSgp_AliveCount(s) == 0) return snprintf(err, n, "all %d workers died; set gps = 0 to go on serially", s->n), -1;
        r = set_up_all(w, s);
        if (r < 0) return snprintf(err, n, "out of memory"), -1;
        if (r > 0) continue;             /* deal again among the survivors */
        if (s->error[0]) return snprintf(err, n, "%s", s->error), -1;
        break;
    }
    s->structure = w->structure;
    s->frame_open = s->frame_fresh = 0;
    return vrSgp_Delivered(w, s) == 0 ? 0 : (snprintf(err, n, "out of memory"), -1);
}
