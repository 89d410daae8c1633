/* exchange.c — a request and its answers over UDP multicast, which loses
 * and repeats messages (SPEC 5): every request carries the run id and a
 * sequence number and is resent with back-off until every worker asked
 * has answered; an answer is taken once, from the worker it names, for the
 * request it names.  A worker silent for DEADLINE_MS, or a forked one that
 * exited, is declared dead.
 *
 *   sender                 the worker an answer is from, if it is awaited
 *   take_answer            the answer to its event an earliest carries
 *   take_*                 an answer of each kind (the VR_HANDLER callbacks)
 *   resend / send_request  the request to every worker, or a setup each
 *   round_kind, exited     a round's kind (stats rounds); a forked worker that is gone
 */
#include <string.h>
#include <sys/wait.h>
#include "exchange.h"
#include "wire.h"
#include "vroc_candidates_t.h"
#include "vroc_earliest_t.h"
#include "vroc_hello_t.h"
#include "vroc_update_t.h"

#define RESEND_MS 5.0
#define RESEND_MAX_MS 200.0
#define DEADLINE_MS 1000.0      /* SPEC 5: a worker silent this long is dead */
#define WALL_DEADLINE_MS 30000.0 /* however busy the waits: a stream of other messages hides no death */

/* ---- answers -------------------------------------------------------------------------- */

static vrGpInfo *sender(vrSgp *s, long long run, long long seq, int gp, int waiting)
{
    if (run != s->run) {
        s->foreign++;
        return NULL;
    }
    if (seq != s->seq || waiting != s->waiting || gp < 0 || gp >= s->n || !s->gp[gp].alive || s->gp[gp].replied)
        return NULL;
    s->received++;
    s->gp[gp].last_heard = s->idle_ms;
    s->gp[gp].last_heard_wall = vrLink_NowMs();
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

static void note_error(vrSgp *s, int gp, const char *error)
{
    if (error[0] && !s->error[0]) snprintf(s->error, sizeof s->error, "worker %d: %s", gp, error);
}

static void count_malformed(vrSgp *s) { s->malformed++; }

/* the answer to its event a worker sent with it (answered): its states,
 * taken if its event is the first of all */
static int take_answer(vrSgp *s, vrGpInfo *g, const vroc_earliest_t *m)
{
    g->answer.n = 0;
    g->answered = m->found && m->answered;
    g->answer_cost.solves = m->answer_solves;
    g->answer_cost.refactors = m->answer_refactors;
    g->answer_cost.factors = m->answer_factors;
    return g->answered ? vrWire_GetStates(m->states, m->nstates, s->max_id, &g->answer) : 0;
}

static int bad_event(const vroc_earliest_t *m)
{
    return m->found && (!isfinite(m->t) || m->kind <= VR_EV_NONE || m->kind > VR_EV_PUSHOUT || !isfinite(m->approach)
                        || !isfinite(m->point[0]) || !isfinite(m->point[1]) || !isfinite(m->point[2]));
}

/* worker g's look-ahead in m: 0, or -1 when m is malformed */
static int note_earliest(vrSgp *s, vrGpInfo *g, const vroc_earliest_t *m)
{
    if (bad_event(m) || take_answer(s, g, m) != 0) return -1;
    g->found = m->found;
    g->t = m->t;
    g->order = m->order;
    g->kind = m->kind;
    g->approach = m->approach;
    g->point = vec3_make(m->point[0], m->point[1], m->point[2]);
    g->quiet = m->quiet && !m->found;
    g->now.checks = m->checks;
    g->now.heap_pops = m->heap_pops;
    g->now.solves = m->solves;
    g->now.refactors = m->refactors;
    g->now.factors = m->factors;
    if (isfinite(m->busy_ms)) g->busy_ms = m->busy_ms;
    g->copies = m->copies;
    g->records = m->records;
    note_overlaps(s, m);
    note_error(s, (int)(g - s->gp), m->error);
    return 0;
}

static void take_earliest(vrSgp *s, const vroc_earliest_t *m)
{
    vrGpInfo *g = sender(s, m->run, m->seq, m->gp, WAIT_EARLIEST);
    if (!g) return;
    if (note_earliest(s, g, m) != 0) s->malformed++;
    else g->replied = 1;
}

static void take_update(vrSgp *s, const vroc_update_t *m)
{
    vrGpInfo *g = m->gp == s->responder ? sender(s, m->run, m->seq, m->gp, WAIT_UPDATE) : NULL;
    if (!g) return;
    s->reply.n = 0;
    if (vrWire_GetStates(m->states, m->nstates, s->max_id, &s->reply) != 0) {
        s->malformed++;
        return;
    }
    g->replied = 1;
    g->now.solves = m->solves;
    g->now.refactors = m->refactors;
    g->now.factors = m->factors;
}

/* the touches of an island step, and the look-ahead after it when asked
 * (g->ahead) */
static void take_candidates(vrSgp *s, const vroc_candidates_t *m)
{
    vrGpInfo *g = sender(s, m->run, m->seq, m->gp, WAIT_CANDIDATES);
    if (!g) return;
    g->ahead = 0;
    if (m->nahead > 1 || vrWire_GetTouches(m, s->max_id, &s->touches) != 0
        || (m->nahead == 1 && note_earliest(s, g, &m->ahead[0]) != 0)) {
        s->malformed++;
        return;
    }
    g->ahead = m->nahead == 1;
    g->replied = 1;
    note_error(s, m->gp, m->error);
}

/* heartbeats of busy workers; announcements of free ones */
static void take_hello(vrSgp *s, const vroc_hello_t *m)
{
    int i;
    if (m->run == s->run && m->gp >= 0 && m->gp < s->n) s->gp[m->gp].last_heard = s->idle_ms, s->gp[m->gp].last_heard_wall = vrLink_NowMs();
    if (m->run != 0) return;
    for (i = 0; i < s->n; i++)
        if (s->gp[i].nonce == m->nonce) {
            s->gp[i].alive = 1;          /* a worker of ours is up */
            return;
        }
    for (i = 0; i < s->n; i++)          /* a free worker started by hand */
        if (s->gp[i].nonce == 0 && !s->gp[i].pid) {
            s->gp[i].nonce = m->nonce;
            s->gp[i].alive = 1;
            return;
        }
}

VR_HANDLER(on_earliest, vroc_earliest_t, vrSgp, take_earliest, count_malformed)
VR_HANDLER(on_update, vroc_update_t, vrSgp, take_update, count_malformed)
VR_HANDLER(on_candidates, vroc_candidates_t, vrSgp, take_candidates, count_malformed)
VR_HANDLER(on_hello, vroc_hello_t, vrSgp, take_hello, count_malformed)

void vrSgp_Subscribe(vrSgp *s)
{
    s->subs[0] = lcm_subscribe(s->link.lcm, VR_CH_EARLIEST, on_earliest, s);
    s->subs[1] = lcm_subscribe(s->link.lcm, VR_CH_UPDATE, on_update, s);
    s->subs[2] = lcm_subscribe(s->link.lcm, VR_CH_HELLO, on_hello, s);
    s->subs[3] = lcm_subscribe(s->link.lcm, VR_CH_CANDIDATES, on_candidates, s);
}

void vrSgp_Unsubscribe(vrSgp *s)
{
    int i;
    for (i = 0; i < 4; i++)
        if (s->subs[i]) lcm_unsubscribe(s->link.lcm, s->subs[i]);
}

/* ---- the round ------------------------------------------------------------------------ */

int vrSgp_AliveCount(const vrSgp *s)
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
    s->requests += s->setup_round ? vrSgp_AliveCount(s) : 1;
    if (s->setup_round) resend(s);
    else vrLink_Publish(&s->link, s->req_channel, s->req.data, s->req.len);
}

