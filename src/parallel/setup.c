/* setup.c — a setup round (SPEC 5): the pairs dealt among the live workers
 * (distribution.c), and each worker sent its setup — the definitions and
 * anchors of the objects of its pairs, the pairs, the parameters — which
 * it answers like a frame start.  A worker's pairs are settled from the
 * poses at the setup time (vrOwner_AddPairAt), or flagged when a body of
 * theirs changed since, so a setup at a frame start changes no result.
 *
 *   deal          the live pairs to the live workers
 *   encode_setup  worker g's setup message
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

int vrSgp_AddAnchor(vrUpdate *up, vrBody *b)
{
    vrBodyState *st = vrUpdate_Body(up, b, b->m.t0);
    if (!st) return -1;
    vrBody_CaptureAnchor(b, st);
    return 0;
}

int vrSgp_AppendStates(vrUpdate *to, const vrUpdate *from)
{
    int i;
    for (i = 0; i < from->n; i++) {
        if (vrGrow((void **)&to->body, &to->cap, to->n + 1, sizeof *to->body) != 0) return -1;
        to->body[to->n++] = from->body[i];
    }
    return 0;
}

int vrSgp_Delivered(vrWorld *w, vrSgp *s)
{
    int r = vrSgp_AppendStates(&s->snap_pending, &w->pending);
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

static int deal(const vrWorld *w, const vrSgp *s, vrDeal *d)
{
    int alive[VR_MAX_GPS], nalive = 0, i;
    for (i = 0; i < s->n; i++)
        if (s->gp[i].alive) alive[nalive++] = i;
    return vrDistribution_Deal(d, &w->table, w->s.distribution, alive, nalive);
}

static int encode_setup(vrWorld *w, vrSgp *s, int g, const vrDeal *d)
{
    vroc_setup_t m;
    vrWireStates ws;
    vrUpdate states;
    vroc_body_def_t *defs;
    char *need = calloc((size_t)w->table.n + 1, 1);
    unsigned char *pending = vrTable_PendingMarks(&w->table, &w->pending);
    int k, i, np = 0, r = -1;
    vrParams p = vrSettings_Params(&w->s);
    memset(&m, 0, sizeof m);
    memset(&ws, 0, sizeof ws);
    vrUpdate_Init(&states);
    for (k = 0; need && k < d->npairs; k++)
        if (d->gp_of[k] == g) need[d->a[k]] = need[d->b[k]] = 1, np++;
    m.a = malloc((size_t)(np + 1) * sizeof *m.a);
    m.b = malloc((size_t)(np + 1) * sizeof *m.b);
    m.flagged = malloc((size_t)(np + 1) * sizeof *m.flagged);
    defs = calloc((size_t)w->table.n + 1, sizeof *defs);
    if (need && pending && m.a && m.b && m.flagged && defs) {
        for (k = 0; k < d->npairs; k++)
            if (d->gp_of[k] == g) {
                m.a[m.npairs] = d->a[k];
                m.b[m.npairs] = d->b[k];
                m.flagged[m.npairs++] = pending[d->a[k]] || pending[d->b[k]];
            }
        for (i = 0; i < w->table.n; i++)
            if (need[i]) {
                vrWire_PutDef(&defs[m.nbodies++], i, &w->table.obj[i]->def, w->table.obj[i]->off_text);
                if (vrSgp_AddAnchor(&states, &w->table.obj[i]->body) != 0) break;
            }
        if (i == w->table.n && vrWire_PutStates(&ws, &states) == 0) {
            s->gp[g].pairs = m.npairs;
            m.run = s->run;
            m.seq = s->seq;
            m.nonce = s->gp[g].nonce;
            m.gp = g;
            m.ngps = s->n;
            vrWire_PutParams(&m.params, &p);
            m.t = w->t;
            m.defs = defs;
            m.states = ws.m;
            r = VR_ENCODE(&s->gp[g].setup, vroc_setup_t, &m);
        }
    }
    free(need);
    free(pending);
    free(m.a);
    free(m.b);
    free(m.flagged);
    free(defs);
    vrWire_FreeStates(&ws);
    vrUpdate_Free(&states);
    return r;
}

int vrSgp_Setup(vrWorld *w, vrSgp *s, char *err, size_t n)
{
    for (;;) {
        int g, died;
        vrDeal d;
        retire_counts(s);
        if (vrSgp_AliveCount(s) == 0) return snprintf(err, n, "all %d workers died; set gps = 0 to go on serially", s->n), -1;
        s->seq++;
        s->error[0] = 0;
        if (deal(w, s, &d) != 0) g = -2;
        else
            for (g = 0; g < s->n; g++)
                if (s->gp[g].alive && encode_setup(w, s, g, &d) != 0) break;
        vrDistribution_Free(&d);
        if (g != s->n) return snprintf(err, n, "out of memory"), -1;
        s->setup_round = 1;
        died = vrSgp_Exchange(s, WAIT_EARLIEST, -1);
        s->setup_round = 0;
        if (died) continue;              /* deal again among the survivors */
        if (s->error[0]) return snprintf(err, n, "%s", s->error), -1;
        break;
    }
    s->structure = w->structure;
    s->frame_open = s->frame_fresh = 0;
    return vrSgp_Delivered(w, s) == 0 ? 0 : (snprintf(err, n, "out of memory"), -1);
}
