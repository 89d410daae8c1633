/* sgp.c — the Synchronization GP (thesis 3.5.2): the shell process as the
 * coordinator of its workers (SPEC 5), an owner set (ownerset.h).
 *
 * It holds every object (it renders and dumps them) and never queries a
 * pair itself.  Per frame, the thesis's protocol with the answer folded
 * into the look-ahead: frame_start to all, each worker's earliest, which
 * carries the worker's answer to its own event (the states it makes);
 * while there is an event, the first of all's answer is taken from its
 * earliest and forwarded to all with the next span's grid, and the
 * earliest comes again.  Rounds per frame = 1 + events (+ the island
 * steps' rounds); the thesis's advance round, where the responder
 * answered, is left for a responder whose earliest carried no answer.
 * Each round is an exchange (exchange.c): resent until answered.  A worker
 * declared dead sends the frame back to its start with the dead worker's
 * pairs dealt to the survivors (setup.c) — a pair's state at a frame start
 * is a pure function of the poses there (vrOwner_AddPairAt), so the result
 * does not change.
 *
 *   recover / snapshot   the frame start kept, and the frame redone from it
 *   encode_frame_start   the span's first request; encode_forward the others
 *   put_owed             an island step answered without a round, told with the next request
 *   earliest_of_all      the first event of all, by (time, pair order)
 *   same_grid            the look-ahead an island step's round carried is the one asked for
 *   taken_answer         the responder's answer from its earliest
 *   sgp_*                the owner set's operations; sgp_end_frame also
 *                        publishes the frame's sounds on VROC_SOUND (SPEC 8)
 */
#include <stdlib.h>
#include <string.h>
#include "exchange.h"
#include "setup.h"
#include "sgp.h"
#include "spawn.h"
#include "wire.h"
#include "contact_set.h"
#include "rest.h"
#include "sound_lcm.h"
#include "vroc_advance_t.h"
#include "vroc_contacts_t.h"
#include "vroc_frame_start_t.h"
#include "vroc_update_t.h"

/* a worker died: back to the frame start, its pairs dealt to the others */
static int recover(vrWorld *w, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    vrFlight f = vrSettings_Flight(&w->s);
    int i;
    for (i = 0; i < s->snap.n; i++) {
        vrRest_KeepFramePose(w, w->table.obj[s->snap.body[i].id]);
        vrBody_Apply(&w->table.obj[s->snap.body[i].id]->body, &s->snap.body[i], &f);
    }
    vrContactSet_Lost(w);
    /* the island steps start warm from where the frame started, as the
     * serial run's did (the frame's own steps had moved it on: a redone
     * frame parted from serial in its last bits, edit fuzzer seed 482);
     * no memory: of no structure, the redo starts cold */
    vrWarm_Copy(&w->warm, &s->snap_warm);
    w->collisions = s->snap_collisions;
    w->island_steps = s->snap_island_steps;
    w->island_contacts = s->snap_island_contacts;
    w->clamps = s->snap_clamps;
    for (i = 0; i < s->n; i++) {   /* the frame is redone: what it counted is counted again */
        s->gp[i].before = s->snap_counts[i];
        memset(&s->gp[i].now, 0, sizeof s->gp[i].now);
    }
    w->pending.n = 0;
    s->taken = -1;
    s->owed_h = 0;
    s->ahead = 0;
    if (vrUpdate_AppendStates(&w->pending, &s->snap_pending) != 0) return snprintf(err, n, "out of memory"), -1;
    s->snap_pending.n = 0;
    if (vrSgp_Setup(w, s, err, n) != 0) return -1;
    return VR_RESTART_FRAME;
}

static void snapshot(vrWorld *w, vrSgp *s)
{
    int i;
    s->snap.n = 0;
    for (i = 0; i < w->table.n; i++)
        if (w->table.obj[i] && w->table.obj[i]->live) vrSgp_AddAnchor(&s->snap, &w->table.obj[i]->body);
    s->snap_collisions = w->collisions;
    s->snap_island_steps = w->island_steps;
    s->snap_island_contacts = w->island_contacts;
    s->snap_clamps = w->clamps;
    vrWarm_Copy(&s->snap_warm, &w->warm);   /* no memory: structure -1, a redo starts cold */
    for (i = 0; i < s->n; i++) s->snap_counts[i] = vrSgp_Counts(s, i);
}

