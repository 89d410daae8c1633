/* test_quiet.c — contacts that have nothing to do cost little and change
 * no bit (SPEC 7, quiet.c): bodies sliding on a table or on the floor take
 * no event while they slide (their island steps answer their contacts),
 * a ball sliding on a level face is not looked at between island steps
 * (quiet.c's quiet_slide), the heap looks at far fewer pairs than heap = 0,
 * which looks at every pair at every internal step, and gives the same
 * bits.  Bodies start half the contact gap (1 mm) above what they lie on. */
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "scene.h"

/* A ball sliding off a table and a ball falling along a wall, while a cube
 * spinning at 30 rad/s far away makes the internal steps fine (some 300 a
 * frame): the two contacts cannot change before the frame ends until the
 * ball nears the table's edge, so with the heap they are looked at about
 * once a frame (quiet.c's quiet_slide), and the run gives the same bits as
 * heap = 0, which looks at them at every step. */
static vrWorld *quiet_scene(int heap)
{
    vrWorld *w = vrScene_World(0.05, 0.01, 9.8);
    vrObjectId spinner;
    double spin[3] = {0, 30, 20};
    if (!heap) vrScene_Set(w, vrScene_HeapOff);
    vrScene_Box(w, "table", vec3_make(1, 1, 0.05), vec3_make(0, 0, 0), -1, 1);
    vrScene_Box(w, "wall", vec3_make(0.05, 1, 3), vec3_make(5, 0, 0), -1, 1);
    vrScene_Sphere(w, "slider", 0.1, vec3_make(0.013, 0, 0.1505), vec3_make(1, 0, 0), 1, 1); /* off mid-frame */
    vrScene_Sphere(w, "faller", 0.1, vec3_make(5 - 0.05 - 0.1 - 0.0005, 0, 2.5), vec3_make(0, 0.3, 0), 1, 1);
    spinner = vrScene_Box(w, "spinner", vec3_make(0.15, 0.15, 0.15), vec3_make(-5, 0, 5), 1, 1);
    vrScene_Edit(w, spinner, vrScene_SetSpin, spin);
    return w;
}

/* a scene made with the heap (*a) and without (*b), 30 frames each: 1
 * when they dump the same bits */
static int quiet_pair(vrWorld *(*scene)(int heap), vrWorld **a, vrWorld **b)
{
    *a = scene(1);
    *b = scene(0);
    if (vrScene_Step(*a, 30) != 0 || vrScene_Step(*b, 30) != 0) return 0;
    printf("    heap on: %lld checks, heap off: %lld checks, %ld internal steps in the last frame\n", vrScene_Stats(*a).checks,
           vrScene_Stats(*b).checks, vrScene_Stats(*a).subframes);
    return vrScene_SameDumps(*a, *b);
}

static int test_quiet_slides_cost_a_check_a_frame_and_no_bit(void)
{
    vrWorld *a, *b;
    ENSURE(quiet_pair(quiet_scene, &a, &b));
    ENSURE(vrScene_State(a, 2).position[2] < 0.1);           /* the slider fell off the table */
    ENSURE(vrScene_Stats(a).subframes > 100);
    ENSURE(vrScene_Stats(a).checks * 5 < vrScene_Stats(b).checks);   /* heap off: every pair at every step */
    vrWorld_Destroy(a);
    vrWorld_Destroy(b);
    return 0;
}

/* Boxes sliding and turning flat on a table and on the floor, while a cube
 * spinning at 30 rad/s far away makes the internal steps fine: with the
 * heap the contacts are looked at far less than at every internal step,
 * and the run gives the same bits as heap = 0.  One cube slides off the
 * table's edge mid-frame (it tips over the edge in its island and falls);
 * a flat asymmetric box turns (the integrator's rotation) as it slides on
 * the floor. */
