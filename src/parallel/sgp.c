/* sgp.c — the Synchronization GP (thesis 3.5.2): the shell process as the
 * coordinator of its workers (SPEC 5).
 *
 * It holds every object (it renders and dumps them) and never queries a
 * pair itself.  Per frame, the thesis's protocol: frame_start to all, each
 * worker's earliest; while there is an event: advance (the responder
 * answers with its update), then the update forwarded to all with the next
 * span's grid, and the earliest again.  Rounds per frame = 1 + events.
 *
 * Reliability over UDP: every request carries the run id and a sequence
 * number and is resent (with back-off) until answered; workers answer
 * repeats from a cache.  A worker silent for DEADLINE_MS is declared dead:
 * the frame is redone from its start with the dead worker's pairs dealt to
 * the survivors — a pair's state at a frame start is a pure function of the
 * poses there (vrOwner_AddPairAt), so the result does not change.
 */
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "grow.h"
#include "config.h"
#include "link.h"
#include "sgp.h"
#include "wire.h"
#include "worker.h"
#include "vroc_advance_t.h"
#include "vroc_candidates_t.h"
#include "vroc_contacts_t.h"
#include "vroc_earliest_t.h"
#include "vroc_frame_start_t.h"
#include "vroc_hello_t.h"
#include "vroc_setup_t.h"
#include "vroc_shutdown_t.h"
#include "vroc_update_t.h"

#define MAX_GPS 64
#define RESEND_MS 5.0
#define RESEND_MAX_MS 200.0
#define DEADLINE_MS 1000.0      /* SPEC 5: a worker silent this long is dead */
#define ANNOUNCE_MS 10000.0     /* workers have this long to announce themselves */
#define MAX_OVERLAPS 64

enum { WAIT_EARLIEST, WAIT_UPDATE, WAIT_CANDIDATES };

/* a worker's owner's counters (stats keys) */
typedef struct vrGpCounts { long long checks, heap_pops, solves, refactors, factors; } vrGpCounts;

typedef struct vrGpInfo {
    long long nonce;
    pid_t pid;                  /* forked workers; 0 otherwise */
    int alive, replied;
    double last_heard;
    int found;                  /* its last earliest */
    double t;
    long long order;
    int kind;
    vrGpCounts now;             /* of its owner, as it last said */
    vrGpCounts before;          /* of the owners it had before: a setup makes a new one */
    int copies, pairs;
    vrBuf setup;                /* its setup during a setup round */
} vrGpInfo;

struct vrSgp {
    vrLink link;
    char url[256];
    int n;
    vrGpInfo gp[MAX_GPS];
    vrWorker *local[MAX_GPS];   /* memq://: workers in this process */
    long long run, seq;
    long structure;             /* the world's, at the last setup */
    int waiting, responder, setup_round, max_id;
    vrBuf req;                  /* the broadcast request awaiting answers */
    const char *req_channel;
    vrUpdate reply;             /* the responder's states */
    vrCandidates candidates;    /* frame end: what the workers found */
    int overlap[MAX_OVERLAPS][2], noverlap;
    char error[256];
    int frame_open;
    vrUpdate snap, snap_pending;   /* the frame start, to redo the frame */
    long long snap_collisions;
    vrGpCounts snap_counts[MAX_GPS];  /* each worker's counts then (before + now) */
    long long requests, received, foreign, malformed;
    lcm_subscription_t *subs[4];
};

/* ---- replies ------------------------------------------------------------------------ */

static vrGpInfo *sender(vrSgp *s, long long run, long long seq, int gp, int waiting)
{
    if (run != s->run) {
        s->foreign++;
        return NULL;
    }
    if (seq != s->seq || waiting != s->waiting || gp < 0 || gp >= s->n || !s->gp[gp].alive || s->gp[gp].replied)
        return NULL;
    s->received++;
    s->gp[gp].last_heard = vrLink_NowMs();
    return &s->gp[gp];
}

static void note_overlaps(vrSgp *s, const vroc_earliest_t *m)
{
    int i;
    for (i = 0; i < m->noverlap && s->noverlap < MAX_OVERLAPS; i++) {
        s->overlap[s->noverlap][0] = m->a[i];
        s->overlap[s->noverlap][1] = m->b[i];
        s->noverlap++;
    }
}

