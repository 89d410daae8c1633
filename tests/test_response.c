/* test_response.c — the 15x15 KLU response (SPEC 3.4) against the
 * closed-form impulse, on random contacts and on the axis-aligned ones that
 * break a reused pivot order. */
#include "test.h"
#include "response.h"

#define TEST_LCG_SEED 12345ULL
#include "test_lcg.h"

/* a random rigid body: mass, SPD inertia R D R^T, lever arm, velocities */
static void random_body(vrImpactBody *b, int is_static)
{
    quat q = quat_normalize(quat_make(sym(1), sym(1), sym(1), sym(1)));
    mat33 R = mat33_from_quat(q), D = mat33_diag(0.1 + uni(), 0.1 + uni(), 0.1 + uni());
    b->is_static = is_static;
    b->mass = 0.2 + 3 * uni();
    b->inertia = mat33_rotate_tensor(&R, &D);
    b->inv_inertia = mat33_inverse(&b->inertia);
    b->p = rvec(0.5);
    b->v = is_static ? vec3_zero() : rvec(3);
    b->w = is_static ? vec3_zero() : rvec(2);
}

/* the response's velocities equal those of R = -j n with the closed-form j */
static int check_against_closed_form(vrResponder *r, const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e)
{
    vec3 v1, w1, v2, w2, R;
    double j = vrResponse_ClosedForm(b1, b2, n, e), scale = 1 + fabs(j);
    vec3 Rj = vec3_scale(n, -j);
    ENSURE(vrResponder_Solve(r, b1, b2, n, e, 0, &v1, &w1, &v2, &w2, &R) == 0);
    ENSURE_NEAR(R.x, Rj.x, 1e-12 * scale);
    ENSURE_NEAR(R.y, Rj.y, 1e-12 * scale);
    ENSURE_NEAR(R.z, Rj.z, 1e-12 * scale);
    if (!b1->is_static) {
        vec3 dv = vec3_sub(v1, vec3_madd(b1->v, 1.0 / b1->mass, Rj));
        ENSURE(vec3_len(dv) < 1e-12 * scale);
    } else {
        ENSURE(vec3_len(vec3_sub(v1, b1->v)) == 0 && vec3_len(vec3_sub(w1, b1->w)) == 0);
    }
    if (!b2->is_static) {
        vec3 dw = vec3_sub(w2, vec3_add(b2->w, mat33_mulv(&b2->inv_inertia, vec3_cross(b2->p, vec3_neg(Rj)))));
        ENSURE(vec3_len(dw) < 1e-12 * scale * 10);
    }
    return 0;
}

static int test_klu_matches_closed_form_on_random_contacts(void)
{
    vrResponder *r = vrResponder_Create();
    int i;
    ENSURE(r);
    for (i = 0; i < 2000; i++) {
        vrImpactBody b1, b2;
        vec3 n = vec3_normalize(rvec(1));
        random_body(&b1, i % 7 == 3);
        random_body(&b2, i % 5 == 1 && i % 7 != 3);
        if (check_against_closed_form(r, &b1, &b2, n, uni())) { vrResponder_Free(r); return 1; }
    }
    ENSURE(vrResponder_Stats(r).solves == 2000);
    vrResponder_Free(r);
    return 0;
}

/* axis-aligned normals and lever arms put exact zeros on pivots; the solve
 * must notice (singular or poor refactor) and factor afresh */
static int test_axis_aligned_contacts_refactor_from_scratch(void)
{
    vrResponder *r = vrResponder_Create();
    vrImpactBody b1, b2;
    vrResponseStats s;
    int axis;
    ENSURE(r);
    for (axis = 0; axis < 3; axis++) {
        vec3 n = vec3_make(axis == 0, axis == 1, axis == 2);
        b1.is_static = 0; b2.is_static = 1;
        b1.mass = 1; b2.mass = 1;
        b1.inertia = b2.inertia = mat33_diag(0.4, 0.4, 0.4);
        b1.inv_inertia = b2.inv_inertia = mat33_diag(2.5, 2.5, 2.5);
        b1.p = vec3_scale(n, -0.1);   /* a sphere resting on a plane: p parallel to n */
        b2.p = vec3_scale(n, 0.5);
        b1.v = vec3_scale(n, 2.0);
        b1.w = b2.v = b2.w = vec3_zero();
        if (check_against_closed_form(r, &b1, &b2, n, 0.8)) { vrResponder_Free(r); return 1; }
    }
    s = vrResponder_Stats(r);
    ENSURE(s.solves == 3);
    ENSURE(s.refactors == 3);
    ENSURE(s.factors == 3);        /* one canonical factorisation per zero pattern */
    vrResponder_Free(r);
    return 0;
}

