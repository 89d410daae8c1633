/* test_panel.c — the virtual tool panel (SPEC 8, thesis A.1) worked as the
 * hand's dispatch works it: hand samples pushed into the world at times
 * inside a frame, their poses taken back from the hand's track at those
 * times and handed to vrPanel_TriggerDown / HandMoved / TriggerUp.  Each
 * button does what it says, each slider sets the value its knob's place
 * gives (closed forms), and only at the frame boundary; the sheet follows
 * the hand rigidly; panel = 0 takes nothing; the panel is never an object
 * (not in dump or stats, a ball falls through its place as through air);
 * and a frame shows it in its colour, lit as SPEC 4's headlight says. */
#include <stdlib.h>
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "panel.h"
#include "panel_draw.h"
#include "world_state.h"
#include "scene.h"

static char err[512];

static vrWorld *panel_world(int on)
{
    vrWorld *w = vrWorld_Create();
    vrSettings s = *vrWorld_Settings(w);
    s.panel = on;
    vrWorld_SetSettings(w, &s, NULL, 0);
    return w;
}

static vec3 control(const vrWorld *w, vrPanelControl c)
{
    double x[3];
    vrWorld_PanelControl(w, c, x);
    return vec3_make(x[0], x[1], x[2]);
}

/* the sheet's axes in the world: its x (along the 45 cm) and its normal */
static vec3 sheet_axis(const vrWorld *w, vec3 local)
{
    double p[3], q[4];
    vrWorld_PanelPose(w, p, q);
    return quat_rotate(quat_make(q[0], q[1], q[2], q[3]), local);
}

/* a hand sample at t pushed into the world, and the hand's pose at t as
 * the dispatch takes it from the track */
static vrTrackerSample hand_at(vrWorld *w, double t, vec3 p, quat q, unsigned buttons)
{
    vrTrackerSample s, pose;
    s.t = t;
    s.position[0] = p.x, s.position[1] = p.y, s.position[2] = p.z;
    s.orientation[0] = q.w, s.orientation[1] = q.x, s.orientation[2] = q.y, s.orientation[3] = q.z;
    s.buttons = buttons;
    if (vrWorld_PushSample(w, VR_DEVICE_HAND, &s, err, sizeof err) != 0) printf("    push: %s\n", err);
    vrTrack_At(&w->track[VR_DEVICE_HAND], t, &pose);
    return pose;
}

/* a press and release of the trigger at p, at t and t + 0.01 */
static int click(vrWorld *w, double t, vec3 p)
{
    vrTrackerSample down = hand_at(w, t, p, quat_identity(), VR_BUTTON_TRIGGER), up;
    int took = vrPanel_TriggerDown(w, &down);
    up = hand_at(w, t + 0.01, p, quat_identity(), 0);
    if (took) vrPanel_TriggerUp(w, &up);
    return took;
}

/* ---- buttons ------------------------------------------------------------------ */
static int test_stop_play_step_buttons_are_requested_in_the_order_pressed(void)
{
    vrWorld *w = panel_world(1);
    vrPanelControl req[8];
    ENSURE(click(w, 0.02, control(w, VR_PANEL_STOP)) == 1);
    ENSURE(click(w, 0.04, control(w, VR_PANEL_PLAY)) == 1);
    /* within reach: 1.9 cm off the step button's centre, along the normal */
    ENSURE(click(w, 0.06, vec3_madd(control(w, VR_PANEL_STEP), 0.019, sheet_axis(w, vec3_make(0, 0, 1)))) == 1);
    ENSURE(vrWorld_PanelRequests(w, req, 8) == 3);
    ENSURE(req[0] == VR_PANEL_STOP && req[1] == VR_PANEL_PLAY && req[2] == VR_PANEL_STEP);
    ENSURE(vrWorld_PanelRequests(w, req, 8) == 0);           /* taken once */
    ENSURE(vrWorld_Settings(w)->time_step == 0.1 && vrWorld_Settings(w)->select == 0);
    vrWorld_Destroy(w);
    return 0;
}

