/* worker.c — a GP: the thesis's Graphic Processor, a pair owner driven by
 * the SGP's messages (SPEC 5).  What it holds (its objects' copies and
 * one vrOwner over its pairs) is worker_hold.c's; its answers and
 * heartbeats, worker_reply.c's; its state, worker_state.h.
 *
 *   answer_ahead   the answer to its own event, sent with it (one round an event)
 *   look_ahead, check_overlaps   a span's first event; the overlaps of a check
 *   start_request  a new request: the last answer's fate, the busy clock
 *   owed_island    an island step the SGP answered without a round, done late
 *   maybe_die      VROC_FAULT_KILL, for the tests of a dying worker
 *   take_*         a request of each kind (the VR_HANDLER callbacks)
 */
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "progress.h"
#include "worker_hold.h"
#include "worker_reply.h"
#include "wire.h"
#include "vroc_advance_t.h"
#include "vroc_candidates_t.h"
#include "vroc_contacts_t.h"
#include "vroc_frame_start_t.h"
#include "vroc_setup_t.h"
#include "vroc_shutdown_t.h"
#include "vroc_update_t.h"

/* ---- requests ---------------------------------------------------------------------------- */

/* Its answer to its event, made with the look-ahead: when the event turns
 * out to be the first of all, the SGP takes it from the earliest, and the
 * event costs one round instead of an advance and its update as well.  A
 * response reads only the bodies (vrEffect_Compute), which no clock move
 * changes, so it is the answer an advance would get. */
static void answer_ahead(vrWorker *k)
{
    vrOwnerStats before, after;
    vrOwner_Stats(k->owner, &before);
    k->answer.n = 0;
    k->answered = vrOwner_Respond(k->owner, &k->first, &k->answer) == 0;
    vrOwner_Stats(k->owner, &after);
    k->answer_cost.solves = after.response.solves - before.response.solves;
    k->answer_cost.refactors = after.response.refactors - before.response.refactors;
    k->answer_cost.factors = after.response.factors - before.response.factors;
    if (!k->answered) {          /* the advance finds it unanswerable too: silence */
        k->answered = 1;
        vrWorker_Settle(k, 0);
    }
}

/* a span's look-ahead on grid: k->first (has_first), quiet, the answer
 * to its event; vrOwner_FirstEvent's 1, 0 or -1, or -2 for a bad grid */
static int find_first(vrWorker *k, const vroc_grid_t *grid, int allow)
{
    vrGrid g;
    int r;
    if (vrWire_GetGrid(grid, &g) != 0) return -2;
    r = vrOwner_FirstEvent(k->owner, &g, allow, &k->first);
    k->has_first = r == 1;
    k->quiet = r == 0 && !k->thesis_rounds && vrOwner_Quiet(k->owner);
    if (k->has_first && !k->thesis_rounds) answer_ahead(k);
    return r;
}

static const char *first_failed(int r) { return r == -2 ? "bad grid" : r < 0 ? "out of memory" : NULL; }

static void look_ahead(vrWorker *k, int64_t seq, const vroc_grid_t *grid, int allow)
{
    int r = find_first(k, grid, allow);
    vrWorker_SendEarliest(k, seq, r == 1, &k->first, 0, NULL, NULL, first_failed(r));
}

/* a new request: the answer sent with the last earliest was not taken
 * unless it says so; its work starts now */
static void start_request(vrWorker *k, int taken)
{
    vrWorker_Settle(k, taken);
    k->quiet = 0;
    k->busy_from = vrLink_NowMs();
}

/* The island step the SGP answered without a round because every worker
 * said it would find nothing (quiet): done now, where the contacts
 * request would have done it (every clock at t, no state since), so that
 * what it records (the step's time and length) is the same.  NULL, or
 * what went wrong. */
static const char *owed_island(vrWorker *k, double t, double h)
{
    vrTouches list = {0, 0, NULL};
    int r, found;
    if (!(h > 0)) return NULL;
    if (!isfinite(t) || !isfinite(h)) return "bad island step";
    vrOwner_Advance(k->owner, t);
    r = vrOwner_Touching(k->owner, t, h, &list);
    found = list.n;
    vrTouches_Free(&list);
    return r != 0 ? "out of memory" : found ? "an island step answered without a round had contacts" : NULL;
}

