/* track.h — the samples of one tracker (SPEC 8): a head or a hand, each
 * sample a time, a pose and for the hand a button mask.  Between samples a
 * pose is interpolated (positions linearly, orientations by slerp); the
 * buttons are those of the last sample at or before the time asked. */
#ifndef VROC_TRACK_H
#define VROC_TRACK_H

#include "vroc.h"
#include "vec.h"

typedef struct vrTrack {
    vrTrackerSample *s;      /* by time, never decreasing */
    int n, cap;
} vrTrack;

/* 0; -1 out of memory; -2 the sample is earlier than the last one */
int vrTrack_Push(vrTrack *tr, const vrTrackerSample *s);
/* forgets the samples no time from t on needs (all but the last at or
 * before t), so that a live tracker's samples do not pile up */
void vrTrack_Forget(vrTrack *tr, double t);
/* the pose at t, interpolated; before the first sample, that sample; after
 * the last, the last (a tracker that stops sending holds its pose).
 * -1 when there is no sample. */
int vrTrack_At(const vrTrack *tr, double t, vrTrackerSample *out);
/* the velocity at t of the motion the interpolation makes: v of the
 * position and w (world frame, rad/s) of the orientation, on the segment
 * that holds t, the later one where two meet (zero outside the samples).
 * -1 when there is no sample. */
int vrTrack_Velocity(const vrTrack *tr, double t, double v[3], double w[3]);
/* the rotation vector r (world frame) with exp(r / 2) q0 = q1, the short
 * way: the turn of a slerp from q0 to q1 */
vec3 vrTrack_Turn(quat q0, quat q1);
void vrTrack_Clear(vrTrack *tr);
void vrTrack_Free(vrTrack *tr);

#endif
