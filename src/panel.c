/* panel.c — the virtual tool panel (SPEC 8).  Not built yet: the panel
 * never takes the trigger, so the hand goes straight to objects. */
#include "panel.h"

int vrPanel_TriggerDown(vrWorld *w, const vrTrackerSample *hand) { (void)w, (void)hand; return 0; }
void vrPanel_HandMoved(vrWorld *w, const vrTrackerSample *hand) { (void)w, (void)hand; }
void vrPanel_TriggerUp(vrWorld *w, const vrTrackerSample *hand) { (void)w, (void)hand; }
int vrPanel_Holds(const vrWorld *w) { (void)w; return 0; }
