/* test_motion.c — free flight (SPEC 3.2) against closed forms: exact
 * parabolas, the speed cap, torque-free rotation keeping L, the symmetric
 * top's precession against the general integrator, and determinism of the
 * pose as a pure function of the anchor and the time. */
#include <string.h>
#include "test.h"
#include "body.h"

static vrFlight flight(vec3 g, double vmax, double wmax)
{
    vrFlight f;
    f.accel = g;
    f.max_linear = vmax;
    f.max_angular = wmax;
    return f;
}

/* a box of half extents (a, b, c) and mass m */
static void box_body(vrBody *b, double m, double a, double bb, double c)
{
    mat33 unit = mat33_diag((bb * bb + c * c) / 3.0, (a * a + c * c) / 3.0, (a * a + bb * bb) / 3.0);
    memset(b, 0, sizeof *b);
    b->shape.kind = VR_SHAPE_BOX;
    b->shape.half = vec3_make(a, bb, c);
    vrBody_SetMassProperties(b, m, &unit, fmin(a, fmin(bb, c)), sqrt(a * a + bb * bb + c * c));
}

static int test_projectile_is_an_exact_parabola(void)
{
    vrBody b;
    vrFlight f = flight(vec3_make(0, 0, -9.8), 100, 4);
    vec3 x, v;
    box_body(&b, 2, 0.1, 0.1, 0.1);
    vrBody_Anchor(&b, 1.0, vec3_make(1, 2, 3), vec3_make(0.5, 0, 4), quat_identity(), vec3_zero(), &f);
    vrBody_Position(&b, 1.7, &x);
    vrBody_Velocity(&b, 1.7, &v);
    ENSURE_NEAR(x.x, 1 + 0.5 * 0.7, 1e-15);
    ENSURE_NEAR(x.z, 3 + 4 * 0.7 - 4.9 * 0.49, 1e-14);
    ENSURE_NEAR(v.z, 4 - 9.8 * 0.7, 1e-14);
    return 0;
}

/* thesis eq. (5)'s split: once |v| reaches max_linear, v stays constant */
static int test_speed_cap_holds_velocity_constant(void)
{
    vrBody b;
    vrFlight f = flight(vec3_make(0, 0, -10), 8, 4);
    vec3 x, v;
    box_body(&b, 1, 0.1, 0.1, 0.1);
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_zero(), quat_identity(), vec3_zero(), &f);
    ENSURE_NEAR(b.m.tcap, 0.8, 1e-15);
    vrBody_Velocity(&b, 2.0, &v);
    vrBody_Position(&b, 2.0, &x);
    ENSURE_NEAR(v.z, -8, 1e-14);
    ENSURE_NEAR(x.z, -0.5 * 10 * 0.64 - 8 * 1.2, 1e-13);
    /* an initial velocity above the cap is clamped at the anchor */
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_make(30, 40, 0), quat_identity(), vec3_zero(), &f);
    ENSURE_NEAR(vec3_len(b.m.v0), 8, 1e-14);
    return 0;
}

static int test_max_angular_clamps_spin_at_anchor(void)
{
    vrBody b;
    vrFlight f = flight(vec3_zero(), 8, 4);
    vrPose p;
    box_body(&b, 1, 0.1, 0.2, 0.3);
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_zero(), quat_identity(), vec3_make(1, 2, 3), &f);
    vrBody_Pose(&b, 0, &p);
    ENSURE(vec3_len(vrBody_Omega(&b, &p)) <= 4 + 1e-12);
    ENSURE_NEAR(vec3_len(vrBody_Omega(&b, &p)), 4, 1e-12);
    return 0;
}

static double rot_energy(vrBody *b, double t)
{
    vrPose p;
    vrBody_Pose(b, t, &p);
    return 0.5 * vec3_dot(vrBody_Omega(b, &p), b->m.L);
}

/* an asymmetric box tumbles: L is constant by construction; the energy of
 * the splitting integrator stays within 1e-6 per simulated second (SPEC 3.2) */
