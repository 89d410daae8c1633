/* test_impacts.c — impacts against closed forms (SPEC 3.4): a dropped ball
 * bounces back to h e^2, keeps its energy over 100 bounces at e = 1 (and
 * over bounces a few millimetres high) and
 * stops and rests at e = 0; head-on balls follow the 1-D formulas; e = 1/2
 * halves the speed against a wall; off-centre hits of tumbling cubes and
 * superquadrics keep linear and angular momentum (and energy at e = 1). */
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "world_state.h"
#include "scene.h"

/* ---- bouncing --------------------------------------------------------------- */

/* a table top at z = 0.05 (slab 0.1 thick); a ball of radius 0.1 is in
 * contact at the contact gap g_c = min(d, 1 mm) (SPEC 7), its centre at
 * 0.15 + g_c */
static double contact_gap(double d) { return d < 1e-3 ? d : 1e-3; }

static vrWorld *drop_scene(double e, double h, double d, double time_step, vrObjectId *ball)
{
    vrWorld *w = vrScene_World(time_step, d, 9.8);
    vrScene_Box(w, "table", vec3_make(2, 2, 0.05), vec3_make(0, 0, 0), -1, 1.0);
    *ball = vrScene_Sphere(w, "ball", 0.1, vec3_make(0, 0, 0.15 + contact_gap(d) + h), vec3_zero(), 1, e);
    return w;
}

/* SPEC 3: a ball dropped from h above the contact height bounces back to
 * h e^2 above it */
static int test_ball_dropped_from_h_bounces_to_h_e2(void)
{
    double h = 1.0, d = 0.01, e = 0.8, apex = -1, contact = 0.15 + contact_gap(d), low = 1e9;
    vrObjectId ball;
    vrWorld *w = drop_scene(e, h, d, 0.001, &ball);
    int i;
    for (i = 0; i < 1500; i++) {
        vrObjectState s;
        ENSURE(vrScene_Step(w, 1) == 0);
        s = vrScene_State(w, ball);
        if (s.position[2] < low) low = s.position[2];
        if (low < contact + 1e-3 && s.position[2] > apex) apex = s.position[2];
    }
    /* it turned around at the contact gap, never below it (sampled every 1 ms at ~4.4 m/s) */
    ENSURE(low >= contact - 1e-12 && low <= contact + sqrt(2 * 9.8 * h) * 0.001);
    ENSURE_NEAR(apex - contact, h * e * e, 1e-3);
    ENSURE(vrScene_Stats(w).collisions >= 1);
    vrWorld_Destroy(w);
    return 0;
}

/* e = 1 loses nothing: 100 bounces, energy to 1e-6 relative */
static int test_elastic_ball_keeps_energy_over_100_bounces(void)
{
    vrObjectId ball;
    vrWorld *w = drop_scene(1.0, 1.0, 0.01, 0.1, &ball);
    double e0;
    vrStats s;
    ENSURE(vrScene_Step(w, 0) == 0);
    e0 = vrScene_Stats(w).energy;
    ENSURE(vrScene_Step(w, 920) == 0);                      /* ~ 100 bounces of 0.9 s */
    s = vrScene_Stats(w);
    printf("    %lld bounces, energy %.17g -> %.17g\n", s.collisions, e0, s.energy);
    ENSURE(s.collisions >= 100);
    ENSURE_NEAR(s.energy, e0, 1e-6 * fabs(e0));
    vrWorld_Destroy(w);
    return 0;
}

/* ...and so do bounces a few millimetres high, which come in faster than
 * v_rest (0.14 m/s: a fall through g_c) but within the island step's
 * reach (2 g_c): dropped from 3, 4, 5 and 8 mm above the contact height,
 * 10 ms frames, the ball keeps bouncing for 5 s, 30 to 120 times, with
 * its energy to 1e-9.  Before, a point coming in slower than v_rest plus
 * the speed that closes its gap within the step was slowed to the latter
 * (and flew the rest of the step with the step's gravity paid in, which
 * loses m |g h|^2 / 2): at 4 mm the ball came to rest on its first
 * bounce. */
