/* island_step.c — the island step (SPEC 7): at the start of each contact
 * step, the contacts of that instant are solved together.
 *
 * The owners report every pair touching at t (within twice the contact
 * gap g_c); the pairs join their moving bodies into islands (static bodies
 * join nothing: two boxes on one floor are two islands); each island's
 * impulses are found together by island.c with the step's gravity already
 * in the velocities, and its bodies fly the step without the global force
 * (semi-implicit Euler, which never gains energy with inelastic contact),
 * straight on to the next island step.  A point's gap may close to g_c
 * within the step and no further (its floor), so bodies come to rest g_c
 * apart, with no push-out and no event per internal step.  A resting body
 * touched by a moving one wakes, with its resting island, before the step
 * is solved, and joins its island with its own contacts.  Impacts that bounce
 * stay events of their own (SPEC 3.1): islands have restitution 0.
 *
 * Everything here is a function of the states at t and of the touching
 * pairs sorted by pair order, so serial and parallel runs, and heap on and
 * off, give the same bits.
 *   by_pair             the touching pairs' order
 *   Island, add_body    one island's bodies and contacts for the solve
 *                       (which touches make which island: island_group.c)
 *   island_body         a body as island.c needs it
 *   solve_one           an island solved, its bodies' new states
 *   leave_contact       bodies no longer touching fly under the force again
 *   wake_touched        resting islands a touch reaches, woken before the solve
 *   vrIsland_Step
 */
#include <stdlib.h>
#include <string.h>
#include "island_step.h"
#include "island.h"
#include "island_group.h"
#include "balance.h"
#include "config.h"
#include "ownerset.h"
#include "owners.h"
#include "contact_set.h"

/* Gauss-Seidel sweeps at most (island.c).  A settling pile's big islands
 * end at the cap whatever it is (they converge to ~1e-5 m/s in 64); warm
 * started, the next step goes on from where this one stopped, and 32 let
 * the pile of 100 rest as soon and gain less energy than the tests allow,
 * at two thirds of 64's cost */
#define SWEEPS 32
#define SWEEP_TOL 1e-8     /* m/s: a sweep that changes no impulse more than this ends them */
/* An island answered at an instant (an impact that cannot bounce, or an
 * instant taken back) is solved from no impulses, not warm started: 8
 * sweeps, as Box2D's velocity iterations.  What they leave coming in is
 * answered at the instant as any event, or taken up by the next step.
 * With 32, a landing pile of 300 (seeds 1-3) spent 29-39 % more time
 * before it rested, its instants' big islands most of it. */
#define INSTANT_SWEEPS 8

static int by_pair(const void *x, const void *y)
{
    const vrTouch *a = x, *b = y;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    return a->b < b->b ? -1 : a->b > b->b;
}

/* one island's solve (the world's isl_work): its bodies (object ids, in
 * id order; statics too), its contacts, and by body whether some
 * contact's impulse acts on it (pushed_bodies) */
typedef struct vrIslandWork Island;

/* body id's index in the island, added if new; slot (by id, -1 where
 * none) finds it without a search (an island of a thousand bodies) */
static int add_body(Island *is, int *slot, int id)
{
    if (slot[id] >= 0) return slot[id];
    if (is->n == is->cap) {
        int cap = is->cap ? 2 * is->cap : 16;
        int *ids = realloc(is->id, (size_t)cap * sizeof *ids);
        vrIslandBody *b = ids ? realloc(is->body, (size_t)cap * sizeof *b) : NULL;
        unsigned char *pushed = b ? realloc(is->pushed, (size_t)cap) : NULL;
        if (ids) is->id = ids;
        if (b) is->body = b;
        if (!pushed) return -1;
        is->pushed = pushed, is->cap = cap;
    }
    is->id[is->n] = id;
    return slot[id] = is->n++;
}

/* body id at t as island.c sees it: a moving one with the step's gravity
 * (vrBody_StepGravity) in its velocity */
static void island_body(vrWorld *w, int id, double t, vec3 accel, double h, vrIslandBody *out)
{
    vrBody *b = &w->table.obj[id]->body;
    vrPose pose;
    memset(out, 0, sizeof *out);
    vrBody_Pose(b, t, &pose);
    out->x = pose.p;
    out->dynamic = !vrBody_Immovable(b);
    out->inv_inertia = !out->dynamic ? mat33_zero() : vrBody_InvInertiaWorld(b, &pose);
    out->inv_mass = !out->dynamic ? 0 : b->inv_mass;
    if (b->is_static) return;
    vrBody_Velocity(b, t, &out->v);   /* a held body: the hand's motion, no force */
    if (out->dynamic) out->paid = vrBody_StepGravity(b, accel, h), out->v = vec3_add(out->v, out->paid);
    out->w = vrBody_Omega(b, &pose);
}

