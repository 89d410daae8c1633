/* island.c — an island's impulses, found together (island.h; SPEC 7):
 * Gauss-Seidel sweeps over its contacts (island_contact.c takes one), the
 * ground-up pass, and the energy check.
 *   sweep, residual        every contact once, in order; what they leave
 *   levels, shock_pass     the ground-up pass with lower bodies held still
 *   stalled                a try's sweeps judged not to reach tol by the cap
 *   reserve_*, solve       a try's state (the caller's scratch, island.h); a try
 *   elastic_bounce, elastic_retry   an elastic island's Newton bounce that lost, as Poisson's
 *   solve_tries            the tries the energy check (island_energy.c) asks for, and a step's
 *                          sweeping on
 *   solve_with, vrIsland_Solve, vrIsland_SolveStep, vrIslandScratch_Free
 *   vrIsland_Pushed        the bodies a solve's impulses act on
 */
#include <stdlib.h>
#include <string.h>
#include "island_contact.h"
#include "island_energy.h"
#include "grow.h"

static double sweep(vrIslandSolve *s)
{
    double most = 0;
    int ci;
    for (ci = 0; ci < s->ncontact; ci++) most = vr_max(most, vrSolve_ContactStep(s, ci));
    return most;
}

/* what the sweeps leave: the normal velocities below their floors */
static double residual(vrIslandSolve *s)
{
    double worst = 0;
    int ci, i;
    for (ci = 0; ci < s->ncontact; ci++) {
        const vrIslandContact *c = &s->c[ci];
        for (i = 0; i < c->npoints; i++) {
            if (vrSolve_Point(s, ci, i)->kn > 0) worst = vr_max(worst, c->floor[i] - vrSolve_NormalVelocity(s, ci, i));
        }
    }
    return worst;
}

/* breadth first from the static bodies: a body's level is the fewest
 * contacts between it and one (-1: it touches none, even through others);
 * returns 1 when some body is static */
static int levels(vrIslandBody *b, int nb, const vrIslandContact *c, int nc)
{
    int i, k, changed = 1, any = 0;
    for (i = 0; i < nb; i++) {
        b[i].level = b[i].dynamic ? -1 : 0;
        any |= !b[i].dynamic;
    }
    for (k = 0; changed && any; k++) {
        changed = 0;
        for (i = 0; i < nc; i++) {
            vrIslandBody *A = &b[c[i].a], *B = &b[c[i].b];
            if (A->level == k && B->level < 0) B->level = k + 1, changed = 1;
            if (B->level == k && A->level < 0) A->level = k + 1, changed = 1;
        }
    }
    return any;
}

/* the level a contact's pass belongs to: its higher body's (the one it
 * settles), -1 when a body of it touches no static body */
static int pass_level(const vrIslandBody *b, const vrIslandContact *c)
{
    int la = b[c->a].level, lb = b[c->b].level;
    return la < 0 || lb < 0 ? -1 : la > lb ? la : lb;
}


/* From the ground up: level by level, the contacts that settle the bodies
 * of that level (against the bodies under them, held still, and among
 * themselves), swept until they settle, so that a body is settled against
 * what lies under it before anything above is settled against it, and is
 * not moved again by what lies above. */
static void shock_pass(vrIslandSolve *s, int sweeps, double tol)
{
    int *at = s->pass, ci, level, top = -1, k;
    for (ci = 0; ci < s->ncontact; ci++) at[ci] = pass_level(s->body, &s->c[ci]), top = top > at[ci] ? top : at[ci];
    for (level = 1; level <= top; level++) {
        for (ci = 0; ci < s->ncontact; ci++)
            if (at[ci] == level) vrSolve_Hold(s, ci, s->body[s->c[ci].a].level < level, s->body[s->c[ci].b].level < level);
        for (k = 0; k < sweeps; k++) {
            double most = 0;
            for (ci = 0; ci < s->ncontact; ci++)
                if (at[ci] == level) most = vr_max(most, vrSolve_ContactStep(s, ci));
            if (most <= tol) break;
        }
    }
    /* The rows are left as held: nothing sweeps after this pass, and the
     * residual reads only their directions (the same held or not) and
     * whether a point's kn is positive (it is, held or not: a contact of
     * a level has a body of that level, free).  Making them again for
     * nothing cost a pile 2 % of its instructions. */
}

/* Sweeps that will not reach tol by the cap: from sweep STALL_FIRST on,
 * the change, falling as fast as over the last STALL_SPAN sweeps, would
 * still be above tol at the cap's last sweep (or it did not fall).  A
 * settling pile's big islands sit at ~1e-5 m/s from sweep to sweep up to
 * the cap, and those sweeps were half of its solve's contact steps.
 * change[] is a ring of the last STALL_SPAN sweeps' changes. */
