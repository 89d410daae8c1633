/* test_sliding.c — bodies lying on others slide at constant distance
 * (SPEC 7: an island's contacts, frictionless here): a ball slides within
 * the contact gap without sinking or hopping and falls off the edge;
 * slanted nudges and a support made static sink nothing; a body or support
 * made thinner drops at once; flush tables have no seam, while a real step
 * or a curb still stops a sliding box.  The bodies start half the contact
 * gap g_c = 1 mm above what they lie on. */
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "scene.h"

#define GC 1e-3                      /* the contact gap (SPEC 7) */
#define ON(z) ((z) + 0.5 * GC)       /* a centre z half the gap above lying at z */

/* a ball sliding at 1 m/s on a table stays within the contact gap, lying
 * on it, and loses no energy; off the edge it falls, no longer lying on it */
static int test_sliding_ball_stays_in_envelope_and_leaves_edge(void)
{
    vrWorld *w = vrScene_World(0.05, 0.01, 9.8);
    vrObjectId ball;
    double e0, zmin = 1e9, zmax = -1e9;
    int f, left = 0;
    vrScene_Box(w, "table", vec3_make(1, 1, 0.05), vec3_make(0, 0, 0), -1, 1);
    ball = vrScene_Sphere(w, "ball", 0.1, vec3_make(0, 0, ON(0.15)), vec3_make(1, 0, 0), 1, 1);
    ENSURE(vrScene_Step(w, 0) == 0);
    e0 = vrScene_Stats(w).energy;
    for (f = 0; f < 18; f++) {          /* 0.9 s: centre from x = 0 to 0.9, still over the table */
        vrObjectState s;
        ENSURE(vrScene_Step(w, 1) == 0);
        s = vrScene_State(w, ball);
        zmin = fmin(zmin, s.position[2]);
        zmax = fmax(zmax, s.position[2]);
        ENSURE(vrScene_Stats(w).energy <= e0 + 1e-9 * fabs(e0));
    }
    ENSURE(vrScene_State(w, ball).state == VR_STATE_SUPPORTED);
    ENSURE(zmin >= 0.15 - 1e-12 && zmax <= 0.15 + GC + 1e-12);   /* no sinking, no hopping */
    ENSURE_NEAR(vrScene_State(w, ball).linear_vel[0], 1.0, 1e-3);
    for (f = 0; f < 20 && !left; f++) {
        ENSURE(vrScene_Step(w, 1) == 0);
        left = vrScene_State(w, ball).position[2] < 0.1;
    }
    ENSURE(left);                        /* it fell off the edge */
    ENSURE(vrScene_State(w, ball).state == VR_STATE_MOVING);
    ENSURE(vrScene_Stats(w).energy <= e0 + 1e-6 * fabs(e0));
    vrWorld_Destroy(w);
    return 0;
}

/* ---- flush surfaces ------------------------------------------------------------------------ */

/* two tables side by side, their tops flush at z = 0.05 (or the right one's
 * `rise` higher; it is `half_z` thick, by half); a box (or ball) slides from
 * the left one toward the seam at x = 0 at 1 m/s and is looked at after 1.5 s */
static vrObjectState across_seam(int ball, double rise, double half_z)
{
    vrWorld *w = vrScene_World(0.01, 0.01, 9.8);
    const double v[3] = { 1, 0, 0 };
    vrObjectId slider;
    vrObjectState s;
    vrScene_Box(w, "left", vec3_make(1, 0.5, 0.05), vec3_make(-1, 0, 0), -1, 1);
    vrScene_Box(w, "right", vec3_make(0.5, 0.5, half_z), vec3_make(0.5, 0, 0.05 + rise - half_z), -1, 1);
    slider = ball ? vrScene_Sphere(w, "slider", 0.1, vec3_make(-0.6, 0, ON(0.15)), vec3_make(1, 0, 0), 1, 1)
                  : vrScene_Box(w, "slider", vec3_make(0.1, 0.1, 0.1), vec3_make(-0.6, 0, ON(0.15)), 1, 1);
    vrScene_Edit(w, slider, vrScene_SetVelocity, v);
    vrScene_Step(w, 150);
    s = vrScene_State(w, slider);
    vrWorld_Destroy(w);
    return s;
}

/* Box2D's "ghost collisions": the edge of the next table inside the
 * envelope must not kick a body back when the tops are flush */