static int test_elastic_ball_keeps_bouncing_millimetres_high(void)
{
    const double heights[] = {0.003, 0.004, 0.005, 0.008};
    int k;
    for (k = 0; k < 4; k++) {
        vrObjectId ball;
        vrWorld *w = drop_scene(1.0, heights[k], 0.01, 0.01, &ball);
        double e0;
        vrStats s;
        ENSURE(vrScene_Step(w, 0) == 0);
        e0 = vrScene_Stats(w).energy;
        ENSURE(vrScene_Step(w, 500) == 0);
        s = vrScene_Stats(w);
        printf("    from %g mm: %lld bounces, energy %.17g -> %.17g, %s\n", heights[k] * 1e3, s.collisions, e0, s.energy,
               vrScene_State(w, ball).state == VR_STATE_REST ? "at rest" : "bouncing");
        ENSURE(vrScene_State(w, ball).state != VR_STATE_REST);
        ENSURE(s.collisions >= 30);
        ENSURE_NEAR(s.energy, e0, 1e-9 * fabs(e0));
        vrWorld_Destroy(w);
    }
    return 0;
}

/* e = 0: it stops on the first impact and comes to rest on the table (a
 * contact impulse or two may follow while gravity brings it back in
 * before the next island step holds it: which grid points the rest of the
 * step is looked at sets whether the approach there is faster than v_eps) */
static int test_inelastic_ball_stops_and_rests(void)
{
    vrObjectId ball;
    vrWorld *w = drop_scene(0.0, 0.5, 0.01, 0.1, &ball);
    vrObjectState s;
    ENSURE(vrScene_Step(w, 30) == 0);
    s = vrScene_State(w, ball);
    ENSURE(vrScene_Stats(w).collisions <= 3);
    ENSURE(s.state == VR_STATE_REST);
    ENSURE(s.position[2] >= 0.15 && s.position[2] <= 0.15 + 0.01 + 1e-12);
    vrWorld_Destroy(w);
    return 0;
}

/* ---- collisions of two bodies --------------------------------------------------- */

static int test_head_on_equal_masses_exchange_velocities(void)
{
    vrWorld *w = vrScene_World(0.1, 0.01, 0);
    vrObjectId a = vrScene_Sphere(w, "a", 0.1, vec3_make(-1, 0, 0), vec3_make(1, 0, 0), 1, 1);
    vrObjectId b = vrScene_Sphere(w, "b", 0.1, vec3_make(1, 0, 0), vec3_make(-0.5, 0, 0), 1, 1);
    ENSURE(vrScene_Step(w, 20) == 0);
    ENSURE_NEAR(vrScene_State(w, a).linear_vel[0], -0.5, 1e-9);
    ENSURE_NEAR(vrScene_State(w, b).linear_vel[0], 1.0, 1e-9);
    ENSURE(vrScene_Stats(w).collisions == 1);
    ENSURE(vrScene_Stats(w).klu_solves == vrScene_Stats(w).collisions);
    vrWorld_Destroy(w);
    return 0;
}

/* 1D elastic formulas: v1' = (m1-m2)/(m1+m2) v1, v2' = 2 m1/(m1+m2) v1 */
static int test_head_on_unequal_masses_follow_1d_formulas(void)
{
    vrWorld *w = vrScene_World(0.1, 0.01, 0);
    vrObjectId a = vrScene_Sphere(w, "a", 0.1, vec3_make(-1, 0, 0), vec3_make(2, 0, 0), 1, 1);
    vrObjectId b = vrScene_Sphere(w, "b", 0.2, vec3_make(1, 0, 0), vec3_zero(), 3, 1);
    ENSURE(vrScene_Step(w, 20) == 0);
    ENSURE_NEAR(vrScene_State(w, a).linear_vel[0], -1.0, 1e-9);
    ENSURE_NEAR(vrScene_State(w, b).linear_vel[0], 1.0, 1e-9);
    vrWorld_Destroy(w);
    return 0;
}

