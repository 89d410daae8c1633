/* test_schedule.c — the expected earliest event time (SPEC 3.3) is a true
 * lower bound: sampled along the real motion, no pair comes within d before
 * its key; and the internal-step grid keeps every step under d/2 of travel. */
#include <string.h>
#include "test.h"
#include "schedule.h"
#include "owner.h"
#include "scene.h"
#include "primitives.h"

#define TEST_LCG_SEED 777ULL
#include "test_lcg.h"

static vrPolyhedron *cube_poly;

static void make_body(vrBody *b, int id, int sphere, int is_static)
{
    double h = 0.1 + 0.3 * uni();      /* drawn for a cube too: the same cases as ever */
    if (sphere) vrScene_SphereBody(b, id, h, is_static);
    else vrScene_BoxBody(b, id, cube_poly, vec3_make(0.2, 0.2, 0.2), is_static);
}

static double distance(vrBody *a, vrBody *b, double t, vrWalkCache *c, vec3 *n)
{
    vrPose pa, pb;
    vrContact ct;
    vrBody_Pose(a, t, &pa);
    vrBody_Pose(b, t, &pb);
    vrContact_Distance(&a->shape, &pa, &b->shape, &pb, c, &ct);
    if (n) *n = ct.n;
    return ct.dist;
}

/* Random pairs (spheres and cubes of half-size 0.2 m, static or free,
 * some supported), speeds to 8.7 m/s, spins to `spin` rad/s, gravity in
 * two thirds: sampled along the real motion, no pair comes within d before
 * its key.  The first distance is 1.5 m +- 1 m apart (near: 1 mm to 0.2 m
 * beyond d).  Counts the finite keys and the violations. */
static void key_trials(double spin, int near, int trials, int *finite, int *violations)
{
    vrFlight f;
    int trial;
    f.max_linear = 6;
    f.max_angular = spin > 5 ? 2 * spin : 5;
    for (trial = 0; trial < trials; trial++) {
        vrBody a, b;
        vrWalkCache cache;
        double d = 0.01 + 0.1 * uni(), key, D0, horizon;
        vec3 n0;
        int k;
        memset(&cache, 0, sizeof cache);
        f.accel = trial % 3 ? vec3_make(0, 0, -9.8) : vec3_zero();
        make_body(&a, 1, trial % 2, 0);
        make_body(&b, 2, trial % 5 < 2, trial % 4 == 0);
        if (trial % 7 == 0) b.contact = 1;   /* in an island's contact step: no global force */
        vrBody_Anchor(&a, 0, vec3_zero(), rvec(5), quat_normalize(quat_make(sym(1), sym(1), sym(1), sym(1))),
                      vec3_scale(rvec(1), 0.0267 * spin / sqrt(3.0)), &f);
        vrBody_Anchor(&b, 0, vec3_add(vec3_make(1.5, 0, 0), rvec(1)), rvec(5),
                      quat_normalize(quat_make(sym(1), sym(1), sym(1), sym(1))),
                      vec3_scale(rvec(1), 0.0267 * spin / sqrt(3.0)), &f);
        D0 = distance(&a, &b, 0, &cache, &n0);
        if (near && D0 > 0) {   /* slide b along the normal to 1 mm .. 0.2 m beyond d */
            b.m.x0 = vec3_madd(b.m.x0, d + 0.001 + 0.2 * uni() - D0, n0);
            b.pose_valid = 0;
            D0 = distance(&a, &b, 0, &cache, &n0);
        }
        if (D0 <= d) continue;
        key = vrSchedule_Key(&a, &b, 0, D0, n0, d, &f);
        if (key < INFINITY) (*finite)++;
        horizon = fmin(key, near ? 0.5 : 3.0);
        for (k = 1; k <= 400; k++) {
            double t = horizon * k / 400.0;
            if (t >= key) break;
            if (distance(&a, &b, t, &cache, NULL) <= d) { (*violations)++; break; }
        }
    }
}