static int test_asymmetric_box_keeps_energy(void)
{
    vrBody b;
    vrFlight f = flight(vec3_zero(), 8, 100);
    double e0, worst = 0;
    int i;
    box_body(&b, 3, 0.1, 0.25, 0.4);
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_zero(), quat_identity(), vec3_make(0.05, 0.9, 0.02), &f);
    ENSURE(b.rot == VR_ROT_GENERAL);
    e0 = rot_energy(&b, 0);
    for (i = 1; i <= 100; i++) {
        double e = rot_energy(&b, 0.1 * i);
        if (fabs(e - e0) / e0 > worst) worst = fabs(e - e0) / e0;
    }
    printf("    energy drift over 10 s of tumbling: %.3g relative\n", worst);
    ENSURE(worst < 1e-6);
    return 0;
}

/* rotation about the middle axis is unstable: a tiny perturbation makes the
 * box flip (the tennis-racket effect) — a real tumble, not a constant spin */
static int test_middle_axis_spin_flips(void)
{
    vrBody b;
    vrFlight f = flight(vec3_zero(), 8, 100);
    vrPose p;
    double least = 1;
    int i;
    /* moments Iz < Iy < Ix: y is the middle axis; spin about it, slightly off */
    box_body(&b, 1, 0.05, 0.2, 0.4);
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_zero(), quat_identity(),
                  mat33_mulv(&b.inertia, vec3_make(1e-3, 5, 1e-3)), &f);
    for (i = 0; i < 400; i++) {
        vec3 yb;
        vrBody_Pose(&b, 0.05 * i, &p);
        yb = vrPose_rotate(&p, vec3_make(0, 1, 0));
        if (yb.y < least) least = yb.y;
    }
    ENSURE(least < -0.9);  /* the body's y axis turned over */
    return 0;
}

/* the general integrator on a symmetric body agrees with the exact
 * precession of the symmetric top (two methods, one answer) */
static int test_symmetric_top_matches_integrator(void)
{
    vrBody s, g;
    vrFlight f = flight(vec3_zero(), 8, 100);
    vec3 L = vec3_make(0.3, 0.2, 0.5);
    int i;
    box_body(&s, 2, 0.1, 0.1, 0.3);
    ENSURE(s.sym_axis >= 0 && s.sym_axis < 3);
    g = s;
    vrBody_Anchor(&s, 0, vec3_zero(), vec3_zero(), quat_from_axis_angle(vec3_make(0, 0.6, 0.8), 0.7), L, &f);
    ENSURE(s.rot == VR_ROT_SYMMETRIC);
    g.sym_axis = -1;                    /* pretend asymmetric */
    vrBody_Anchor(&g, 0, vec3_zero(), vec3_zero(), quat_from_axis_angle(vec3_make(0, 0.6, 0.8), 0.7), L, &f);
    ENSURE(g.rot == VR_ROT_GENERAL);
    for (i = 1; i <= 20; i++) {
        vrPose ps, pg;
        vrBody_Pose(&s, 0.25 * i, &ps);
        vrBody_Pose(&g, 0.25 * i, &pg);
        ENSURE_MSG(quat_angle_between(ps.q, pg.q) < 1e-5, "t=%g angle %g", 0.25 * i, quat_angle_between(ps.q, pg.q));
    }
    return 0;
}

/* the pose at t is a pure function of the anchor and t: queries in any
 * order, after any cache history, give the same bits */
static int test_pose_is_pure_function_of_time(void)
{
    vrBody a, b;
    vrFlight f = flight(vec3_make(0, 0, -9.8), 8, 100);
    double ts[] = {0.9, 0.1, 3.2, 3.1, 0.15, 2.0, 0.9};
    int i;
    box_body(&a, 1, 0.1, 0.2, 0.35);
    vrBody_Anchor(&a, 0.5, vec3_make(1, 1, 1), vec3_make(1, 0, 2), quat_identity(), vec3_make(0.2, 0.1, 0.05), &f);
    b = a;
    for (i = 0; i < 7; i++) {
        vrPose pa, pb;
        vrBody fresh = b;      /* a copy whose cache has seen nothing since the anchor */
        vrBody_Pose(&a, 0.5 + ts[i], &pa);
        vrBody_Pose(&fresh, 0.5 + ts[i], &pb);
        ENSURE(memcmp(&pa.q, &pb.q, sizeof pa.q) == 0);
        ENSURE(memcmp(&pa.p, &pb.p, sizeof pa.p) == 0);
    }
    return 0;
}

