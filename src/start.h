/* start.h — a start (vrWorld_Start, before every frame): new objects join
 * the simulation, changed settings reach the owners, the owners are chosen
 * and brought to date, and what was added or moved is checked for overlaps
 * (SPEC 1.4). */
#ifndef VROC_START_H
#define VROC_START_H

#include "world_state.h"

/* objects not yet in the simulation join it: their states go out as
 * changes, so that their pairs are evaluated at the next span start */
int vrWorld_MakeLive(vrWorld *w, char *err, size_t n);
/* every object built and live, a saved run's bodies as they were read
 * (resume.h): the first part of a start, and a saved file's last line */
int vrWorld_GoLive(vrWorld *w, char *err, size_t n);
/* the live dynamic bodies again, after objects joined or left */
int vrWorld_ListDynamic(vrWorld *w);
/* vrWorld_SetSettings: checked whole, then kept for the next frame; here
 * because a start takes the tool panel's sliders through it too */
int vrWorld_TakeSettings(vrWorld *w, const vrSettings *s, char *err, size_t n);

#endif