static int test_key_never_overestimates(void)
{
    int finite = 0, violations = 0;
    ENSURE(vrPolyhedron_Cube(vec3_make(0.2, 0.2, 0.2), &cube_poly, NULL, 0) == 0);
    key_trials(6, 0, 3000, &finite, &violations);
    printf("    %d finite keys, %d violations\n", finite, violations);
    ENSURE(finite > 1000);
    ENSURE(violations == 0);
    /* turning fast close by, where the key follows the near vertices */
    finite = violations = 0;
    key_trials(100, 1, 3000, &finite, &violations);
    printf("    spinning to 100 rad/s, close: %d finite keys, %d violations\n", finite, violations);
    vrPolyhedron_Free(cube_poly);
    ENSURE(finite > 1000);
    ENSURE(violations == 0);
    return 0;
}

/* SPEC 3.2: the grid for free bodies is n = ceil(span * 2 * reach / d) */
/* Bounding spheres of free bodies under the same force fly straight
 * relative to each other: their key is the first time their gap comes
 * down to d (+ 1e-9 m kept for rounding), from the quadratic solved here in
 * long double, never later; a pair that flies past gets no key before the
 * speed cap could bend its path.  Pairs a speed cap bends, or with a
 * supported body, are sampled along their motion: never within d before
 * their key. */
static int test_sphere_keys_are_exact_for_free_pairs(void)
{
    vrFlight f;
    int trial, exact = 0, past = 0, bounded = 0;
    f.max_angular = 100;
    ENSURE(vrPolyhedron_Cube(vec3_make(0.2, 0.2, 0.2), &cube_poly, NULL, 0) == 0);
    for (trial = 0; trial < 5000; trial++) {
        vrBody a, b;
        vrCentres centres;
        vec3 xa, xb, va, vb, dir;
        long double dx[3], dv[3], A = 0, B = 0, C, disc, tau = -1, D;
        double d = 0.01 + 0.1 * uni(), gap, key, t = 0.25;
        int k;
        f.accel = trial % 3 ? vec3_make(0, 0, -9.8) : vec3_zero();
        f.max_linear = trial < 3000 ? 1e6 : 4 + 4 * uni();   /* from 3000 on the cap bends the paths */
        make_body(&a, 1, trial % 2, 0);
        make_body(&b, 2, trial % 5 < 2, 0);
        if (trial % 7 == 0) b.contact = 1;   /* in an island's contact step: no global force */
        va = rvec(5);             /* b comes at a from 3 m, aimed within about a metre */
        vrBody_Anchor(&a, 0, rvec(1), va, quat_identity(), vec3_scale(rvec(1), 0.1), &f);
        vrBody_Anchor(&b, 0, vec3_add(vec3_make(3, 0, 0), rvec(1)), vec3_add(va, vec3_add(vec3_make(-4, 0, 0), rvec(0.8))),
                      quat_identity(), vec3_scale(rvec(1), 0.1), &f);
        vrCentres_At(&a, &b, t, &centres);
        xa = centres.xa, xb = centres.xb;
        vrBody_Velocity(&a, t, &va);
        vrBody_Velocity(&b, t, &vb);
        dir = vec3_normalize(vec3_sub(xb, xa));
        gap = vec3_len(vec3_sub(xb, xa)) - a.r_out - b.r_out;
        if (gap <= d + 1e-6) continue;
        key = vrSchedule_SphereKey(&a, &b, t, &centres, gap, dir, d, &f);
        dx[0] = (long double)xb.x - xa.x, dx[1] = (long double)xb.y - xa.y, dx[2] = (long double)xb.z - xa.z;
        dv[0] = (long double)vb.x - va.x, dv[1] = (long double)vb.y - va.y, dv[2] = (long double)vb.z - va.z;
        D = (long double)a.r_out + b.r_out + d;
        for (k = 0; k < 3; k++) A += dv[k] * dv[k], B += 2 * dx[k] * dv[k];
        C = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2] - D * D;
        disc = B * B - 4 * A * C;
        if (disc >= 0 && B < 0) tau = (-B - sqrtl(disc)) / (2 * A);
        if (trial >= 3000 || (b.contact && trial % 3)) {   /* the cap, or another acceleration: sampled */
            double horizon = fmin(key, t + 3.0);
            bounded++;
            for (k = 1; k <= 2000; k++) {
                double s = t + (horizon - t) * k / 2000.0;
                if (s >= key) break;
                vrBody_Position(&a, s, &xa);
                vrBody_Position(&b, s, &xb);
                ENSURE_MSG(vec3_len(vec3_sub(xb, xa)) - a.r_out - b.r_out > d, "trial %d: within d at %g, key %g",
                           trial, s, key);
            }
            continue;
        }
        if (tau < 0) {
            past++;
            ENSURE_MSG(key > 1e3, "trial %d: flies past, key %.17g", trial, key);
        } else {
            exact++;
            ENSURE_MSG(key <= t + (double)tau && key >= t + (double)tau - 1e-6, "trial %d: key %.17g, contact %.17g",
                       trial, key, t + (double)tau);
        }
    }
    vrPolyhedron_Free(cube_poly);
    printf("    %d meeting pairs keyed at the contact, %d flying past never, %d capped or supported sampled\n", exact,
           past, bounded);
    ENSURE(exact > 300 && past > 300 && bounded > 100);
    return 0;
}

