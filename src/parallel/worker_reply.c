/* worker_reply.c — a worker's answers to the SGP (SPEC 5): the last one
 * kept for repeated requests, the earliest event it found with what the
 * coordinator needs of it, and heartbeats while it is busy.
 *
 *   vrWorker_Answer, vrWorker_Fresh   an answer sent and kept; a request new or repeated
 *   vrWorker_Counts, vrWorker_Settle  the KLU counts of answers taken; an answer's fate
 *   vrWorker_NoteBusy                 the time spent on requests
 *   vrWorker_SendEarliest             the `earliest` message, with the answer to its event
 *   vrWorker_Beat                     a heartbeat while a long look-ahead keeps it busy
 */
#include <string.h>
#include <unistd.h>
#include "worker_reply.h"
#include "wire.h"
#include "vroc_earliest_t.h"
#include "vroc_hello_t.h"

void vrWorker_Answer(vrWorker *k, const char *channel, int64_t seq)
{
    k->reply_channel = channel;
    k->reply_seq = seq;
    vrLink_Publish(k->link, channel, k->reply.data, k->reply.len);
}

int vrWorker_Fresh(vrWorker *k, int64_t run, int64_t seq)
{
    if (k->silent || run != k->run || seq < k->last_seq) return 0;
    if (seq == k->last_seq) {
        if (k->reply_seq == seq) vrLink_Publish(k->link, k->reply_channel, k->reply.data, k->reply.len);
        return 0;
    }
    k->last_seq = seq;
    return 1;
}

/* the owner's counts less those of answers the SGP did not take, and of
 * the answer it has not decided on: klu_solves counts answered events
 * alike whatever the workers (SPEC 1.3) */
vrResponseStats vrWorker_Counts(const vrWorker *k)
{
    vrOwnerStats os;
    vrResponseStats r;
    memset(&os, 0, sizeof os);
    if (k->owner) vrOwner_Stats(k->owner, &os);
    r = os.response;
    r.solves -= k->wasted.solves + (k->answered ? k->answer_cost.solves : 0);
    r.refactors -= k->wasted.refactors + (k->answered ? k->answer_cost.refactors : 0);
    r.factors -= k->wasted.factors + (k->answered ? k->answer_cost.factors : 0);
    return r;
}

void vrWorker_Settle(vrWorker *k, int taken)
{
    if (k->answered && !taken) {
        k->wasted.solves += k->answer_cost.solves;
        k->wasted.refactors += k->answer_cost.refactors;
        k->wasted.factors += k->answer_cost.factors;
    }
    k->answered = 0;
}

void vrWorker_NoteBusy(vrWorker *k)
{
    double now = vrLink_NowMs();
    k->busy_ms += now - k->busy_from;
    k->busy_from = now;
}

/* the answer to its event in m; -1 on no memory (then it goes unanswered:
 * the SGP asks with an advance) */
static int put_answer(const vrWorker *k, vroc_earliest_t *m, vrWireStates *ws)
{
    if (!k->answered || vrWire_PutStates(ws, &k->answer) != 0) return -1;
    m->answered = 1;
    m->nstates = ws->n;
    m->states = ws->m;
    m->answer_solves = k->answer_cost.solves;
    m->answer_refactors = k->answer_cost.refactors;
    m->answer_factors = k->answer_cost.factors;
    return 0;
}

void vrWorker_PutEarliest(vrWorker *k, int64_t seq, int found, const vrEvent *ev, int noverlap, int32_t *a,
                          int32_t *b, const char *error, vroc_earliest_t *m, vrWireStates *ws)
{
    vrOwnerStats os;
    vrResponseStats rs = vrWorker_Counts(k);
    memset(m, 0, sizeof *m);
    memset(&os, 0, sizeof os);
    memset(ws, 0, sizeof *ws);
    if (k->owner) vrOwner_Stats(k->owner, &os);
    m->run = k->run;
    m->seq = seq;
    m->gp = k->gp;
    m->found = (int8_t)found;
    if (found) {
        m->t = ev->t;
        m->order = ev->order;
        m->kind = (int8_t)ev->kind;
        m->approach = ev->approach;
        m->point[0] = ev->c.x, m->point[1] = ev->c.y, m->point[2] = ev->c.z;
        put_answer(k, m, ws);
    }
    m->solves = rs.solves;
    m->refactors = rs.refactors;
    m->factors = rs.factors;
    vrWorker_NoteBusy(k);
    m->busy_ms = k->busy_ms;
    m->quiet = (int8_t)k->quiet;
    m->checks = os.checks;
    m->heap_pops = os.heap_pops;
    m->copies = k->owner ? vrOwner_BodyCount(k->owner) : 0;
    m->records = k->owner ? vrOwner_PairCount(k->owner) : 0;
    m->noverlap = noverlap;
    m->a = a;
    m->b = b;
    m->error = (char *)(error ? error : "");
}

void vrWorker_SendEarliest(vrWorker *k, int64_t seq, int found, const vrEvent *ev,
                           int noverlap, int32_t *a, int32_t *b, const char *error)
{
    vroc_earliest_t m;
    vrWireStates ws;
    vrWorker_PutEarliest(k, seq, found, ev, noverlap, a, b, error, &m, &ws);
    if (VR_ENCODE(&k->reply, vroc_earliest_t, &m) == 0) vrWorker_Answer(k, VR_CH_EARLIEST, seq);
    vrWire_FreeStates(&ws);
}

void vrWorker_Beat(void *ctx)
{
    vrWorker *k = ctx;
    double now = vrLink_NowMs();
    vroc_hello_t m;
    vrBuf b = {NULL, 0, 0};
    if (now - k->last_hello < HELLO_MS) return;
    k->last_hello = now;
    m.nonce = k->nonce;
    m.pid = (int32_t)getpid();
    m.run = k->run;
    m.gp = k->gp;
    m.seq = k->last_seq;
    if (VR_ENCODE(&b, vroc_hello_t, &m) == 0) vrLink_Publish(k->link, VR_CH_HELLO, b.data, b.len);
    vrBuf_Free(&b);
}