static void check_overlaps(vrWorker *k, int64_t seq, double t, const int32_t *owed, int nowed)
{
    int (*pairs)[2] = NULL, nmax = 64, count = 0, i;
    int *ids = nowed >= 0 ? malloc((size_t)nowed * sizeof *ids + 1) : NULL;
    int32_t *a, *b;
    pairs = malloc((size_t)nmax * sizeof *pairs);
    for (i = 0; ids && i < nowed; i++) ids[i] = owed[i];
    if (!ids || !pairs || (count = vrOwner_Overlapping(k->owner, t, VR_START_OVERLAP, ids, nowed, pairs, nmax)) < 0) {
        free(pairs);             /* reported as out of memory below */
        pairs = NULL;
        count = 0;
    }
    free(ids);
    if (count > nmax) count = nmax;
    a = malloc((size_t)(count + 1) * sizeof *a);
    b = malloc((size_t)(count + 1) * sizeof *b);
    for (i = 0; a && b && i < count; i++) {
        a[i] = pairs[i][0];
        b[i] = pairs[i][1];
    }
    vrWorker_SendEarliest(k, seq, 0, NULL, a && b ? count : 0, a, b, pairs && a && b ? NULL : "out of memory");
    free(pairs);
    free(a);
    free(b);
}

static void take_setup(vrWorker *k, const vroc_setup_t *m)
{
    char err[256] = "";
    if (m->nonce != k->nonce || k->silent) return;
    if (m->run != k->run) {              /* a new run claims this worker */
        k->run = m->run;
        k->last_seq = k->reply_seq = -1;
        k->frames = 0;
    }
    if (vrWorker_Fresh(k, m->run, m->seq)) {
        start_request(k, 0);
        memset(&k->wasted, 0, sizeof k->wasted);   /* a new owner counts from 0 */
        k->gp = m->gp;
        if (vrWorker_SetUp(k, m, err, sizeof err) != 0 && !err[0]) strcpy(err, "setup failed");
        vrWorker_SendEarliest(k, m->seq, 0, NULL, 0, NULL, NULL, err[0] ? err : NULL);
    }
}

/* VROC_FAULT_KILL=gp:frame[:round] — the worker dies at that frame's
 * start, or at its round-th event (forward), in the middle of the frame
 * (tests) */
static void maybe_die(vrWorker *k)
{
    if (k->gp != k->kill_gp || k->frames != k->kill_frame || k->rounds != k->kill_round) return;
    if (k->forked) raise(SIGKILL);
    k->silent = 1;                       /* in one process: fall silent instead */
}

static void take_frame(vrWorker *k, const vroc_frame_start_t *m)
{
    const char *bad;
    if (!k->owner || !vrWorker_Fresh(k, m->run, m->seq) || !isfinite(m->t)) return;
    start_request(k, 0);
    if (!m->check) {
        k->frames++;
        k->rounds = 0;
        maybe_die(k);
    }
    if (k->silent) return;
    if ((bad = owed_island(k, m->island_t, m->island_h)) != NULL) {
        vrWorker_SendEarliest(k, m->seq, 0, NULL, 0, NULL, NULL, bad);
        return;
    }
    vrOwner_Advance(k->owner, m->t);
    if (vrWorker_ApplyStates(k, m->states, m->nstates) != 0) vrWorker_SendEarliest(k, m->seq, 0, NULL, 0, NULL, NULL, "bad body state");
    else if (m->check) check_overlaps(k, m->seq, m->t, m->owed, m->nowed);
    else look_ahead(k, m->seq, &m->grid, m->allow_instant);
}

/* the SGP asks for the answer to our event (it lacked the one our
 * earliest carried) */
static void take_advance(vrWorker *k, const vroc_advance_t *m)
{
    vroc_update_t u;
    vrWireStates ws;
    vrResponseStats rs;
    if (!k->owner || !vrWorker_Fresh(k, m->run, m->seq)) return;
    if (k->silent || m->responder != k->gp) return;
    if (!k->has_first || k->first.order != m->order || k->first.t != m->t) return;
    k->busy_from = vrLink_NowMs();
    vrOwner_AdvanceTo(k->owner, &k->first);
    if (!k->answered) answer_ahead(k);
    if (!k->answered) return;            /* silence: the SGP gives up on us */
    vrWorker_Settle(k, 1);
    memset(&u, 0, sizeof u);
    memset(&ws, 0, sizeof ws);
    rs = vrWorker_Counts(k);
    u.run = k->run;
    u.seq = m->seq;
    u.gp = k->gp;
    u.t = m->t;
    u.solves = rs.solves;
    u.refactors = rs.refactors;
    u.factors = rs.factors;
    u.taken = k->gp;
    if (vrWire_PutStates(&ws, &k->answer) == 0) {
        u.nstates = ws.n;
        u.states = ws.m;
        if (VR_ENCODE(&k->reply, vroc_update_t, &u) == 0) vrWorker_Answer(k, VR_CH_UPDATE, m->seq);
    }
    vrWire_FreeStates(&ws);
    vrWorker_NoteBusy(k);
}