static int test_sliding_over_flush_tables_feels_no_seam(void)
{
    int ball;
    for (ball = 0; ball < 2; ball++) {
        vrObjectState s = across_seam(ball, 0, 0.05);
        printf("    %s: x %.15g z %.15g v (%g, %g, %g)\n", ball ? "ball" : "box", s.position[0], s.position[2],
               s.linear_vel[0], s.linear_vel[1], s.linear_vel[2]);
        /* no kick: a ghost collision would turn it back or lift it by mm */
        ENSURE(fabs(s.position[0] - 0.9) < 1e-6 && fabs(s.position[2] - ON(0.15)) < 1e-6);
        ENSURE(fabs(s.linear_vel[0] - 1) < 1e-6 && fabs(s.linear_vel[2]) < 1e-6);
        ENSURE(fabs(s.angular_vel[0]) + fabs(s.angular_vel[1]) + fabs(s.angular_vel[2]) < 1e-6);
    }
    return 0;
}

/* a real step stops it.  A wall (taller than the box) sends it straight
 * back (e = 1, the impulse through its centre of mass, g_c from the wall);
 * a 2 cm curb, higher than the gap under the box, is hit low: the box
 * pitches and rocks but does not cross (without the curb it is at x = 0.9) */
static int test_a_real_step_still_stops_a_sliding_box(void)
{
    vrObjectState wall = across_seam(0, 0.3, 0.5), curb = across_seam(0, 0.02, 0.05);
    printf("    wall: v (%g, %g, %g); curb: x %g v (%g, %g, %g)\n", wall.linear_vel[0], wall.linear_vel[1],
           wall.linear_vel[2], curb.position[0], curb.linear_vel[0], curb.linear_vel[1], curb.linear_vel[2]);
    ENSURE(fabs(wall.linear_vel[0] + 1) < 1e-9 && fabs(wall.linear_vel[2]) < 1e-9);
    ENSURE(fabs(wall.position[0] + 1.1 + 2 * GC) < 1e-9);   /* back from x = -0.1 - g_c at t = 0.5 - g_c */
    ENSURE(curb.position[0] < -0.1);
    return 0;
}

/* A big ball creeping at 8 mm/s along a table nudges a small one whose
 * centre is 5 cm lower: the normal between them slants down onto the small
 * ball, and the push gives it a downward speed of some 0.7 mm/s, slower
 * than v_eps, that no contact impulse would ever answer.  The three
 * contacts are one island, solved together (SPEC 7): the balls keep their
 * heights (before islands, the small one sank and the big one rose, for
 * ever).  The small ball, at rest when the big one touches it, wakes into
 * that island step's solve, which pushes it: no contact impulse of its own
 * (`collisions` stays 0). */
static int test_a_slanted_nudge_does_not_sink_a_supported_ball(void)
{
    vrWorld *w = vrScene_World(0.05, 0.01, 9.8);
    vrObjectId big, small;
    vrObjectState s;
    vrScene_Box(w, "table", vec3_make(1, 1, 0.05), vec3_make(0, 0, 0), -1, 1);
    big = vrScene_Sphere(w, "big", 0.15, vec3_make(0, 0, ON(0.2)), vec3_make(0.008, 0, 0), 1, 1);
    small = vrScene_Sphere(w, "small", 0.1, vec3_make(0.26, 0, ON(0.15)), vec3_make(0, 0, 0), 1, 1);
    ENSURE(vrScene_Step(w, 80) == 0);
    s = vrScene_State(w, small);
    printf("    small ball: x %.6f, z %.17g, vx %.3g mm/s, vz %.3g\n", s.position[0], s.position[2],
           1e3 * s.linear_vel[0], s.linear_vel[2]);
    ENSURE(s.linear_vel[0] > 0.001);              /* it was pushed along */
    ENSURE(fabs(s.linear_vel[2]) < 1e-9);
    ENSURE_NEAR(s.position[2], ON(0.15), 1e-9);
    ENSURE_NEAR(vrScene_State(w, big).position[2], ON(0.2), 1e-9);
    vrWorld_Destroy(w);
    return 0;
}

static void set_mass(vrObjectDef *d, const void *arg) { d->mass = *(const double *)arg; d->mass_set = 1; }

/* The same nudge on a table that was a dynamic body lying on the floor
 * and is made static once the balls rest on it: the small ball holds its
 * height as on a table static from the start. */
