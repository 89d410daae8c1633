/* test_distbound.c — the Taylor bounds that let the impact bisection skip
 * halvings (distbound.h) hold along the real motion, are tight enough to
 * decide near their measurement, and refuse motions they cannot bound. */
#include <string.h>
#include "test.h"
#include "distbound.h"
#include "scene.h"
#include "primitives.h"

#define TEST_LCG_SEED 0xD15B0D5ULL
#include "test_lcg.h"

static vrPolyhedron *cube_poly, *plate_poly;

enum { SPHERE, CUBE, PLATE };

static void make_body(vrBody *b, int id, int kind, int is_static)
{
    if (kind == SPHERE) vrScene_SphereBody(b, id, 0.1 + 0.2 * uni(), is_static);
    else if (kind == CUBE) vrScene_BoxBody(b, id, cube_poly, vec3_make(0.15, 0.15, 0.15), is_static);
    else vrScene_BoxBody(b, id, plate_poly, vec3_make(0.4, 0.3, 0.05), is_static);
}

static quat random_turn(void) { return quat_normalize(quat_make(sym(1), sym(1), sym(1), sym(1))); }

/* the distance at t, with closest points that are points of the bodies
 * (what the bisection measures) */
static void measure(vrBody *a, vrBody *b, double t, vrContact *c, vrPose *pa, vrPose *pb)
{
    vrWalkCache cold;
    memset(&cold, 0, sizeof cold);
    vrBody_Pose(a, t, pa);
    vrBody_Pose(b, t, pb);
    vrContact_Within(&a->shape, pa, &b->shape, pb, &cold, 0, c);
}

/* a pair 1 mm to 5 cm apart at te: a spinning cube or a sphere against a
 * static plate, a cube or a sphere, speeds to 16 m/s, spins to 115 rad/s,
 * under gravity; anchored 0 to 0.05 s before te, at the origin or (every
 * other trial) up to 8.7 m from it late in a run (te up to 60 s), where
 * positions and times round as coarsely as in a minute-long room scene */
static int random_pair(vrBody *a, vrBody *b, int trial, vrFlight *f, double te, vrContact *c)
{
    vrPose pa, pb;
    vec3 along, far = trial % 2 ? rvec(5) : vec3_zero();
    double t0 = trial % 2 ? te - 0.05 * uni() : 0;
    make_body(a, 1, trial % 3 == 0 ? SPHERE : CUBE, 0);
    make_body(b, 2, trial % 4 == 0 ? PLATE : trial % 4 == 1 ? SPHERE : CUBE, trial % 4 == 0);
    f->accel = vec3_make(0, 0, -9.8);
    f->max_linear = 1e3;
    f->max_angular = 1e3;
    vrBody_Anchor(a, t0, far, rvec(9), random_turn(), vec3_scale(rvec(1), uni()), f);
    vrBody_Anchor(b, t0, vec3_add(far, vec3_make(0, 0, 0.6)), rvec(9), random_turn(), vec3_scale(rvec(1), uni()), f);
    /* slide b along the centre line until the gap at te is as drawn */
    measure(a, b, te, c, &pa, &pb);
    along = vec3_scale(vec3_normalize(vec3_sub(c->pb, c->pa)), 0.001 + 0.049 * uni() - c->dist);
    b->m.x0 = vec3_add(b->m.x0, along);
    b->pose_valid = 0;
    measure(a, b, te, c, &pa, &pb);
    return c->dist > 0;
}

/* Sampled through a window of up to 0.05 s about the measurement (a
 * cube turns up to 5 rad in it), neither bound ever crosses the distance:
 * asked whether the pair is within its own distance there, the bounds never
 * decide, even with a tolerance a hundred times smaller than the
 * bisection's (1e-14 m; at 1e-15 m a few of the pairs far from the origin
 * late in a run do cross: rounding, which BOUND_TOL's 1e-12 m covers a
 * hundred times over). */