static int test_select_button_toggles_the_select_setting_at_once(void)
{
    vrWorld *w = panel_world(1);
    vrPanelControl req[4];
    vrTrackerSample down = hand_at(w, 0.03, control(w, VR_PANEL_SELECT), quat_identity(), VR_BUTTON_TRIGGER);
    ENSURE(vrPanel_TriggerDown(w, &down) == 1);
    ENSURE(vrWorld_Settings(w)->select == 1);                /* mid-frame: no physics reads it */
    ENSURE(vrPanel_Holds(w));                                /* the trigger stays the panel's */
    vrPanel_TriggerUp(w, &down);
    ENSURE(!vrPanel_Holds(w));
    ENSURE(click(w, 0.05, control(w, VR_PANEL_SELECT)) == 1);
    ENSURE(vrWorld_Settings(w)->select == 0);
    ENSURE(vrWorld_PanelRequests(w, req, 4) == 0);           /* no time request */
    vrWorld_Destroy(w);
    return 0;
}

static int test_a_hand_beyond_reach_of_controls_and_sheet_is_not_taken(void)
{
    vrWorld *w = panel_world(1);
    vec3 n = sheet_axis(w, vec3_make(0, 0, 1));
    vec3 x = sheet_axis(w, vec3_make(1, 0, 0));
    vrPanelControl req[4];
    ENSURE(click(w, 0.02, vec3_madd(control(w, VR_PANEL_PLAY), 0.021, n)) == 0);   /* 2.1 cm in front */
    ENSURE(click(w, 0.04, vec3_madd(control(w, VR_PANEL_STOP), -0.09, x)) == 0);   /* 1.5 cm off the sheet's edge */
    ENSURE(vrWorld_PanelRequests(w, req, 4) == 0 && !vrPanel_Holds(w));
    vrWorld_Destroy(w);
    return 0;
}

static int test_panel_off_takes_nothing(void)
{
    vrWorld *w = panel_world(0);
    vrPanelControl req[4];
    int c;
    for (c = 0; c < VR_PANEL_CONTROLS; c++) ENSURE(click(w, 0.01 + 0.02 * c, control(w, (vrPanelControl)c)) == 0);
    ENSURE(vrWorld_PanelRequests(w, req, 4) == 0);
    ENSURE(vrWorld_Settings(w)->select == 0 && !vrPanel_Holds(w));
    vrWorld_Destroy(w);
    return 0;
}

/* ---- sliders ------------------------------------------------------------------ */
/* the knob taken at its centre and moved by d along its line, and by 3 cm
 * across it (only the projection counts), at t0 and t0 + 0.02 */
static void drag_knob(vrWorld *w, vrPanelControl slider, double t0, double d)
{
    vec3 at = control(w, slider), x = sheet_axis(w, vec3_make(1, 0, 0)), n = sheet_axis(w, vec3_make(0, 0, 1));
    vrTrackerSample down = hand_at(w, t0, at, quat_identity(), VR_BUTTON_TRIGGER), moved, up;
    if (vrPanel_TriggerDown(w, &down) != 1) printf("    the knob was not taken\n");
    moved = hand_at(w, t0 + 0.01, vec3_madd(vec3_madd(at, d / 2, x), 0.03, n), quat_identity(), VR_BUTTON_TRIGGER);
    vrPanel_HandMoved(w, &moved);
    up = hand_at(w, t0 + 0.02, vec3_madd(vec3_madd(at, d, x), 0.03, n), quat_identity(), 0);
    vrPanel_TriggerUp(w, &up);
}

/* the line is 36 cm: the knob's place moves by d / 0.36; time_step =
 * 2 s x place.  The frame after the boundary is the new time_step long. */