static int test_a_support_made_static_holds_like_a_static_one(void)
{
    vrWorld *w = vrScene_World(0.05, 0.01, 9.8);
    vrObjectId table, small;
    vrObjectState s;
    double fixed = -1;
    vrScene_Box(w, "floor", vec3_make(2, 2, 0.05), vec3_make(0, 0, -0.1 - 0.5 * GC), -1, 0);
    table = vrScene_Box(w, "table", vec3_make(1, 1, 0.05), vec3_make(0, 0, 0), 1, 0);
    vrScene_Box(w, "wall", vec3_make(0.05, 1, 0.5), vec3_make(-1, 0, 0.55), -1, 0);  /* nothing else moves the table */
    vrScene_Sphere(w, "big", 0.15, vec3_make(-0.3, 0, ON(0.2)), vec3_make(0, 0, 0), 1, 1);
    small = vrScene_Sphere(w, "small", 0.1, vec3_make(-0.04, 0, ON(0.15)), vec3_make(0, 0, 0), 1, 1);
    ENSURE(vrScene_Step(w, 2) == 0);
    vrScene_Edit(w, table, set_mass, &fixed);
    {   /* now the big ball creeps toward the small one, as in the test above */
        double v[3] = {0.008, 0, 0};
        vrObjectId big = vrWorld_FindObject(w, "big");
        vrScene_Edit(w, big, vrScene_SetVelocity, v);
    }
    ENSURE(vrScene_Step(w, 80) == 0);
    s = vrScene_State(w, small);
    printf("    small ball: x %.6f, z %.17g, vz %.3g\n", s.position[0], s.position[2], s.linear_vel[2]);
    ENSURE(s.linear_vel[0] > 0.001);
    ENSURE(fabs(s.linear_vel[2]) < 1e-9);
    ENSURE_NEAR(s.position[2], ON(0.15), 1e-9);
    vrWorld_Destroy(w);
    return 0;
}

static void set_half_height(vrObjectDef *d, const void *arg) { d->size[2] = *(const double *)arg; }

/* A box sliding on a table is made thinner mid-run, or the table is (an
 * edit at a frame start, same poses): the contact is looked at anew at
 * that instant, at the same poses as the last look of the frame before,
 * but for a new shape.  The box is 3 cm (2 cm) above the table now: the
 * island step at that instant finds it touching nothing, and it falls
 * freely for the whole next frame, 0.5 g (0.05 s)^2 (a contact kept from
 * the old shape, or a slide thought quiet until the frame's end, would hold
 * it up longer), then lands on the table. */
static int test_a_box_or_table_made_thinner_mid_run_drops_the_box(void)
{
    int heap, which;
    for (heap = 0; heap < 2; heap++)
        for (which = 0; which < 2; which++) {
            vrWorld *w = vrScene_World(0.05, 0.01, 9.8);
            vrObjectId table, b;
            double v[3] = {0.5, 0, 0}, thin_box = 0.07, thin_table = 0.03, top, half;
            vrObjectState s;
            if (!heap) vrScene_Set(w, vrScene_HeapOff);
            table = vrScene_Box(w, "table", vec3_make(1, 1, 0.05), vec3_make(0, 0, 0), -1, 1);
            b = vrScene_Box(w, "box", vec3_make(0.1, 0.1, 0.1), vec3_make(-0.5, 0, ON(0.15)), 1, 0);
            vrScene_Edit(w, b, vrScene_SetVelocity, v);
            ENSURE(vrScene_Step(w, 3) == 0);
            ENSURE(vrScene_State(w, b).state == VR_STATE_SUPPORTED);
            if (which) vrScene_Edit(w, table, set_half_height, &thin_table);
            else vrScene_Edit(w, b, set_half_height, &thin_box);
            ENSURE(vrScene_Step(w, 1) == 0);
            s = vrScene_State(w, b);
            printf("    heap %d, %s made thinner: a frame later z %.6f (%s)\n", heap, which ? "table" : "box",
                   s.position[2], s.state == VR_STATE_SUPPORTED ? "supported" : "not supported");
            ENSURE_NEAR(s.position[2], ON(0.15) - 0.5 * 9.8 * 0.05 * 0.05, 1e-12);
            ENSURE(vrScene_Step(w, 20) == 0);
            s = vrScene_State(w, b);       /* on the table again, within the envelope */
            top = which ? thin_table : 0.05;
            half = which ? 0.1 : thin_box;
            ENSURE(s.position[2] >= top + half - 1e-9 && s.position[2] <= top + half + GC + 1e-9);
            ENSURE(s.state == VR_STATE_SUPPORTED || s.state == VR_STATE_REST);
            vrWorld_Destroy(w);
        }
    return 0;
}

static const vrTest tests[] = {
    TEST(test_sliding_ball_stays_in_envelope_and_leaves_edge),
    TEST(test_a_slanted_nudge_does_not_sink_a_supported_ball),
    TEST(test_a_support_made_static_holds_like_a_static_one),
    TEST(test_a_box_or_table_made_thinner_mid_run_drops_the_box),
    TEST(test_sliding_over_flush_tables_feels_no_seam),
    TEST(test_a_real_step_still_stops_a_sliding_box),
};

const vrTestSuite vrSuite_Sliding = {"sliding", tests, TEST_COUNT(tests), NULL, NULL, 0};