static void on_earliest(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    vrSgp *s = user;
    vroc_earliest_t m;
    vrGpInfo *g;
    (void)ch;
    if (vroc_earliest_t_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        s->malformed++;
        return;
    }
    g = sender(s, m.run, m.seq, m.gp, WAIT_EARLIEST);
    if (g && m.found && (!isfinite(m.t) || m.kind <= VR_EV_NONE || m.kind > VR_EV_SUPPORT_BEGIN)) {
        s->malformed++;
        g = NULL;
    }
    if (g) {
        g->replied = 1;
        g->found = m.found;
        g->t = m.t;
        g->order = m.order;
        g->kind = m.kind;
        g->now.checks = m.checks;
        g->now.heap_pops = m.heap_pops;
        g->copies = m.copies;
        note_overlaps(s, &m);
        if (m.error[0] && !s->error[0]) snprintf(s->error, sizeof s->error, "worker %d: %s", m.gp, m.error);
    }
    vroc_earliest_t_decode_cleanup(&m);
}

static void on_update(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    vrSgp *s = user;
    vroc_update_t m;
    vrGpInfo *g;
    (void)ch;
    if (vroc_update_t_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        s->malformed++;
        return;
    }
    g = m.gp == s->responder ? sender(s, m.run, m.seq, m.gp, WAIT_UPDATE) : NULL;
    if (g) {
        s->reply.n = 0;
        if (vrWire_GetStates(m.states, m.nstates, s->max_id, &s->reply) != 0) {
            s->malformed++;
        } else {
            g->replied = 1;
            g->now.solves = m.solves;
            g->now.refactors = m.refactors;
            g->now.factors = m.factors;
        }
    }
    vroc_update_t_decode_cleanup(&m);
}

static void on_candidates(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    vrSgp *s = user;
    vroc_candidates_t m;
    vrGpInfo *g;
    (void)ch;
    if (vroc_candidates_t_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        s->malformed++;
        return;
    }
    g = sender(s, m.run, m.seq, m.gp, WAIT_CANDIDATES);
    if (g) {
        if (vrWire_GetCandidates(&m, s->max_id, &s->candidates) != 0) s->malformed++;
        else g->replied = 1;
        if (m.error[0] && !s->error[0]) snprintf(s->error, sizeof s->error, "worker %d: %s", m.gp, m.error);
    }
    vroc_candidates_t_decode_cleanup(&m);
}

/* heartbeats of busy workers; announcements of free ones */
static void on_hello(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    vrSgp *s = user;
    vroc_hello_t m;
    int i;
    (void)ch;
    if (vroc_hello_t_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        s->malformed++;
        return;
    }
    if (m.run == s->run && m.gp >= 0 && m.gp < s->n) s->gp[m.gp].last_heard = vrLink_NowMs();
    if (m.run != 0) return;
    for (i = 0; i < s->n; i++)
        if (s->gp[i].nonce == m.nonce) {
            s->gp[i].alive = 1;          /* a worker of ours is up */
            return;
        }
    for (i = 0; i < s->n; i++)          /* a free worker started by hand */
        if (s->gp[i].nonce == 0 && !s->gp[i].pid) {
            s->gp[i].nonce = m.nonce;
            s->gp[i].alive = 1;
            return;
        }
}

/* ---- waiting ---------------------------------------------------------------------------- */

static int alive_count(const vrSgp *s)
{
    int i, k = 0;
    for (i = 0; i < s->n; i++) k += s->gp[i].alive;
    return k;
}

static void resend(vrSgp *s)
{
    int i;
    if (!s->setup_round) {
        vrLink_Publish(&s->link, s->req_channel, s->req.data, s->req.len);
        return;
    }
    for (i = 0; i < s->n; i++)
        if (s->gp[i].alive && !s->gp[i].replied)
            vrLink_Publish(&s->link, VR_CH_SETUP, s->gp[i].setup.data, s->gp[i].setup.len);
}

/* sends the request once; messages counts requests and first answers, not
 * resends or duplicates, so that it depends on the run, not on timing */
static void send_request(vrSgp *s)
{
    s->requests += s->setup_round ? alive_count(s) : 1;
    if (s->setup_round) resend(s);
    else vrLink_Publish(&s->link, s->req_channel, s->req.data, s->req.len);
}

/* a forked worker that exited is dead at once, not after the deadline */
static int exited(vrGpInfo *g)
{
    int status;
    return g->pid > 0 && waitpid(g->pid, &status, WNOHANG) == g->pid;
}

