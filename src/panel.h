/* panel.h — the virtual tool panel (SPEC 8, thesis appendix A.1): a
 * 45 x 25 cm sheet in the world, drawn in the frames, never colliding,
 * with buttons (stop, play, step, select) and sliders (time_step,
 * collision_dist) worked by the hand.
 *
 * The hand's trigger is dispatched by the grab code (SPEC 8's precedence
 * at trigger down: a panel control, then the panel itself, then an
 * object, then flying): it asks the panel first, at each trigger change
 * and each hand move, at the hand sample's time.  Those calls come in the
 * middle of a frame, so nothing here changes the physics: a slider's new
 * value waits in the panel until the next frame boundary, where
 * vrWorld_Start takes it (vrPanel_TakeSettings); stop, play and step are
 * requests the caller that runs frames reads (vrWorld_PanelRequests);
 * only select, which no physics reads, changes at once.
 *
 * The sheet's frame: origin at its centre, x along its 45 cm (to the
 * right seen from the front), y up its 25 cm, z the front's normal.  The
 * controls lie in its plane (z = 0); the layout is man vroc's TOOL PANEL.
 */
#ifndef VROC_PANEL_H
#define VROC_PANEL_H

#include "vroc.h"
#include "vec.h"

#define VR_PANEL_HALF_W 0.225       /* m: the sheet is 45 x 25 cm (thesis A.1.1) */
#define VR_PANEL_HALF_H 0.125
#define VR_PANEL_REACH 0.02         /* m: the trigger takes a control this near its centre (SPEC 8), */
                                    /* and the sheet this near its plane */
#define VR_PANEL_SLIDER_HALF 0.18   /* m: half a slider's line */
#define VR_PANEL_TIME_STEP_MIN 0.001   /* s: the time_step slider's low end (man vroc: not 0) */
#define VR_PANEL_TIME_STEP_MAX 2.0
#define VR_PANEL_DIST_MIN 0.001     /* m: the collision_dist slider, logarithmic */
#define VR_PANEL_DIST_MAX 2.0

/* what the trigger holds */
typedef enum vrPanelHold { VR_HOLD_NONE, VR_HOLD_BUTTON, VR_HOLD_KNOB, VR_HOLD_SHEET } vrPanelHold;

typedef struct vrPanel {
    vec3 p;                  /* the sheet's centre, world */
    quat q;                  /* sheet frame to world, unit */
    vrPanelHold hold;
    vrPanelControl knob;     /* VR_HOLD_KNOB: the slider held */
    vec3 grip_p;             /* VR_HOLD_SHEET: the sheet's pose in the hand's frame */
    quat grip_q;
    double u[2];             /* a moved knob's place along its line, 0..1, by slider */
    int moved[2];            /* u[k] holds a value for the next frame boundary */
    vrPanelControl req[VR_PANEL_REQUESTS_MAX];   /* stop, play, step presses, oldest first */
    int nreq;
} vrPanel;

/* the default placement (man vroc): 1 m in front of the default eye
 * (0,-8,3), 0.5 m below it, facing it */
void vrPanel_Init(vrPanel *p);
/* `restart`: nothing held, no request or moved knob left; the sheet stays
 * where the user put it */
void vrPanel_Restart(vrPanel *p);

/* the trigger went down with the hand at `hand` (world pose): 1 when the
 * panel took it (a control pressed or a slider's knob held, or the sheet
 * itself grabbed to move it), 0 when the trigger goes on to objects */
int vrPanel_TriggerDown(vrWorld *w, const vrTrackerSample *hand);
/* the hand moved while the panel holds the trigger: a held knob or the
 * held sheet follows it */
void vrPanel_HandMoved(vrWorld *w, const vrTrackerSample *hand);
/* the trigger went up: the panel lets go of whatever it held */
void vrPanel_TriggerUp(vrWorld *w, const vrTrackerSample *hand);
/* 1 while the panel holds the trigger */
int vrPanel_Holds(const vrWorld *w);

/* The frame boundary (vrWorld_Start): 1 and *s = the world's settings
 * with the moved sliders' values, when a knob moved since the last call
 * (the moves are then forgotten); 0 when nothing moved. */
int vrPanel_TakeSettings(vrWorld *w, vrSettings *s);

/* a slider's value at knob place u (0..1), and the place of a value
 * (clamped to the line's ends): time_step linear, max(1 ms, 2 s u);
 * collision_dist logarithmic, 1 mm 2000^u */
double vrPanel_SliderValue(vrPanelControl slider, double u);
double vrPanel_SliderPlace(vrPanelControl slider, double value);
/* a control's centre in the sheet's frame (a slider's: its knob's, now) */
vec3 vrPanel_LocalCentre(const vrWorld *w, vrPanelControl c);

#endif
