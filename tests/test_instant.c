/* test_instant.c — the contacts of one instant (SPEC 7, instant_undo.h):
 * a ball striking a body that lies on the floor bounces off it as off the
 * floor, and the body stays lying; a Newton's cradle on a table still
 * sends out one ball.  Analytic cases: the ball's apex after the bounce,
 * from its state (free flight is exact), is z_c + e^2 (h - z_c) for a
 * drop from h onto a contact height z_c. */
#include <math.h>
#include <stdio.h>
#include "test.h"
#include "scene.h"

#define G 9.8
#define GC 0.001   /* the contact gap g_c (SPEC 7) */

/* the apex of a body in free flight, from its state */
static double apex(const vrObjectState *s) { return s->position[2] + s->linear_vel[2] * s->linear_vel[2] / (2 * G); }

/* A box (half height hz) lying on a static floor whose top is at z = 0, at
 * gap g_c; a ball of radius r dropped from rest at height h above it */
static vrWorld *ball_over_box(double e, double box_mass, double h, vrObjectId *box, vrObjectId *ball)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    vrScene_Box(w, "floor", vec3_make(1, 1, 0.05), vec3_make(0, 0, -0.05), -1, e);
    *box = vrScene_Box(w, "box", vec3_make(0.2, 0.2, 0.1), vec3_make(0, 0, 0.1 + GC), box_mass, e);
    *ball = vrScene_Sphere(w, "ball", 0.1, vec3_make(0, 0, 0.2 + 2 * GC + 0.1 + h), vec3_zero(), 1, e);
    return w;
}

/* A 1 kg ball dropped 1 m onto a 5 kg box lying on the floor, e = 0.8
 * everywhere: the floor holds the box, so the ball leaves at e times its
 * speed (its apex z_c + e^2 (1 m)) and the box does not move.  Answered
 * pair by pair, the ball's impulse sent the box into the floor at 1.3 m/s
 * and the floor's sent it up at 1 m/s (a 6 cm hop), and the ball left at
 * 2.2 m/s, not 3.5. */
static int test_a_ball_dropped_on_a_box_lying_on_the_floor_bounces_as_off_the_floor(void)
{
    vrObjectId box, ball;
    vrWorld *w = ball_over_box(0.8, 5, 1.0, &box, &ball);
    double z_box = vrScene_State(w, box).position[2], z_c = z_box + 0.1 + GC + 0.1, top = 0, want;
    vrObjectState s;
    int f;
    for (f = 0; f < 100 && vrScene_State(w, ball).linear_vel[2] <= 0; f++) {
        ENSURE(vrScene_Step(w, 1) == 0);
        top = fmax(top, vrScene_State(w, box).position[2] - z_box);
    }
    s = vrScene_State(w, ball);
    want = z_c + 0.64 * (z_box + 0.1 + GC + 0.1 + 1.0 - z_c);
    printf("    bounced in frame %d: apex %.12f m (analytic %.12f), box risen %.3g m\n", f, apex(&s), want, top);
    ENSURE(s.linear_vel[2] > 0);
    ENSURE_NEAR(apex(&s), want, 1e-9);
    for (; f < 150; f++) {
        ENSURE(vrScene_Step(w, 1) == 0);
        top = fmax(top, vrScene_State(w, box).position[2] - z_box);
    }
    ENSURE_MSG(top < 1e-6, "the box rose %.3g m", top);
    ENSURE(vrScene_State(w, box).state == VR_STATE_REST);
    vrWorld_Destroy(w);
    return 0;
}

/* e = 1 everywhere, the ball dropped 8 mm onto the box: it keeps bouncing,
 * its energy kept to 1e-8 over 300 frames (each bounce is a solve of the
 * three together, left within its sweeps' tolerance: 6e-10 J a bounce, a
 * 1e-8 of the bounce's own energy), and the box does not move.  Pair by
 * pair, the box came into the floor slower than v_rest, did not bounce,
 * and the energy it took was lost: the ball lost its whole bounce. */
