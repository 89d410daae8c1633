/* ownerset.h — what the coordinator asks of the pair owners (ARCHITECTURE
 * "the loop, once"): the serial owner of every pair (owners.c), or the
 * workers through LCM (parallel/sgp.c).  The frame loop and rest.c call
 * through it; the two owner sets implement it. */
#ifndef VROC_OWNERSET_H
#define VROC_OWNERSET_H

#include "vroc.h"
#include "owner.h"

/* an owner-set operation's answer: a worker died, the frame starts over */
#define VR_RESTART_FRAME 2

/* first_event first delivers the states in w->pending. */
typedef struct vrOwnerSet {
    int (*first_event)(vrWorld *w, const vrGrid *g, int allow_instant, vrEvent *ev, char *err, size_t n);
    /* every clock moves to ev->t; the responder's new states */
    int (*respond)(vrWorld *w, const vrEvent *ev, vrUpdate *up, char *err, size_t n);
    void (*end_frame)(vrWorld *w, double T);
    /* the pairs of the bodies ids[0..nids) overlapping deeper than tol */
    int (*overlapping)(vrWorld *w, double tol, const int *ids, int nids, int (*out)[2], int max, char *err,
                       size_t n);
    /* an island step at t for a contact step of h (h = 0: the contacts of
     * an instant): every clock moves to t, and the pairs that touch there
     * are appended to out (vrOwner_Touching).  At an instant of the pair
     * (a, b) only its islands' touches are needed: an owner set may give
     * just those (the serial owner does: vrOwner_TouchingFrom) */
    int (*touching)(vrWorld *w, double t, double h, int a, int b, vrTouches *out, char *err, size_t n);
} vrOwnerSet;

#endif