/* the island step answered without a round goes with the next request */
static void put_owed(vrSgp *s, double *t, double *h)
{
    *t = s->owed_t;
    *h = s->owed_h;
    s->owed_h = 0;
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
    put_owed(s, &m.island_t, &m.island_h);
    if (r == 0) r = VR_ENCODE(&s->req, vroc_frame_start_t, &m);
    free(m.owed);
    vrWire_FreeStates(&ws);
    s->req_channel = VR_CH_FRAME;
    s->taken = -1;
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
    m.taken = s->taken;
    put_owed(s, &m.island_t, &m.island_h);
    if (r == 0) r = VR_ENCODE(&s->req, vroc_update_t, &m);
    vrWire_FreeStates(&ws);
    s->req_channel = VR_CH_FORWARD;
    s->taken = -1;
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
    ev->approach = s->gp[best].approach;   /* the sound's (loop.c): the rest stays the responder's */
    ev->c = s->gp[best].point;
    ev->a = (int)(ev->order >> 32);
    ev->b = (int)(ev->order & 0xffffffff);
    return 1;
}

/* every worker's look-ahead found nothing, and an island step at its end
 * would find nothing either */
static int all_quiet(const vrSgp *s)
{
    int i, k = 0;
    for (i = 0; i < s->n; i++) {
        if (s->gp[i].alive && !s->gp[i].quiet) return 0;
        k += s->gp[i].alive;
    }
    return k > 0;
}

/* the grid a look-ahead was made on is g, to the bit */
static int same_grid(const vrGrid *g, const vrGrid *h)
{
    return g->t0 == h->t0 && g->T == h->T && g->h == h->h && g->n == h->n && g->frame_T == h->frame_T
           && g->a == h->a && g->k0 == h->k0;
}

static int sgp_first_event(vrWorld *w, const vrGrid *g, int allow, vrEvent *ev, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    int r;
    if (s->sound_failed) {
        s->sound_failed = 0;
        return snprintf(err, n, "cannot publish the sound events on VROC_SOUND at %s", s->url), -1;
    }
    if (s->ahead && w->pending.n == 0 && allow == s->ahead_allow && same_grid(g, &s->ahead_g)) {
        s->ahead = 0;            /* the island step's round looked ahead already: no round */
        s->quiet = all_quiet(s);
        s->quiet_t = g->T;
        return earliest_of_all(s, ev);
    }
    s->ahead = 0;
    s->seq++;
    s->error[0] = 0;
    if (!s->frame_open || s->frame_fresh) {
        if (!s->frame_open) snapshot(w, s);
        r = encode_frame_start(w, s, g, allow, 0, NULL, 0);
        if (r == 0) r = vrSgp_Delivered(w, s);
        s->frame_open = 1;
        s->frame_fresh = 0;
    } else {
        r = encode_forward(w, s, g, allow);
        w->pending.n = 0;
    }
    if (r != 0) return snprintf(err, n, "out of memory"), -1;
    if (vrSgp_Exchange(s, WAIT_EARLIEST, -1)) return recover(w, err, n);
    if (s->error[0]) return snprintf(err, n, "%s", s->error), -1;
    s->quiet = all_quiet(s);
    s->quiet_t = g->T;
    return earliest_of_all(s, ev);
}

/* The responder's answer to ev from its earliest, if it sent one: its
 * KLU counts join its statistics (the worker counts it from the next
 * forward on, which says it was taken). */
static int taken_answer(vrSgp *s, const vrEvent *ev, vrUpdate *up)
{
    vrGpInfo *g = &s->gp[s->responder];
    if (!g->answered || g->order != ev->order || g->t != ev->t) return 0;
    g->now.solves += g->answer_cost.solves;
    g->now.refactors += g->answer_cost.refactors;
    g->now.factors += g->answer_cost.factors;
    g->answered = 0;
    s->taken = s->responder;
    return vrUpdate_AppendStates(up, &g->answer) == 0 ? 1 : -1;
}