static int add_contact(Island *is, const vrTouch *k, int ia, int ib, double mu)
{
    vrIslandContact *c;
    int i;
    if (is->nc == is->ccap) {
        int cap = is->ccap ? 2 * is->ccap : 16;
        vrIslandContact *m = realloc(is->c, (size_t)cap * sizeof *m);
        if (!m) return -1;
        is->c = m, is->ccap = cap;
    }
    c = &is->c[is->nc++];
    memset(c, 0, sizeof *c);
    c->a = ia, c->b = ib, c->n = k->n, c->mu = mu, c->npoints = k->npoints;
    for (i = 0; i < k->npoints; i++) c->p[i] = k->point[i];
    return 0;
}

/* A point may close its gap to g_c within the step and no further (its
 * floor: a speculative contact).  One that comes in faster than v_rest
 * (u, before the step's gravity: what came in), and fast enough that the
 * step's flight (u + lift, the gravity paid in) would close its gap past
 * g_c, is an impact within the step: it bounces, with the pair's
 * restitution, as SPEC 3.1 bounces a free impact.  (Held to its floor
 * unless it came in faster than v_rest plus that floor, an elastic ball
 * dropped 4 mm was slowed to the floor's speed and stopped on its first
 * bounce.)  At an instant (h = 0)
 * every point of a touch (its region, within 2 g_c) that comes in is
 * held, as the pairwise answer and the owners' contact events see the
 * pair: held only within g_c, a box's edge 1.5 mm off the floor coming
 * down was answered again and again at the instant, up to 64 times (a
 * pile of 300 spent 20 s on its first second).  A pair the solve turned
 * back toward each other is held where it is: for the owners it is no
 * island's, and any approach is an event. */

static void set_floors(const vrWorld *w, const Island *is, const vrTouch *k, vrIslandContact *c, double gc, double h,
                       double v_rest)
{
    /* NOLINTBEGIN(clang-analyzer-core.NullDereference): solve_one's first loop added both bodies of
     * each touch its second gives here (the analyzer does not know that slot is -1 between islands) */
    const vrIslandBody *A = &is->body[c->a], *B = &is->body[c->b];
    double e = fmin(w->table.obj[k->a]->body.elasticity, w->table.obj[k->b]->body.elasticity);
    double lift = vec3_dot(c->n, vec3_sub(B->paid, A->paid));   /* the step's gravity in n.(v_b - v_a) */
    int i;
    c->e = e;
    for (i = 0; i < c->npoints; i++) {
        vec3 ua = vec3_add(A->v, vec3_cross(A->w, vec3_sub(c->p[i], A->x)));
        vec3 ub = vec3_add(B->v, vec3_cross(B->w, vec3_sub(c->p[i], B->x)));
        double u = vec3_dot(c->n, vec3_sub(ub, ua)) - lift;
        double allow = k->leaving < 0 || h == 0 ? 0 : vr_max(0, k->gap[i] - gc) / h;
        c->floor[i] = u < -v_rest && u + lift < -allow ? -e * u : -allow;
    }
    /* NOLINTEND(clang-analyzer-core.NullDereference) */
}

/* Which bodies the step's impulses act on.  One they do not act on (a
 * ball coming down through the last 2 mm above the floor, or leaving it)
 * is in no island this step: it flies free from t, under the force, as it
 * flew, instead of straight at the velocity with the step's gravity paid
 * in.  Its free flight is exact, where the paid one (semi-implicit Euler)
 * loses m |g h|^2 / 2 a step: an elastic ball bouncing 4 mm high lost 1.5
 * % a bounce.  Without a force the two flights are one, and such a body
 * stays in its island (two bodies touching at rest in zero g). */
static void pushed_bodies(Island *is)
{
    if (is->pushed) vrIsland_Pushed(is->c, is->nc, is->pushed, is->n);   /* NULL: no body added yet, no contact */
}

/* the island of root r: its contacts (the touches of run), solved; its
 * moving bodies' states into up (none of them is in it yet) */