#define STALL_SPAN 4
#define STALL_FIRST 8

static int stalled(double *change, int k, double most, int sweeps, double tol)
{
    double was = change[k % STALL_SPAN];
    change[k % STALL_SPAN] = most;
    if (k < STALL_FIRST || !(was > 0)) return 0;
    if (most >= was) return 1;
    return most * pow(most / was, (double)(sweeps - 1 - k) / STALL_SPAN) > tol;
}

/* what an early stop may leave after the ground-up pass: more, and the
 * sweeps go on to the cap (a cube on a steep edge of the cube under it
 * sank into it 1.5 um a step at 3.5e-4 m/s, pushed out every 0.25 s into
 * the floor, whose push-out lifted the lower one unpaid, pile seed 8) */
#define STALL_LEFT 1e-6

/* levels() once a solve, when first asked (*known -1 until then) */
static int on_ground(int *known, vrIslandBody *b, int nb, const vrIslandContact *c, int nc)
{
    if (*known < 0) *known = levels(b, nb, c, nc);
    return *known;
}

/* sweeps from k on to the cap, until one changes no impulse by more than
 * tol, or (stall) until they stall on a grounded island; the sweep they
 * stopped after, plus one (the cap when they ran to it) */
static int sweep_on(vrIslandSolve *s, int nbody, int k, int sweeps, double tol, int stall, double *change,
                    int *grounded, vrIslandStats *st)
{
    for (; k < sweeps; k++) {
        double most = sweep(s);
        st->sweeps++;
        if (most <= tol) return sweeps;
        if (stall && stalled(change, k, most, sweeps, tol) && on_ground(grounded, s->body, nbody, s->c, s->ncontact))
            return k + 1;
    }
    return sweeps;
}

static int valid(const vrIslandBody *body, int nbody, const vrIslandContact *c, int ncontact)
{
    int i, k;
    for (i = 0; i < ncontact; i++) {
        if (c[i].a < 0 || c[i].a >= nbody || c[i].b < 0 || c[i].b >= nbody || c[i].a == c[i].b) return 0;
        if (c[i].npoints < 1 || c[i].npoints > VR_ISLAND_POINTS || !(c[i].mu >= 0)) return 0;
        for (k = 0; k < c[i].npoints; k++)
            if (!isfinite(c[i].floor[k])) return 0;
    }
    for (i = 0; i < nbody; i++)
        if (body[i].dynamic && !(body[i].inv_mass > 0)) return 0;
    return 1;
}

void vrIsland_Pushed(const vrIslandContact *c, int ncontact, unsigned char *pushed, int nbody)
{
    int k, i;
    memset(pushed, 0, (size_t)nbody);
    for (k = 0; k < ncontact; k++) {
        int acts = vec3_len2(c[k].friction) > 0 || c[k].twist != 0;
        for (i = 0; i < c[k].npoints && !acts; i++) acts = c[k].lambda[i] != 0;
        if (acts) pushed[c[k].a] = pushed[c[k].b] = 1;
    }
}

void vrIslandScratch_Free(vrIslandScratch *x)
{
    free(x->pt);
    free(x->patch);
    free(x->m);
    free(x->pass);
    free(x->lcp);
    free(x->before);
    free(x->bounceless);
    free(x->inertia);
    free(x->bounced);
    free(x->pushed);
    memset(x, 0, sizeof *x);
}

/* room for n contacts' solve arrays */
static int reserve_contacts(vrIslandScratch *x, int n)
{
    return vrGrow((void **)&x->pt, &x->ptcap, n * VR_ISLAND_POINTS, sizeof *x->pt)
        || vrGrow((void **)&x->patch, &x->patchcap, n, sizeof *x->patch)
        || vrGrow((void **)&x->m, &x->mcap, n * VR_LCP_MAX * VR_LCP_MAX, sizeof *x->m)
        || vrGrow((void **)&x->pass, &x->passcap, n, sizeof *x->pass)
        || vrGrow((void **)&x->lcp, &x->lcpcap, n, sizeof *x->lcp) ? -1 : 0;
}

/* room for n bodies' copies and inertias, and nc contacts' bounce marks */
static int reserve_bodies(vrIslandScratch *x, int n, int nc)
{
    return vrGrow((void **)&x->before, &x->beforecap, n, sizeof *x->before)
        || vrGrow((void **)&x->bounceless, &x->bouncelesscap, n, sizeof *x->bounceless)
        || vrGrow((void **)&x->inertia, &x->inertiacap, n, sizeof *x->inertia)
        || vrGrow((void **)&x->bounced, &x->bouncedcap, nc, sizeof *x->bounced)
        || vrGrow((void **)&x->pushed, &x->pushedcap, n, sizeof *x->pushed) ? -1 : 0;
}