/* masses and inertias over 12 orders of magnitude: where a canonical pivot
 * order goes bad the solve must notice and factor afresh, and stay right */
static int test_extreme_scales_stay_accurate(void)
{
    vrResponder *r = vrResponder_Create();
    vrResponseStats s;
    int i;
    ENSURE(r);
    for (i = 0; i < 500; i++) {
        vrImpactBody b1, b2;
        double k1 = pow(10, -6 + 12 * uni()), k2 = pow(10, -6 + 12 * uni());
        vec3 n = vec3_normalize(rvec(1));
        random_body(&b1, 0);
        random_body(&b2, 0);
        b1.mass *= k1;
        b1.inertia = mat33_scale(&b1.inertia, k1 * pow(10, -3 + 6 * uni()));
        b1.inv_inertia = mat33_inverse(&b1.inertia);
        b2.mass *= k2;
        b2.inertia = mat33_scale(&b2.inertia, k2);
        b2.inv_inertia = mat33_inverse(&b2.inertia);
        {
            vec3 v1, w1, v2, w2, R;
            double j = vrResponse_ClosedForm(&b1, &b2, n, 0.5);
            ENSURE(vrResponder_Solve(r, &b1, &b2, n, 0.5, 0, &v1, &w1, &v2, &w2, &R) == 0);
            ENSURE_MSG(vec3_len(vec3_add(R, vec3_scale(n, j))) <= 1e-9 * fabs(j), "case %d: %.17g vs %.17g m %g %g rel %g", i, vec3_dot(R, n), -j, b1.mass, b2.mass, vec3_len(vec3_add(R, vec3_scale(n, j)))/fabs(j));
        }
    }
    s = vrResponder_Stats(r);
    printf("    %lld solves, %lld refactors, %lld factorisations\n", s.solves, s.refactors, s.factors);
    vrResponder_Free(r);
    return 0;
}

/* a ball hitting a wall head-on with e: its normal speed becomes e times */
static int test_restitution_scales_normal_speed(void)
{
    vrResponder *r = vrResponder_Create();
    vrImpactBody ball, wall;
    vec3 v1, w1, v2, w2;
    vec3 n = vec3_make(1, 0, 0);
    ENSURE(r);
    ball.is_static = 0; wall.is_static = 1;
    ball.mass = 2; wall.mass = 1;
    ball.inertia = mat33_diag(0.08, 0.08, 0.08);
    ball.inv_inertia = mat33_inverse(&ball.inertia);
    wall.inertia = wall.inv_inertia = mat33_identity();
    ball.p = vec3_make(0.5, 0, 0);
    wall.p = vec3_make(-1, 0, 0);
    ball.v = vec3_make(3, 1, 0);
    ball.w = wall.v = wall.w = vec3_zero();
    ENSURE(vrResponder_Solve(r, &ball, &wall, n, 0.5, 0, &v1, &w1, &v2, &w2, NULL) == 0);
    ENSURE_NEAR(v1.x, -1.5, 1e-14);
    ENSURE_NEAR(v1.y, 1, 1e-14);        /* frictionless: tangential speed kept */
    ENSURE_NEAR(vec3_len(w1), 0, 1e-14);
    vrResponder_Free(r);
    return 0;
}

/* the same contact gives the same bits whatever was solved before (the
 * pivot order must not carry history between processes) */