/* Sends the current request and waits until every target answered (all
 * live workers, or only `target`), resending with back-off.  Returns 0, or
 * 1 when a worker died on the way (it is marked dead). */
static int exchange(vrSgp *s, int waiting, int target)
{
    double start = vrLink_NowMs(), last, interval = RESEND_MS;
    int i, died = 0;
    s->waiting = waiting;
    for (i = 0; i < s->n; i++) {
        s->gp[i].replied = !s->gp[i].alive || (target >= 0 && i != target);
        s->gp[i].last_heard = start;
    }
    send_request(s);
    last = start;
    for (;;) {
        double now;
        int all = 1;
        for (i = 0; i < s->n; i++) all &= s->gp[i].replied;
        if (all) return died;
        vrLink_Handle(&s->link, 2);
        now = vrLink_NowMs();
        if (now - last >= interval) {
            resend(s);
            last = now;
            interval = fmin(2 * interval, RESEND_MAX_MS);
        }
        for (i = 0; i < s->n; i++) {
            vrGpInfo *g = &s->gp[i];
            if (g->replied || (now - g->last_heard < DEADLINE_MS && !exited(g))) continue;
            g->alive = 0;
            g->replied = 1;
            died = 1;
        }
        if (died) return 1;
    }
}

/* ---- setup -------------------------------------------------------------------------------- */

/* SPEC 5 / thesis 6.4: which worker owns pair k of (i, j).  Round-robin
 * deals pairs in order; the improved distribution cuts the objects into m
 * groups and gives each worker whole blocks of pairs between groups, so a
 * worker holds copies of few groups (the thesis's 6 objects on 3 workers:
 * at most 4 objects each). */
typedef struct vrDeal { int *gp_of; int npairs; } vrDeal;

static int groups_for(int workers, int objects)
{
    int m = 1;
    while (m * (m - 1) / 2 < workers && m < objects) m++;
    return m;
}

static int block_of(int g1, int g2, int m) { return g1 * m - g1 * (g1 - 1) / 2 + (g2 - g1); }

/* Greedy, biggest block first: among the workers that can take the block
 * without going past a fair share (+20 %), the one it adds fewest new
 * groups to, then the least loaded; if none can, the least loaded.  For the
 * thesis's example this is its figure 6.3: 4 objects and 5 pairs each. */
static void assign_blocks(const long long *size, int m, int nalive, int *owner)
{
    long long total = 0, cap, load[MAX_GPS] = {0};
    char uses[MAX_GPS][MAX_GPS * 2] = {{0}};
    int blocks = m * (m + 1) / 2, b, k, g1, g2;
    for (b = 0; b < blocks; b++) {
        total += size[b];
        owner[b] = -1;
    }
    cap = (total * 12 + nalive * 10 - 1) / (nalive * 10);
    for (;;) {
        int best = -1, bg1 = 0, bg2 = 0, who = -1, wc = 0;
        for (g1 = 0; g1 < m; g1++)
            for (g2 = g1; g2 < m; g2++) {
                b = block_of(g1, g2, m);
                if (owner[b] < 0 && (best < 0 || size[b] > size[best])) { best = b; bg1 = g1; bg2 = g2; }
            }
        if (best < 0) return;
        for (k = 0; k < nalive; k++) {
            int c = !uses[k][bg1] + (bg2 != bg1 && !uses[k][bg2]);
            if (load[k] + size[best] > cap) continue;
            if (who < 0 || c < wc || (c == wc && load[k] < load[who])) { who = k; wc = c; }
        }
        for (k = 0; who < 0 && k < nalive; k++)
            if (who < 0 || load[k] < load[who]) who = k;
        if (who < 0) who = 0;
        owner[best] = who;
        load[who] += size[best];
        uses[who][bg1] = uses[who][bg2] = 1;
    }
}

static void deal_improved(const vrWorld *w, const int *alive, int nalive, int *pair_i, int *pair_j, vrDeal *d)
{
    int m = groups_for(nalive, w->table.n), per = (w->table.n + m - 1) / m, k;
    long long *size = calloc((size_t)(m * (m + 1) / 2), sizeof *size);
    int *owner = malloc((size_t)(m * (m + 1) / 2) * sizeof *owner);
    if (!size || !owner || m > 2 * MAX_GPS) {
        for (k = 0; k < d->npairs; k++) d->gp_of[k] = alive[k % nalive];
    } else {
        for (k = 0; k < d->npairs; k++) size[block_of(pair_i[k] / per, pair_j[k] / per, m)]++;
        assign_blocks(size, m, nalive, owner);
        for (k = 0; k < d->npairs; k++) d->gp_of[k] = alive[owner[block_of(pair_i[k] / per, pair_j[k] / per, m)]];
    }
    free(size);
    free(owner);
}