static int test_time_step_slider_moved_by_d_sets_two_seconds_times_the_knobs_place(void)
{
    vrWorld *w = panel_world(1);
    double d = 0.09, u = 0.1 / 2 + d / 0.36, t;
    vec3 start = control(w, VR_PANEL_TIME_STEP);
    drag_knob(w, VR_PANEL_TIME_STEP, 0.02, d);
    ENSURE(vrWorld_Settings(w)->time_step == 0.1);           /* not mid-frame */
    ENSURE_NEAR(vec3_dist(control(w, VR_PANEL_TIME_STEP), start), d, 1e-12);   /* the knob shows it */
    ENSURE(vrScene_Step(w, 1) == 0);                         /* the boundary, then a frame */
    ENSURE_NEAR(vrWorld_Settings(w)->time_step, 2 * u, 1e-12);
    t = vrWorld_Time(w);
    ENSURE_NEAR(t, 2 * u, 1e-12);
    ENSURE(vrScene_Step(w, 1) == 0);
    ENSURE_NEAR(vrWorld_Time(w), 2 * (2 * u), 1e-12);
    vrWorld_Destroy(w);
    return 0;
}

/* logarithmic: collision_dist = 1 mm x 2000^place; 0.25 m sits at
 * log(250) / log(2000) */
static int test_collision_dist_slider_moved_by_d_sets_1mm_times_2000_to_the_place(void)
{
    vrWorld *w = panel_world(1);
    double d = -0.12, u = log(250.0) / log(2000.0) + d / 0.36;
    drag_knob(w, VR_PANEL_COLLISION_DIST, 0.03, d);
    ENSURE(vrWorld_Settings(w)->collision_dist == 0.25);
    ENSURE(vrScene_Step(w, 1) == 0);
    ENSURE_NEAR(vrWorld_Settings(w)->collision_dist, 0.001 * pow(2000.0, u), 1e-12);
    ENSURE_NEAR(vrWorld_Settings(w)->time_step, 0.1, 0);     /* the other slider untouched */
    vrWorld_Destroy(w);
    return 0;
}

static int test_knobs_stop_at_their_lines_ends(void)
{
    vrWorld *w = panel_world(1);
    drag_knob(w, VR_PANEL_TIME_STEP, 0.01, 1.0);
    drag_knob(w, VR_PANEL_COLLISION_DIST, 0.05, -1.0);
    ENSURE(vrScene_Step(w, 1) == 0);
    ENSURE(vrWorld_Settings(w)->time_step == 2.0);
    ENSURE_NEAR(vrWorld_Settings(w)->collision_dist, 0.001, 1e-15);
    drag_knob(w, VR_PANEL_TIME_STEP, 2.2, -1.0);            /* 0 would stop track time: 1 ms */
    drag_knob(w, VR_PANEL_COLLISION_DIST, 2.3, 1.0);
    ENSURE(vrScene_Step(w, 1) == 0);
    ENSURE(vrWorld_Settings(w)->time_step == 0.001);
    ENSURE_NEAR(vrWorld_Settings(w)->collision_dist, 2.0, 1e-12);
    vrWorld_Destroy(w);
    return 0;
}

/* a value the other settings refuse is an error naming the slider; the
 * knob goes back to the setting */
static int test_a_slider_value_the_settings_refuse_is_a_clear_error(void)
{
    vrWorld *w = panel_world(1);
    vrSettings s = *vrWorld_Settings(w);
    s.internal_step = 1e-6;                                  /* 0.1 s: 1e5 steps, 2 s would be 2e6 */
    ENSURE(vrWorld_SetSettings(w, &s, err, sizeof err) == 0);
    drag_knob(w, VR_PANEL_TIME_STEP, 0.01, 1.0);
    ENSURE(vrWorld_Step(w, 1, err, sizeof err) != 0);
    ENSURE_MSG(strstr(err, "tool panel") && strstr(err, "internal_step"), "%s", err);
    ENSURE(vrWorld_Settings(w)->time_step == 0.1);
    ENSURE_NEAR(vrPanel_LocalCentre(w, VR_PANEL_TIME_STEP).x, 0.18 * (2 * 0.05 - 1), 1e-15);
    vrWorld_Destroy(w);
    return 0;
}