static int sgp_respond(vrWorld *w, const vrEvent *ev, vrUpdate *up, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    vroc_advance_t m;
    int r;
    up->n = 0;
    s->taken = -1;
    s->ahead = 0;
    if ((r = taken_answer(s, ev, up)) != 0) return r > 0 ? 0 : (snprintf(err, n, "out of memory"), -1);
    m.run = s->run;
    m.seq = ++s->seq;
    m.t = ev->t;
    m.responder = s->responder;
    m.order = ev->order;
    if (VR_ENCODE(&s->req, vroc_advance_t, &m) != 0) return snprintf(err, n, "out of memory"), -1;
    s->req_channel = VR_CH_ADVANCE;
    if (vrSgp_Exchange(s, WAIT_UPDATE, s->responder)) return recover(w, err, n);
    return vrUpdate_AppendStates(up, &s->reply) == 0 ? 0 : (snprintf(err, n, "out of memory"), -1);
}

/* SPEC 8: workers on a network URL publish the frame's sounds on it
 * (memq:// is this process's own: nobody could listen).  end_frame cannot
 * fail, so a refusal fails the next frame. */
static void sgp_end_frame(vrWorld *w, double T)
{
    vrSgp *s = w->sgp;
    (void)T;
    s->frame_open = s->frame_fresh = s->ahead = 0;
    s->snap_pending.n = 0;
    if (strncmp(s->url, "memq://", 7) != 0
        && vrSounds_Publish(s->link.out, w->sounds.ev, w->sounds.n, vrSounds_Name(&w->s)) != 0)
        s->sound_failed = 1;
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
    s->ahead = 0;
    g.t0 = g.T = g.frame_T = g.a = w->t;
    g.h = 0;
    g.n = g.k0 = 0;
    for (;;) {
        s->seq++;
        s->error[0] = 0;
        s->noverlap = 0;
        if (encode_frame_start(w, s, &g, 1, 1, ids, nids) != 0) return snprintf(err, n, "out of memory"), -1;
        if (!vrSgp_Exchange(s, WAIT_EARLIEST, -1)) break;
        if (vrSgp_Setup(w, s, err, n) != 0) return -1;   /* a worker died: deal again and ask again */
    }
    if (vrSgp_Delivered(w, s) != 0) return snprintf(err, n, "out of memory"), -1;
    if (s->error[0]) return snprintf(err, n, "%s", s->error), -1;
    qsort(s->overlap, (size_t)s->noverlap, sizeof s->overlap[0], cmp_pair);
    for (i = 0; i < s->noverlap && i < max; i++) {
        out[i][0] = s->overlap[i][0];
        out[i][1] = s->overlap[i][1];
    }
    return s->noverlap;
}

/* The look-ahead the contact step will start with if its island step
 * changes nothing (loop.c), asked for with the island step: its first
 * round is then saved.  A worker does the look-ahead right after the
 * step's touches, as it would at the next request (whose clock move to
 * the step's start undoes nothing then); when the step changed bodies or
 * the grid, the next request goes as before and the looks the changes
 * did not touch stand (keep_looks) or are made again.  Not in a frame's
 * first round, which the frame start must follow. */
static void ask_ahead(const vrWorld *w, vrSgp *s, double h, vroc_contacts_t *m)
{
    s->ahead = 0;
    if (!w->ahead.valid || !(h > 0) || s->frame_fresh) return;
    m->ahead = 1;
    vrWire_PutGrid(&m->grid, &w->ahead.g);
    m->allow_instant = (int8_t)w->ahead.allow;
    s->ahead_g = w->ahead.g;
    s->ahead_allow = w->ahead.allow;
}

/* every worker alive answered the island step with its look-ahead */
static int all_ahead(const vrSgp *s)
{
    int i, k = 0;
    for (i = 0; i < s->n; i++) {
        if (s->gp[i].alive && !s->gp[i].ahead) return 0;
        k += s->gp[i].alive;
    }
    return k > 0;
}

