/* hand_filter.h — the 1€ filter on the hand's samples (Casiez, Roussel,
 * Vogel, CHI 2012), the optional smoothing of SPEC 8 (hand_filter = 1).
 *
 * Each sample is filtered once, in time order, as the frame loop passes
 * it (grab.c): an exponential smoothing of the position whose cutoff
 * rises with the filtered speed, fc = hand_min_cutoff + hand_beta |dx|
 * (dx smoothed at a fixed 1 Hz), alpha = 1 / (1 + 1 / (2 pi fc Te)) for
 * the time Te since the last sample; the orientation is slerped toward
 * the sample by the same alpha.  Between filtered samples the pose is
 * interpolated as the raw ones are (lerp, slerp), so the held object
 * follows, and a throw takes, the filtered motion: smoother, and behind
 * the hand (a lag of about (1 - alpha) / alpha samples at a steady speed). */
#ifndef VROC_HAND_FILTER_H
#define VROC_HAND_FILTER_H

#include "vroc.h"
#include "vec.h"

typedef struct vrHandFiltered {
    double t;
    vec3 x, dx;              /* the filtered position and speed */
    quat q;
} vrHandFiltered;

typedef struct vrHandFilter {
    int n;                   /* samples filtered: 0, 1, or 2 for two or more (prev valid) */
    vrHandFiltered prev, last;
} vrHandFilter;

/* the filter after sample s, from f (min_cutoff Hz, beta s/m) */
vrHandFiltered vrHandFilter_Next(const vrHandFilter *f, const vrTrackerSample *s, double min_cutoff, double beta);
/* s filtered: the filter moves on */
void vrHandFilter_Take(vrHandFilter *f, const vrTrackerSample *s, double min_cutoff, double beta);
/* the filtered pose between a and b at t (a.t <= t <= b.t) */
void vrHandFilter_Between(const vrHandFiltered *a, const vrHandFiltered *b, double t, vrTrackerSample *out);

#endif