/* more presses between two reads than the queue holds keep the first ones */
static int test_presses_beyond_the_queue_keep_the_first_32(void)
{
    vrWorld *w = panel_world(1);
    vrPanelControl req[VR_PANEL_REQUESTS_MAX + 8];
    int k;
    for (k = 0; k < VR_PANEL_REQUESTS_MAX; k++) ENSURE(click(w, 0.02 * k, control(w, VR_PANEL_STEP)) == 1);
    for (k = 0; k < 8; k++) ENSURE(click(w, 0.7 + 0.02 * k, control(w, VR_PANEL_STOP)) == 1);
    ENSURE(vrWorld_PanelRequests(w, req, VR_PANEL_REQUESTS_MAX + 8) == VR_PANEL_REQUESTS_MAX);
    for (k = 0; k < VR_PANEL_REQUESTS_MAX; k++) ENSURE(req[k] == VR_PANEL_STEP);
    vrWorld_Destroy(w);
    return 0;
}

/* restart lets go of what the trigger held and forgets presses and moved
 * knobs not yet taken; the sheet stays where the hand put it */
static int test_restart_lets_go_and_forgets_presses_but_keeps_the_sheet(void)
{
    vrWorld *w = panel_world(1);
    vec3 on_sheet = vec3_add(control(w, VR_PANEL_PLAY), sheet_axis(w, vec3_make(0, -0.15, 0)));
    vec3 moved_to = vec3_add(on_sheet, vec3_make(0.3, 0.2, 0.5)), stop;
    vrTrackerSample down, moved;
    vrPanelControl req[4];
    ENSURE(click(w, 0.01, control(w, VR_PANEL_STOP)) == 1);
    drag_knob(w, VR_PANEL_TIME_STEP, 0.02, 0.1);
    down = hand_at(w, 0.05, on_sheet, quat_identity(), VR_BUTTON_TRIGGER);
    ENSURE(vrPanel_TriggerDown(w, &down) == 1);
    moved = hand_at(w, 0.06, moved_to, quat_identity(), VR_BUTTON_TRIGGER);
    vrPanel_HandMoved(w, &moved);
    stop = control(w, VR_PANEL_STOP);
    vrWorld_Restart(w);
    ENSURE(!vrPanel_Holds(w) && vrWorld_PanelRequests(w, req, 4) == 0);
    ENSURE(vec3_dist(control(w, VR_PANEL_STOP), stop) == 0);
    ENSURE(vrScene_Step(w, 1) == 0);
    ENSURE(vrWorld_Settings(w)->time_step == 0.1 && vrWorld_Time(w) == 0.1);
    vrWorld_Destroy(w);
    return 0;
}

/* ---- the sheet -------------------------------------------------------------------- */
/* taken on the sheet away from the controls, the hand turned and moved:
 * every control c goes to p1 + R(q1 q0^-1) (c - p0) */
static int test_sheet_taken_follows_the_hand_rigidly_and_turns_with_it(void)
{
    vrWorld *w = panel_world(1);
    quat q0 = quat_from_axis_angle(vec3_normalize(vec3_make(1, 2, 3)), 0.4);
    quat q1 = quat_mul(quat_from_axis_angle(vec3_normalize(vec3_make(-2, 1, 0.5)), 1.1), q0);
    quat turn = quat_mul(q1, quat_conj(q0));
    vec3 p0 = vec3_add(control(w, VR_PANEL_STOP), sheet_axis(w, vec3_make(0.06, -0.17, 0.01)));
    vec3 p1 = vec3_make(1.5, -6, 3.2), before[VR_PANEL_CONTROLS];
    vrTrackerSample down, moved, up;
    int c;
    for (c = 0; c < VR_PANEL_CONTROLS; c++) before[c] = control(w, (vrPanelControl)c);
    down = hand_at(w, 0.02, p0, q0, VR_BUTTON_TRIGGER);
    ENSURE(vrPanel_TriggerDown(w, &down) == 1 && vrPanel_Holds(w));
    moved = hand_at(w, 0.05, vec3_lerp(p0, p1, 0.5), q1, VR_BUTTON_TRIGGER);
    vrPanel_HandMoved(w, &moved);
    up = hand_at(w, 0.08, p1, q1, 0);
    vrPanel_TriggerUp(w, &up);
    ENSURE(!vrPanel_Holds(w));
    for (c = 0; c < VR_PANEL_CONTROLS; c++) {
        vec3 want = vec3_add(p1, quat_rotate(turn, vec3_sub(before[c], p0)));
        ENSURE_MSG(vec3_dist(control(w, (vrPanelControl)c), want) < 1e-12, "%s off by %g",
                   vrPanel_ControlName((vrPanelControl)c), vec3_dist(control(w, (vrPanelControl)c), want));
    }
    /* let go, the hand moves on alone */
    moved = hand_at(w, 0.09, vec3_make(0, 0, 0), q0, 0);
    vrPanel_HandMoved(w, &moved);
    ENSURE(vec3_dist(control(w, VR_PANEL_STOP), vec3_add(p1, quat_rotate(turn, vec3_sub(before[0], p0)))) < 1e-12);
    vrWorld_Destroy(w);
    return 0;
}

