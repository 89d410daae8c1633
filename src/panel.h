/* panel.h — the virtual tool panel (SPEC 8): a 45 x 25 cm sheet in the
 * world, drawn in the frames, never colliding, with buttons (stop, play,
 * step, select) and sliders (time_step, collision_dist) worked by the hand.
 *
 * The hand's trigger is dispatched by the grab code (SPEC 8's precedence
 * at trigger down: a panel control, then the panel itself, then an
 * object, then flying): it asks the panel first, at each trigger change
 * and each hand move, at the hand sample's time. */
#ifndef VROC_PANEL_H
#define VROC_PANEL_H

#include "vroc.h"

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

#endif
