/* tracker.c — the world's head and hand (SPEC 8): the samples pushed by
 * track files, live trackers and windows, and the poses they give.
 *
 *   collect          a track file's samples, into tracks of their own first
 *   vrWorld_ReadTrack   `track FILE`: checked whole, then replacing
 */
#include <string.h>
#include "polyhedron.h"
#include "world_state.h"

static int valid_device(vrDevice dev) { return dev == VR_DEVICE_HEAD || dev == VR_DEVICE_HAND; }

int vrWorld_PushSample(vrWorld *w, vrDevice dev, const vrTrackerSample *s, char *err, size_t n)
{
    vrTrack *tr;
    int r;
    if (!valid_device(dev)) return vrGeom_Fail(err, n, "no such tracker device %d", (int)dev);
    tr = &w->track[dev];
    if (!isfinite(s->t)) return vrGeom_Fail(err, n, "a sample's time must be finite");
    vrTrack_Forget(tr, w->t);   /* a live tracker's samples do not pile up */
    r = vrTrack_Push(tr, s);
    if (r == -2) return vrGeom_Fail(err, n, "sample time %.17g is before the %s's last (%.17g)", s->t,
                                    dev == VR_DEVICE_HEAD ? "head" : "hand", tr->s[tr->n - 1].t);
    return r == 0 ? 0 : vrGeom_Fail(err, n, "out of memory");
}

int vrWorld_TrackerPose(const vrWorld *w, vrDevice dev, vrTrackerSample *out)
{
    if (!valid_device(dev)) return -1;
    return vrTrack_At(&w->track[dev], w->t, out);
}

void vrWorld_ClearTracker(vrWorld *w, vrDevice dev)
{
    if (valid_device(dev)) vrTrack_Clear(&w->track[dev]);
}

double vrWorld_Time(const vrWorld *w) { return w->t; }

vrObjectId vrWorld_Held(const vrWorld *w) { return w->grab.held >= 0 ? w->grab.held : VR_NO_OBJECT; }

void vrWorld_FlyOffset(const vrWorld *w, double offset[3]) { vrGrab_FlyOffset(w, offset); }

/* loop.c's run_frame: frame times are t_base + k time_step */
double vrWorld_NextFrameEnd(const vrWorld *w)
{
    return w->t_base + (double)(w->frames + 1 - w->frames_base) * w->s.time_step;
}

typedef struct Collected {
    vrTrack track[2];
    double t0;
} Collected;

static int collect(void *user, vrDevice dev, const vrTrackerSample *s, char *err, size_t n)
{
    Collected *c = user;
    vrTrackerSample at = *s;
    at.t = c->t0 + s->t;
    return vrTrack_Push(&c->track[dev], &at) == 0 ? 0 : vrGeom_Fail(err, n, "out of memory");
}

/* the devices the file names lose their samples: the file's replace them */
static void replace(vrWorld *w, Collected *c)
{
    int d;
    for (d = 0; d < 2; d++) {
        if (c->track[d].n == 0) continue;
        vrTrack_Free(&w->track[d]);
        w->track[d] = c->track[d];
        memset(&c->track[d], 0, sizeof c->track[d]);
    }
}

int vrWorld_ReadTrack(vrWorld *w, const char *path, char *err, size_t n)
{
    Collected c;
    int r, d;
    memset(&c, 0, sizeof c);
    c.t0 = w->t;
    r = vrTrackFile_Read(path, collect, &c, err, n);
    if (r == 0) replace(w, &c);
    for (d = 0; d < 2; d++) vrTrack_Free(&c.track[d]);
    return r;
}

void vrWorld_FreeTrackers(vrWorld *w)
{
    vrTrack_Free(&w->track[VR_DEVICE_HEAD]);
    vrTrack_Free(&w->track[VR_DEVICE_HAND]);
}
