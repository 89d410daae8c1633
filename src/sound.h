/* sound.h — collision sounds (SPEC 8, thesis 4.3's sound server): one
 * event per impact faster than sound_min_speed, at most one per pair per
 * VR_SOUND_REFRACTORY seconds, so that a rolling or resting contact does
 * not drone. */
#ifndef VROC_SOUND_H
#define VROC_SOUND_H

#include "vroc.h"
#include "event.h"

#define VR_SOUND_REFRACTORY 0.1   /* s: a pair's sounds at least this far apart */
#define VR_SOUND_FULL_SPEED 10.0  /* m/s: an impact this fast sounds at collision_vol */

typedef struct vrSoundLast { long long order; double t; } vrSoundLast;

typedef struct vrSounds {
    vrSoundEvent *ev;        /* this frame's */
    int n, cap;
    vrSoundLast *last;       /* pairs that sounded, in the order they did: those within the
                                refractory time, and some past it (dropped in batches) */
    int nlast, lastcap;
    vrSoundLast *latest;     /* each pair's latest sound, hashed by pair order (open
                                addressing, order -1: empty): whether it is quiet, in O(1) */
    int nlatest, latestcap;
} vrSounds;

/* an impulse event ev (serial owner: with its point and approach): a
 * sound when it is fast enough and its pair has been quiet long enough.
 * -1 when out of memory. */
int vrSounds_Note(vrSounds *s, const vrEvent *ev, const vrSettings *set);
/* a new frame: the last frame's events go */
void vrSounds_Frame(vrSounds *s);
/* a pair that sounded at t (a saved file's, SPEC 11): it stays quiet
 * until its refractory time is over.  -1 when out of memory. */
int vrSounds_Remember(vrSounds *s, long long order, double t);
/* every pair may sound again (restart) */
void vrSounds_Clear(vrSounds *s);
void vrSounds_Free(vrSounds *s);

#endif