static int test_restitution_half_against_wall_halves_speed(void)
{
    vrWorld *w = vrScene_World(0.1, 0.01, 0);
    vrObjectId a = vrScene_Sphere(w, "a", 0.1, vec3_make(0, 0, 0), vec3_make(2, 0, 0), 1, 0.5);
    vrScene_Box(w, "wall", vec3_make(0.1, 1, 1), vec3_make(1, 0, 0), -1, 1);
    ENSURE(vrScene_Step(w, 10) == 0);
    ENSURE_NEAR(vrScene_State(w, a).linear_vel[0], -1.0, 1e-9);
    ENSURE_NEAR(vrScene_State(w, a).linear_vel[1], 0.0, 1e-12);
    vrWorld_Destroy(w);
    return 0;
}

/* linear momentum, angular momentum about the origin, and energy (e = 1)
 * of two tumbling bodies before and after an off-centre hit */
typedef struct { vec3 P, L; double E; } vrMomenta;

static void momenta(const vrWorld *w, const vrObjectId *ids, const double *m, const double *k, int n, vrMomenta *out)
{
    int i;
    out->P = out->L = vec3_zero();
    out->E = 0;
    for (i = 0; i < n; i++) {
        vrObjectState s = vrScene_State(w, ids[i]);
        vec3 x = vrScene_Position(&s), v = vrScene_LinearVel(&s), om = vec3_make(s.angular_vel[0], s.angular_vel[1], s.angular_vel[2]);
        out->P = vec3_madd(out->P, m[i], v);
        /* isotropic bodies (spheres, cubes): spin momentum I omega, I = k m */
        out->L = vec3_add(out->L, vec3_add(vec3_scale(vec3_cross(x, v), m[i]), vec3_scale(om, k[i] * m[i])));
        out->E += 0.5 * m[i] * vec3_dot(v, v) + 0.5 * k[i] * m[i] * vec3_dot(om, om);
    }
}

static int conserve_case(double e)
{
    vrWorld *w = vrScene_World(0.05, 0.01, 0);
    vrObjectId ids[2];
    double m[2] = {1.3, 2.1}, k[2] = {2.0 * 0.15 * 0.15 / 3.0, 2.0 * 0.2 * 0.2 / 3.0};
    double rot1[4] = {0.3, 0.9, 0.2, 0.7}, rot2[4] = {-0.5, 0.2, 0.8, 1.1};
    double spin1[3] = {0.4, -1.1, 0.7}, spin2[3] = {-0.9, 0.3, 0.5};
    vrMomenta before, after;
    ids[0] = vrScene_Box(w, "a", vec3_make(0.15, 0.15, 0.15), vec3_make(-1, 0.05, 0.07), m[0], e);
    ids[1] = vrScene_Box(w, "b", vec3_make(0.2, 0.2, 0.2), vec3_make(1, -0.04, -0.1), m[1], e);
    vrScene_Edit(w, ids[0], vrScene_SetRotation, rot1);
    vrScene_Edit(w, ids[1], vrScene_SetRotation, rot2);
    vrScene_Edit(w, ids[0], vrScene_SetSpin, spin1);
    vrScene_Edit(w, ids[1], vrScene_SetSpin, spin2);
    {
        vrObjectDef d;
        vrWorld_GetObjectDef(w, ids[0], &d);
        d.linear_vel[0] = 1.5;
        vrWorld_SetObjectDef(w, ids[0], &d, NULL, 0);
    }
    ENSURE(vrScene_Step(w, 0) == 0);
    momenta(w, ids, m, k, 2, &before);
    ENSURE(vrScene_Step(w, 30) == 0);
    ENSURE(vrScene_Stats(w).collisions >= 1);
    momenta(w, ids, m, k, 2, &after);
    ENSURE(vec3_len(vec3_sub(after.P, before.P)) < 1e-9);
    ENSURE_MSG(vec3_len(vec3_sub(after.L, before.L)) < 1e-9, "dL %g", vec3_len(vec3_sub(after.L, before.L)));
    if (e == 1.0) ENSURE_NEAR(after.E, before.E, 1e-9 * before.E);
    else ENSURE(after.E < before.E);
    vrWorld_Destroy(w);
    return 0;
}