/* ---- never an object ---------------------------------------------------------------- */
static int count_lines(const char *s)
{
    int n = 0;
    for (; *s; s++) n += *s == '\n';
    return n;
}

static int test_panel_is_never_in_dump_or_stats(void)
{
    vrWorld *w = panel_world(1);
    char *dump;
    vrScene_Sphere(w, "ball", 0.1, vec3_make(0, -7, 2.5), vec3_zero(), 1, 1);   /* at the panel's centre */
    ENSURE(vrScene_Step(w, 2) == 0);
    dump = vrScene_Dump(w);
    ENSURE(dump && count_lines(dump) == 2);                  /* the header and the ball */
    free(dump);
    ENSURE(vrScene_Stats(w).objects == 1 && vrScene_Stats(w).pairs == 0);
    vrWorld_Destroy(w);
    return 0;
}

/* a ball dropped from h through the panel's place onto a table bounces
 * back to h e^2 (SPEC 3), and crosses the panel in free fall */
static int test_ball_dropped_through_the_panel_falls_as_if_it_were_not_there(void)
{
    double h = 3.0, e = 0.8, g = 9.8, contact = 0.15 + 1e-3, z0 = contact + h, apex = -1, low = 1e9, worst = 0;
    int crossing = 0;
    vrWorld *w = vrScene_World(0.001, 0.01, g);
    vrSettings s = *vrWorld_Settings(w);
    vrObjectId ball;
    int i;
    s.panel = 1;
    ENSURE(vrWorld_SetSettings(w, &s, err, sizeof err) == 0);
    vrScene_Box(w, "table", vec3_make(1, 1, 0.05), vec3_make(0, -7, 0), -1, 1.0);
    ball = vrScene_Sphere(w, "ball", 0.1, vec3_make(0, -7, z0), vec3_zero(), 1, e);
    for (i = 1; i <= 1500; i++) {
        vrObjectState st;
        ENSURE(vrScene_Step(w, 1) == 0);
        st = vrScene_State(w, ball);
        if (st.position[2] < low) low = st.position[2];
        if (st.position[2] > 2.2 && st.position[2] < 2.8 && low > 2.2)   /* through the sheet's place */
            worst = fmax(worst, fabs(st.position[2] - (z0 - g * st.t * st.t / 2))), crossing++;
        if (low < contact + sqrt(2 * g * h) * 0.001 && st.position[2] > apex) apex = st.position[2];   /* it bounced */
    }
    ENSURE(low >= contact - 1e-12);
    ENSURE(crossing > 50);                                   /* 0.6 m at ~6 m/s, in 1 ms frames */
    ENSURE_MSG(worst < 1e-9, "off free fall by %g at the panel", worst);
    ENSURE_NEAR(apex - contact, h * e * e, 1e-3);
    vrWorld_Destroy(w);
    return 0;
}

/* ---- drawn ----------------------------------------------------------------------------- */
/* the pixel of world point x in a view with ipd 0 (both eyes at `eye`) */
static void pixel_of(const vrView *v, vec3 x, int *col, int *row)
{
    vec3 eye = vec3_make(v->eye[0], v->eye[1], v->eye[2]);
    vec3 f = vec3_normalize(vec3_sub(vec3_make(v->look[0], v->look[1], v->look[2]), eye));
    vec3 r = vec3_normalize(vec3_cross(f, vec3_make(v->up[0], v->up[1], v->up[2]))), u = vec3_cross(r, f);
    vec3 d = vec3_sub(x, eye);
    double t = tan(v->fov * 3.14159265358979323846 / 360), z = vec3_dot(d, f);
    double nx = vec3_dot(d, r) / (z * t * v->width / v->height), ny = vec3_dot(d, u) / (z * t);
    *col = (int)((nx + 1) / 2 * v->width);
    *row = (int)((1 - ny) / 2 * v->height);
}

