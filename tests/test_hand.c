/* test_hand.c — the mouse as the hand (SPEC 8, 9: shell/hand.c) against
 * the geometry of the view and the clock, in closed form: a drag of known
 * pixel speed across a box's front gives hand samples in the world whose
 * interpolated velocity at the release instant (vrTrack_Velocity, what a
 * throw takes) is that pixel speed on the pick plane; wall time maps to
 * the simulation time the frames reach; a drag while time is stopped
 * falls at the end of the frame to come, the last pose winning.
 *
 * The shell's files are not in the library the runner links, so the one
 * under test is compiled in here (it sees include/vroc.h only). */
#include <math.h>
#include <string.h>
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "scene.h"
#include "world_state.h"
#include "../shell/hand.c"

#define W 640
#define H 512
#define STEP_S 0.1              /* the frames' time_step; real time: one a 0.1 s */

/* the eye 8 m in front of a unit box's face at y = -0.5 (depth 7.5) */
static vrView front_view(void)
{
    vrView v = vrView_Default();
    v.eye[0] = 0, v.eye[1] = -8, v.eye[2] = 1;
    v.look[0] = 0, v.look[1] = 0, v.look[2] = 1;
    v.width = W, v.height = H;
    return v;
}

static vrWorld *box_world(void)
{
    vrWorld *w = vrScene_World(STEP_S, 0.25, 0);
    vrScene_Box(w, "box", vec3_make(0.5, 0.5, 0.5), vec3_make(0, 0, 1), 1, 1);
    return w;
}

/* a real-time run that keeps time: frame k ends at k STEP_S, due at wall
 * time k STEP_S, so a wall moment is that simulated moment */
static HandClock running_at(double wall)
{
    HandClock c;
    double k = floor(wall / STEP_S);
    c.now = k * STEP_S, c.next = (k + 1) * STEP_S, c.wall_next = (k + 1) * STEP_S, c.rate = 1;
    return c;
}

static void ray(const vrView *v, double x, double y, double o[3], double d[3])
{
    vrView_PointerRay(v, x, y, W, H, o, d);
}

static const double forward[3] = {0, 1, 0};

/* presses at the centre at wall 0.01, then `steps` moves of dx pixels
 * every dt s; the pointer's x at the end */
static double drag(ShHand *h, vrWorld *w, const vrView *v, int steps, double dx, double dt)
{
    double o[3], d[3], x = W / 2.0, t = 0.01;
    HandClock c = running_at(t);
    int k;
    ray(v, x, H / 2.0, o, d);
    if (hand_press(h, w, o, d, forward, &c, t) != 1) return -1;
    for (k = 0; k < steps; k++) {
        x += dx, t += dt;
        c = running_at(t);
        ray(v, x, H / 2.0, o, d);
        if (hand_move(h, w, o, d, &c, t) != 0) return -1;
    }
    return x;
}

/* the time of the sample whose trigger went up */
static double release_time(const vrTrack *tr)
{
    int k = 1;
    while (k < tr->n && !(tr->s[k - 1].buttons && !tr->s[k].buttons)) k++;
    return k < tr->n ? tr->s[k].t : -1;
}

/* metres per pixel on the plane facing the view at depth 7.5 */
static double pixel_m(const vrView *v) { return 7.5 * 2 * tan(v->fov * VR_PI / 360) / H; }

/* 8 pixels every 20 ms to the right, released on the next step: the throw
 * (the velocity at the release instant) is 400 pixels a second on the
 * plane, along the screen's right (+x), nothing across */
static int test_a_steady_drag_throws_at_its_pixel_speed_on_the_plane(void)
{
    vrWorld *w = box_world();
    vrView v = front_view();
    ShHand h;
    double x, o[3], d[3], vel[3], spin[3], t, want = 400 * pixel_m(&v);
    HandClock c;
    hand_init(&h);
    x = drag(&h, w, &v, 10, 8, 0.02);
    ENSURE(x > 0);
    t = 0.01 + 11 * 0.02;
    c = running_at(t);
    ray(&v, x + 8, H / 2.0, o, d);
    ENSURE(hand_release(&h, w, o, d, &c, t) == 0);
    t = release_time(&w->track[VR_DEVICE_HAND]);
    ENSURE(vrTrack_Velocity(&w->track[VR_DEVICE_HAND], t, vel, spin) == 0);
    ENSURE_MSG(fabs(vel[0] - want) < 1e-9 * want && fabs(vel[1]) < 1e-9 && fabs(vel[2]) < 1e-9,
               "throw (%.12g,%.12g,%.12g), want (%.12g,0,0)", vel[0], vel[1], vel[2], want);
    vrWorld_Destroy(w);
    return 0;
}

/* the trigger is down from the press to the release, then up; the
 * samples' times are the wall moments (the run keeps real time) and
 * never decrease */
static int test_the_trigger_is_held_from_press_to_release(void)
{
    vrWorld *w = box_world();
    vrView v = front_view();
    const vrTrack *tr = &w->track[VR_DEVICE_HAND];
    ShHand h;
    double x, o[3], d[3], t = 0.01 + 4 * 0.03;
    HandClock c;
    int k;
    hand_init(&h);
    x = drag(&h, w, &v, 3, 5, 0.03);
    c = running_at(t);
    ray(&v, x, H / 2.0, o, d);
    ENSURE(hand_release(&h, w, o, d, &c, t) == 0);
    ENSURE(tr->n >= 5);
    ENSURE_NEAR(tr->s[0].t, 0.01, 1e-15);
    for (k = 0; k < tr->n; k++) {
        ENSURE(k == 0 || tr->s[k].t >= tr->s[k - 1].t);
        ENSURE(tr->s[k].buttons == (tr->s[k].t < t ? VR_BUTTON_TRIGGER : 0u));
    }
    ENSURE_NEAR(tr->s[4].t, t, 1e-15);
    vrWorld_Destroy(w);
    return 0;
}