static int solve(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                 int frictionless, int stall, vrIslandStats *st, vrIslandScratch *x)
{
    vrIslandSolve s;
    double change[STALL_SPAN] = {0};
    int ci, i, k, grounded;
    st->sweeps = st->shock = st->frictionless = st->bounceless = 0;
    st->residual = 0;
    if (!valid(body, nbody, c, ncontact)) return -1;
    if (ncontact == 0) return 0;
    if (reserve_contacts(x, ncontact) != 0) return -1;
    s.pt = x->pt, s.patch = x->patch, s.m = x->m, s.pass = x->pass, s.lcp = x->lcp;
    s.body = body, s.c = c, s.ncontact = ncontact, s.frictionless = frictionless;
    for (ci = 0; ci < ncontact; ci++) {
        if (!c[ci].warm || frictionless) {
            for (i = 0; i < c[ci].npoints; i++) c[ci].lambda[i] = 0;
            c[ci].friction = vec3_zero();
            c[ci].twist = 0;
        }
        vrSolve_Hold(&s, ci, 0, 0);
        if (c[ci].warm && !frictionless) vrSolve_ApplyImpulses(&s, ci);
    }
    grounded = -1;   /* levels() made only when asked: most solves converge in a sweep or two */
    k = sweep_on(&s, nbody, 0, sweeps, tol, stall, change, &grounded, st);
    if (residual(&s) > tol && on_ground(&grounded, body, nbody, c, ncontact)) {
        shock_pass(&s, sweeps, tol);
        st->shock = 1;
        if (k < sweeps && residual(&s) > STALL_LEFT) {
            /* stopped early, and the ground-up pass left a contact short */
            for (ci = 0; ci < ncontact; ci++) vrSolve_Hold(&s, ci, 0, 0);
            sweep_on(&s, nbody, k, sweeps, tol, 0, change, &grounded, st);
            if (residual(&s) > tol) shock_pass(&s, sweeps, tol);
        }
    }
    st->residual = residual(&s);
    return 0;
}

/* Newton's bounces at several points may lose energy too: a turning box
 * whose corner bounces off a wall brings another corner, not yet within
 * g_c, in faster than its floor lets it close, and that point is held,
 * inelastically (the physics fuzzer's seed 5462: e = 1 and no force, 0.083
 * J of 24.1 J).  An island whose contacts are frictionless and whose
 * bounces are elastic (e = 1) has nothing to lose, and goes to Poisson's
 * bounce (island_energy.h), which keeps it. */
static int elastic_bounce(const vrIslandContact *c, int ncontact)
{
    int i, k, bounce = 0;
    for (i = 0; i < ncontact; i++) {
        if (c[i].mu > 0) return 0;
        for (k = 0; k < c[i].npoints; k++)
            if (c[i].floor[k] > 0) {
                if (c[i].e < 1) return 0;
                bounce = 1;
            }
    }
    return bounce;
}

/* more than the sweeps' tolerance leaves of an elastic bounce's energy
 * (6e-10 J of 0.08 J a bounce, test_instant's ball on a box) */
#define ELASTIC_LOSS 1e-6

/* Newton's answer (its velocities in body, try 0 of solve_tries) lost
 * energy where elastic_bounce says none is to be lost: answered again
 * without bounces, every point of a bounced contact held, and bounced as
 * Poisson's; kept when that keeps more (an island whose held resting
 * contacts take no Poisson bounce may not), else Newton's stands */
static void elastic_retry(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                         int stall, vrIslandStats *st, vrIslandScratch *x, double e0)
{
    double k;
    vrIslandBody *newton;
    vrIslandContact *cn;
    vrIslandStats sn = *st;
    int r;
    /* the bounces first: most islands have friction or none, and their
     * energy was measured already (solve_tries) */
    if (!elastic_bounce(c, ncontact)) return;
    k = vrIslandEnergy_Kinetic(body, x->inertia, nbody);
    if (!(k < e0 * (1 - ELASTIC_LOSS))) return;
    newton = malloc((size_t)nbody * sizeof *newton);
    cn = malloc((size_t)ncontact * sizeof *cn);
    if (newton && cn) {   /* no memory: Newton's answer stands */
        memcpy(newton, body, (size_t)nbody * sizeof *newton);
        memcpy(cn, c, (size_t)ncontact * sizeof *cn);
        memcpy(body, x->before, (size_t)nbody * sizeof *body);
        vrIslandEnergy_NoBounces(c, ncontact, x->bounced, 1);
        r = solve(body, nbody, c, ncontact, sweeps, tol, 1, stall, st, x);
        if (r == 0) vrIslandEnergy_Poisson(body, nbody, c, ncontact, x->bounced, x->inertia, e0, x->bounceless);
        if (r == 0 && vrIslandEnergy_Kinetic(body, x->inertia, nbody) > k) {
            st->frictionless = st->bounceless = 1;
        } else {
            memcpy(body, newton, (size_t)nbody * sizeof *body);
            memcpy(c, cn, (size_t)ncontact * sizeof *c);
            *st = sn;
        }
    }
    free(newton);
    free(cn);
}