/* A body hanging still (no velocity, force or spin) serves one pose for
 * every time; it must be the pose a fresh copy computes at that time, bit
 * for bit, signed zeros included, and a body anchored anew must not be
 * served the old pose. */
static int test_a_still_body_has_one_pose_for_every_time(void)
{
    vrFlight none = flight(vec3_zero(), 8, 100), g = flight(vec3_make(0, 0, -9.8), 8, 100);
    struct { vec3 x, v; const vrFlight *f; } c[] = {
        {{1, -2, 3}, {0, 0, 0}, &none},     /* still */
        {{-0.0, 1, 0}, {0, 0, 0}, &none},   /* x0 + (-0) keeps -0, x0 + (+0) does not */
        {{0, 1, 2}, {-0.0, 0, 0}, &none},   /* v0 = -0: +0 at tau < 0, -0 after */
        {{0, 1, 2}, {0, 0, 0}, &g},         /* falls */
    };
    double ts[] = {4.0, -3.0, 7.5, 0.25, -0.5, 4.0};
    int k, i;
    for (k = 0; k < 4; k++) {
        vrBody a, fresh0;
        box_body(&a, 1, 0.1, 0.2, 0.35);
        vrBody_Anchor(&a, 1.0, c[k].x, c[k].v, quat_identity(), vec3_zero(), c[k].f);
        fresh0 = a;
        for (i = 0; i < 6; i++) {
            vrPose pa, pb;
            vrBody fresh = fresh0;
            vrBody_Pose(&a, ts[i], &pa);
            vrBody_Pose(&fresh, ts[i], &pb);
            ENSURE_MSG(memcmp(&pa.p, &pb.p, sizeof pa.p) == 0 && memcmp(&pa.q, &pb.q, sizeof pa.q) == 0,
                       "case %d at t = %g", k, ts[i]);
        }
        ENSURE(a.still == (k == 0));
        /* anchored anew with a speed: a new pose at a new time */
        {
            vrPose p0, p1;
            vrBody_Pose(&a, 2.0, &p0);
            vrBody_Anchor(&a, 2.0, p0.p, vec3_make(1, 0, 0), p0.q, vec3_zero(), &none);
            vrBody_Pose(&a, 3.0, &p1);
            ENSURE(p1.p.x == p0.p.x + 1.0);
        }
    }
    return 0;
}

/* an isotropic body spins at constant omega about L: exact */
static int test_isotropic_spin_is_exact(void)
{
    vrBody b;
    vrFlight f = flight(vec3_zero(), 8, 100);
    vrPose p;
    box_body(&b, 1, 0.2, 0.2, 0.2);
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_zero(), quat_identity(), vec3_scale(vec3_make(0, 0, 1), b.moments.x * 2.0), &f);
    ENSURE(b.rot == VR_ROT_ISOTROPIC);
    vrBody_Pose(&b, 0.75, &p);
    ENSURE_NEAR(quat_angle_between(quat_identity(), p.q), 1.5, 1e-14);
    return 0;
}

/* A cube's or sphere's world tensor is its body tensor: R (cI) R^T = cI.
 * Computed by rotation it carries rounding-sized off-diagonal entries, which
 * changed the response matrix's zero pattern (and cost a KLU factorisation)
 * at almost every contact; a box of three sides still turns with its pose. */
