/* panel.c — the virtual tool panel (SPEC 8, thesis appendix A.1): where
 * its controls are, and what the hand's trigger does to them.
 *
 *   button_centre, slider_line   the layout, in the sheet's frame
 *   knob_place       a slider's knob: where the hand put it, else where its setting puts it
 *   to_sheet, to_world           between the sheet's frame and the world's
 *   nearest_control  the control within reach of the hand, nearest first
 *   press            a button: select toggles, stop/play/step are queued
 *   take_knob, follow_knob       a slider held: its knob follows the hand along its line
 *   take_sheet, follow_sheet     the sheet held: it follows the hand rigidly
 *
 * The upper half is the thesis's tape player (stop, play, step) and the
 * select toggle, the lower half its two sliders (A.1.2).
 */
#include <math.h>
#include <string.h>
#include "panel.h"
#include "world_state.h"

static const char *const names[VR_PANEL_CONTROLS] = {"stop", "play", "step", "select", "time_step", "collision_dist"};

const char *vrPanel_ControlName(vrPanelControl c)
{
    return c >= 0 && c < VR_PANEL_CONTROLS ? names[c] : NULL;
}

static int is_slider(vrPanelControl c) { return c == VR_PANEL_TIME_STEP || c == VR_PANEL_COLLISION_DIST; }
static int slider_index(vrPanelControl c) { return c == VR_PANEL_TIME_STEP ? 0 : 1; }

/* ---- the layout ----------------------------------------------------------- */
/* buttons 10 cm apart across the upper half's middle line */
static vec3 button_centre(vrPanelControl c) { return vec3_make(-0.15 + 0.10 * (double)c, 0.0625, 0); }

/* a slider's line: y in the lower half, x from -VR_PANEL_SLIDER_HALF to +;
 * the two lines 5.5 cm apart, so that no point is within reach of both */
static double slider_y(vrPanelControl c) { return c == VR_PANEL_TIME_STEP ? -0.035 : -0.09; }

double vrPanel_SliderValue(vrPanelControl slider, double u)
{
    u = fmin(1, fmax(0, u));
    if (slider == VR_PANEL_TIME_STEP) return fmax(VR_PANEL_TIME_STEP_MIN, VR_PANEL_TIME_STEP_MAX * u);
    /* three decades: equal knob moves change collision_dist by equal factors */
    return VR_PANEL_DIST_MIN * pow(VR_PANEL_DIST_MAX / VR_PANEL_DIST_MIN, u);
}

double vrPanel_SliderPlace(vrPanelControl slider, double value)
{
    double u = slider == VR_PANEL_TIME_STEP ? value / VR_PANEL_TIME_STEP_MAX
                                            : log(value / VR_PANEL_DIST_MIN) / log(VR_PANEL_DIST_MAX / VR_PANEL_DIST_MIN);
    return isfinite(u) ? fmin(1, fmax(0, u)) : 0;
}

static double setting_of(const vrSettings *s, vrPanelControl slider)
{
    return slider == VR_PANEL_TIME_STEP ? s->time_step : s->collision_dist;
}

static int knob_held(const vrPanel *p, vrPanelControl slider) { return p->hold == VR_HOLD_KNOB && p->knob == slider; }

/* the hand's place for the knob while held or until the frame boundary
 * takes it; otherwise the setting's (a value beyond the slider's range:
 * the end it is beyond) */
static double knob_place(const vrWorld *w, vrPanelControl slider)
{
    const vrPanel *p = &w->panel;
    int k = slider_index(slider);
    if (p->moved[k] || knob_held(p, slider)) return p->u[k];
    return vrPanel_SliderPlace(slider, setting_of(&w->s, slider));
}

static vec3 knob_centre(double u, vrPanelControl slider)
{
    return vec3_make(VR_PANEL_SLIDER_HALF * (2 * u - 1), slider_y(slider), 0);
}

vec3 vrPanel_LocalCentre(const vrWorld *w, vrPanelControl c)
{
    return is_slider(c) ? knob_centre(knob_place(w, c), c) : button_centre(c);
}

/* ---- frames --------------------------------------------------------------- */
static vec3 sample_pos(const vrTrackerSample *s) { return vec3_make(s->position[0], s->position[1], s->position[2]); }
static quat sample_quat(const vrTrackerSample *s)
{
    return quat_normalize(quat_make(s->orientation[0], s->orientation[1], s->orientation[2], s->orientation[3]));
}

static vec3 to_sheet(const vrPanel *p, vec3 x) { return quat_unrotate(p->q, vec3_sub(x, p->p)); }
static vec3 to_world(const vrPanel *p, vec3 x) { return vec3_add(quat_rotate(p->q, x), p->p); }

void vrPanel_Init(vrPanel *p)
{
    /* facing the default eye (0,-8,3) from (0,-7,2.5): the front's normal
     * (0,-2,1)/sqrt(5), a turn of atan2(2,1) about x from upright-facing-up */
    memset(p, 0, sizeof *p);
    p->p = vec3_make(0, -7, 2.5);
    p->q = quat_from_axis_angle(vec3_make(1, 0, 0), atan2(2, 1));
    p->grip_q = quat_identity();
}

void vrPanel_Restart(vrPanel *p)
{
    p->hold = VR_HOLD_NONE;
    p->moved[0] = p->moved[1] = 0;
    p->nreq = 0;
}

/* ---- the trigger ---------------------------------------------------------- */
/* the control nearest the hand point (sheet frame) within reach, or -1 */
static int nearest_control(const vrWorld *w, vec3 at)
{
    int c, best = -1;
    double best_d = VR_PANEL_REACH;
    for (c = 0; c < VR_PANEL_CONTROLS; c++) {
        double d = vec3_dist(at, vrPanel_LocalCentre(w, (vrPanelControl)c));
        if (d <= best_d) best = c, best_d = d;
    }
    return best;
}