static int test_bounds_never_cross_the_distance(void)
{
    int trial, k, crossed = 0, valid = 0, lower = 0, upper = 0;
    for (trial = 0; trial < 10000; trial++) {
        vrBody a, b;
        vrFlight f;
        vrContact c;
        vrDistBound db;
        vrPose pa, pb;
        double te = (trial % 2 ? 60 : 0.05) * uni(), w = 0.05 * pow(10, -4 * uni());
        if (!random_pair(&a, &b, trial, &f, te, &c)) continue;
        measure(&a, &b, te, &c, &pa, &pb);
        vrDistBound_Make(&db, &a, &pa, &b, &pb, te, c.pa, c.pb, 1, te - w, te + w);
        if (!db.valid) continue;
        valid++;
        for (k = 0; k <= 40; k++) {
            double t = te - w + 2 * w * k / 40.0;
            vrContact at;
            measure(&a, &b, t, &at, &pa, &pb);
            if (at.dist <= 0) continue;   /* MPR's depth need not be the least: no bound to check */
            if (vrDistBound_Decide(&db, t, at.dist, 1e-14) >= 0) crossed++;
            lower += vrDistBound_Decide(&db, t, at.dist - 1e-3, 1e-12) == 0;
            upper += vrDistBound_Decide(&db, t, at.dist + 1e-3, 1e-12) == 1;
        }
    }
    printf("    %d measurements, %d crossings; 1 mm off, decided %d (below) and %d (above) of %d\n",
           valid, crossed, lower, upper, 41 * valid);
    ENSURE(valid > 1200);
    ENSURE(crossed == 0);
    /* tight: decided in most samples 1 mm away, in a window of up to 0.05 s */
    ENSURE(lower > 41 * valid / 2 && upper > 41 * valid / 4);
    return 0;
}

/* Near the measurement the bounds are second-order tight: 10 us away from
 * a cube turning at up to 115 rad/s, the pair closing or sliding at up to
 * 30 m/s, they decide a threshold 0.1 mm from the distance either way. */
static int test_bounds_decide_near_the_measurement(void)
{
    int trial, undecided = 0, n = 0;
    for (trial = 0; trial < 500; trial++) {
        vrBody a, b;
        vrFlight f;
        vrContact c, at;
        vrDistBound db;
        vrPose pa, pb;
        double te = 0.01, t = te + (trial % 2 ? 1e-5 : -1e-5);
        if (!random_pair(&a, &b, trial, &f, te, &c)) continue;
        measure(&a, &b, te, &c, &pa, &pb);
        vrDistBound_Make(&db, &a, &pa, &b, &pb, te, c.pa, c.pb, 1, te - 1e-5, te + 1e-5);
        measure(&a, &b, t, &at, &pa, &pb);
        ENSURE(db.valid);
        n++;
        undecided += vrDistBound_Decide(&db, t, at.dist - 1e-4, 1e-12) != 0;
        undecided += vrDistBound_Decide(&db, t, at.dist + 1e-4, 1e-12) != 1;
    }
    printf("    %d of %d undecided\n", undecided, 2 * n);
    ENSURE(n > 400 && undecided < n / 10);
    return 0;
}

/* A cube rocking over a plate, its bottom edge tilted 1 mrad: the edge's
 * higher end comes down past the lower one within 0.1 ms, so the bound
 * must follow every vertex that could overtake the lowest, not only it. */
static int test_bounds_follow_the_vertex_that_overtakes(void)
{
    vrBody a, b;
    vrFlight f;
    vrContact c, at;
    vrDistBound db;
    vrPose pa, pb;
    quat q = quat_mul(quat_from_axis_angle(vec3_make(0, 1, 0), -1e-3),
                      quat_from_axis_angle(vec3_make(1, 0, 0), 0.25 * VR_PI));
    int k, crossed = 0;
    f.accel = vec3_zero();
    f.max_linear = f.max_angular = 1e3;
    make_body(&a, 1, CUBE, 0);
    make_body(&b, 2, PLATE, 1);
    vrBody_Anchor(&a, 0, vec3_make(0, 0, 0.05 + 0.15 * sqrt(2.0) + 0.02), vec3_zero(), q,
                  vec3_make(0, a.moments.x * 50, 0), &f);
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_zero(), quat_identity(), vec3_zero(), &f);
    measure(&a, &b, 0, &c, &pa, &pb);
    vrDistBound_Make(&db, &a, &pa, &b, &pb, 0, c.pa, c.pb, 1, 0, 1e-3);
    ENSURE(db.valid && c.dist > 0.0198 && c.dist < 0.0199);   /* 0.02 less the tilt */
    for (k = 1; k <= 100; k++) {
        double t = 1e-5 * k;
        measure(&a, &b, t, &at, &pa, &pb);
        ENSURE(at.dist > 0);
        crossed += vrDistBound_Decide(&db, t, at.dist, 1e-13) >= 0;
    }
    ENSURE(crossed == 0);
    return 0;
}