/* Every clock to the answered event's time.  With keep_looks the looks
 * past it stand but for the answered pair's (when the answer was ours, in
 * our earliest) and the changed bodies' (vrWorker_ApplyStates); an
 * answer the SGP asked for (take_advance) took its pair's back already. */
static void advance_to_answer(vrWorker *k, const vroc_update_t *m)
{
    vrEvent none;
    if (m->taken == k->gp && k->has_first && k->first.t == m->t) {
        vrOwner_AdvanceTo(k->owner, &k->first);
        return;
    }
    memset(&none, 0, sizeof none);
    none.t = m->t;
    none.order = -1;                     /* no pair of ours */
    vrOwner_AdvanceTo(k->owner, &none);
}

static void take_forward(vrWorker *k, const vroc_update_t *m)
{
    const char *bad;
    if (!k->owner || m->gp >= 0 || !vrWorker_Fresh(k, m->run, m->seq) || !isfinite(m->t)) return;
    start_request(k, m->taken == k->gp);
    k->rounds++;
    maybe_die(k);
    if (k->silent) return;
    if ((bad = owed_island(k, m->island_t, m->island_h)) != NULL) {
        vrWorker_SendEarliest(k, m->seq, 0, NULL, 0, NULL, NULL, bad);
        return;
    }
    advance_to_answer(k, m);
    if (vrWorker_ApplyStates(k, m->states, m->nstates) != 0) vrWorker_SendEarliest(k, m->seq, 0, NULL, 0, NULL, NULL, "bad body state");
    else look_ahead(k, m->seq, &m->grid, m->allow_instant);
}

/* an island step: the pairs that touch, and with ahead the contact
 * step's look-ahead after it (the thesis's rounds have none) */
static void report_touches(vrWorker *k, const vroc_contacts_t *m)
{
    vrTouches list = {0, 0, NULL};
    vroc_candidates_t r;
    vroc_earliest_t ahead;
    vrWireStates ws;
    memset(&r, 0, sizeof r);
    memset(&ws, 0, sizeof ws);
    r.run = k->run;
    r.seq = m->seq;
    r.gp = k->gp;
    r.error = "";
    if (vrOwner_Touching(k->owner, m->t, m->h, &list) != 0 || vrWire_PutTouches(&r, &list) != 0) {
        vrWire_FreeTouches(&r);
        memset(&r, 0, sizeof r);
        r.run = k->run;
        r.seq = m->seq;
        r.gp = k->gp;
        r.error = "out of memory";
    } else if (m->ahead && !k->thesis_rounds) {
        int f = find_first(k, &m->grid, m->allow_instant);
        vrWorker_PutEarliest(k, m->seq, f == 1, &k->first, 0, NULL, NULL, first_failed(f), &ahead, &ws);
        r.nahead = 1;
        r.ahead = &ahead;
    }
    if (VR_ENCODE(&k->reply, vroc_candidates_t, &r) == 0) vrWorker_Answer(k, VR_CH_CANDIDATES, m->seq);
    r.nahead = 0;
    r.ahead = NULL;
    vrWire_FreeTouches(&r);
    vrWire_FreeStates(&ws);
    vrTouches_Free(&list);
    vrWorker_NoteBusy(k);
}

/* an island step's answer that names what went wrong */
static void touches_failed(vrWorker *k, int64_t seq, const char *why)
{
    vroc_candidates_t r;
    memset(&r, 0, sizeof r);
    r.run = k->run, r.seq = seq, r.gp = k->gp, r.error = (char *)why;
    if (VR_ENCODE(&k->reply, vroc_candidates_t, &r) == 0) vrWorker_Answer(k, VR_CH_CANDIDATES, seq);
}

static void take_contacts(vrWorker *k, const vroc_contacts_t *m)
{
    const char *bad;
    if (!k->owner || !vrWorker_Fresh(k, m->run, m->seq) || !isfinite(m->t) || !(m->h >= 0)) return;
    start_request(k, 0);
    if ((bad = owed_island(k, m->island_t, m->island_h)) != NULL) {
        touches_failed(k, m->seq, bad);
        return;
    }
    vrOwner_Advance(k->owner, m->t);
    if (vrWorker_ApplyStates(k, m->states, m->nstates) != 0) {
        touches_failed(k, m->seq, "bad body state");
        return;
    }
    report_touches(k, m);
}

static void take_shutdown(vrWorker *k, const vroc_shutdown_t *m)
{
    if (k->run != 0 && m->run == k->run) k->done = 1;
}

/* a message that does not decode is dropped: the SGP asks again */
static void ignore(vrWorker *k) { (void)k; }