static int on_sheet(vec3 at)
{
    return fabs(at.x) <= VR_PANEL_HALF_W && fabs(at.y) <= VR_PANEL_HALF_H && fabs(at.z) <= VR_PANEL_REACH;
}

/* select changes no physics, so it acts at once (the next trigger down
 * sees it); time is the caller's: stop, play and step wait for it */
static void press(vrWorld *w, vrPanelControl c)
{
    vrPanel *p = &w->panel;
    p->hold = VR_HOLD_BUTTON;
    if (c == VR_PANEL_SELECT) w->s.select = !w->s.select;
    else if (p->nreq < VR_PANEL_REQUESTS_MAX) p->req[p->nreq++] = c;
}

/* the knob keeps its offset from the hand's projection on the line, so
 * that taking it changes nothing: the hand's moves along the line move it
 * by as much */
static void take_knob(vrWorld *w, vrPanelControl slider, vec3 at)
{
    vrPanel *p = &w->panel;
    int k = slider_index(slider);
    p->u[k] = knob_place(w, slider);
    p->grip_p = vec3_make(at.x - knob_centre(p->u[k], slider).x, 0, 0);
    p->knob = slider;
    p->hold = VR_HOLD_KNOB;
}

static void follow_knob(vrWorld *w, vec3 at)
{
    vrPanel *p = &w->panel;
    int k = slider_index(p->knob);
    double u = fmin(1, fmax(0, ((at.x - p->grip_p.x) / VR_PANEL_SLIDER_HALF + 1) / 2));
    if (u == p->u[k]) return;
    p->u[k] = u;
    p->moved[k] = 1;
}

/* the sheet's pose in the hand's frame, kept while held */
static void take_sheet(vrPanel *p, const vrTrackerSample *hand)
{
    quat qh = sample_quat(hand);
    p->grip_p = quat_unrotate(qh, vec3_sub(p->p, sample_pos(hand)));
    p->grip_q = quat_mul(quat_conj(qh), p->q);
    p->hold = VR_HOLD_SHEET;
}

static void follow_sheet(vrPanel *p, const vrTrackerSample *hand)
{
    quat qh = sample_quat(hand);
    p->p = vec3_add(sample_pos(hand), quat_rotate(qh, p->grip_p));
    p->q = quat_normalize(quat_mul(qh, p->grip_q));
}

int vrPanel_TriggerDown(vrWorld *w, const vrTrackerSample *hand)
{
    vrPanel *p = &w->panel;
    vec3 at;
    int c;
    if (!w->s.panel) return 0;
    at = to_sheet(p, sample_pos(hand));
    c = nearest_control(w, at);
    if (c >= 0 && is_slider((vrPanelControl)c)) take_knob(w, (vrPanelControl)c, at);
    else if (c >= 0) press(w, (vrPanelControl)c);
    else if (on_sheet(at)) take_sheet(p, hand);
    else return 0;
    return 1;
}

void vrPanel_HandMoved(vrWorld *w, const vrTrackerSample *hand)
{
    vrPanel *p = &w->panel;
    if (!vrPanel_Holds(w)) return;
    if (p->hold == VR_HOLD_KNOB) follow_knob(w, to_sheet(p, sample_pos(hand)));
    else if (p->hold == VR_HOLD_SHEET) follow_sheet(p, hand);
}

void vrPanel_TriggerUp(vrWorld *w, const vrTrackerSample *hand)
{
    vrPanel_HandMoved(w, hand);   /* the last move, at the release's time */
    w->panel.hold = VR_HOLD_NONE;
}

/* with the panel off nothing is held (it was turned off under the hand) */
int vrPanel_Holds(const vrWorld *w) { return w->s.panel && w->panel.hold != VR_HOLD_NONE; }

int vrPanel_TakeSettings(vrWorld *w, vrSettings *s)
{
    vrPanel *p = &w->panel;
    if (!p->moved[0] && !p->moved[1]) return 0;
    *s = w->s;
    if (p->moved[0]) s->time_step = vrPanel_SliderValue(VR_PANEL_TIME_STEP, p->u[0]);
    if (p->moved[1]) s->collision_dist = vrPanel_SliderValue(VR_PANEL_COLLISION_DIST, p->u[1]);
    p->moved[0] = p->moved[1] = 0;
    return 1;
}

/* ---- what include/vroc.h shows -------------------------------------------- */
int vrWorld_PanelControl(const vrWorld *w, vrPanelControl c, double centre[3])
{
    vec3 x;
    if (c < 0 || c >= VR_PANEL_CONTROLS) return -1;
    x = to_world(&w->panel, vrPanel_LocalCentre(w, c));
    centre[0] = x.x, centre[1] = x.y, centre[2] = x.z;
    return 0;
}

void vrWorld_PanelPose(const vrWorld *w, double position[3], double orientation[4])
{
    const vrPanel *p = &w->panel;
    position[0] = p->p.x, position[1] = p->p.y, position[2] = p->p.z;
    orientation[0] = p->q.w, orientation[1] = p->q.x, orientation[2] = p->q.y, orientation[3] = p->q.z;
}

int vrWorld_PanelRequests(vrWorld *w, vrPanelControl *out, int max)
{
    vrPanel *p = &w->panel;
    int n = p->nreq < max ? p->nreq : max, i;
    for (i = 0; i < n; i++) out[i] = p->req[i];
    for (i = n; i < p->nreq; i++) p->req[i - n] = p->req[i];   /* what did not fit waits */
    p->nreq -= n;
    return n;
}