static vrWorld *quiet_support_scene(int heap)
{
    vrWorld *w = vrScene_World(0.05, 0.01, 9.8);
    vrObjectId tipper, plate, spinner;
    double turn[3] = {0, 0, 3}, flat_turn[3] = {0, 0, 2}, spin[3] = {0, 30, 20};
    double v[3] = {0.8, 0, 0}, slow[3] = {0, -0.3, 0};
    if (!heap) vrScene_Set(w, vrScene_HeapOff);
    vrScene_Box(w, "table", vec3_make(1, 1, 0.05), vec3_make(0, 0, 0), -1, 1);
    vrScene_Box(w, "floor", vec3_make(4, 4, 0.05), vec3_make(0, 0, -1), -1, 1);
    tipper = vrScene_Box(w, "tipper", vec3_make(0.1, 0.1, 0.1), vec3_make(0.43, 0.3, 0.1505), 1, 1);
    vrScene_Edit(w, tipper, vrScene_SetVelocity, v);
    vrScene_Edit(w, tipper, vrScene_SetSpin, turn);
    plate = vrScene_Box(w, "plate", vec3_make(0.2, 0.1, 0.03), vec3_make(-2, 1, -0.95 + 0.03 + 0.0005), 1, 1);
    vrScene_Edit(w, plate, vrScene_SetVelocity, slow);
    vrScene_Edit(w, plate, vrScene_SetSpin, flat_turn);
    spinner = vrScene_Box(w, "spinner", vec3_make(0.15, 0.15, 0.15), vec3_make(-3, -3, 5), 1, 1);
    vrScene_Edit(w, spinner, vrScene_SetSpin, spin);
    return w;
}

static int test_quiet_supports_cost_a_check_a_frame_and_no_bit(void)
{
    vrWorld *a, *b;
    ENSURE(quiet_pair(quiet_support_scene, &a, &b));
    ENSURE(vrScene_State(a, 2).position[2] < 0);             /* the tipper fell off the table */
    ENSURE(vrScene_State(a, 3).position[2] > -0.95);         /* the plate slides on the floor */
    ENSURE(vrScene_Stats(a).collisions > 0);                 /* the tipper lands on the floor */
    ENSURE(vrScene_Stats(a).subframes > 100);
    /* heap = 0 looks at the pairs with a record (those whose boxes meet,
     * SPEC 10) at every internal step, no longer at the far ones too */
    ENSURE(vrScene_Stats(a).checks < vrScene_Stats(b).checks);
    vrWorld_Destroy(a);
    vrWorld_Destroy(b);
    return 0;
}

/* A ball and a turning box sliding slowly across the middle of a big
 * table, 100 frames a second: they take no event at all while they slide
 * (SPEC 7: a resting or sliding contact costs no event per grid step), and
 * the run gives the same bits as heap = 0. */
static vrWorld *slow_slide_scene(int heap)
{
    vrWorld *w = vrScene_World(0.01, 0.01, 9.8);
    vrObjectId b;
    double v[3] = {0, 0.2, 0}, turn[3] = {0, 0, 1};
    if (!heap) vrScene_Set(w, vrScene_HeapOff);
    vrScene_Box(w, "table", vec3_make(2, 2, 0.05), vec3_make(0, 0, 0), -1, 1);
    vrScene_Sphere(w, "ball", 0.1, vec3_make(-0.5, 0, 0.1505), vec3_make(0.2, 0, 0), 1, 1);
    b = vrScene_Box(w, "box", vec3_make(0.1, 0.05, 0.1), vec3_make(0.5, 0, 0.1505), 1, 1);
    vrScene_Edit(w, b, vrScene_SetVelocity, v);
    vrScene_Edit(w, b, vrScene_SetSpin, turn);
    return w;
}