/* A cube sliding under a plate at the speed cap keeps its velocity though
 * gravity pulls (SPEC 3.2): bounds made after the cap follow a line, not
 * the parabola the force alone would give. */
static int test_bounds_after_the_cap_follow_a_line(void)
{
    vrBody a, b;
    vrFlight f;
    vrContact c, at;
    vrDistBound db;
    vrPose pa, pb;
    int k, crossed = 0;
    f.accel = vec3_make(0, 0, -9.8);
    f.max_linear = 2;
    f.max_angular = 1e3;
    make_body(&a, 1, CUBE, 0);
    make_body(&b, 2, PLATE, 1);
    vrBody_Anchor(&a, 0, vec3_zero(), vec3_make(3, 0, 0), quat_identity(), vec3_zero(), &f);   /* clamped to 2 m/s */
    vrBody_Anchor(&b, 0, vec3_make(0, 0, 0.35), vec3_zero(), quat_identity(), vec3_zero(), &f);
    measure(&a, &b, 0.01, &c, &pa, &pb);
    vrDistBound_Make(&db, &a, &pa, &b, &pb, 0.01, c.pa, c.pb, 1, 0.01, 0.07);
    ENSURE(db.valid && c.dist > 0.149 && a.m.tcap == 0);
    for (k = 1; k <= 60; k++) {
        double t = 0.01 + 1e-3 * k;
        measure(&a, &b, t, &at, &pa, &pb);
        if (at.dist > 0) crossed += vrDistBound_Decide(&db, t, at.dist, 1e-13) >= 0;
    }
    ENSURE(crossed == 0);
    return 0;
}

/* A sphere or a turning cube sliding at 5 to 10 m/s over a static plate, 1
 * to 5 mm above it: 2 ms later, still over the plate, the bounds decide
 * that it is within 1 um above its distance (every sphere, most cubes:
 * another vertex may come lowest).  The distance to the plate's point that
 * was nearest grows with the square of the slide, by millimetres here, so
 * only the plate's plane can tell.  Sliding off the plate's edge instead,
 * the plane no longer bounds the distance: no threshold the body has not
 * come within is ever decided. */
static int test_bounds_follow_a_body_sliding_over_a_wall(void)
{
    int trial, n = 0, spheres = 0, decided = 0, spheres_decided = 0, crossed = 0;
    vrFlight f;
    f.accel = vec3_make(0, 0, -9.8);
    f.max_linear = f.max_angular = 1e3;
    for (trial = 0; trial < 400; trial++) {
        vrBody a, b;
        vrContact c, at;
        vrDistBound db;
        vrPose pa, pb;
        double ang = 2 * VR_PI * uni(), speed = 5 + 5 * uni(), te = 0.01, t = te + 2e-3, gap = 0.001 + 0.004 * uni();
        int leaving = trial % 2, sphere = trial % 4 < 2;
        /* the plate is 0.8 x 0.6 m, its top at z = 0.05; a cube reaches 0.26 m from its centre */
        vec3 x = leaving ? vec3_make(0.395, sym(0.1), 0.4) : vec3_make(sym(0.1), sym(0.02), 0.4);
        vec3 v = leaving ? vec3_make(speed, 0, sym(0.1)) : vec3_make(speed * cos(ang), speed * sin(ang), sym(0.1));
        make_body(&a, 1, sphere ? SPHERE : CUBE, 0);
        make_body(&b, 2, PLATE, 1);
        vrBody_Anchor(&b, 0, vec3_zero(), vec3_zero(), quat_identity(), vec3_zero(), &f);
        vrBody_Anchor(&a, te, x, v, sphere ? quat_identity() : random_turn(), sphere ? vec3_zero() : rvec(0.1), &f);
        /* lower it until the gap at te is as drawn */
        measure(&a, &b, te, &c, &pa, &pb);
        a.m.x0.z -= c.dist - gap;
        a.pose_valid = 0;
        measure(&a, &b, te, &c, &pa, &pb);
        vrDistBound_Make(&db, &a, &pa, &b, &pb, te, c.pa, c.pb, 1, te, t);
        ENSURE(db.valid && c.dist > 0 && (leaving || fabs(c.dist - gap) < 1e-9));
        measure(&a, &b, t, &at, &pa, &pb);
        if (at.dist <= 0) continue;   /* a corner turned into the plate */
        crossed += vrDistBound_Decide(&db, t, at.dist - 1e-9, 1e-14) == 1;
        if (leaving) continue;
        n++;
        spheres += sphere;
        decided += vrDistBound_Decide(&db, t, at.dist + 1e-6, 1e-12) == 1;
        spheres_decided += sphere && vrDistBound_Decide(&db, t, at.dist + 1e-6, 1e-12) == 1;
    }
    printf("    %d slides over the plate: %d decided (%d of %d spheres); %d crossings\n", n, decided,
           spheres_decided, spheres, crossed);
    ENSURE(crossed == 0);
    ENSURE(n > 150 && spheres_decided == spheres && decided > 3 * n / 4);
    return 0;
}

