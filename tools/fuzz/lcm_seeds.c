/* lcm_seeds.c — writes fuzz_lcm's first corpus into DIR: one session a
 * worker would see (setup of two spheres and their deal, a frame, an
 * advance, a forwarded update that takes worker 0's answer, contacts,
 * shutdown) and one message of each of the SGP's kinds (an earliest with
 * the answer to its event), each well formed, so that the fuzzer starts from
 * messages that pass the nonce, run and sequence checks. */
#include <stdio.h>
#include <string.h>
#include "wire.h"
#include "vroc_advance_t.h"
#include "vroc_contacts_t.h"
#include "vroc_earliest_t.h"
#include "vroc_frame_start_t.h"
#include "vroc_hello_t.h"
#include "vroc_setup_t.h"
#include "vroc_shutdown_t.h"
#include "vroc_update_t.h"
#include "lcm_records.h"

#define RUN 5

static unsigned char out[1 << 16];
static int used;

/* appends one record: [kind][length, big-endian][the encoded message] */
#define PUT(kind, T, msg)                                                               \
    do {                                                                                \
        int n_ = T##_encode(out + used + 3, 0, (int)sizeof out - used - 3, (msg));      \
        if (n_ < 0) return -1;                                                          \
        out[used] = (unsigned char)(kind);                                              \
        out[used + 1] = (unsigned char)(n_ >> 8);                                       \
        out[used + 2] = (unsigned char)n_;                                              \
        used += 3 + n_;                                                                 \
    } while (0)

static int save(const char *dir, const char *name)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "wb");
    if (!f) return -1;
    if (fwrite(out, 1, (size_t)used, f) != (size_t)used) {
        fclose(f);
        return -1;
    }
    used = 0;
    return fclose(f) != 0 ? -1 : 0;
}

static void state_at(vroc_body_state_t *s, int id, double x)
{
    memset(s, 0, sizeof *s);
    s->id = id;
    s->x[0] = x;
    s->v[0] = id ? -1 : 1;
    s->q[0] = 1;
}

static int session(const char *dir)
{
    vrObjectDef def = vrObjectDef_Default(VR_SPHERE);
    vrParams par;
    vroc_body_def_t defs[2];
    vroc_body_state_t states[2];
    int32_t alive = 0, owed = 0;
    vroc_setup_t s;
    vroc_frame_start_t f;
    vroc_advance_t adv = {RUN, 3, 0.05, 0, 0};
    vroc_update_t u;
    vroc_contacts_t c;
    vroc_shutdown_t bye = {RUN, 6};
    memset(&par, 0, sizeof par);
    par.d = 0.25;
    par.flight.max_linear = 8;
    par.flight.max_angular = 4;
    par.use_heap = 1;
    memset(&s, 0, sizeof s);
    s.run = RUN, s.seq = 1, s.nonce = 1, s.gp = 0, s.ngps = 1, s.nbodies = 2, s.nalive = 1, s.per = 1, s.groups = 1, s.parts = 1;
    vrWire_PutParams(&s.params, &par);
    vrWire_PutDef(&defs[0], 0, &def, NULL);
    vrWire_PutDef(&defs[1], 1, &def, NULL);
    state_at(&states[0], 0, -2);
    state_at(&states[1], 1, 2);
    s.defs = defs, s.states = states, s.alive = &alive, s.block_gp = &owed, s.pending = &owed;
    PUT(REC_SETUP, vroc_setup_t, &s);
    memset(&f, 0, sizeof f);
    f.run = RUN, f.seq = 2, f.allow_instant = 1, f.states = states, f.owed = &owed;
    f.grid.T = 0.1, f.grid.h = 0.01, f.grid.n = 10, f.grid.frame_T = 0.1;
    PUT(REC_FRAME, vroc_frame_start_t, &f);
    PUT(REC_ADVANCE, vroc_advance_t, &adv);
    memset(&u, 0, sizeof u);
    u.run = RUN, u.seq = 4, u.t = 0.05, u.nstates = 2, u.states = states, u.grid = f.grid, u.taken = 0;
    PUT(REC_FORWARD, vroc_update_t, &u);
    memset(&c, 0, sizeof c);
    c.run = RUN, c.seq = 5, c.t = 0.06, c.h = 0.004, c.nstates = 2, c.states = states;
    PUT(REC_CONTACTS, vroc_contacts_t, &c);
    PUT(REC_SHUTDOWN, vroc_shutdown_t, &bye);
    if (save(dir, "session") != 0) return -1;
    PUT(REC_UPDATE, vroc_update_t, &u);
    return save(dir, "update");
}

static int sgp_kinds(const char *dir)
{
    vroc_body_state_t answer[2];
    vroc_hello_t h = {1, 42, RUN, 0, 1};
    vroc_earliest_t e;
    vroc_candidates_t c;
    int32_t a = 0, b = 1, np = 1, leaving = 0;
    double dist = 0.001, normal[3] = {1, 0, 0}, gap = 0.001, point[3] = {0, 0, 0};
    PUT(REC_HELLO, vroc_hello_t, &h);
    if (save(dir, "hello") != 0) return -1;
    memset(&e, 0, sizeof e);
    e.run = RUN, e.seq = 2, e.found = 1, e.t = 0.05, e.approach = -1.5, e.a = &a, e.b = &b, e.error = "";
    state_at(&answer[0], 0, -0.5);       /* the answer to its event, as a responder sends it */
    state_at(&answer[1], 1, 0.5);
    e.answered = 1, e.nstates = 2, e.states = answer, e.answer_solves = 1, e.busy_ms = 0.25;
    PUT(REC_EARLIEST, vroc_earliest_t, &e);
    if (save(dir, "earliest") != 0) return -1;
    memset(&c, 0, sizeof c);
    c.run = RUN, c.seq = 3, c.n = 1, c.a = &a, c.b = &b, c.npoints = &np, c.dist = &dist, c.leaving = &leaving;
    c.n3 = 3, c.normal = normal, c.npt = 1, c.gaps = &gap, c.npt3 = 3, c.points = point, c.error = "";
    PUT(REC_CANDIDATES, vroc_candidates_t, &c);
    return save(dir, "candidates");
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: lcm_seeds DIR\n");
        return 2;
    }
    if (session(argv[1]) != 0 || sgp_kinds(argv[1]) != 0) {
        fprintf(stderr, "lcm_seeds: cannot write the seeds into %s\n", argv[1]);
        return 1;
    }
    return 0;
}