/* a hand that stopped before letting go drops: 100 ms still, then the
 * release throws at rest */
static int test_a_drag_that_stopped_before_the_release_drops(void)
{
    vrWorld *w = box_world();
    vrView v = front_view();
    ShHand h;
    double x, o[3], d[3], vel[3], spin[3], t;
    HandClock c;
    hand_init(&h);
    x = drag(&h, w, &v, 10, 8, 0.02);
    t = 0.01 + 10 * 0.02 + 0.1;
    c = running_at(t);
    ray(&v, x, H / 2.0, o, d);
    ENSURE(hand_release(&h, w, o, d, &c, t) == 0);
    ENSURE(vrTrack_Velocity(&w->track[VR_DEVICE_HAND], t, vel, spin) == 0);
    ENSURE(vel[0] == 0 && vel[1] == 0 && vel[2] == 0);
    vrWorld_Destroy(w);
    return 0;
}

/* time stopped (rate 0): every sample at the end of the frame to come,
 * the last one winning there: the hand holds its pose until time runs,
 * then is where the drag ended, by the plane's formula, trigger up */
static int test_a_drag_while_stopped_lands_at_the_next_frame_end(void)
{
    vrWorld *w = box_world();
    vrView v = front_view();
    HandClock c = {0, STEP_S, 0, 0};
    vrTrackerSample s;
    ShHand h;
    double o[3], d[3], x = W / 2.0 + 0.5, y = H / 2.0 + 0.5;
    int k;
    hand_init(&h);
    ray(&v, x, y, o, d);
    ENSURE(hand_press(&h, w, o, d, forward, &c, 5.0) == 1);
    for (k = 0; k < 20; k++) {
        ray(&v, x + 3 * (k + 1), y - 2 * (k + 1), o, d);
        ENSURE(hand_move(&h, w, o, d, &c, 5.0 + k) == 0);
    }
    ENSURE(hand_release(&h, w, o, d, &c, 30.0) == 0);
    for (k = 0; k < w->track[VR_DEVICE_HAND].n; k++) ENSURE(w->track[VR_DEVICE_HAND].s[k].t == STEP_S);
    ENSURE(vrWorld_Step(w, 1, NULL, 0) == 0);
    ENSURE(vrWorld_TrackerPose(w, VR_DEVICE_HAND, &s) == 0);
    /* 60 pixels right, 40 up on the plane y = -0.5 */
    ENSURE_NEAR(s.position[0], h.point[0] + 60 * pixel_m(&v), 1e-12);
    ENSURE_NEAR(s.position[1], -0.5, 1e-12);
    ENSURE_NEAR(s.position[2], h.point[2] + 40 * pixel_m(&v), 1e-12);
    ENSURE(s.buttons == 0);
    vrWorld_Destroy(w);
    return 0;
}

/* wall to simulated time: in a run at real time a moment tw before the
 * frame due at wall_next is that much before its end; read late it is the
 * end; taken before the last frame ended, that frame's end; never before
 * the last sample */
static int test_wall_moments_fall_in_the_frame_to_come(void)
{
    ShHand h;
    HandClock c = {2.0, 2.1, 100.0, 1};
    memset(&h, 0, sizeof h);
    ENSURE_NEAR(hand_time(&h, &c, 99.97), 2.07, 1e-12);
    ENSURE(hand_time(&h, &c, 100.5) == 2.1);
    ENSURE(hand_time(&h, &c, 99.5) == 2.0);
    h.pushed = 1, h.last_t = 2.09;
    ENSURE(hand_time(&h, &c, 99.97) == 2.09);
    c.rate = 0;                 /* stopped */
    h.pushed = 0;
    ENSURE(hand_time(&h, &c, 99.97) == 2.1);
    return 0;
}

/* a track file that leads the hand: the window's sample before it is
 * refused with the file's time in the message, not pushed back in time */
static int test_a_sample_before_the_hands_last_is_refused_with_a_message(void)
{
    vrWorld *w = box_world();
    vrView v = front_view();
    vrTrackerSample ahead = {5, {0, 0, 0}, {1, 0, 0, 0}, 0};
    ShHand h;
    double o[3], d[3];
    HandClock c = running_at(0.05);
    hand_init(&h);
    ENSURE(vrWorld_PushSample(w, VR_DEVICE_HAND, &ahead, NULL, 0) == 0);
    ray(&v, W / 2.0, H / 2.0, o, d);
    ENSURE(hand_press(&h, w, o, d, forward, &c, 0.05) == -1);
    ENSURE_MSG(strstr(h.error, "before the hand's last") != NULL, "%s", h.error);
    vrWorld_Destroy(w);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_a_steady_drag_throws_at_its_pixel_speed_on_the_plane),
    TEST(test_the_trigger_is_held_from_press_to_release),
    TEST(test_a_drag_that_stopped_before_the_release_drops),
    TEST(test_a_drag_while_stopped_lands_at_the_next_frame_end),
    TEST(test_wall_moments_fall_in_the_frame_to_come),
    TEST(test_a_sample_before_the_hands_last_is_refused_with_a_message),
};

const vrTestSuite vrSuite_Hand = {"hand", tests, TEST_COUNT(tests), NULL, NULL, 0};
