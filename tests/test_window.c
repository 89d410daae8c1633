/* test_window.c — the window's geometry (SPEC 9), in closed form: the
 * trackball turns the head about look by pi*|drag|/height, the wheel
 * scales its distance by 0.9 a step, the pointer's ray leaves the eye at
 * the pixel's angle, and a ray meets the first object's faces at the
 * distance a ruler gives.  (The window itself: tests/window.sh, under
 * Xvfb.) */
#include <math.h>
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "scene.h"

static vrView view_from(double ex, double ey, double ez)
{
    vrView v = vrView_Default();
    v.eye[0] = ex, v.eye[1] = ey, v.eye[2] = ez;
    v.look[0] = 0, v.look[1] = 0, v.look[2] = 1;
    v.up[0] = 0, v.up[1] = 0, v.up[2] = 1;
    v.width = 640, v.height = 512;
    return v;
}

static int near3(const double a[3], double x, double y, double z, double tol)
{
    return fabs(a[0] - x) <= tol && fabs(a[1] - y) <= tol && fabs(a[2] - z) <= tol;
}

/* half a window height to the right: the scene turns a quarter turn to the
 * right about the screen's up (z here), so the eye goes a quarter turn the
 * other way round look: from -y to -x */
static int test_trackball_half_height_drag_right_turns_a_quarter_turn(void)
{
    vrView v = view_from(0, -8, 1);
    vrView_Trackball(&v, 256, 0);
    ENSURE_MSG(near3(v.eye, -8, 0, 1, 1e-12), "eye (%g,%g,%g)", v.eye[0], v.eye[1], v.eye[2]);
    ENSURE(near3(v.up, 0, 0, 1, 1e-12));
    return 0;
}

/* half a height down: the front turns down, the eye goes over the top,
 * looking down with the screen's up now +y */
static int test_trackball_half_height_drag_down_puts_the_eye_overhead(void)
{
    vrView v = view_from(0, -8, 1);
    vrView_Trackball(&v, 0, 256);
    ENSURE_MSG(near3(v.eye, 0, 0, 9, 1e-12), "eye (%g,%g,%g)", v.eye[0], v.eye[1], v.eye[2]);
    ENSURE(near3(v.up, 0, 1, 0, 1e-12));
    return 0;
}

/* a drag in pieces along one line is the drag at once (the axis stays),
 * and a drag there and back returns the head where it was */
static int test_trackball_drags_compose_and_undo(void)
{
    vrView a = view_from(3, -7, 4), b = a;
    int i;
    for (i = 0; i < 8; i++) vrView_Trackball(&a, 16, 12);
    vrView_Trackball(&b, 128, 96);
    ENSURE(near3(a.eye, b.eye[0], b.eye[1], b.eye[2], 1e-12));
    vrView_Trackball(&b, -128, -96);
    ENSURE(near3(b.eye, 3, -7, 4, 1e-12));
    /* the distance to look never changes */
    ENSURE_NEAR(vec3_len(vec3_make(a.eye[0], a.eye[1], a.eye[2] - 1)), sqrt(9 + 49 + 9), 1e-12);
    return 0;
}

static int test_zoom_scales_the_distance_to_look_by_0_9_a_step(void)
{
    vrView v = view_from(0, -8, 1);
    vrView_Zoom(&v, 1);
    ENSURE(near3(v.eye, 0, -7.2, 1, 1e-12));
    vrView_Zoom(&v, -2);
    ENSURE(near3(v.eye, 0, -8 / 0.9, 1, 1e-12));
    vrView_Zoom(&v, 1000);       /* never reaches look */
    ENSURE(v.eye[1] < 0);
    return 0;
}

/* the centre pixel looks along the view; the top edge's middle is fov/2 up */
static int test_pointer_ray_leaves_at_the_pixel_angle(void)
{
    vrView v = view_from(0, -8, 1);
    double o[3], d[3];
    vrView_PointerRay(&v, 320, 256, 640, 512, o, d);
    ENSURE(near3(o, 0, -8, 1, 0) && near3(d, 0, 1, 0, 1e-15));
    vrView_PointerRay(&v, 320, 0, 640, 512, o, d);
    ENSURE_NEAR(atan2(d[2], d[1]), 22.5 * VR_PI / 180, 1e-12);
    vrView_PointerRay(&v, 640, 256, 640, 512, o, d);   /* right edge: aspect 1.25 */
    ENSURE_NEAR(d[0] / d[1], 1.25 * tan(22.5 * VR_PI / 180), 1e-12);
    return 0;
}

/* a unit cube's face 4 m ahead; behind it, hidden, a second cube; beside
 * them nothing; a cube turned 45 degrees shows its edge at 5 - sqrt 2 */
static int test_ray_cast_meets_the_first_face_at_its_distance(void)
{
    vrWorld *w = vrScene_World(0.1, 0.25, 0);
    vrObjectId near_id = vrScene_Box(w, "near", vec3_make(1, 1, 1), vec3_make(0, 0, 0), 1, 1), id;
    double o[3] = {0, -5, 0}, d[3] = {0, 1, 0}, t, axis[4] = {0, 0, 1, VR_PI / 4};
    vrScene_Box(w, "far", vec3_make(1, 1, 1), vec3_make(0, 5, 0), 1, 1);
    ENSURE(vrWorld_RayCast(w, o, d, &id, &t) == 0);
    ENSURE(id == near_id);
    ENSURE_NEAR(t, 4, 1e-12);
    o[0] = 3;
    ENSURE(vrWorld_RayCast(w, o, d, &id, &t) == -1);
    o[0] = 0;
    vrScene_Edit(w, near_id, vrScene_SetRotation, axis);
    ENSURE(vrWorld_Start(w, NULL, 0) == 0);
    ENSURE(vrWorld_RayCast(w, o, d, &id, &t) == 0 && id == near_id);
    ENSURE_NEAR(t, 5 - sqrt(2), 1e-12);
    vrWorld_Destroy(w);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_trackball_half_height_drag_right_turns_a_quarter_turn),
    TEST(test_trackball_half_height_drag_down_puts_the_eye_overhead),
    TEST(test_trackball_drags_compose_and_undo),
    TEST(test_zoom_scales_the_distance_to_look_by_0_9_a_step),
    TEST(test_pointer_ray_leaves_at_the_pixel_angle),
    TEST(test_ray_cast_meets_the_first_face_at_its_distance),
};

const vrTestSuite vrSuite_Window = {"window", tests, TEST_COUNT(tests), NULL, NULL, 0};
