/* grab.h — the hand's select mode (SPEC 8, thesis 1.3 and A.1): the
 * trigger grabs the dynamic object nearest the hand within grab_reach,
 * which then follows the hand rigidly as a kinematic body (body.h) until
 * the trigger goes up and throws it with the hand's v + w x r; reselect
 * takes the previous object again where it is; outside select mode the
 * trigger flies the viewpoint along the hand's +y at fly_speed.  The
 * panel (panel.h) has the trigger first.
 *
 * The frame loop (loop.c) calls vrGrab_Cut at the start of each contact
 * step and at each hand sample time it returns: button changes act at
 * their sample's time, and a held object is re-aimed at the hand at each
 * of the hand's samples.  With no hand track, or outside select mode, it
 * cuts nothing and changes no body: every result stays the same bits. */
#ifndef VROC_GRAB_H
#define VROC_GRAB_H

#include <stdio.h>
#include "vroc.h"
#include "vec.h"
#include "hand_filter.h"

typedef struct vrGrab {
    double t_done;       /* the hand's samples up to here are dispatched */
    unsigned buttons;    /* the buttons as dispatched at t_done */
    int held;            /* the object the hand holds, or -1 */
    int last;            /* the one it held before (reselect), or -1 */
    vec3 off_p;          /* the held object's centre in the hand's frame */
    quat off_q;          /* its orientation in the hand's frame */
    int flying;          /* the trigger flies the view (outside select mode) */
    double fly_t;        /* flown up to this time */
    vec3 fly;            /* the viewpoint's offset so far (m, world) */
    vec3 fly_dir;        /* the hand's +y at fly_t */
    vrHandFilter filter; /* the samples up to t_done, filtered (hand_filter.h) */
} vrGrab;

void vrGrab_Init(vrGrab *g);
/* At time `at`, where a contact step [at, end] starts or a hand sample
 * cut it: the hand's button changes up to `at` dispatched (panel, grab,
 * release, reselect, fly); *cut is where this step must be cut next (the
 * next hand sample before end that matters, else end), and a held
 * object is re-anchored to reach the hand's target there.  The states it
 * changes are in w->update, applied.  0, or -1 with a message. */
int vrGrab_Cut(vrWorld *w, double at, double end, double *cut, char *err, size_t n);
/* the offset the trigger has flown the viewpoint by, at the world's time */
void vrGrab_FlyOffset(const vrWorld *w, double out[3]);
/* save (SPEC 11, grab_save.c): the `state grab ...` line of a saved
 * file (none while the hand has done nothing), and its reader; the
 * signatures of save.h's sections (id is unused) */
struct vrSaveLine;
void vrGrab_Save(vrWorld *w, int id, FILE *out);
int vrGrab_Read(vrWorld *w, int id, struct vrSaveLine *l, char *err, size_t n);
#define VR_GRAB_SAVE_KEYS "t_done buttons held last off_p off_q flying fly_t fly fly_dir f_n f_pt f_px f_pq f_pdx f_lt f_lx f_lq f_ldx"

#endif