static int test_offcentre_cube_hit_conserves_momenta(void)
{
    return conserve_case(1.0) || conserve_case(0.4);
}

/* the same with two asymmetric superquadrics (tumbling: the splitting
 * integrator) and their true inertia tensors from the divergence theorem */
static void true_momenta(vrWorld *w, const vrObjectId *ids, int n, vrMomenta *out)
{
    int i;
    out->P = out->L = vec3_zero();
    out->E = 0;
    for (i = 0; i < n; i++) {
        vrObjectState s = vrScene_State(w, ids[i]);
        const vrBody *b = &vrWorld_Object(w, ids[i])->body;
        vrPose p = vrPose_make(vrScene_Position(&s), quat_make(s.orientation[0], s.orientation[1], s.orientation[2], s.orientation[3]));
        mat33 I = mat33_rotate_tensor(&p.R, &b->inertia);
        vec3 v = vrScene_LinearVel(&s), om = vec3_make(s.angular_vel[0], s.angular_vel[1], s.angular_vel[2]);
        out->P = vec3_madd(out->P, b->mass, v);
        out->L = vec3_add(out->L, vec3_add(vec3_scale(vec3_cross(p.p, v), b->mass), mat33_mulv(&I, om)));
        out->E += 0.5 * b->mass * vec3_dot(v, v) + 0.5 * vec3_dot(om, mat33_mulv(&I, om));
    }
}

static int superquadric_case(double e)
{
    vrWorld *w = vrScene_World(0.05, 0.01, 0);
    vrObjectId ids[2];
    vrMomenta before, after;
    int i;
    for (i = 0; i < 2; i++) {
        vrObjectDef d = vrObjectDef_Default(VR_SUPERQUADRIC);
        d.exp1 = 0.5; d.exp2 = 0.7;
        d.a1 = 0.25 - 0.05 * i; d.a2 = 0.15; d.a3 = 0.1 + 0.04 * i;
        d.translate[0] = i ? 0.8 : -0.8; d.translate[1] = i ? -0.05 : 0.06; d.translate[2] = i ? 0.04 : 0;
        d.linear_vel[0] = i ? -0.7 : 1.1;
        d.angular_vel[0] = i ? 0.3 : -0.8; d.angular_vel[1] = i ? 1.2 : 0.4; d.angular_vel[2] = i ? -0.5 : 0.9;
        d.rotate_set = 1;
        d.rotate_axis[0] = 0.2 + i; d.rotate_axis[1] = 1; d.rotate_axis[2] = 0.3;
        d.rotate_angle = 0.6 + i;
        d.mass = 1.5 + i;
        d.mass_set = 1;
        d.elasticity = e;
        ids[i] = vrScene_Add(w, i ? "sq1" : "sq0", VR_SUPERQUADRIC, &d);
    }
    ENSURE(vrWorld_Start(w, NULL, 0) == 0);
    ENSURE(vrWorld_Object(w, ids[0])->body.rot == VR_ROT_GENERAL);
    true_momenta(w, ids, 2, &before);
    ENSURE(vrScene_Step(w, 30) == 0);
    ENSURE(vrScene_Stats(w).collisions >= 1);
    true_momenta(w, ids, 2, &after);
    ENSURE(vec3_len(vec3_sub(after.P, before.P)) < 1e-9);
    ENSURE_MSG(vec3_len(vec3_sub(after.L, before.L)) < 1e-9, "dL %g", vec3_len(vec3_sub(after.L, before.L)));
    if (e == 1.0) ENSURE_NEAR(after.E, before.E, 1e-6 * before.E);   /* tumbling: the integrator's 1e-8 */
    else ENSURE(after.E < before.E);
    vrWorld_Destroy(w);
    return 0;
}