static int deal(const vrWorld *w, const vrSgp *s, int **pi, int **pj, vrDeal *d)
{
    int alive[MAX_GPS], nalive = 0, i, j, k = 0, cap = 64;
    for (i = 0; i < s->n; i++)
        if (s->gp[i].alive) alive[nalive++] = i;
    *pi = malloc((size_t)cap * sizeof **pi);
    *pj = malloc((size_t)cap * sizeof **pj);
    for (i = 0; *pi && *pj && i < w->table.n; i++)
        for (j = i + 1; j < w->table.n; j++) {
            if (!vrTable_LivePair(&w->table, i, j)) continue;
            if (k == cap) {
                int *a = realloc(*pi, (size_t)(cap *= 2) * sizeof *a), *b;
                if (a) *pi = a;
                b = realloc(*pj, (size_t)cap * sizeof *b);
                if (b) *pj = b;
                if (!a || !b) return -1;
            }
            (*pi)[k] = i;
            (*pj)[k++] = j;
        }
    if (!*pi || !*pj) return -1;
    d->npairs = k;
    d->gp_of = malloc((size_t)(k ? k : 1) * sizeof *d->gp_of);
    if (!d->gp_of) return -1;
    if (w->s.distribution == VR_DIST_IMPROVED) deal_improved(w, alive, nalive, *pi, *pj, d);
    else
        for (k = 0; k < d->npairs; k++) d->gp_of[k] = alive[k % nalive];
    return 0;
}

/* appends b's anchor as it is, to be restored bit for bit */
static int anchor_of(vrUpdate *up, vrBody *b)
{
    vrBodyState *st = vrUpdate_Body(up, b, b->m.t0);
    if (!st) return -1;
    vrBody_CaptureAnchor(b, st);
    return 0;
}

