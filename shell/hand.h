/* hand.h — the mouse as the hand (SPEC 8's select mode, SPEC 9): a click
 * on an object puts the hand's trigger down at the picked point, a drag
 * moves the hand point on the plane through that point that faces the
 * view, a release lets the trigger up with the pointer's velocity.  The
 * samples go into the world (vrWorld_PushSample) at simulation times the
 * window's clock gives (HandClock), and into $VROC_HAND_LOG. */
#ifndef VROC_HAND_H
#define VROC_HAND_H

#include <stdio.h>
#include "vroc.h"

#define HAND_SAMPLES 32
#define HAND_VELOCITY_S 0.05    /* the release velocity: over the last 50 ms of motion */

/* Where the pointer's wall-clock moments fall in simulation time.  Time
 * runs from `now` (the world's time) to `next` (the end of the frame to
 * come), which is due at wall time `wall_next`; `rate` is simulated
 * seconds per wall second (1 in a real-time run, 0 when no frame is due
 * at a wall time: stopped, or a script's frames read the window between
 * them).  A moment at wall time tw is at next - rate (wall_next - tw),
 * within [now, next]: the frames reach it. */
typedef struct HandClock {
    double now, next, wall_next, rate;
} HandClock;

typedef struct ShHand {
    int held;                   /* the trigger is down */
    vrObjectId object;          /* the object picked */
    char name[VR_NAME_MAX + 1];
    double point[3], normal[3]; /* the plane the hand moves on */
    double t[HAND_SAMPLES], p[HAND_SAMPLES][3];   /* the drag, in simulation time */
    int count;                  /* samples kept, the newest at count-1 */
    int pushed;                 /* a sample went into the world: last_t holds */
    double last_t;              /* its time: times never decrease */
    double last_p[3];           /* its position */
    char error[256];            /* the world refused a sample ("" none) */
    FILE *log;                  /* $VROC_HAND_LOG */
} ShHand;

void hand_init(ShHand *h);
void hand_done(ShHand *h);
/* the simulation time of a moment at wall time tw (never before the last
 * sample's) */
double hand_time(const ShHand *h, const HandClock *c, double tw);
/* The ray from the eye o along d (unit), the view's forward f, at wall
 * time tw: 1 when it picked an object (the trigger is now down on it).
 * Each returns -1 when the world refused the sample (h->error says why). */
int hand_press(ShHand *h, vrWorld *w, const double o[3], const double d[3], const double f[3],
               const HandClock *c, double tw);
int hand_move(ShHand *h, vrWorld *w, const double o[3], const double d[3], const HandClock *c, double tw);
int hand_release(ShHand *h, vrWorld *w, const double o[3], const double d[3], const HandClock *c, double tw);

#endif