/* A sphere passing another at 10 m/s, 2 mm apart: the distance is that of
 * the centres less the radii, which grows with the square of the pass
 * only as the centres' distance does; the surface points that were
 * nearest drift 1 cm apart in 1 ms.  The bounds follow the centres. */
static int test_bounds_follow_a_sphere_passing_a_sphere(void)
{
    vrBody a, b;
    vrFlight f;
    vrContact c, at;
    vrDistBound db;
    vrPose pa, pb;
    int k, decided = 0, crossed = 0;
    f.accel = vec3_zero();
    f.max_linear = f.max_angular = 1e3;
    make_body(&a, 1, SPHERE, 0);
    make_body(&b, 2, SPHERE, 1);
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_zero(), quat_identity(), vec3_zero(), &f);
    vrBody_Anchor(&a, 0, vec3_make(-0.01, 0, a.shape.radius + b.shape.radius + 0.002), vec3_make(10, 0, 0),
                  quat_identity(), vec3_zero(), &f);
    measure(&a, &b, 1e-3, &c, &pa, &pb);
    vrDistBound_Make(&db, &a, &pa, &b, &pb, 1e-3, c.pa, c.pb, 1, 0, 2e-3);
    ENSURE(db.valid && fabs(c.dist - 0.002) < 1e-12);
    for (k = 0; k <= 20; k++) {
        double t = 1e-4 * k;
        measure(&a, &b, t, &at, &pa, &pb);
        decided += vrDistBound_Decide(&db, t, at.dist + 1e-6, 1e-12) == 1;
        crossed += vrDistBound_Decide(&db, t, at.dist, 1e-14) >= 0;
    }
    printf("    %d of 21 times decided, %d crossings\n", decided, crossed);
    ENSURE(decided == 21 && crossed == 0);
    return 0;
}

/* The schedule's key (schedule.c): how long the lower bound along the
 * measured direction stays clear of d (in closed form, as far as the bound
 * goes), for pairs 1 mm to 5 cm apart closing
 * at up to 30 m/s with spins to 115 rad/s, the envelope d half the gap.
 * Started at te, or at a later time the pair is known to be clear until
 * (as the speed bounds tell the schedule), the answer never passes a
 * sampled time within d, comes no earlier than the start, and gets past
 * it in most pairs; started later, it gets exactly as far (the same first
 * roots) or, if it starts past them, further. */
static int test_clear_never_passes_the_envelope(void)
{
    int trial, k, n = 0, passed = 0, advanced = 0, later_further = 0, short_of_bound = 0;
    for (trial = 0; trial < 2000; trial++) {
        vrBody a, b;
        vrFlight f;
        vrContact c, at;
        vrDistBound db;
        vrPose pa, pb;
        double te = (trial % 2 ? 60 : 0.05) * uni(), until = te + 0.05, d, first = until, from, t0, t1;
        if (!random_pair(&a, &b, trial, &f, te, &c)) continue;
        d = 0.5 * c.dist;
        for (k = 1; k <= 2000 && first == until; k++) {   /* the first sampled time within d */
            double t = te + (until - te) * k / 2000.0;
            measure(&a, &b, t, &at, &pa, &pb);
            if (at.dist <= d) first = t;
        }
        measure(&a, &b, te, &c, &pa, &pb);
        vrDistBound_MakeAlong(&db, &a, &pa, &b, &pb, te, vec3_normalize(vec3_sub(c.pb, c.pa)), te, until);
        if (!db.valid) continue;
        n++;
        from = te + (first - te) * 0.9 * uni();
        t0 = vrDistBound_Clear(&db, d, te, until);
        t1 = vrDistBound_Clear(&db, d, from, until);
        ENSURE(t0 >= te && t1 >= from);
        passed += t0 > first || t1 > first;
        advanced += t0 > te;
        later_further += t1 >= t0;
        /* as far as the bound goes: 1 ns later it is no longer clear of d */
        short_of_bound += t0 < until && vrDistBound_Decide(&db, t0 + 1e-9, d, 1e-9) == 0;
    }
    printf("    %d pairs: %d passed the envelope, %d advanced from te, %d as far or further from later, %d stopped"
           " short of the bound's crossing\n", n, passed, advanced, later_further, short_of_bound);
    ENSURE(n > 1000);
    ENSURE(passed == 0);
    ENSURE(advanced > n / 2 && later_further == n && short_of_bound == 0);
    return 0;
}