static int solve_one(vrWorld *w, Island *is, const vrRooted *run, int len, int r, double t, double h, vrUpdate *up)
{
    int instant = h == 0;
    vrParams p = vrSettings_Params(&w->s);
    vec3 gh = vec3_scale(p.flight.accel, h);
    double gc = vrParams_Gap(&p), v_rest = vrParams_RestSpeed(&p);
    int i, k, nc;
    is->n = is->nc = 0;
    for (k = 0; k < len; k++) {
        const vrTouch *c = &w->touches.t[run[k].k];
        double mu = sqrt(w->table.obj[c->a]->body.friction * w->table.obj[c->b]->body.friction);
        int ia = add_body(is, w->isl_slot, c->a), ib = ia < 0 ? -1 : add_body(is, w->isl_slot, c->b);
        if (ib < 0 || add_contact(is, c, ia, ib, mu) != 0) break;
    }
    for (i = 0; i < is->n; i++) w->isl_slot[is->id[i]] = -1;   /* as it was: -1 everywhere */
    if (k < len) return -1;
    for (i = 0; i < is->n; i++) island_body(w, is->id[i], t, p.flight.accel, h, &is->body[i]);
    for (k = 0, nc = 0; k < len; k++) {
        const vrTouch *c = &w->touches.t[run[k].k];
        set_floors(w, is, c, &is->c[nc], gc, h, v_rest);
        if (!instant && w->warm.structure == w->structure) vrWarm_Start(&w->warm, c->a, c->b, h, gc, &is->c[nc]);
        nc++;
    }
    if (vrIsland_SolveStep(is->body, is->n, is->c, is->nc, instant ? INSTANT_SWEEPS : SWEEPS, SWEEP_TOL, NULL,
                           &w->solve_scratch) != 0)
        return -1;
    if (instant) w->collisions += is->nc;      /* contacts answered (SPEC 7) */
    else w->island_steps++, w->island_contacts += is->nc;
    for (k = 0; k < is->nc && !instant; k++)
        if (vrWarm_Keep(&w->warm_next, is->id[is->c[k].a], is->id[is->c[k].b], h, &is->c[k]) != 0) return -1;
    pushed_bodies(is);
    for (i = 0; i < is->n; i++) {
        vrBody *b = &w->table.obj[is->id[i]]->body;
        vrBodyState *st;
        vrPose pose;
        mat33 inertia;
        int jolted;
        if (vrBody_Immovable(b)) continue;
        if (!(st = vrUpdate_Append(up, b, t))) return -1;
        if (!instant && !is->pushed[i] && vec3_len2(gh) > 0) {   /* free: as it flew, under the force */
            st->resting = 0, st->contact = 0, st->island = -1;
            continue;
        }
        pose = vrPose_make(st->x, st->q);
        inertia = vrBody_InertiaWorld(b, &pose);
        jolted = instant && vrBody_Jolted(vec3_sub(is->body[i].v, st->v),
                                          vec3_sub(is->body[i].w, mat33_mulv(&is->body[i].inv_inertia, st->L)), b->r_out, v_rest);
        st->v = is->body[i].v;
        st->L = mat33_mulv(&inertia, is->body[i].w);
        if (jolted) vrBodyState_Jolt(st, p.flight.accel);   /* an answer to a response: flight as it was, or free */
        st->resting = 0;
        if (instant) continue;
        st->contact = 1;
        st->island = r;
    }
    return 0;
}

/* a body that flew the last step in contact and touches nothing now
 * flies under the force again from t (its gravity was paid up to t); the
 * contact set holds every body in contact, in id order */
static int leave_contact(vrWorld *w, const int *in_island, double t, vrUpdate *up)
{
    int k;
    for (k = 0; k < w->ncontact_ids; k++) {
        int i = w->contact_ids[k];
        vrObject *o = w->table.obj[i];
        vrBodyState *st;
        if (!o || !o->live || !o->body.contact || o->body.resting || in_island[i]) continue;
        if (!(st = vrUpdate_Append(up, &o->body, t))) return -1;   /* in no island: not in up */
        st->contact = 0;
        st->island = -1;
    }
    return 0;
}

static int step(vrWorld *w, int *parent, int *in_island, double t, double h, vrUpdate *up)
{
    int i, len, m, rc = 0, n = vrIsland_Union(w, parent, in_island, w->isl_ids);
    vrRooted *g = vrIsland_Group(w, parent, &m);
    const vrRooted *run;
    if (!g) return -1;
    for (i = 0; i < n && rc == 0; i++)
        if (vrIsland_Root(parent, w->isl_ids[i]) == w->isl_ids[i]) {
            run = vrIsland_Run(g, m, w->isl_ids[i], &len);
            rc = solve_one(w, &w->isl_work, run, len, w->isl_ids[i], t, h, up);
        }
    if (rc == 0) rc = leave_contact(w, in_island, t, up);
    free(g);
    return rc;
}

