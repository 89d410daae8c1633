/* hand.h — the mouse as the hand (SPEC 8's select mode, SPEC 9): a click
 * picks the object under the pointer, a drag moves the hand point on the
 * plane through the grabbed point that faces the view, a release throws
 * with the pointer's velocity.  The samples go out through one function,
 * hand_send (hand.c), to be connected to the hand API of SPEC 8. */
#ifndef VROC_HAND_H
#define VROC_HAND_H

#include <stdio.h>
#include "vroc.h"

#define HAND_SAMPLES 32
#define HAND_VELOCITY_S 0.05    /* the release velocity: over the last 50 ms of motion */

typedef enum HandPhase { HAND_DOWN, HAND_MOVE, HAND_UP } HandPhase;

/* what the window hands to the hand: a SPEC 8 hand sample and more */
typedef struct HandSample {
    HandPhase phase;
    double t;                   /* s since the window opened */
    double pos[3];              /* the hand point, world, m */
    double vel[3];              /* its velocity, m/s (HAND_UP: the throw) */
    vrObjectId object;          /* the object grabbed */
    const char *name;
} HandSample;

typedef struct ShHand {
    int held;
    vrObjectId object;
    char name[VR_NAME_MAX + 1];
    double point[3], normal[3]; /* the plane the hand moves on */
    double t[HAND_SAMPLES], p[HAND_SAMPLES][3];
    int count;                  /* samples kept, the newest at count-1 */
    double t0;
    FILE *log;                  /* $VROC_HAND_LOG */
} ShHand;

void hand_init(ShHand *h, double t0);
void hand_done(ShHand *h);
/* the ray from the eye o along d (unit), the view's forward f: 1 when it
 * picked an object (the hand now holds it) */
int hand_press(ShHand *h, vrWorld *w, const double o[3], const double d[3], const double f[3], double t);
void hand_move(ShHand *h, const double o[3], const double d[3], double t);
void hand_release(ShHand *h, const double o[3], const double d[3], double t);

#endif