static int test_offcentre_superquadric_hit_conserves_momenta(void)
{
    return superquadric_case(1.0) || superquadric_case(0.4);
}

/* A superquadric's long edge on a wall (physics fuzzer seed 532): its
 * contact points' hull was a sliver, and clipped by the sliver's edges the
 * wall's face gave a region as long as the wall; the bounce floors at its
 * far ends were 80 m/s, the island solve gained 94 times the energy, fell
 * back to no bounce, and the body stopped dead at the wall.  With e = 1 it
 * bounces as a whole, its normal velocity reversed, energy kept. */
static int test_a_superquadric_edge_bounces_off_a_wall_whole(void)
{
    vrWorld *w = vrScene_World(0.05, 0.005, 0);
    vrObjectDef d = vrObjectDef_Default(VR_SUPERQUADRIC);
    const double tilt[4] = {1, 0, 0, 5.95479221487949e-11}, spin[3] = {4.2e-8, 0, 0};
    const double v[3] = {-2.09215, 1.13895, -1.46799};
    vrObjectState st;
    vrStats before, after;
    vrObjectId id;
    int k;
    vrScene_Box(w, "wall", vec3_make(0.1, 1.6, 1.6), vec3_make(-1.6, 0, 1.5), -1, 1);
    d.a1 = 0.0418552, d.a2 = 0.038095, d.a3 = 0.0965177, d.exp1 = 0.412424, d.exp2 = 1.6611;
    d.translate[0] = -1.3871399, d.translate[1] = 0.07706902699594553, d.translate[2] = 1.0321221;
    d.mass = 0.5, d.mass_set = 1, d.elasticity = 1;
    for (k = 0; k < 3; k++) d.linear_vel[k] = v[k];
    id = vrScene_Add(w, "edge", VR_SUPERQUADRIC, &d);
    vrScene_Edit(w, id, vrScene_SetRotation, tilt);
    vrScene_Edit(w, id, vrScene_SetSpin, spin);
    ENSURE(vrScene_Step(w, 0) == 0);
    before = vrScene_Stats(w);
    ENSURE(vrScene_Step(w, 2) == 0);
    after = vrScene_Stats(w);
    st = vrScene_State(w, id);
    printf("    vx %.17g after the wall, %lld collisions, energy %.17g -> %.17g\n", st.linear_vel[0],
           after.collisions, before.energy, after.energy);
    ENSURE(after.collisions == 1);
    ENSURE(fabs(st.linear_vel[0] + v[0]) < 1e-9 && fabs(st.linear_vel[1] - v[1]) < 1e-9);
    ENSURE(fabs(after.energy - before.energy) < 1e-9 * before.energy);
    vrWorld_Destroy(w);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_ball_dropped_from_h_bounces_to_h_e2),
    TEST(test_elastic_ball_keeps_energy_over_100_bounces),
    TEST(test_elastic_ball_keeps_bouncing_millimetres_high),
    TEST(test_inelastic_ball_stops_and_rests),
    TEST(test_head_on_equal_masses_exchange_velocities),
    TEST(test_head_on_unequal_masses_follow_1d_formulas),
    TEST(test_restitution_half_against_wall_halves_speed),
    TEST(test_offcentre_cube_hit_conserves_momenta),
    TEST(test_offcentre_superquadric_hit_conserves_momenta),
    TEST(test_a_superquadric_edge_bounces_off_a_wall_whole),
};

const vrTestSuite vrSuite_Impacts = {"impacts", tests, TEST_COUNT(tests), NULL, NULL, 0};
