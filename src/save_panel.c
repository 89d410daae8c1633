/* save_panel.c — the tool panel's section of a saved file (save_sections.h):
 *   panel   where the sheet is (the hand may have moved it: it is drawn in
 *           every frame, so a reader that put it back at its default place
 *           would draw other frames), what the hand holds of it (a knob or
 *           the sheet, with the grip), and a slider's place not yet taken
 *           at a frame boundary.
 * Written only when the panel is not as vrPanel_Init leaves it, so a
 * run that never touched it saves no line.  Presses (stop, play, step)
 * are the shell's, acted on after each frame: none is left at a save.
 */
#include <string.h>
#include "panel.h"
#include "save_sections.h"
#include "save_line.h"
#include "world_state.h"

static int untouched(const vrPanel *p)
{
    vrPanel d;
    vrPanel_Init(&d);
    return memcmp(&p->p, &d.p, sizeof d.p) == 0 && memcmp(&p->q, &d.q, sizeof d.q) == 0
        && p->hold == VR_HOLD_NONE && !p->moved[0] && !p->moved[1];
}

static void put_pose(FILE *out, const char *pkey, vec3 p, const char *qkey, quat q)
{
    double a[3] = {p.x, p.y, p.z}, b[4] = {q.w, q.x, q.y, q.z};
    vrSave_Vector(out, pkey, a, 3);
    vrSave_Vector(out, qkey, b, 4);
}

void vrSave_WritePanel(vrWorld *w, int id, FILE *out)
{
    const vrPanel *p = &w->panel;
    (void)id;
    if (untouched(p)) return;
    fputs("state panel", out);
    put_pose(out, "p", p->p, "q", p->q);
    vrSave_Integer(out, "hold", p->hold);
    vrSave_Integer(out, "knob", p->knob);
    put_pose(out, "grip_p", p->grip_p, "grip_q", p->grip_q);
    vrSave_Vector(out, "u", p->u, 2);
    vrSave_Integer(out, "moved", p->moved[0] + 2 * p->moved[1]);
    fputc('\n', out);
}

static int get_pose(vrSaveLine *l, const char *pkey, vec3 *p, const char *qkey, quat *q, char *err, size_t n)
{
    double a[3];
    if (vrSaveLine_Numbers(l, pkey, a, 3, 0, err, n) != 0 || vrSave_GetQuat(l, qkey, q, err, n) != 0) return -1;
    *p = vec3_make(a[0], a[1], a[2]);
    return 0;
}

int vrSave_ReadPanel(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    vrPanel p = w->panel;
    long long hold, knob, moved;
    (void)id;
    if (get_pose(l, "p", &p.p, "q", &p.q, err, n) != 0 || get_pose(l, "grip_p", &p.grip_p, "grip_q", &p.grip_q, err, n) != 0
        || vrSaveLine_Integer(l, "hold", VR_HOLD_NONE, VR_HOLD_SHEET, &hold, err, n) != 0
        || vrSaveLine_Integer(l, "knob", 0, VR_PANEL_CONTROLS - 1, &knob, err, n) != 0
        || vrSaveLine_Numbers(l, "u", p.u, 2, 0, err, n) != 0
        || vrSaveLine_Integer(l, "moved", 0, 3, &moved, err, n) != 0)
        return -1;
    if (!(p.u[0] >= 0 && p.u[0] <= 1 && p.u[1] >= 0 && p.u[1] <= 1)) {
        snprintf(err, n, "state panel: u must be two places 0..1 along the sliders");
        return -1;
    }
    if (hold == VR_HOLD_KNOB && knob != VR_PANEL_TIME_STEP && knob != VR_PANEL_COLLISION_DIST) {
        snprintf(err, n, "state panel: a held knob must be time_step's or collision_dist's (knob=%d or %d)",
                 (int)VR_PANEL_TIME_STEP, (int)VR_PANEL_COLLISION_DIST);
        return -1;
    }
    p.hold = (vrPanelHold)hold;
    p.knob = (vrPanelControl)knob;
    p.moved[0] = (int)(moved & 1);
    p.moved[1] = (int)(moved >> 1);
    w->panel = p;
    return 0;
}