static int round_kind(const vrSgp *s)
{
    if (s->setup_round) return ROUND_SETUP;
    if (!strcmp(s->req_channel, VR_CH_FORWARD)) return ROUND_FORWARD;
    if (!strcmp(s->req_channel, VR_CH_ADVANCE)) return ROUND_ADVANCE;
    return !strcmp(s->req_channel, VR_CH_CONTACTS) ? ROUND_CONTACTS : ROUND_FRAME;
}

static int exited(vrGpInfo *g)
{
    int status;
    return g->pid > 0 && waitpid(g->pid, &status, WNOHANG) == g->pid;
}

static int exchange(vrSgp *s, int waiting, int target)
{
    double start = vrLink_NowMs(), last, before, interval = RESEND_MS;
    int i, died = 0;
    s->waiting = waiting;
    s->idle_ms = 0;
    for (i = 0; i < s->n; i++) {
        s->gp[i].replied = !s->gp[i].alive || (target >= 0 && i != target);
        s->gp[i].last_heard = 0;
        s->gp[i].last_heard_wall = start;
    }
    send_request(s);
    last = start;
    for (;;) {
        double now;
        int all = 1;
        for (i = 0; i < s->n; i++) all &= s->gp[i].replied;
        if (all) return died;
        /* A worker is silent while waits bring nothing: time spent in
         * handlers (in-process workers answer inside them) or in a wait
         * that brought a message is not silence.  (A run of 200 objects with
         * in-process workers under ASan, on two cores shared by seven
         * builds, failed once with wall-clock silence: a setup's handlers
         * can take longer than DEADLINE_MS there.) */
        before = vrLink_NowMs();
        if (vrLink_Handle(&s->link, 2) == 0) s->idle_ms += vrLink_NowMs() - before;
        now = vrLink_NowMs();
        if (now - last >= interval) {
            resend(s);
            last = now;
            interval = fmin(2 * interval, RESEND_MAX_MS);
        }
        for (i = 0; i < s->n; i++) {
            vrGpInfo *g = &s->gp[i];
            if (g->replied || (s->idle_ms - g->last_heard < DEADLINE_MS && now - g->last_heard_wall < WALL_DEADLINE_MS && !exited(g)))
                continue;
            g->alive = 0;
            g->replied = 1;
            died = 1;
        }
        if (died) return 1;
    }
}

int vrSgp_Exchange(vrSgp *s, int waiting, int target)
{
    double start = vrLink_NowMs();
    int died;
    s->rounds[round_kind(s)]++;
    s->quiet = 0;                        /* sgp.c sets it after a look-ahead */
    died = exchange(s, waiting, target);
    s->wait_ms += vrLink_NowMs() - start;
    return died;
}