/* the touching pairs at t, sorted by pair (h = 0: an instant's, of the
 * pair (a, b): those of its islands at least) */
static int gather(vrWorld *w, double t, double h, int a, int b, char *err, size_t n)
{
    int r;
    w->touches.n = 0;
    r = vrOwners_Of(w)->touching(w, t, h, a, b, &w->touches, err, n);
    if (r == 0 && w->touches.n > 1) qsort(w->touches.t, (size_t)w->touches.n, sizeof *w->touches.t, by_pair);
    return r;
}

/* the islands of a and b at an instant, solved */
static int instant(vrWorld *w, int *parent, int *in_island, double t, int a, int b, vrUpdate *up)
{
    Island *is = &w->isl_work;
    int ra, rb, m, len, rc = 0;
    vrRooted *g;
    const vrRooted *run;
    vrIsland_Union(w, parent, in_island, NULL);   /* the pair (a, b) is one of the touches */
    if (!(g = vrIsland_Group(w, parent, &m))) return -1;
    ra = a >= 0 && vrIsland_Moves(w, a) ? vrIsland_Root(parent, a) : -1;   /* a, b < 0: no pair (clang-tidy) */
    rb = b >= 0 && vrIsland_Moves(w, b) ? vrIsland_Root(parent, b) : -1;
    if (ra >= 0) run = vrIsland_Run(g, m, ra, &len), rc = solve_one(w, is, run, len, ra, t, 0, up);
    if (rc == 0 && rb >= 0 && rb != ra) run = vrIsland_Run(g, m, rb, &len), rc = solve_one(w, is, run, len, rb, t, 0, up);
    free(g);
    return rc;
}

/* body id's velocities at t after the solve: its state in up (slot[id]
 * >= 0), else as it flies */
static void velocities_after(vrWorld *w, const vrUpdate *up, const int *slot, int id, double t, vec3 *x, vec3 *v,
                             vec3 *om)
{
    vrBody *b = &w->table.obj[id]->body;
    vrPose pose;
    mat33 iw;
    if (b->is_static) {
        *x = *v = *om = vec3_zero();
        return;
    }
    if (slot[id] < 0) {
        vrBody_Pose(b, t, &pose);
        vrBody_Velocity(b, t, v);
        *x = pose.p, *om = vrBody_Omega(b, &pose);
        return;
    }
    pose = vrPose_make(up->body[slot[id]].x, up->body[slot[id]].q);
    iw = vrBody_InvInertiaWorld(b, &pose);
    *x = pose.p, *v = up->body[slot[id]].v, *om = mat33_mulv(&iw, up->body[slot[id]].L);
}

/* A pair that was leaving may come back when the solve pushes one of its
 * bodies (a ball pressed off a box into its neighbour): such touches are
 * marked turned back (-1), and the step is solved again with them, so
 * that no contact impulse follows it at its instant.  The number turned
 * back; -1 when out of memory. */
static int turned_back(vrWorld *w, const vrUpdate *up, double t)
{
    int *slot = w->isl_slot, i, k, count = 0;
    for (i = 0; i < up->n; i++) slot[up->body[i].id] = i;
    for (k = 0; k < w->touches.n; k++) {
        vrTouch *c = &w->touches.t[k];
        vec3 xa, va, wa, xb, vb, wb;
        if (c->leaving <= 0 || (slot[c->a] < 0 && slot[c->b] < 0)) continue;
        velocities_after(w, up, slot, c->a, t, &xa, &va, &wa);
        velocities_after(w, up, slot, c->b, t, &xb, &vb, &wb);
        for (i = 0; i < c->npoints; i++) {
            vec3 ua = vec3_add(va, vec3_cross(wa, vec3_sub(c->point[i], xa)));
            vec3 ub = vec3_add(vb, vec3_cross(wb, vec3_sub(c->point[i], xb)));
            if (vec3_dot(c->n, vec3_sub(ub, ua)) < -VR_V_EPS) break;
        }
        if (i < c->npoints) c->leaving = -1, count++;
    }
    for (i = 0; i < up->n; i++) slot[up->body[i].id] = -1;   /* as it was: -1 everywhere */
    return count;
}