/* the setup of worker g: the objects of its pairs, the pairs */
static int encode_setup(vrWorld *w, vrSgp *s, int g, const int *pi, const int *pj, const vrDeal *d)
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
        if (d->gp_of[k] == g) need[pi[k]] = need[pj[k]] = 1, np++;
    m.a = malloc((size_t)(np + 1) * sizeof *m.a);
    m.b = malloc((size_t)(np + 1) * sizeof *m.b);
    m.flagged = malloc((size_t)(np + 1) * sizeof *m.flagged);
    defs = calloc((size_t)w->table.n + 1, sizeof *defs);
    if (need && pending && m.a && m.b && m.flagged && defs) {
        for (k = 0; k < d->npairs; k++)
            if (d->gp_of[k] == g) {
                m.a[m.npairs] = pi[k];
                m.b[m.npairs] = pj[k];
                m.flagged[m.npairs++] = pending[pi[k]] || pending[pj[k]];
            }
        for (i = 0; i < w->table.n; i++)
            if (need[i]) {
                vrWire_PutDef(&defs[m.nbodies++], i, &w->table.obj[i]->def, w->table.obj[i]->off_text);
                if (anchor_of(&states, &w->table.obj[i]->body) != 0) break;
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

static int append_states(vrUpdate *to, const vrUpdate *from)
{
    int i;
    for (i = 0; i < from->n; i++) {
        if (vrGrow((void **)&to->body, &to->cap, to->n + 1, sizeof *to->body) != 0) return -1;
        to->body[to->n++] = from->body[i];
    }
    return 0;
}

/* the states delivered since the frame began, for redoing it */
static int delivered(vrWorld *w, vrSgp *s)
{
    int r = append_states(&s->snap_pending, &w->pending);
    w->pending.n = 0;
    return r;
}

/* all that worker g's owners counted */
static vrGpCounts counts_of(const vrSgp *s, int g)
{
    const vrGpCounts *b = &s->gp[g].before, *c = &s->gp[g].now;
    vrGpCounts t;
    t.checks = b->checks + c->checks, t.heap_pops = b->heap_pops + c->heap_pops;
    t.solves = b->solves + c->solves, t.refactors = b->refactors + c->refactors;
    t.factors = b->factors + c->factors;
    return t;
}

/* a setup gives every worker a new owner, whose counters start at 0: the
 * stats keep what the old ones counted */
static void retire_counts(vrSgp *s)
{
    int g;
    for (g = 0; g < s->n; g++) {
        s->gp[g].before = counts_of(s, g);
        memset(&s->gp[g].now, 0, sizeof s->gp[g].now);
    }
}

static int setup_all(vrWorld *w, vrSgp *s, char *err, size_t n)
{
    for (;;) {
        int *pi = NULL, *pj = NULL, g, died;
        vrDeal d = {NULL, 0};
        retire_counts(s);
        if (alive_count(s) == 0) return snprintf(err, n, "all %d workers died; set gps = 0 to go on serially", s->n), -1;
        s->seq++;
        s->error[0] = 0;
        if (deal(w, s, &pi, &pj, &d) != 0) g = -2;
        else
            for (g = 0; g < s->n; g++)
                if (s->gp[g].alive && encode_setup(w, s, g, pi, pj, &d) != 0) break;
        free(pi);
        free(pj);
        free(d.gp_of);
        if (g != s->n) return snprintf(err, n, "out of memory"), -1;
        s->setup_round = 1;
        died = exchange(s, WAIT_EARLIEST, -1);
        s->setup_round = 0;
        if (died) continue;              /* deal again among the survivors */
        if (s->error[0]) return snprintf(err, n, "%s", s->error), -1;
        break;
    }
    s->structure = w->structure;
    s->frame_open = 0;
    return delivered(w, s) == 0 ? 0 : (snprintf(err, n, "out of memory"), -1);
}

/* ---- workers: forked, claimed, or in this process ----------------------------------------- */

static int local_url(const char *url) { return strncmp(url, "memq://", 7) == 0; }

/* ttl >= 1: workers on other hosts, started by hand with vroc-gp URL */
static int remote_url(const char *url)
{
    const char *t = strstr(url, "ttl=");
    return t && atoi(t + 4) >= 1;
}

static int fork_workers(vrSgp *s, char *err, size_t n)
{
    int i;
    fflush(NULL);                        /* the children must not repeat our buffered output */
    for (i = 0; i < s->n; i++) {
        pid_t pid;
        s->gp[i].nonce = s->run ^ ((long long)(i + 1) << 40);
        pid = fork();
        if (pid < 0) return snprintf(err, n, "cannot fork worker %d", i), -1;
        if (pid == 0) {
            char e[256];
            _exit(vrWorker_Main(s->url, s->gp[i].nonce, 1, e, sizeof e) == 0 ? 0 : 1);
        }
        s->gp[i].pid = pid;
    }
    return 0;
}

static int await_workers(vrSgp *s, char *err, size_t n)
{
    double start = vrLink_NowMs();
    while (alive_count(s) < s->n) {
        if (vrLink_NowMs() - start > ANNOUNCE_MS)
            return snprintf(err, n, "only %d of %d workers announced themselves on %s", alive_count(s), s->n, s->url), -1;
        vrLink_Handle(&s->link, 20);
    }
    return 0;
}

static long long new_run_id(void)
{
    double t = vrLink_NowMs();
    unsigned long long r = (unsigned long long)getpid() << 32 ^ (unsigned long long)(t * 1e3);
    r = (r ^ (r >> 31)) * 0x9e3779b97f4a7c15ULL;
    return (long long)(r >> 2) | 1;      /* positive and never 0 (0 means free) */
}

static vrSgp *open_sgp(const vrWorld *w, char *err, size_t n)
{
    vrSgp *s = calloc(1, sizeof *s);
    int i;
    if (!s) return snprintf(err, n, "out of memory"), NULL;
    snprintf(s->url, sizeof s->url, "%s", w->s.lcm_url);
    s->n = w->s.gps;
    s->run = new_run_id();
    s->structure = -1;
    s->responder = -1;
    vrUpdate_Init(&s->reply);
    vrUpdate_Init(&s->snap);
    vrUpdate_Init(&s->snap_pending);
    if (!local_url(s->url) && !remote_url(s->url) && fork_workers(s, err, n) != 0) {
        vrSgp_Free(s);
        return NULL;
    }
    if (vrLink_Open(&s->link, s->url, err, n) != 0) {
        vrSgp_Free(s);
        return NULL;
    }
    s->subs[0] = lcm_subscribe(s->link.lcm, VR_CH_EARLIEST, on_earliest, s);
    s->subs[1] = lcm_subscribe(s->link.lcm, VR_CH_UPDATE, on_update, s);
    s->subs[2] = lcm_subscribe(s->link.lcm, VR_CH_HELLO, on_hello, s);
    s->subs[3] = lcm_subscribe(s->link.lcm, VR_CH_CANDIDATES, on_candidates, s);
    for (i = 0; local_url(s->url) && i < s->n; i++) {
        s->gp[i].nonce = s->run ^ ((long long)(i + 1) << 40);
        s->local[i] = vrWorker_Create(&s->link, s->gp[i].nonce, 0);
        s->gp[i].alive = s->local[i] != NULL;
    }
    if (await_workers(s, err, n) != 0) {
        vrSgp_Free(s);
        return NULL;
    }
    return s;
}

void vrSgp_Free(vrSgp *s)
{
    vroc_shutdown_t m;
    vrBuf b = {NULL, 0, 0};
    int i, k;
    if (!s) return;
    if (s->link.lcm) {
        m.run = s->run;
        m.seq = ++s->seq;
        if (VR_ENCODE(&b, vroc_shutdown_t, &m) == 0)
            for (k = 0; k < 3; k++) vrLink_Publish(&s->link, VR_CH_SHUTDOWN, b.data, b.len);
        vrBuf_Free(&b);
    }
    for (i = 0; i < s->n; i++) {
        double start = vrLink_NowMs();
        struct timespec pause = {0, 2000000};
        int status;
        vrWorker_Free(s->local[i]);
        while (s->gp[i].pid > 0 && waitpid(s->gp[i].pid, &status, WNOHANG) == 0) {
            if (vrLink_NowMs() - start > 1000) {
                kill(s->gp[i].pid, SIGKILL);
                waitpid(s->gp[i].pid, &status, 0);
                break;
            }
            nanosleep(&pause, NULL);
        }
        vrBuf_Free(&s->gp[i].setup);
    }
    for (i = 0; i < 4; i++)
        if (s->subs[i]) lcm_unsubscribe(s->link.lcm, s->subs[i]);
    vrLink_Close(&s->link);
    vrBuf_Free(&s->req);
    vrUpdate_Free(&s->reply);
    vrCandidates_Free(&s->candidates);
    vrUpdate_Free(&s->snap);
    vrUpdate_Free(&s->snap_pending);
    free(s);
}

int vrSgp_Sync(vrWorld *w, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    if (s && (s->n != w->s.gps || strcmp(s->url, w->s.lcm_url) != 0)) {
        vrSgp_Retire(w);                 /* its counts stay in the stats */
        s = NULL;
    }
    if (!s) {
        w->sgp = s = open_sgp(w, err, n);
        if (!s) return -1;
    }
    s->max_id = w->table.n;
    return s->structure == w->structure ? 0 : setup_all(w, s, err, n);
}

/* ---- the owner-set operations ---------------------------------------------------------------- */

/* a worker died: back to the frame start, its pairs dealt to the others */
static int recover(vrWorld *w, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    vrFlight f = vrSettings_Flight(&w->s);
    int i;
    for (i = 0; i < s->snap.n; i++)
        vrBody_Apply(&w->table.obj[s->snap.body[i].id]->body, &s->snap.body[i], &f);
    w->collisions = s->snap_collisions;
    for (i = 0; i < s->n; i++) {   /* the frame is redone: what it counted is counted again */
        s->gp[i].before = s->snap_counts[i];
        memset(&s->gp[i].now, 0, sizeof s->gp[i].now);
    }
    w->pending.n = 0;
    if (append_states(&w->pending, &s->snap_pending) != 0) return snprintf(err, n, "out of memory"), -1;
    s->snap_pending.n = 0;
    if (setup_all(w, s, err, n) != 0) return -1;
    return VR_RESTART_FRAME;
}

static void snapshot(vrWorld *w, vrSgp *s)
{
    int i;
    s->snap.n = 0;
    for (i = 0; i < w->table.n; i++)
        if (w->table.obj[i] && w->table.obj[i]->live) anchor_of(&s->snap, &w->table.obj[i]->body);
    s->snap_collisions = w->collisions;
    for (i = 0; i < s->n; i++) s->snap_counts[i] = counts_of(s, i);
}

/* check: ids[0..nids) are the bodies whose overlaps are asked for */
static int encode_frame_start(vrWorld *w, vrSgp *s, const vrGrid *g, int allow, int check, const int *ids, int nids)
{
    vroc_frame_start_t m;
    vrWireStates ws;
    int r;
    memset(&m, 0, sizeof m);
    memset(&ws, 0, sizeof ws);
    r = vrWire_PutStates(&ws, &w->pending);
    m.run = s->run;
    m.seq = s->seq;
    m.t = w->t;
    vrWire_PutGrid(&m.grid, g);
    m.allow_instant = (int8_t)allow;
    m.check = (int8_t)check;
    m.nstates = ws.n;
    m.states = ws.m;
    if (check && nids > 0 && !(m.owed = malloc((size_t)nids * sizeof *m.owed))) r = -1;
    for (m.nowed = 0; m.owed && m.nowed < nids; m.nowed++) m.owed[m.nowed] = ids[m.nowed];
    if (r == 0) r = VR_ENCODE(&s->req, vroc_frame_start_t, &m);
    free(m.owed);
    vrWire_FreeStates(&ws);
    s->req_channel = VR_CH_FRAME;
    return r;
}

static int encode_forward(vrWorld *w, vrSgp *s, const vrGrid *g, int allow)
{
    vroc_update_t m;
    vrWireStates ws;
    int r;
    memset(&m, 0, sizeof m);
    memset(&ws, 0, sizeof ws);
    r = vrWire_PutStates(&ws, &w->pending);
    m.run = s->run;
    m.seq = s->seq;
    m.gp = -1;
    m.t = g->t0;
    m.nstates = ws.n;
    m.states = ws.m;
    vrWire_PutGrid(&m.grid, g);
    m.allow_instant = (int8_t)allow;
    if (r == 0) r = VR_ENCODE(&s->req, vroc_update_t, &m);
    vrWire_FreeStates(&ws);
    s->req_channel = VR_CH_FORWARD;
    return r;
}

/* the earliest reply of all, by (time, pair order) */
static int earliest_of_all(vrSgp *s, vrEvent *ev)
{
    int i, best = -1;
    for (i = 0; i < s->n; i++) {
        const vrGpInfo *g = &s->gp[i];
        if (!g->alive || !g->found) continue;
        if (best < 0 || g->t < s->gp[best].t || (g->t == s->gp[best].t && g->order < s->gp[best].order)) best = i;
    }
    s->responder = best;
    if (best < 0) return 0;
    memset(ev, 0, sizeof *ev);
    ev->t = s->gp[best].t;
    ev->order = s->gp[best].order;
    ev->kind = s->gp[best].kind;
    ev->a = (int)(ev->order >> 32);
    ev->b = (int)(ev->order & 0xffffffff);
    return 1;
}

static int sgp_first_event(vrWorld *w, const vrGrid *g, int allow, vrEvent *ev, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    int r;
    s->seq++;
    s->error[0] = 0;
    if (!s->frame_open) {
        snapshot(w, s);
        r = encode_frame_start(w, s, g, allow, 0, NULL, 0);
        if (r == 0) r = delivered(w, s);
        s->frame_open = 1;
    } else {
        r = encode_forward(w, s, g, allow);
        w->pending.n = 0;
    }
    if (r != 0) return snprintf(err, n, "out of memory"), -1;
    if (exchange(s, WAIT_EARLIEST, -1)) return recover(w, err, n);
    if (s->error[0]) return snprintf(err, n, "%s", s->error), -1;
    return earliest_of_all(s, ev);
}

static int sgp_respond(vrWorld *w, const vrEvent *ev, vrUpdate *up, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    vroc_advance_t m;
    m.run = s->run;
    m.seq = ++s->seq;
    m.t = ev->t;
    m.responder = s->responder;
    m.order = ev->order;
    if (VR_ENCODE(&s->req, vroc_advance_t, &m) != 0) return snprintf(err, n, "out of memory"), -1;
    s->req_channel = VR_CH_ADVANCE;
    if (exchange(s, WAIT_UPDATE, s->responder)) return recover(w, err, n);
    up->n = 0;
    return append_states(up, &s->reply) == 0 ? 0 : (snprintf(err, n, "out of memory"), -1);
}

static void sgp_end_frame(vrWorld *w, double T)
{
    (void)T;
    w->sgp->frame_open = 0;
    w->sgp->snap_pending.n = 0;
}

static int cmp_pair(const void *x, const void *y)
{
    const int *a = x, *b = y;
    return a[0] != b[0] ? (a[0] < b[0] ? -1 : 1) : a[1] < b[1] ? -1 : a[1] > b[1];
}

static int sgp_overlapping(vrWorld *w, double tol, const int *ids, int nids, int (*out)[2], int max, char *err,
                           size_t n)
{
    vrSgp *s = w->sgp;
    vrGrid g;
    int i;
    (void)tol;                           /* workers use VR_START_OVERLAP */
    g.t0 = g.T = w->t;
    g.h = 0;
    g.n = 0;
    for (;;) {
        s->seq++;
        s->error[0] = 0;
        s->noverlap = 0;
        if (encode_frame_start(w, s, &g, 1, 1, ids, nids) != 0) return snprintf(err, n, "out of memory"), -1;
        if (!exchange(s, WAIT_EARLIEST, -1)) break;
        if (setup_all(w, s, err, n) != 0) return -1;   /* a worker died: deal again and ask again */
    }
    if (delivered(w, s) != 0) return snprintf(err, n, "out of memory"), -1;
    if (s->error[0]) return snprintf(err, n, "%s", s->error), -1;
    qsort(s->overlap, (size_t)s->noverlap, sizeof s->overlap[0], cmp_pair);
    for (i = 0; i < s->noverlap && i < max; i++) {
        out[i][0] = s->overlap[i][0];
        out[i][1] = s->overlap[i][1];
    }
    return s->noverlap;
}

/* frame end: ask every worker for the contacts that could carry the
 * wanted bodies (an extra round, only in frames that have such bodies) */
static int sgp_candidates(vrWorld *w, double T, const unsigned char *want, vrCandidates *out, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    vroc_contacts_t m;
    int i, k = 0, r;
    memset(&m, 0, sizeof m);
    m.want = malloc((size_t)w->table.n * sizeof *m.want + 1);
    if (!m.want) return snprintf(err, n, "out of memory"), -1;
    for (i = 0; i < w->table.n; i++)
        if (want[i]) m.want[k++] = i;
    m.nwant = k;
    m.run = s->run;
    m.seq = ++s->seq;
    m.t = T;
    s->error[0] = 0;
    s->candidates.n = 0;
    r = VR_ENCODE(&s->req, vroc_contacts_t, &m);
    free(m.want);
    if (r != 0) return snprintf(err, n, "out of memory"), -1;
    s->req_channel = VR_CH_CONTACTS;
    if (exchange(s, WAIT_CANDIDATES, -1)) return recover(w, err, n);
    if (s->error[0]) return snprintf(err, n, "%s", s->error), -1;
    for (i = 0; i < s->candidates.n; i++) {
        vrCandidate *c = vrCandidates_Add(out);
        if (!c) return snprintf(err, n, "out of memory"), -1;
        *c = s->candidates.c[i];
    }
    return 0;
}

const vrOwnerSet vrSgp_Owners = {sgp_first_event, sgp_respond, sgp_end_frame, sgp_overlapping, sgp_candidates};

void vrSgp_Stats(const vrSgp *s, vrStats *st)
{
    int i;
    st->gps = s->n;
    st->messages = s->requests + s->received;
    st->foreign = s->foreign;
    st->malformed = s->malformed;
    for (i = 0; i < s->n && i < 64; i++) {
        const vrGpInfo *g = &s->gp[i];
        vrGpCounts c = counts_of(s, i);
        st->gp_checks[i] = c.checks;
        st->gp_copies[i] = g->alive ? g->copies : 0;
        st->gp_pairs[i] = g->alive ? g->pairs : 0;
        st->checks += c.checks;
        st->heap_pops += c.heap_pops;
        st->klu_solves += c.solves;
        st->klu_refactors += c.refactors;
        st->klu_factors += c.factors;
        if (g->alive) st->copies += g->copies;
    }
}

void vrSgp_Retire(vrWorld *w)
{
    vrStats st;
    memset(&st, 0, sizeof st);
    vrSgp_Stats(w->sgp, &st);
    w->retired.checks += st.checks;
    w->retired.heap_pops += st.heap_pops;
    w->retired.response.solves += st.klu_solves;
    w->retired.response.refactors += st.klu_refactors;
    w->retired.response.factors += st.klu_factors;
    vrSgp_Free(w->sgp);
    w->sgp = NULL;
}

int vrWorker_Run(const char *url, char *err, size_t n)
{
    unsigned long long nonce = (unsigned long long)new_run_id() ^ (unsigned long long)getpid();
    return vrWorker_Main(url, (long long)(nonce >> 1) | 1, 0, err, n);
}