VR_HANDLER(on_setup, vroc_setup_t, vrWorker, take_setup, ignore)
VR_HANDLER(on_frame, vroc_frame_start_t, vrWorker, take_frame, ignore)
VR_HANDLER(on_advance, vroc_advance_t, vrWorker, take_advance, ignore)
VR_HANDLER(on_forward, vroc_update_t, vrWorker, take_forward, ignore)
VR_HANDLER(on_contacts, vroc_contacts_t, vrWorker, take_contacts, ignore)
VR_HANDLER(on_shutdown, vroc_shutdown_t, vrWorker, take_shutdown, ignore)

/* ---- life ----------------------------------------------------------------------------------- */

/* VROC_THESIS_ROUNDS=1: the thesis's rounds, for the bench's and the
 * tests' comparison: no answer with the earliest (an advance round per
 * event) and never quiet (a round at every island step) */
static void parse_knobs(vrWorker *k)
{
    const char *a = getenv("VROC_THESIS_ROUNDS");
    k->thesis_rounds = a && strcmp(a, "1") == 0;
}

static void parse_kill(vrWorker *k)
{
    const char *v = getenv("VROC_FAULT_KILL");
    k->kill_gp = k->kill_frame = -1;
    k->kill_round = 0;
    /* NOLINTNEXTLINE(cert-err34-c): a test's fault knob; less than gp:frame reads as none */
    if (v && sscanf(v, "%d:%d:%d", &k->kill_gp, &k->kill_frame, &k->kill_round) < 2) k->kill_gp = k->kill_frame = -1;
}

vrWorker *vrWorker_Create(vrLink *link, long long nonce, int forked)
{
    vrWorker *k = calloc(1, sizeof *k);
    if (!k) return NULL;
    k->link = link;
    k->nonce = nonce;
    k->forked = forked;
    k->parent = getppid();
    k->gp = -1;
    k->last_seq = k->reply_seq = -1;
    vrUpdate_Init(&k->scratch);
    vrUpdate_Init(&k->answer);
    parse_kill(k);
    parse_knobs(k);
    k->subs[0] = lcm_subscribe(link->lcm, VR_CH_SETUP, on_setup, k);
    k->subs[1] = lcm_subscribe(link->lcm, VR_CH_FRAME, on_frame, k);
    k->subs[2] = lcm_subscribe(link->lcm, VR_CH_ADVANCE, on_advance, k);
    k->subs[3] = lcm_subscribe(link->lcm, VR_CH_FORWARD, on_forward, k);
    k->subs[4] = lcm_subscribe(link->lcm, VR_CH_SHUTDOWN, on_shutdown, k);
    k->subs[5] = lcm_subscribe(link->lcm, VR_CH_CONTACTS, on_contacts, k);
    if (!k->subs[0] || !k->subs[1] || !k->subs[2] || !k->subs[3] || !k->subs[4] || !k->subs[5]) {
        vrWorker_Free(k);
        return NULL;
    }
    return k;
}

void vrWorker_Free(vrWorker *k)
{
    int i;
    if (!k) return;
    for (i = 0; i < 6; i++)
        if (k->subs[i]) lcm_unsubscribe(k->link->lcm, k->subs[i]);
    vrOwner_Free(k->owner);
    vrTable_Free(&k->objects);
    vrUpdate_Free(&k->scratch);
    vrUpdate_Free(&k->answer);
    vrBuf_Free(&k->reply);
    free(k->ids);
    free(k->setup_pending);
    free(k);
}

int vrWorker_Tick(vrWorker *k)
{
    if (k->run == 0) {             /* free: tell the SGPs we are here */
        k->last_hello = 0;
        vrWorker_Beat(k);
    }
    if (k->forked && getppid() != k->parent) k->done = 1;   /* our SGP is gone */
    return k->done;
}

int vrWorker_Main(const char *url, long long nonce, int forked, char *err, size_t n)
{
    vrLink link;
    vrWorker *k;
    double last = 0;
    if (vrLink_Open(&link, url, VR_LINK_WORKER, err, n) != 0) return -1;
    k = vrWorker_Create(&link, nonce, forked);
    if (!k) {
        vrLink_Close(&link);
        snprintf(err, n, "out of memory");
        return -1;
    }
    vrProgress_Set(vrWorker_Beat, k);   /* a long build is not silence (progress.h) */
    while (!k->done) {
        double now;
        vrLink_Handle(&link, (int)HELLO_MS);
        now = vrLink_NowMs();
        if (now - last >= HELLO_MS) {
            last = now;
            vrWorker_Tick(k);
        }
    }
    vrProgress_Set(NULL, NULL);
    vrWorker_Free(k);
    vrLink_Close(&link);
    return 0;
}

int vrWorker_Run(const char *url, char *err, size_t n)
{
    unsigned long long nonce = (unsigned long long)vrLink_NewId() ^ (unsigned long long)getpid();
    return vrWorker_Main(url, (long long)(nonce >> 1) | 1, 0, err, n);
}