static int test_grid_follows_thesis_rule_without_spin(void)
{
    vrBody b, *list[1] = {&b};
    vrFlight f;
    vrGrid g;
    mat33 unit = mat33_diag(0.004, 0.004, 0.004);
    memset(&b, 0, sizeof b);
    b.shape.kind = VR_SHAPE_SPHERE;
    b.shape.radius = 0.1;
    vrBody_SetMassProperties(&b, 1, &unit, 0.1, 0.1);
    f.accel = vec3_zero();
    f.max_linear = 8;
    f.max_angular = 4;
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_make(8, 0, 0), quat_identity(), vec3_zero(), &f);
    vrSchedule_Grid(list, 1, 0, 0.1, 0.25, 0, &f, &g);
    ENSURE(g.n == 7);                         /* ceil(0.1 * 2 * 8 / 0.25) = ceil(6.4) */
    ENSURE(vrGrid_Point(&g, g.n) == 0.1);
    vrSchedule_Grid(list, 1, 0.1, 0.1, 0.25, 0, &f, &g);
    ENSURE(g.n == 0);                         /* nothing left of the frame */
    b.resting = 1;
    vrSchedule_Grid(list, 1, 0, 0.1, 0.25, 0, &f, &g);
    ENSURE(g.n == 1);                         /* nothing free: one step */
    return 0;
}

/* A span started by an event inside a contact step keeps the step's
 * points: those after the event are the first span's, bit for bit, and
 * the bracket before its first point starts at the step's point before
 * the event.  A faster reach halves the step; every old point stays. */
static int test_a_span_keeps_its_contact_steps_points(void)
{
    vrGrid first, later, finer;
    long steps = 0, k;
    const double a = 0.3, T = 0.31, d = 0.25;
    vrSchedule_AnchoredGrid(80, a, a, T, d, 0, &steps, &first);   /* 0.01 * 2 * 80 / 0.25 = 6.4 */
    ENSURE(steps == 7 && first.n == 7 && vrGrid_Point(&first, 7) == T && vrGrid_Before(&first, 1) == a);
    vrSchedule_AnchoredGrid(80, a, 0.3047, T, d, 0, &steps, &later);
    printf("    after an event at 0.3047: %ld points from k0 = %ld\n", later.n, later.k0);
    ENSURE(steps == 7 && later.k0 == 3 && later.n == 4 && vrGrid_Point(&later, later.n) == T);
    for (k = 1; k < later.n; k++) ENSURE(vrGrid_Point(&later, k) == vrGrid_Point(&first, k + 3));
    ENSURE(vrGrid_Before(&later, 1) == vrGrid_Point(&first, 3) && vrGrid_Before(&later, 1) < 0.3047);
    ENSURE(vrSchedule_FirstPointAtOrAfter(&later, vrGrid_Point(&first, 5)) == 2);
    vrSchedule_AnchoredGrid(200, a, 0.3047, T, d, 0, &steps, &finer);   /* 16 needed: 7 -> 14 -> 28 */
    ENSURE(steps == 28 && finer.h == (T - a) / 28.0);
    for (k = 1; k < 7; k++) ENSURE(vrGrid_Point(&first, k) == a + (double)(4 * k) * finer.h);
    vrSchedule_AnchoredGrid(1, a, 0.305, T, d, 0, &steps, &finer);       /* never coarser within the step */
    ENSURE(steps == 28);
    return 0;
}