#define TURN_BACK_ROUNDS 4   /* solves again at most (then the events answer what is left) */

/* the step (h > 0) or the instant of a and b (h = 0), solved again while
 * its solve turns leaving pairs back; the counts kept are the last solve's */
static int solve_all(vrWorld *w, double t, double h, int a, int b, char *err, size_t n)
{
    int round, r = -1, ready = vrIslandScratch_Reserve(w) == 0 && vrContactSet_Prune(w) == 0;
    int *parent = w->isl_parent, *in_island = w->isl_in;
    long long collisions = w->collisions, steps = w->island_steps, contacts = w->island_contacts;
    for (round = 0; ready && round <= TURN_BACK_ROUNDS; round++) {
        w->collisions = collisions, w->island_steps = steps, w->island_contacts = contacts;
        w->update.n = 0;
        w->warm_next.n = 0;
        r = h > 0 ? step(w, parent, in_island, t, h, &w->update) : instant(w, parent, in_island, t, a, b, &w->update);
        if (r != 0 || round == TURN_BACK_ROUNDS || (r = turned_back(w, &w->update, t)) <= 0) break;
        r = 0;
    }
    if (r != 0 || vrWorld_ApplyUpdate(w, &w->update) != 0) return vrGeom_Fail(err, n, "out of memory or a bad island");
    if (h > 0) {              /* the step's impulses start the next one's solve */
        vrWarm keep = w->warm;
        w->warm = w->warm_next, w->warm_next = keep;
        vrWarm_Sort(&w->warm);
        w->warm.structure = w->structure;
    }
    return 0;
}

/* 1 when the touches hold the pair (a, b), coming together */
static int touches_pair(const vrWorld *w, int a, int b)
{
    vrTouch key;
    const vrTouch *k;
    key.a = a < b ? a : b, key.b = a < b ? b : a;
    /* cppcheck-suppress uninitvar ; by_pair reads a and b only */
    k = w->touches.n ? bsearch(&key, w->touches.t, (size_t)w->touches.n, sizeof key, by_pair) : NULL;
    return k && k->leaving <= 0;
}

int vrIsland_Instant(vrWorld *w, double t, int a, int b, char *err, size_t n)
{
    int r = gather(w, t, 0, a, b, err, n);
    if (r != 0) return r;
    return touches_pair(w, a, b) ? solve_all(w, t, 0, a, b, err, n) : 1;
}

/* Islands wake as one, before they are solved (SPEC 7): a resting body in
 * a touch that is not leaving (its other body moves or is held: two frozen
 * bodies' pairs are not scheduled) wakes with its whole resting island
 * (vrWorld_ApplyUpdate), so that the touches gathered again hold its own
 * contacts, with static bodies and the rest of its island, unscheduled
 * while it rested.  Woken only after the solve, such a body took the
 * step's gravity with nothing under it, and its corners met the floor one
 * impulse at a time, which turned that gravity into spin (pile seed 7
 * gained 4.7e-5 J at frame 505).  1 when some body woke, 0, -1 (memory). */
static int wake_touched(vrWorld *w, double t)
{
    int k, e, woke = 0;
    w->update.n = 0;
    for (k = 0; k < w->touches.n; k++) {
        const vrTouch *c = &w->touches.t[k];
        int x[2];
        if (c->leaving > 0) continue;
        x[0] = c->a, x[1] = c->b;
        for (e = 0; e < 2; e++) {
            vrBody *b = &w->table.obj[x[e]]->body;
            vrBodyState *st;
            if (!b->resting) continue;
            if (!(st = vrUpdate_Body(&w->update, b, t))) return -1;
            st->resting = 0;
            woke = 1;
        }
    }
    return woke && vrWorld_ApplyUpdate(w, &w->update) != 0 ? -1 : woke;
}

int vrIsland_Step(vrWorld *w, double t, double h, char *err, size_t n)
{
    int r;
    for (;;) {      /* each round wakes a resting island at least: it ends */
        if ((r = gather(w, t, h, -1, -1, err, n)) != 0) return r;
        if ((r = wake_touched(w, t)) < 0) return vrGeom_Fail(err, n, "out of memory");
        if (r == 0) break;
    }
    if (vrIslandScratch_Reserve(w) != 0 || vrBalance_Mark(w, t) != 0) return vrGeom_Fail(err, n, "out of memory");
    return solve_all(w, t, h, -1, -1, err, n);
}
