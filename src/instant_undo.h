/* instant_undo.h — the pairwise answers of one instant, taken back when
 * they drive a body into something immovable it rests on (SPEC 7,
 * instant_undo.c).
 *
 * Impacts that can bounce are answered pair by pair at their instant, so
 * that a Newton's cradle sends out one ball.  A ball striking a box that
 * lies on the floor is not a cradle: the floor holds the box, and the
 * three answered together leave the box lying and send the ball up at e
 * times its speed.  Pair by pair, the ball's impulse sent the box into the
 * floor and the floor's sent it up again (a 6 cm hop under a 1 kg ball
 * dropped 1 m on 5 kg, e = 0.8).  So the loop notes the states that the
 * instant's pairwise answers change, as they were; when a follow-up at
 * that instant drives a body so changed into a static (or held) body, every
 * answer of the instant is taken back and the instant starts again, its
 * first impact then answered with its islands (island_step.c's instant),
 * once an instant. */
#ifndef VROC_INSTANT_UNDO_H
#define VROC_INSTANT_UNDO_H

#include "event.h"

struct vrWorld;

typedef struct vrInstantLog {
    double t;               /* the instant noted (NaN: none) */
    int held;               /* 1: taken back, its next answer with its islands; 2: so answered */
    int together;           /* an islands' answer or a push-out at t: nothing to take back */
    long long collisions, clamps;   /* stats collisions and clamps as t's answers found them */
    int answers;            /* answers noted at t */
    vrUpdate before;        /* the bodies t's pairwise answers changed, as they were */
    long long *order;       /* the pairs answered pairwise at t */
    int norder, ordercap;
} vrInstantLog;

void vrInstantLog_Init(vrInstantLog *l);
void vrInstantLog_Free(vrInstantLog *l);
/* a frame starts: nothing noted (a frame run again starts as clean) */
void vrInstantLog_Frame(vrInstantLog *l);
/* ev answered by up, before up is applied: the bodies it changes, as
 * they are; together = 1 for an islands' answer (nothing then to note,
 * and the instant can no longer be taken back; so too after a push-out,
 * and once it was taken back).  -1: out of memory */
int vrInstantLog_Note(struct vrWorld *w, const vrEvent *ev, const vrUpdate *up, int together);
/* 1 when ev, a follow-up at the noted instant, drives a body one of its
 * pairwise answers changed into an immovable body, through a pair not
 * yet answered, under the global force accel (none: never): the instant
 * is to be taken back */
int vrInstantLog_Drives(const struct vrWorld *w, const vrEvent *ev, vec3 accel);
/* the instant taken back: its states as they were put in up (to be
 * applied as an answer is), collisions as they were, held set; the
 * number of answers taken back (the loop counts an instant's answers), or
 * -1 when out of memory */
int vrInstantLog_Undo(struct vrWorld *w, vrUpdate *up);
/* 1 when ev is the first event at an instant taken back (its first
 * impact again): answered with its islands.  Those islands so answered,
 * the instant's later events are answered as any (pairwise): a pile's big
 * islands, left by their sweeps a little short, came back at the instant
 * again and again, each then solved whole (a landing pile of 300 took
 * five island answers for each instant taken back) */
static inline int vrInstantLog_Held(const vrInstantLog *l, const vrEvent *ev) { return l->held == 1 && ev->t == l->t; }

#endif