/* How long a pair surely stays within a level above its distance (quiet.c
 * keeps a pair in the envelope quiet that long): for pairs 1 mm to 5 cm
 * apart, moving at up to 16 m/s and spinning at up to 115 rad/s, the level
 * 0.1 to 5 cm above the distance, the answer never passes a sampled time
 * beyond the level, and gets past te in most pairs: by the witness points,
 * and over a static plate by the lowest point's height. */
static int test_stays_within_never_passes_the_level(void)
{
    int trial, k, n = 0, passed = 0, advanced = 0, over_plate = 0;
    for (trial = 0; trial < 2000; trial++) {
        vrBody a, b;
        vrFlight f;
        vrContact c, at;
        vrDistBound db;
        vrPose pa, pb;
        double te = (trial % 2 ? 60 : 0.05) * uni(), until = te + 0.05, level, stay;
        if (!random_pair(&a, &b, trial, &f, te, &c)) continue;
        level = c.dist + 0.001 + 0.049 * uni();
        measure(&a, &b, te, &c, &pa, &pb);
        vrDistBound_Make(&db, &a, &pa, &b, &pb, te, c.pa, c.pb, 1, te, until);
        if (!db.valid) continue;
        n++;
        stay = vrDistBound_StaysWithin(&db, level, until);
        ENSURE(stay >= te && stay <= until);
        advanced += stay > te;
        over_plate += stay > te && trial % 4 == 0;
        for (k = 1; k <= 400; k++) {
            measure(&a, &b, te + (stay - te) * k / 400.0, &at, &pa, &pb);
            passed += at.dist > level + 1e-12;   /* a sphere's root is exact: to rounding */
        }
    }
    printf("    %d pairs: %d samples past the level, %d advanced (%d over the plate)\n", n, passed, advanced, over_plate);
    ENSURE(n > 1000);
    ENSURE(passed == 0);
    ENSURE(advanced > n * 19 / 20 && over_plate > n / 8);
    return 0;
}

/* No bounds for what they do not model: a plate tumbling (its spin is not
 * constant), or a body reaching the speed cap inside the window. */
static int test_no_bounds_for_tumbling_or_capped_motion(void)
{
    vrBody a, b;
    vrFlight f;
    vrContact c;
    vrDistBound db;
    vrPose pa, pb;
    f.accel = vec3_make(0, 0, -9.8);
    f.max_linear = 1e3;
    f.max_angular = 1e3;
    make_body(&a, 1, PLATE, 0);
    make_body(&b, 2, CUBE, 1);
    vrBody_Anchor(&a, 0, vec3_zero(), vec3_make(0, 0, -1), quat_identity(), vec3_make(0.01, 0.02, 0.03), &f);
    vrBody_Anchor(&b, 0, vec3_make(0, 0, -0.3), vec3_zero(), quat_identity(), vec3_zero(), &f);
    measure(&a, &b, 0.001, &c, &pa, &pb);
    ENSURE(c.dist > 0 && a.rot != VR_ROT_ISOTROPIC && a.rot != VR_ROT_NONE);
    vrDistBound_Make(&db, &a, &pa, &b, &pb, 0.001, c.pa, c.pb, 1, 0, 0.002);
    ENSURE(!db.valid);
    /* the same plate not turning: bounds */
    vrBody_Anchor(&a, 0, vec3_zero(), vec3_make(0, 0, -1), quat_identity(), vec3_zero(), &f);
    measure(&a, &b, 0.001, &c, &pa, &pb);
    vrDistBound_Make(&db, &a, &pa, &b, &pb, 0.001, c.pa, c.pb, 1, 0, 0.002);
    ENSURE(db.valid);
    /* falling from 0.99 m/s, the cap of 1 m/s comes after ~1 ms */
    f.max_linear = 1;
    vrBody_Anchor(&a, 0, vec3_zero(), vec3_make(0, 0, -0.99), quat_identity(), vec3_zero(), &f);
    measure(&a, &b, 0.0005, &c, &pa, &pb);
    vrDistBound_Make(&db, &a, &pa, &b, &pb, 0.0005, c.pa, c.pb, 1, 0, 0.0009);
    ENSURE(db.valid);
    vrDistBound_Make(&db, &a, &pa, &b, &pb, 0.0005, c.pa, c.pb, 1, 0, 0.002);
    ENSURE(!db.valid);
    ENSURE(vrDistBound_Decide(&db, 0.0005, 1.0, 0) == -1);
    return 0;
}