static int test_an_isotropic_body_has_one_world_inertia(void)
{
    vrBody cube, brick;
    mat33 noisy = mat33_diag(0.3, 0.3 * (1 + 4e-16), 0.3 * (1 - 2e-16));
    int k, i, j, turned = 0;
    memset(&cube, 0, sizeof cube);
    noisy.m[0][1] = noisy.m[1][0] = 1e-18;              /* a divergence-theorem sum's rounding */
    vrBody_SetMassProperties(&cube, 2, &noisy, 0.5, 0.9);
    ENSURE(cube.sym_axis == 3);
    box_body(&brick, 1, 0.1, 0.2, 0.3);
    for (k = 0; k < 50; k++) {
        quat q = quat_from_axis_angle(vec3_make(0.3 + k, 1 - 0.1 * k, 0.7), 0.37 * k + 0.1);
        vrPose pose = vrPose_make(vec3_zero(), q);
        mat33 I = vrBody_InertiaWorld(&cube, &pose), inv = vrBody_InvInertiaWorld(&cube, &pose);
        mat33 Ib = vrBody_InertiaWorld(&brick, &pose);
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) {
                ENSURE(I.m[i][j] == (i == j ? I.m[0][0] : 0.0));
                ENSURE(inv.m[i][j] == (i == j ? 1.0 / I.m[0][0] : 0.0));
            }
        ENSURE_NEAR(I.m[0][0], 0.6, 1e-15);
        turned += Ib.m[0][1] != 0.0;
    }
    ENSURE(turned >= 45);
    return 0;
}

/* the box the broadphase uses: every position of the path in [t1, t2] is
 * inside it, and it is no larger than the path (up a thrown ball's apex,
 * past the speed cap) */
static int test_path_box_is_the_paths_extent(void)
{
    vrBody b;
    vrFlight f = flight(vec3_make(0, 0, -9.8), 6, 4);
    int trial, i;
    unsigned s = 12345;
    box_body(&b, 1, 0.1, 0.1, 0.1);
    for (trial = 0; trial < 200; trial++) {
        vec3 v, lo, hi, slo, shi, x;
        double t1, t2;
        s = s * 1103515245u + 12345u; v.x = (double)(s >> 16 & 1023) / 128.0 - 4;
        s = s * 1103515245u + 12345u; v.y = (double)(s >> 16 & 1023) / 128.0 - 4;
        s = s * 1103515245u + 12345u; v.z = (double)(s >> 16 & 1023) / 128.0 - 4;
        s = s * 1103515245u + 12345u; t1 = (double)(s >> 16 & 1023) / 1024.0;
        t2 = t1 + 0.05 + (trial % 7) * 0.2;
        vrBody_Anchor(&b, 0.25, vec3_make(1, -2, 3), v, quat_identity(), vec3_zero(), &f);
        vrBody_PathBox(&b, t1, t2, &lo, &hi);
        vrBody_Position(&b, t1, &slo);
        shi = slo;
        for (i = 0; i <= 4000; i++) {
            vrBody_Position(&b, t1 + (t2 - t1) * i / 4000.0, &x);
            ENSURE(x.x >= lo.x - 1e-12 && x.y >= lo.y - 1e-12 && x.z >= lo.z - 1e-12);
            ENSURE(x.x <= hi.x + 1e-12 && x.y <= hi.y + 1e-12 && x.z <= hi.z + 1e-12);
            slo = vec3_make(fmin(slo.x, x.x), fmin(slo.y, x.y), fmin(slo.z, x.z));
            shi = vec3_make(fmax(shi.x, x.x), fmax(shi.y, x.y), fmax(shi.z, x.z));
        }
        /* samples 1/4000 of the span apart miss the extremes by < 6 m/s x that */
        ENSURE(vec3_len(vec3_sub(lo, slo)) + vec3_len(vec3_sub(hi, shi)) < 6 * (t2 - t1) / 4000.0 * 2);
    }
    return 0;
}

static const vrTest tests[] = {
    TEST(test_projectile_is_an_exact_parabola),
    TEST(test_speed_cap_holds_velocity_constant),
    TEST(test_max_angular_clamps_spin_at_anchor),
    TEST(test_asymmetric_box_keeps_energy),
    TEST(test_middle_axis_spin_flips),
    TEST(test_symmetric_top_matches_integrator),
    TEST(test_pose_is_pure_function_of_time),
    TEST(test_a_still_body_has_one_pose_for_every_time),
    TEST(test_isotropic_spin_is_exact),
    TEST(test_an_isotropic_body_has_one_world_inertia),
    TEST(test_path_box_is_the_paths_extent),
};

const vrTestSuite vrSuite_Motion = {"motion", tests, TEST_COUNT(tests), NULL, NULL, 0};