static int test_quiet_contacts_are_looked_at_once_in_several_frames(void)
{
    vrWorld *a = slow_slide_scene(1), *b = slow_slide_scene(0);
    ENSURE(vrScene_Step(a, 60) == 0 && vrScene_Step(b, 60) == 0);
    printf("    60 frames: heap on %lld checks, heap off %lld; the box is %s\n", vrScene_Stats(a).checks, vrScene_Stats(b).checks,
           vrScene_State(a, 2).state == VR_STATE_SUPPORTED ? "supported" : "not supported");
    ENSURE(vrScene_SameDumps(a, b));
    ENSURE(vrScene_State(a, 1).state == VR_STATE_SUPPORTED && vrScene_State(a, 2).state == VR_STATE_SUPPORTED);
    ENSURE(vrScene_State(a, 1).position[0] > -0.39 && vrScene_State(a, 2).position[1] > 0.11);  /* both slid on */
    ENSURE(vrScene_Stats(a).collisions == 0);
    vrWorld_Destroy(a);
    vrWorld_Destroy(b);
    return 0;
}

/* Bodies that come within the envelope (d = 1 cm) and leave it without
 * touching, or touch and fly out, while a cube spinning at 100 rad/s far
 * away makes the internal steps fine (some 130 a frame): two balls passing 3
 * mm apart, a ball bouncing off a wall at 0.5 m/s, a turning cube gliding
 * 4 mm past a wall.  In the envelope and not touching, a pair is looked at
 * again only when it may touch or leave (quiet.c's approach horizon), not
 * at each of the hundreds of steps it spends there; the run gives the same
 * bits as heap = 0. */
static vrWorld *envelope_scene(int heap)
{
    vrWorld *w = vrScene_World(0.05, 0.01, 0);
    vrObjectId spinner, cube;
    double spin[3] = {0, 100, 60}, turn[3] = {0.5, 0, 0}, glide[3] = {0, 0.4, 0};
    if (!heap) vrScene_Set(w, vrScene_HeapOff);
    vrScene_Box(w, "wall", vec3_make(0.05, 3, 3), vec3_make(2, 0, 0), -1, 1);
    vrScene_Sphere(w, "left", 0.1, vec3_make(-0.5, 0, 0), vec3_make(1, 0, 0), 1, 1);
    vrScene_Sphere(w, "right", 0.1, vec3_make(0.5, 0.203, 0), vec3_make(-1, 0, 0), 1, 1);
    vrScene_Sphere(w, "bouncer", 0.1, vec3_make(2 - 0.05 - 0.1 - 0.05, 1, 1), vec3_make(0.5, 0, 0), 1, 1);
    cube = vrScene_Box(w, "glider", vec3_make(0.1, 0.1, 0.1), vec3_make(2 - 0.05 - 0.1 - 0.004, -1, -1), 1, 1);
    vrScene_Edit(w, cube, vrScene_SetVelocity, glide);
    vrScene_Edit(w, cube, vrScene_SetSpin, turn);
    spinner = vrScene_Box(w, "spinner", vec3_make(0.15, 0.15, 0.15), vec3_make(-5, 0, 5), 1, 1);
    vrScene_Edit(w, spinner, vrScene_SetSpin, spin);
    return w;
}

static int test_quiet_pairs_pass_through_the_envelope_in_a_few_looks(void)
{
    vrWorld *a, *b;
    ENSURE(quiet_pair(envelope_scene, &a, &b));
    ENSURE(vrScene_Stats(a).collisions == 1);                /* the bouncer, once */
    ENSURE(vrScene_State(a, 3).linear_vel[0] < -0.49);
    ENSURE(vrScene_State(a, 1).position[0] > 0.9 && vrScene_State(a, 2).position[0] < -0.9);  /* passed */
    ENSURE(vrScene_Stats(a).subframes > 100);
    ENSURE(vrScene_Stats(a).checks < 1000);   /* looked at every step there: 4,223 */
    vrWorld_Destroy(a);
    vrWorld_Destroy(b);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_quiet_slides_cost_a_check_a_frame_and_no_bit),
    TEST(test_quiet_supports_cost_a_check_a_frame_and_no_bit),
    TEST(test_quiet_contacts_are_looked_at_once_in_several_frames),
    TEST(test_quiet_pairs_pass_through_the_envelope_in_a_few_looks),
};

const vrTestSuite vrSuite_Quiet = {"quiet", tests, TEST_COUNT(tests), NULL, NULL, 0};