/* A box's support along a direction comes in closed form (distbound.c
 * box_top): the same bits as the eight vertices' largest, in every pose
 * and along every direction, axis-aligned ones included, and the same
 * vertices followed when it turns. */
static int test_a_box_reaches_as_far_as_its_vertices(void)
{
    vrBody box, poly, plate;
    vrFlight f;
    vrPose pq, pp;
    double span;
    int trial, k, diffs = 0;
    f.accel = vec3_make(0, 0, -9.8);
    f.max_linear = 1e3;
    f.max_angular = 1e3;
    make_body(&plate, 3, PLATE, 1);
    vrBody_Anchor(&plate, 0, vec3_make(0, 0, -1), vec3_zero(), quat_identity(), vec3_zero(), &f);
    for (trial = 0; trial < 4000; trial++) {
        vrDistBound a, b;
        quat q = trial % 4 == 0 ? quat_identity() : random_turn();
        int cube = trial % 2;     /* a plate has no constant spin: still */
        vec3 L = !cube || trial % 3 == 0 ? vec3_zero() : vec3_scale(rvec(1), uni());
        vec3 n = trial % 5 == 0 ? vec3_make(0, 0, trial % 2 ? 1 : -1) : vec3_normalize(rvec(1));
        make_body(&box, 1, cube ? CUBE : PLATE, 0);
        vrBody_Anchor(&box, 0, rvec(5), rvec(3), q, L, &f);
        poly = box;
        poly.shape.kind = VR_SHAPE_POLY;
        vrBody_Pose(&box, 0.01, &pq);
        vrBody_Pose(&plate, 0.01, &pp);
        span = 0.001 + uni();     /* the vertices kept depend on the window */
        vrDistBound_MakeAlong(&a, &box, &pq, &plate, &pp, 0.01, n, 0, 0.01 + span);
        vrDistBound_MakeAlong(&b, &poly, &pq, &plate, &pp, 0.01, n, 0, 0.01 + span);
        ENSURE(a.valid && b.valid);
        diffs += memcmp(&a.gap_n, &b.gap_n, sizeof a.gap_n) != 0 || a.a.nv != b.a.nv
               || memcmp(&a.a.headroom, &b.a.headroom, sizeof a.a.headroom) != 0;
        for (k = 0; k < a.a.nv && k < b.a.nv; k++)
            diffs += memcmp(&a.a.g[k], &b.a.g[k], sizeof a.a.g[k]) != 0 || memcmp(&a.a.s[k], &b.a.s[k], sizeof a.a.s[k]) != 0;
    }
    printf("    4000 poses and directions: %d differences between the closed form and the vertices\n", diffs);
    ENSURE(diffs == 0);
    return 0;
}

static int make_polys(void)
{
    return vrPolyhedron_Cube(vec3_make(0.15, 0.15, 0.15), &cube_poly, NULL, 0)
        || vrPolyhedron_Cube(vec3_make(0.4, 0.3, 0.05), &plate_poly, NULL, 0);
}

static void free_polys(void)
{
    vrPolyhedron_Free(cube_poly);
    vrPolyhedron_Free(plate_poly);
}

static const vrTest tests[] = {
    TEST(test_bounds_never_cross_the_distance),
    TEST(test_bounds_decide_near_the_measurement),
    TEST(test_bounds_follow_the_vertex_that_overtakes),
    TEST(test_bounds_after_the_cap_follow_a_line),
    TEST(test_bounds_follow_a_body_sliding_over_a_wall),
    TEST(test_bounds_follow_a_sphere_passing_a_sphere),
    TEST(test_no_bounds_for_tumbling_or_capped_motion),
    TEST(test_clear_never_passes_the_envelope),
    TEST(test_stays_within_never_passes_the_level),
    TEST(test_a_box_reaches_as_far_as_its_vertices),
};

const vrTestSuite vrSuite_Distbound = {"distbound", tests, TEST_COUNT(tests), make_polys, free_polys, 0};