#define MORE_SWEEPS 64   /* a step's solve that gains over the step sweeps on so far */

static int solve_tries(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                       int stall, vrIslandStats *st, vrIslandScratch *x)
{
    vrIslandBody *before;
    mat33 *inertia;
    double e0, C = 0, R = 0;
    int i, r, try;
    vrIslandStats dummy;
    if (!st) st = &dummy;
    if (nbody <= 0 || ncontact <= 0) return solve(body, nbody, c, ncontact, sweeps, tol, 0, stall, st, x);
    if (reserve_bodies(x, nbody, ncontact) != 0) return -1;
    before = x->before, inertia = x->inertia;
    memcpy(before, body, (size_t)nbody * sizeof *before);
    for (i = 0; i < nbody; i++) inertia[i] = body[i].dynamic ? mat33_inverse(&body[i].inv_inertia) : mat33_zero();
    e0 = vrIslandEnergy_Kinetic(body, inertia, nbody);
    /* The exact solution with floors <= 0 never gains energy (the
     * impulses' work at the velocities after is lambda floor + f.u <= 0);
     * a solve left short of it with friction may, and bounces may, and
     * such a solve is done again without friction, then without bounces
     * too, which never gains (each step then lowers the energy or keeps it). */
    for (try = 0; try < 3; try++) {
        if (try == 2) vrIslandEnergy_NoBounces(c, ncontact, x->bounced, 0);
        r = solve(body, nbody, c, ncontact, sweeps, tol, try > 0, stall, st, x);
        st->frictionless = try > 0, st->bounceless = try > 1;
        if (r != 0 || try == 2 || vrIslandEnergy_Kinetic(body, inertia, nbody) <= e0 * (1 + 1e-12) + 1e-300) break;
        memcpy(body, before, (size_t)nbody * sizeof *before);
    }
    if (r == 0 && try == 2) vrIslandEnergy_Poisson(body, nbody, c, ncontact, x->bounced, inertia, e0, x->bounceless);
    if (r == 0 && try == 0) elastic_retry(body, nbody, c, ncontact, sweeps, tol, stall, st, x, e0);
    if (st->frictionless)
        for (i = 0; i < ncontact; i++) c[i].friction = vec3_zero(), c[i].twist = 0;
    if (r == 0) R = vrIslandEnergy_StepGain(body, before, inertia, nbody, c, ncontact, x->pushed, &C);
    if (R > 0 && stall) {
        /* A step's solve stopped at the cap short of the answer (a pile's
         * island of ninety) may gain a little over the step.  Scaled back,
         * every impulse of the island gave way with it, its bodies kept 1
         * to 4 % of the step's gravity, crept into the floor and were
         * answered a corner at a time (pile seed 96, frame 501) or pushed
         * out unpaid (seed 13): the solve sweeps on first, from where it
         * stopped (its impulses as the warm start), then pays back what is
         * left. */
        int frictionless = st->frictionless, bounceless = st->bounceless;
        for (i = 0; i < ncontact; i++) c[i].warm = 1;
        memcpy(body, before, (size_t)nbody * sizeof *before);
        r = solve(body, nbody, c, ncontact, MORE_SWEEPS, tol, frictionless, stall, st, x);
        st->frictionless = frictionless, st->bounceless = bounceless;
        if (r == 0) R = vrIslandEnergy_StepGain(body, before, inertia, nbody, c, ncontact, x->pushed, &C);
    }
    if (r == 0) vrIslandEnergy_PayBack(body, before, nbody, c, ncontact, R, C);
    return r;
}

static int solve_with(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                      int stall, vrIslandStats *st, vrIslandScratch *x)
{
    vrIslandScratch own;
    int r;
    if (x) return solve_tries(body, nbody, c, ncontact, sweeps, tol, stall, st, x);
    memset(&own, 0, sizeof own);
    r = solve_tries(body, nbody, c, ncontact, sweeps, tol, stall, st, &own);
    vrIslandScratch_Free(&own);
    return r;
}

int vrIsland_Solve(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                   vrIslandStats *st)
{
    return solve_with(body, nbody, c, ncontact, sweeps, tol, 0, st, NULL);
}

int vrIsland_SolveStep(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                       vrIslandStats *st, vrIslandScratch *x)
{
    return solve_with(body, nbody, c, ncontact, sweeps, tol, 1, st, x);
}