/* two 0.1 m spheres, no force: a at x0 moving +0.5 m/s, b at rest at 0 */
static void closing_pair(vrBody *a, vrBody *b, double x0, vrFlight *f)
{
    mat33 unit = mat33_diag(0.004, 0.004, 0.004);
    vrBody *x[2] = {a, b};
    int i;
    f->accel = vec3_zero();
    f->max_linear = 50;
    f->max_angular = 50;
    for (i = 0; i < 2; i++) {
        memset(x[i], 0, sizeof *x[i]);
        x[i]->id = i;
        x[i]->shape.kind = VR_SHAPE_SPHERE;
        x[i]->shape.radius = 0.1;
        vrBody_SetMassProperties(x[i], 1, &unit, 0.1, 0.1);
    }
    vrBody_Anchor(a, 0, vec3_make(x0, 0, 0), vec3_make(0.5, 0, 0), quat_identity(), vec3_zero(), f);
    vrBody_Anchor(b, 0, vec3_zero(), vec3_zero(), quat_identity(), vec3_zero(), f);
}

/* the owner's first impact between a and b on grid g, and the time that 48
 * halvings of the first grid step ending within the contact gap g_c =
 * min(d, 1 mm) give, stopping at the first halving whose distance is at
 * g_c (VR_AT_LEVEL below it at most) (this file's own, by the definitions
 * in SPEC 3.2 and 7 and man vroc's); 0 when the owner's first event is
 * not an impact of the pair */
static int owner_and_halvings(vrBody *a, vrBody *b, const vrFlight *f, const vrGrid *g, double d,
                              double *owner, double *halved, long long *checks)
{
    vrParams p;
    vrEvent ev;
    vrOwnerStats st;
    vrOwner *o = vrOwner_Create();
    double lo, hi, gc;
    long k;
    int i, found;
    memset(&p, 0, sizeof p);
    p.d = d, p.flight = *f, p.use_heap = 1;
    gc = vrParams_Gap(&p);
    if (!o) return 0;
    vrOwner_SetParams(o, &p);
    found = vrOwner_HoldBody(o, 0, a) == 0 && vrOwner_HoldBody(o, 1, b) == 0 && vrOwner_AddPair(o, 0, 1) == 0
         && vrOwner_FirstEvent(o, g, 1, &ev) == 1 && ev.kind == VR_EV_IMPACT && ev.a == 0 && ev.b == 1;
    vrOwner_Stats(o, &st);
    *checks = st.checks;
    vrOwner_Free(o);
    if (!found) return 0;
    *owner = ev.t;
    for (k = 1; k <= g->n && distance(a, b, vrGrid_Point(g, k), NULL, NULL) > gc; k++)
        ;
    lo = vrGrid_Point(g, k - 1), hi = vrGrid_Point(g, k);
    for (i = 0; i < 48; i++) {
        double mid = lo + 0.5 * (hi - lo), dist = distance(a, b, mid, NULL, NULL);
        if (dist > gc) {
            lo = mid;
            continue;
        }
        hi = mid;
        if (dist >= gc - VR_AT_LEVEL) break;   /* at the level: the event */
    }
    *halved = hi;
    return 1;
}

/* SPEC 3.2: an impact inside a grid step is found by 48 halvings of that
 * step, the event at the upper end of the final bracket, or at the first
 * halving whose distance is at the level (man vroc).  The owner's event
 * time equals this file's own halvings, to the bit, for an impact near 0.3
 * s and one near 40 s (where the bracket may reach adjacent doubles before
 * the 48th halving and the owner stops early). */
static int test_impact_time_is_the_upper_end_of_the_halvings(void)
{
    static const double x0[2] = {-0.36234567, -20.21234567}, t0[2] = {0, 30};
    int c;
    for (c = 0; c < 2; c++) {
        vrBody a, b;
        vrFlight f;
        vrGrid g;
        double owner, halved;
        long long checks;
        closing_pair(&a, &b, x0[c], &f);
        g.t0 = g.a = t0[c], g.T = g.frame_T = t0[c] + 20, g.n = 2000, g.h = 0.01, g.k0 = 0;
        ENSURE(owner_and_halvings(&a, &b, &f, &g, 0.01, &owner, &halved, &checks));
        printf("    impact at %.17g s (exact %.17g s)\n", owner, (x0[c] + 0.2 + VR_CONTACT_GAP) / -0.5);
        ENSURE_MSG(owner == halved, "owner %.17g, halvings %.17g", owner, halved);
    }
    return 0;
}