static int test_solution_independent_of_history(void)
{
    vrResponder *a = vrResponder_Create(), *b = vrResponder_Create();
    vrImpactBody b1, b2, c1, c2;
    vec3 n = vec3_normalize(vec3_make(0.2, -0.7, 0.4)), va, wa, vb, wb, x, y;
    int i;
    ENSURE(a && b);
    random_body(&b1, 0);
    random_body(&b2, 0);
    for (i = 0; i < 50; i++) {          /* a history for a only, incl. axis-aligned ones */
        random_body(&c1, 0);
        random_body(&c2, i % 3 == 0);
        if (i % 4 == 0) { c1.p = vec3_make(0, 0, -0.2); c2.p = vec3_make(0, 0, 0.2); }
        vrResponder_Solve(a, &c1, &c2, i % 4 == 0 ? vec3_make(0, 0, 1) : vec3_normalize(rvec(1)), 0.5, 0, &va, &wa, &vb, &wb, NULL);
    }
    ENSURE(vrResponder_Solve(a, &b1, &b2, n, 0.7, 0, &va, &wa, &x, &y, NULL) == 0);
    ENSURE(vrResponder_Solve(b, &b1, &b2, n, 0.7, 0, &vb, &wb, &x, &y, NULL) == 0);
    ENSURE(va.x == vb.x && va.y == vb.y && va.z == vb.z && wa.x == wb.x && wa.y == wb.y && wa.z == wb.z);
    vrResponder_Free(a);
    vrResponder_Free(b);
    return 0;
}

/* Light bodies (0.1-0.5 kg, inertias 1e-4 to 1e-3 kg m^2: an apple, a
 * mug) against static ones and each other: the rows come in unit-free
 * (response.c), so KLU's pivots are about one, its rcond says the contact
 * is well conditioned, and iterative refinement is rarely needed (with
 * the rows in kilograms and kg m^2, Office refined nearly every solve). */
static int test_light_bodies_need_no_refinement(void)
{
    vrResponder *r = vrResponder_Create();
    vrImpactBody b1, b2;
    int i;
    for (i = 0; i < 1000; i++) {
        vec3 n = vec3_normalize(rvec(1));
        random_body(&b1, 0);
        random_body(&b2, i % 2 == 0);
        b1.mass = 0.1 + 0.4 * uni();
        b1.inertia = mat33_scale(&b1.inertia, pow(10, -4 + uni()));
        b1.inv_inertia = mat33_inverse(&b1.inertia);
        b1.p = rvec(0.08);
        if (check_against_closed_form(r, &b1, &b2, n, uni())) { vrResponder_Free(r); return 1; }
    }
    printf("    %lld of 1000 solves refined\n", vrResponder_Stats(r).refined);
    ENSURE(vrResponder_Stats(r).refined < 100);
    vrResponder_Free(r);
    return 0;
}

/* a 1 kg ball of radius r falling on a static floor at vn with slip vt,
 * no spin, friction mu and restitution e: the velocities after */
static int ball_on_floor(double mu, double e, double vn, double vt, vec3 *v, vec3 *w)
{
    vrResponder *r = vrResponder_Create();
    vrImpactBody floor, ball;
    vec3 v2, w2;
    double rad = 0.2, I = 0.4 * rad * rad;
    if (!r) return -1;
    memset(&floor, 0, sizeof floor);
    memset(&ball, 0, sizeof ball);
    floor.is_static = 1, floor.mass = 1, floor.inertia = floor.inv_inertia = mat33_identity();
    floor.p = vec3_make(0, 0, -1);
    ball.mass = 1, ball.inertia = mat33_diag(I, I, I), ball.inv_inertia = mat33_diag(1 / I, 1 / I, 1 / I);
    ball.p = vec3_make(0, 0, -rad);
    ball.v = vec3_make(vt, 0, -vn);
    /* body 1 the ball, body 2 the floor: n from the ball toward the floor */
    if (vrResponder_Solve(r, &ball, &floor, vec3_make(0, 0, -1), e, mu, v, w, &v2, &w2, NULL) != 0) {
        vrResponder_Free(r);
        return -1;
    }
    vrResponder_Free(r);
    return 0;
}