static int test_an_elastic_ball_keeps_bouncing_on_an_elastic_box(void)
{
    vrObjectId box, ball;
    vrWorld *w = ball_over_box(1, 5, 0.008, &box, &ball);
    double e0, z_box = vrScene_State(w, box).position[2];
    vrStats st;
    ENSURE(vrScene_Step(w, 0) == 0);
    e0 = vrScene_Stats(w).energy;
    ENSURE(vrScene_Step(w, 300) == 0);
    st = vrScene_Stats(w);
    printf("    %lld contacts answered; energy %.15g -> %.15g J; box moved %.3g m\n", st.collisions, e0, st.energy,
           fabs(vrScene_State(w, box).position[2] - z_box));
    ENSURE(vrScene_State(w, ball).state != VR_STATE_REST);
    ENSURE(st.collisions >= 30);
    ENSURE(st.energy <= e0 && st.energy > e0 - 1e-8 * e0);
    ENSURE(fabs(vrScene_State(w, box).position[2] - z_box) < 1e-6);
    vrWorld_Destroy(w);
    return 0;
}

/* A 1 kg ball dropped 0.5 m onto a stack of three 1 kg boxes on the floor,
 * e = 0.5: the stack stands as it stood, and the ball bounces off its top
 * as off the floor.  Pair by pair, the impulse went down the stack and the
 * floor sent it back up, box by box. */
static int test_a_ball_dropped_on_a_stack_leaves_it_standing(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    vrObjectId box[3], ball;
    double z0[3], risen = 0, z_c, want;
    vrObjectState s;
    int k, f;
    vrScene_Box(w, "floor", vec3_make(1, 1, 0.05), vec3_make(0, 0, -0.05), -1, 0.5);
    for (k = 0; k < 3; k++) {
        char name[16];
        snprintf(name, sizeof name, "b%d", k);
        box[k] = vrScene_Box(w, name, vec3_make(0.1, 0.1, 0.1), vec3_make(0, 0, 0.1 + GC + k * (0.2 + GC)), 1, 0.5);
    }
    ball = vrScene_Sphere(w, "ball", 0.05, vec3_make(0, 0, 3 * (0.2 + GC) + 0.05 + GC + 0.5), vec3_zero(), 1, 0.5);
    for (k = 0; k < 3; k++) z0[k] = vrScene_State(w, box[k]).position[2];
    z_c = z0[2] + 0.1 + GC + 0.05;
    for (f = 0; f < 100 && vrScene_State(w, ball).linear_vel[2] <= 0; f++) {
        ENSURE(vrScene_Step(w, 1) == 0);
        for (k = 0; k < 3; k++) risen = fmax(risen, vrScene_State(w, box[k]).position[2] - z0[k]);
    }
    s = vrScene_State(w, ball);
    want = z_c + 0.25 * 0.5;
    printf("    bounced in frame %d: apex %.12f m (analytic %.12f); the stack rose %.3g m\n", f, apex(&s), want, risen);
    ENSURE(s.linear_vel[2] > 0);
    ENSURE_NEAR(apex(&s), want, 1e-9);
    for (; f < 200; f++) {
        ENSURE(vrScene_Step(w, 1) == 0);
        for (k = 0; k < 3; k++) risen = fmax(risen, vrScene_State(w, box[k]).position[2] - z0[k]);
    }
    ENSURE_MSG(risen < 1e-6, "a box rose %.3g m", risen);
    vrWorld_Destroy(w);
    return 0;
}

/* Five touching balls resting on a table, e = 1, no friction, under
 * gravity; a sixth slides in at 1 m/s: the last goes out at 1 m/s and
 * the rest stay.  Every ball lies on the table, which is immovable, but no
 * impulse of the row drives a ball into it: the instant is not taken back,
 * and its impulses still go down the row one by one. */