/* Two pairs meeting within the same grid step, each alone and both in one
 * owner, in both orders of pair index: the owner's first event is the
 * earlier impact at its halvings' time; a bisection that passes an
 * impact already found at that grid point stops (its event could only be
 * dropped), so fewer distance queries are asked than by the two pairs
 * alone.  Without the heap the pairs are looked at in index order, so the
 * later impact is bisected first in one order: the earlier one's
 * bisection, past the later's event at its start, must not stop. */
static int test_a_bisection_past_an_event_found_stops(void)
{
    static const double x0[2] = {-0.36234567, -0.3643};     /* impacts at 0.3227 and 0.3266 s */
    int run, fewer = 0;
    for (run = 0; run < 4; run++) {
        int order = run % 2, heap = run < 2;
        vrBody s[4];
        vrFlight f;
        vrGrid g;
        vrParams p;
        vrEvent ev;
        vrOwnerStats st;
        vrOwner *o = vrOwner_Create();
        double owner, halved[2];
        long long alone[2], both;
        int i, first = order;          /* the pair with the earlier impact: 0 = bodies 0-1 */
        g.t0 = g.a = 0, g.T = g.frame_T = 1, g.n = 100, g.h = 0.01, g.k0 = 0;
        for (i = 0; i < 2; i++) {       /* each pair alone, for its time and its queries */
            closing_pair(&s[2 * i], &s[2 * i + 1], x0[i == first ? 0 : 1], &f);
            ENSURE(owner_and_halvings(&s[2 * i], &s[2 * i + 1], &f, &g, 0.01, &owner, &halved[i], &alone[i]));
        }
        for (i = 0; i < 4; i++) s[i].id = i;
        vrBody_Anchor(&s[2], 0, vec3_make(s[2].m.x0.x, 5, 0), s[2].m.v0, quat_identity(), vec3_zero(), &f);
        vrBody_Anchor(&s[3], 0, vec3_make(0, 5, 0), vec3_zero(), quat_identity(), vec3_zero(), &f);
        memset(&p, 0, sizeof p);
        p.d = 0.01, p.flight = f, p.use_heap = heap;
        ENSURE(o != NULL);
        vrOwner_SetParams(o, &p);
        for (i = 0; i < 4; i++) ENSURE(vrOwner_HoldBody(o, i, &s[i]) == 0);
        ENSURE(vrOwner_AddPair(o, 0, 1) == 0 && vrOwner_AddPair(o, 2, 3) == 0);
        ENSURE(vrOwner_FirstEvent(o, &g, 1, &ev) == 1);
        vrOwner_Stats(o, &st);
        both = st.checks;
        vrOwner_Free(o);
        ENSURE_MSG(ev.kind == VR_EV_IMPACT && ev.a == 2 * first && ev.t == halved[first],
                   "heap %d, order %d: event of %d-%d at %.17g, the earlier impact %.17g", heap, order, ev.a, ev.b,
                   ev.t, halved[first]);
        printf("    heap %d, earlier impact in pair %d: %lld queries together, %lld + %lld alone\n", heap, first, both,
               alone[0], alone[1]);
        fewer += both < alone[0] + alone[1];
    }
    ENSURE(fewer >= 2);
    return 0;
}

/* The same for spinning cubes (up to 60 rad/s) falling on a static plate
 * or on a cube, and for a cube falling flat over the plate's edge (the
 * faces parallel, the contact overhanging), where the bisection skips the
 * halvings that motion bounds decide (distbound.h): the owner's impact time
 * is still the halvings' to the bit (the stop at the level included), with
 * fewer distance queries. */