/* a bare spot of the sheet (between the button row and the top slider)
 * facing the default eye shows the sheet's colour times 0.2 + 0.8 cos,
 * cos between its normal and the line of sight (SPEC 4's headlight); with
 * the panel off, the black background */
static int test_a_frame_shows_the_panel_in_its_colour_where_it_is_drawn(void)
{
    vrWorld *w = panel_world(1);
    vrView v = vrView_Default();
    vrDisplay *d = NULL;
    vec3 spot, f;
    const unsigned char *px;
    double lit;
    int col, row, width, i;
    vrSettings s;
    v.ipd = 0;
    ENSURE_MSG(vrDisplay_Open(&d, err, sizeof err) == 0, "%s", err);
    spot = vec3_add(vec3_make(w->panel.p.x, w->panel.p.y, w->panel.p.z), sheet_axis(w, vec3_make(0.02, 0.01, 0)));
    f = vec3_normalize(vec3_sub(vec3_make(v.look[0], v.look[1], v.look[2]), vec3_make(v.eye[0], v.eye[1], v.eye[2])));
    lit = 0.2 + 0.8 * -vec3_dot(sheet_axis(w, vec3_make(0, 0, 1)), f);
    pixel_of(&v, spot, &col, &row);
    ENSURE_MSG(vrDisplay_Render(d, w, &v, err, sizeof err) == 0, "%s", err);
    px = vrDisplay_Pixels(d, 0, &width, NULL) + 3 * ((size_t)row * (size_t)width + (size_t)col);
    for (i = 0; i < 3; i++)
        ENSURE_MSG(abs(px[i] - (int)floor(vrPanelDraw_SheetColor[i] * lit + 0.5)) <= 1, "channel %d: %d, want %g",
                   i, px[i], vrPanelDraw_SheetColor[i] * lit);
    s = *vrWorld_Settings(w);
    s.panel = 0;
    ENSURE(vrWorld_SetSettings(w, &s, err, sizeof err) == 0);
    ENSURE(vrDisplay_Render(d, w, &v, err, sizeof err) == 0);
    px = vrDisplay_Pixels(d, 0, &width, NULL) + 3 * ((size_t)row * (size_t)width + (size_t)col);
    ENSURE(px[0] == 0 && px[1] == 0 && px[2] == 0);
    vrDisplay_Close(d);
    vrWorld_Destroy(w);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_stop_play_step_buttons_are_requested_in_the_order_pressed),
    TEST(test_select_button_toggles_the_select_setting_at_once),
    TEST(test_a_hand_beyond_reach_of_controls_and_sheet_is_not_taken),
    TEST(test_panel_off_takes_nothing),
    TEST(test_time_step_slider_moved_by_d_sets_two_seconds_times_the_knobs_place),
    TEST(test_collision_dist_slider_moved_by_d_sets_1mm_times_2000_to_the_place),
    TEST(test_knobs_stop_at_their_lines_ends),
    TEST(test_a_slider_value_the_settings_refuse_is_a_clear_error),
    TEST(test_presses_beyond_the_queue_keep_the_first_32),
    TEST(test_restart_lets_go_and_forgets_presses_but_keeps_the_sheet),
    TEST(test_sheet_taken_follows_the_hand_rigidly_and_turns_with_it),
    TEST(test_panel_is_never_in_dump_or_stats),
    TEST(test_ball_dropped_through_the_panel_falls_as_if_it_were_not_there),
    TEST(test_a_frame_shows_the_panel_in_its_colour_where_it_is_drawn),
};

const vrTestSuite vrSuite_Panel = {"panel", tests, TEST_COUNT(tests), NULL, NULL, 0};