static int test_a_newtons_cradle_on_a_table_sends_out_one_ball(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    vrObjectId id[6];
    int i;
    vrScene_Box(w, "table", vec3_make(2, 1, 0.05), vec3_make(0, 0, -0.05), -1, 1);
    for (i = 0; i < 5; i++) {
        char name[16];
        snprintf(name, sizeof name, "c%d", i);
        id[i] = vrScene_Sphere(w, name, 0.1, vec3_make(i * (0.2 + GC), 0, 0.1 + GC), vec3_zero(), 1, 1);
    }
    id[5] = vrScene_Sphere(w, "striker", 0.1, vec3_make(-0.5, 0, 0.1 + GC), vec3_make(1, 0, 0), 1, 1);
    ENSURE(vrScene_Step(w, 60) == 0);
    printf("    last ball %.12f m/s, striker %.3g m/s\n", vrScene_State(w, id[4]).linear_vel[0],
           vrScene_State(w, id[5]).linear_vel[0]);
    ENSURE_NEAR(vrScene_State(w, id[4]).linear_vel[0], 1, 1e-9);
    for (i = 0; i < 4; i++) ENSURE_NEAR(vrScene_State(w, id[i]).linear_vel[0], 0, 1e-9);
    ENSURE_NEAR(vrScene_State(w, id[5]).linear_vel[0], 0, 1e-9);
    vrWorld_Destroy(w);
    return 0;
}

/* Without gravity nothing lies on anything: a light ball (0.1 kg, 4.7
 * m/s, e = 1 everywhere) strikes the side of a stack of four touching
 * boxes standing on a static floor, the physics fuzzer's seed 3570.  The
 * stack rattles, and its bottom box is driven into the floor again and
 * again; answered pair by pair each answer keeps the energy (to its
 * rounding and the turning boxes' integration, 1e-8 here).  Taken back
 * and answered with the floor holding the stack (as under gravity), its
 * resting contacts took no bounce: 8.1e-4 of the energy was lost. */
static int test_a_stack_struck_without_gravity_keeps_its_energy_with_e_1(void)
{
    static const double half[4][3] = {{0.0755606, 0.0592157, 0.0730111}, {0.0765812, 0.137698, 0.0340213},
                                      {0.139844, 0.0843134, 0.0670391}, {0.094089, 0.0681186, 0.0630661}};
    static const double at[4][3] = {{0.57585496867233621, 0.47098019220830301, 0.073114978104371856},
                                     {0.58183980183054429, 0.47098019220830301, 0.18199442761223561},
                                     {0.62880999538022042, 0.47098019220830301, 0.29249230640003571},
                                     {0.60647697985646265, 0.47098019220830301, 0.4245322613870765}};
    static const double mass[4] = {0.2, 1, 0.2, 5};
    vrWorld *w = vrScene_World(0.05, 0.01, 0);
    double e0;
    vrStats st;
    int k;
    vrScene_Box(w, "floor", vec3_make(1.6, 1.6, 0.1), vec3_make(0, 0, -0.1), -1, 1);
    for (k = 0; k < 4; k++) {
        char name[16];
        snprintf(name, sizeof name, "k%d", k);
        vrScene_Box(w, name, vec3_make(half[k][0], half[k][1], half[k][2]), vec3_make(at[k][0], at[k][1], at[k][2]),
                    mass[k], 1);
    }
    vrScene_Sphere(w, "ball", 0.0231605, vec3_make(0.5784604999988142, 0.792235000002327, 0.40082664999999995),
                   vec3_make(1.8775300000000004, -4.26056, -0.461247), 0.1, 1);
    ENSURE(vrScene_Step(w, 0) == 0);
    e0 = vrScene_Stats(w).energy;
    ENSURE(vrScene_Step(w, 6) == 0);
    st = vrScene_Stats(w);
    printf("    %lld contacts answered; energy %.15g -> %.15g J (%.3g of it)\n", st.collisions, e0, st.energy,
           (st.energy - e0) / e0);
    ENSURE(st.collisions >= 20);
    ENSURE_MSG(fabs(st.energy - e0) <= 1e-8 * e0, "energy %.15g -> %.15g J", e0, st.energy);
    vrWorld_Destroy(w);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_a_ball_dropped_on_a_box_lying_on_the_floor_bounces_as_off_the_floor),
    TEST(test_an_elastic_ball_keeps_bouncing_on_an_elastic_box),
    TEST(test_a_ball_dropped_on_a_stack_leaves_it_standing),
    TEST(test_a_newtons_cradle_on_a_table_sends_out_one_ball),
    TEST(test_a_stack_struck_without_gravity_keeps_its_energy_with_e_1),
};

const vrTestSuite vrSuite_Instant = {"instant", tests, TEST_COUNT(tests), NULL, NULL, 0};