static int test_impact_times_of_spinning_boxes_are_the_halvings(void)
{
    vrPolyhedron *cube = NULL, *plate = NULL;
    int trial, impacts = 0, rc = 1;
    long long checks = 0;
    if (vrPolyhedron_Cube(vec3_make(0.15, 0.15, 0.15), &cube, NULL, 0)
        || vrPolyhedron_Cube(vec3_make(0.5, 0.5, 0.05), &plate, NULL, 0))
        goto out;
    for (trial = 0; trial < 120; trial++) {
        vrBody a, b;
        vrFlight f;
        vrGrid g;
        double owner, halved, d = 0.01, height = 0.4 + 0.3 * uni();
        long long c;
        int flat = trial % 4 == 0, on_cube = trial % 4 == 1;
        quat q = flat ? quat_identity() : quat_normalize(quat_make(sym(1), sym(1), sym(1), sym(1)));
        f.accel = vec3_make(0, 0, -9.8), f.max_linear = 50, f.max_angular = 100;
        vrScene_BoxBody(&a, 0, on_cube ? cube : plate, on_cube ? vec3_make(0.15, 0.15, 0.15) : vec3_make(0.5, 0.5, 0.05),
                        !on_cube);
        vrScene_BoxBody(&b, 1, cube, vec3_make(0.15, 0.15, 0.15), 0);
        vrBody_Anchor(&a, 0, vec3_zero(), on_cube ? vec3_make(sym(1), sym(1), 2) : vec3_zero(), quat_identity(),
                      on_cube ? vec3_scale(rvec(1), 0.9) : vec3_zero(), &f);
        vrBody_Anchor(&b, 0, vec3_make(flat ? 0.5 + sym(0.14) : sym(0.3), sym(0.3), height),
                      vec3_make(sym(1), sym(1), -1 - 2 * uni()), q, flat ? vec3_zero() : vec3_scale(rvec(1), 0.9), &f);
        g.t0 = g.a = 0, g.T = g.frame_T = 1, g.n = 1000 + (long)(500 * uni()), g.h = 1.0 / (double)g.n, g.k0 = 0;
        if (!owner_and_halvings(&a, &b, &f, &g, d, &owner, &halved, &c)) continue;
        impacts++;
        checks += c;
        ENSURE_MSG(owner == halved, "trial %d: owner %.17g, halvings %.17g", trial, owner, halved);
    }
    printf("    %d impacts, %lld distance queries by the owner in all\n", impacts, checks);
    ENSURE(impacts >= 80);
    rc = 0;
out:
    vrPolyhedron_Free(cube);
    vrPolyhedron_Free(plate);
    return rc;
}

/* an owner of bodies a (id 0) and b (id 1) and their pair, d = 0.01 m */
static vrOwner *owner_of(vrBody *a, vrBody *b, const vrFlight *f)
{
    vrParams p;
    vrOwner *o = vrOwner_Create();
    memset(&p, 0, sizeof p);
    p.d = 0.01, p.flight = *f, p.use_heap = 1;
    if (!o) return NULL;
    vrOwner_SetParams(o, &p);
    if (vrOwner_HoldBody(o, 0, a) == 0 && vrOwner_HoldBody(o, 1, b) == 0 && vrOwner_AddPair(o, 0, 1) == 0) return o;
    vrOwner_Free(o);
    return NULL;
}

/* the owner's first event for overlapping a and b over a 0.1 s frame, a
 * push-out, and the states its response gives in *up: 1, else 0 */
static int pushed_out(vrBody *a, vrBody *b, const vrFlight *f, vrUpdate *up)
{
    vrBody *list[2] = {a, b};
    vrOwner *o = owner_of(a, b, f);
    vrGrid g;
    vrEvent ev;
    int ok;
    vrSchedule_Grid(list, 2, 0, 0.1, 0.01, 0, f, &g);
    ok = o && vrOwner_FirstEvent(o, &g, 1, &ev) == 1 && ev.kind == VR_EV_PUSHOUT && vrOwner_Respond(o, &ev, up) == 0;
    printf("    first event %s, %d bodies updated\n", ok ? "a push-out" : "not a push-out", up->n);
    vrOwner_Free(o);
    return ok;
}

/* `hit` is per frame (rest.c): a worker's copy of a body hit in an earlier
 * frame must not send it back with an update that is no impulse (a push-out
 * here), or the shell thinks it was hit and does not let it rest, while the
 * serial run, whose owner holds the shell's own bodies, does */
static int test_a_push_out_in_a_later_frame_is_no_hit(void)
{
    vrBody a, b;
    vrFlight f;
    vrUpdate up;
    int i, ok;
    closing_pair(&a, &b, 0.199, &f);          /* 1 mm inside each other */
    vrBody_Anchor(&a, 0, vec3_make(0.199, 0, 0), vec3_zero(), quat_identity(), vec3_zero(), &f);
    a.hit = b.hit = 1;                        /* an impulse in the frame before */
    vrUpdate_Init(&up);
    ok = pushed_out(&a, &b, &f, &up);
    for (i = 0; ok && i < up.n; i++) ok = up.body[i].hit == 0;
    vrUpdate_Free(&up);
    ENSURE(ok);
    return 0;
}