/* An island step: ask every worker for the pairs that touch (a round at
 * each island step; the states they need went with the last round).  When
 * the last round was the look-ahead that ended here, every worker said
 * an island step would find nothing of its (quiet) and no state changed
 * since, the answer is known: none, and the workers do the step with the
 * next request (owed). */
static int sgp_touching(vrWorld *w, double t, double h, int a, int b, vrTouches *out, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    vroc_contacts_t m;
    vrWireStates ws;
    int i, r;
    (void)a, (void)b;                    /* every worker's touches: the islands are found from them */
    if (!s->frame_open) {      /* the frame's first round: a restart redoes it from here */
        snapshot(w, s);
        s->frame_open = s->frame_fresh = 1;
    }
    if (h > 0 && s->quiet && s->quiet_t == t && w->pending.n == 0 && !(s->owed_h > 0)) {
        s->owed_t = t;
        s->owed_h = h;
        s->quiet = 0;
        return 0;
    }
    memset(&m, 0, sizeof m);
    memset(&ws, 0, sizeof ws);
    r = vrWire_PutStates(&ws, &w->pending);
    m.run = s->run;
    m.seq = ++s->seq;
    m.t = t;
    m.h = h;
    ask_ahead(w, s, h, &m);
    m.nstates = ws.n;
    m.states = ws.m;
    put_owed(s, &m.island_t, &m.island_h);
    s->error[0] = 0;
    s->touches.n = 0;
    if (r == 0) r = VR_ENCODE(&s->req, vroc_contacts_t, &m);
    vrWire_FreeStates(&ws);
    s->taken = -1;
    if (r == 0) r = vrSgp_Delivered(w, s);
    if (r != 0) return snprintf(err, n, "out of memory"), -1;
    s->req_channel = VR_CH_CONTACTS;
    if (vrSgp_Exchange(s, WAIT_CANDIDATES, -1)) return recover(w, err, n);
    if (s->error[0]) return snprintf(err, n, "%s", s->error), -1;
    s->ahead = m.ahead && all_ahead(s);
    for (i = 0; i < s->touches.n; i++) {
        vrTouch *c = vrTouches_Add(out);
        if (!c) return snprintf(err, n, "out of memory"), -1;
        *c = s->touches.t[i];
    }
    return 0;
}

const vrOwnerSet vrSgp_Owners = {sgp_first_event, sgp_respond, sgp_end_frame, sgp_overlapping, sgp_touching};


void vrSgp_Stats(const vrSgp *s, vrStats *st)
{
    int i;
    st->gps = s->n;
    st->messages = s->requests + s->received;
    st->foreign = s->foreign;
    st->malformed = s->malformed;
    for (i = 0; i < ROUND_KINDS; i++) st->rounds[i] = s->rounds[i];
    st->wait_ms = s->wait_ms;
    for (i = 0; i < s->n && i < 64; i++) {
        const vrGpInfo *g = &s->gp[i];
        vrGpCounts c = vrSgp_Counts(s, i);
        st->gp_checks[i] = c.checks;
        st->gp_copies[i] = g->alive ? g->copies : 0;
        st->gp_pairs[i] = g->alive ? g->pairs : 0;
        st->gp_busy_ms += g->busy_ms;
        st->checks += c.checks;
        st->heap_pops += c.heap_pops;
        st->klu_solves += c.solves;
        st->klu_refactors += c.refactors;
        st->klu_factors += c.factors;
        if (g->alive) st->copies += g->copies, st->live_pairs += g->records;
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

int vrSgp_Sync(vrWorld *w, char *err, size_t n)
{
    vrSgp *s = w->sgp;
    if (s && (s->n != w->s.gps || strcmp(s->url, w->s.lcm_url) != 0)) {
        vrSgp_Retire(w);                 /* its counts stay in the stats */
        s = NULL;
    }
    if (!s) {
        w->sgp = s = vrSgp_Open(&w->s, err, n);
        if (!s) return -1;
        s->taken = -1;
    }
    s->max_id = w->table.n;
    return s->structure == w->structure ? 0 : vrSgp_Setup(w, s, err, n);
}