/* Coulomb at an impact, against the closed forms for a ball: with enough
 * friction the contact point leaves the floor sticking (v = 5/7 vt, rolling
 * omega = v / r); with little, the ball keeps sliding and loses mu (1 + e)
 * vn of its tangential speed, spun up by (5/2) mu (1 + e) vn / r. */
static int test_friction_at_impact_sticks_or_slides(void)
{
    double rad = 0.2, e = 0.5, vn = 2, vt = 1;
    vec3 v, w;
    ENSURE(ball_on_floor(1.0, e, vn, vt, &v, &w) == 0);
    ENSURE_NEAR(v.z, e * vn, 1e-12);
    ENSURE_NEAR(v.x, 5.0 / 7 * vt, 1e-12);
    ENSURE_NEAR(w.y * rad, v.x, 1e-12);
    ENSURE(ball_on_floor(0.05, e, vn, vt, &v, &w) == 0);
    ENSURE_NEAR(v.z, e * vn, 1e-12);
    ENSURE_NEAR(v.x, vt - 0.05 * (1 + e) * vn, 1e-12);
    ENSURE_NEAR(w.y, 2.5 * 0.05 * (1 + e) * vn / rad, 1e-12);
    ENSURE(ball_on_floor(0, e, vn, vt, &v, &w) == 0);
    ENSURE_NEAR(v.x, vt, 1e-15);
    return 0;
}

static double kinetic(const vrImpactBody *b, vec3 v, vec3 w)
{
    return b->is_static ? 0 : 0.5 * b->mass * vec3_dot(v, v) + 0.5 * vec3_dot(w, mat33_mulv(&b->inertia, w));
}

/* Random contacts with random friction and restitution: the kinetic
 * energy after never exceeds before, and the tangential impulse never
 * exceeds mu times the normal one. */
static int test_friction_at_impact_never_gains_energy(void)
{
    vrResponder *r = vrResponder_Create();
    double worst = -INFINITY, cone = 0;
    int i;
    ENSURE(r);
    for (i = 0; i < 2000; i++) {
        vrImpactBody b1, b2;
        vec3 n = vec3_normalize(rvec(1)), v1, w1, v2, w2, R;
        double mu = 2 * uni(), e = uni(), u, before, after, Rn;
        random_body(&b1, i % 7 == 3);
        random_body(&b2, i % 5 == 1 && i % 7 != 3);
        u = vec3_dot(n, vec3_sub(vec3_add(b2.v, vec3_cross(b2.w, b2.p)), vec3_add(b1.v, vec3_cross(b1.w, b1.p))));
        if (u >= 0) n = vec3_neg(n);      /* approaching: n.u < 0 */
        ENSURE(vrResponder_Solve(r, &b1, &b2, n, e, mu, &v1, &w1, &v2, &w2, &R) == 0);
        before = kinetic(&b1, b1.v, b1.w) + kinetic(&b2, b2.v, b2.w);
        after = kinetic(&b1, v1, w1) + kinetic(&b2, v2, w2);
        worst = vr_max(worst, (after - before) / before);
        Rn = -vec3_dot(R, n);
        cone = vr_max(cone, vec3_len(vec3_madd(R, Rn, n)) - mu * Rn);
    }
    printf("    largest relative gain %.3g, largest excess over the cone %.3g N s\n", worst, cone);
    ENSURE(worst <= 1e-12);
    ENSURE(cone <= 1e-9);
    vrResponder_Free(r);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_klu_matches_closed_form_on_random_contacts),
    TEST(test_axis_aligned_contacts_refactor_from_scratch),
    TEST(test_extreme_scales_stay_accurate),
    TEST(test_restitution_scales_normal_speed),
    TEST(test_solution_independent_of_history),
    TEST(test_light_bodies_need_no_refinement),
    TEST(test_friction_at_impact_sticks_or_slides),
    TEST(test_friction_at_impact_never_gains_energy),
};

const vrTestSuite vrSuite_Response = {"response", tests, TEST_COUNT(tests), NULL, NULL, 0};