/* SPEC 1.4: a start after edits checks the pairs of the edited and new
 * bodies; the serial owner and the workers are given the same bodies, so
 * they check the same pairs whatever each has flagged (a worker made anew
 * flagged them all and refused a start over an overlap, left by a busy
 * stack, that the serial run did not look at: edit fuzzer seed 1476) */
static int test_the_start_check_looks_at_the_bodies_it_is_given(void)
{
    vrBody a, b, c;
    vrFlight f;
    vrOwner *o;
    int out[4][2], none[1] = {0}, of_a[1] = {0}, of_c[1] = {2}, junk[3] = {-1, 99, 1 << 30}, na, nc, nj, nn;
    closing_pair(&c, &b, 5, &f);              /* c far away */
    c.id = 2;
    closing_pair(&a, &b, 0.19, &f);           /* a and b 1 cm inside each other */
    ENSURE((o = owner_of(&a, &b, &f)) != NULL);
    ENSURE(vrOwner_HoldBody(o, 2, &c) == 0 && vrOwner_AddPair(o, 0, 2) == 0 && vrOwner_AddPair(o, 1, 2) == 0);
    na = vrOwner_Overlapping(o, 0, 1e-6, of_a, 1, out, 4);
    ENSURE(na == 1 && out[0][0] == 0 && out[0][1] == 1);
    nc = vrOwner_Overlapping(o, 0, 1e-6, of_c, 1, out, 4);
    nn = vrOwner_Overlapping(o, 0, 1e-6, none, 0, out, 4);
    nj = vrOwner_Overlapping(o, 0, 1e-6, junk, 3, out, 4);
    printf("    overlapping pairs of a: %d, of c: %d, of none: %d, of unknown ids: %d\n", na, nc, nn, nj);
    ENSURE(nc == 0 && nn == 0 && nj == 0);
    vrOwner_Free(o);
    return 0;
}

/* A box (b) 1 cm into a light board (a) that lies on the floor: the
 * push-out moves the box by the whole depth and leaves the board, which
 * shared, was pushed into the floor, pushed back into the box by that
 * pair's push-out, 64 times an instant, while the overlap grew to 36 mm
 * (edit fuzzer seed 1476: a 1 kg box on a 0.5 kg table) */
static int test_a_push_out_does_not_drive_a_body_into_its_static_support(void)
{
    vrBody a, b;
    vrFlight f;
    vrUpdate up;
    int i, ok, moved_a = 0;
    double lift = 0;
    closing_pair(&a, &b, 0, &f);
    vrBody_Anchor(&b, 0, vec3_make(0, 0, 0.19), vec3_zero(), quat_identity(), vec3_zero(), &f);
    a.contact = 1;                            /* the board lies on the floor (an island's contact step) */
    vrUpdate_Init(&up);
    ok = pushed_out(&a, &b, &f, &up);
    for (i = 0; ok && i < up.n; i++) {
        if (up.body[i].id == 0) moved_a = vec3_len(up.body[i].x) != 0;
        if (up.body[i].id == 1) lift = up.body[i].x.z - 0.19;
    }
    printf("    board moved: %d, box lifted %.9g m (depth 0.01 m)\n", moved_a, lift);
    vrUpdate_Free(&up);
    ENSURE(ok && !moved_a);
    ENSURE_NEAR(lift, 0.01 + VR_PUSHOUT_GAP, 1e-12);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_key_never_overestimates),
    TEST(test_sphere_keys_are_exact_for_free_pairs),
    TEST(test_grid_follows_thesis_rule_without_spin),
    TEST(test_a_span_keeps_its_contact_steps_points),
    TEST(test_impact_time_is_the_upper_end_of_the_halvings),
    TEST(test_a_bisection_past_an_event_found_stops),
    TEST(test_impact_times_of_spinning_boxes_are_the_halvings),
    TEST(test_a_push_out_in_a_later_frame_is_no_hit),
    TEST(test_the_start_check_looks_at_the_bodies_it_is_given),
    TEST(test_a_push_out_does_not_drive_a_body_into_its_static_support),
};

const vrTestSuite vrSuite_Schedule = {"schedule", tests, TEST_COUNT(tests), NULL, NULL, 0};
