/* live.c — live trackers over LCM (SPEC 8): samples on VROC_HEAD and
 * VROC_HAND pushed into the world as they come, track time counted from the
 * `trackers = URL` statement; and the world's sound events published on
 * VROC_SOUND.
 *
 *   take          one message: checked, then pushed (vrWorld_PushSample)
 *   drain         whatever has arrived
 *   vrTrackers_Poll   before a frame: the samples that reach its end
 *
 * A run driven by a tracker is the run its track file gives when every
 * frame starts only once each sending device has sent a sample at or past
 * the frame's end: the poses of the frame are then interpolated between
 * the same samples.  A device that sends nothing for VR_TRACKER_DEADLINE
 * seconds of wall time is no longer waited for (it holds its last pose)
 * until it sends again.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <lcm/lcm.h>
#include "vroc.h"
#include "vroc_tracker_t.h"
#include "sound_lcm.h"

#define VR_CH_HEAD "VROC_HEAD"
#define VR_CH_HAND "VROC_HAND"

typedef struct Device {
    int active;              /* sending: waited for */
    double last_t;           /* its last sample's simulation time */
    double last_wall;        /* when it came, s */
} Device;

struct vrTrackers {
    lcm_t *lcm;
    char url[256];           /* the statement's */
    vrWorld *w;
    double t0;               /* simulation time of track time 0 */
    lcm_subscription_t *sub[2];
    Device dev[2];
    long long received, refused;
};

static double wall_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* a sample a tracker may send: finite, a unit quaternion (then
 * normalised), buttons 0..3 */
static int valid(const vroc_tracker_t *m, vrTrackerSample *s)
{
    double len = 0;
    int i;
    if (!isfinite(m->t) || m->t < 0 || m->buttons < 0 || m->buttons > 3) return 0;
    for (i = 0; i < 3; i++)
        if (!isfinite(m->position[i])) return 0;
    for (i = 0; i < 4; i++) len += m->orientation[i] * m->orientation[i];
    len = sqrt(len);
    if (!(fabs(len - 1) <= 1e-5)) return 0;
    for (i = 0; i < 3; i++) s->position[i] = m->position[i];
    for (i = 0; i < 4; i++) s->orientation[i] = m->orientation[i] / len;
    s->buttons = (unsigned)m->buttons;
    return 1;
}

static void take(vrTrackers *tr, vrDevice d, const lcm_recv_buf_t *rb)
{
    vroc_tracker_t m;
    vrTrackerSample s;
    char err[256];
    int ok;
    if (vroc_tracker_t_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        tr->refused++;
        return;
    }
    ok = valid(&m, &s);
    s.t = tr->t0 + m.t;
    if (d == VR_DEVICE_HEAD) s.buttons = 0;
    vroc_tracker_t_decode_cleanup(&m);
    if (!ok || vrWorld_PushSample(tr->w, d, &s, err, sizeof err) != 0) {
        tr->refused++;   /* malformed, or older than the device's last: dropped */
        return;
    }
    tr->received++;
    tr->dev[d].active = 1;
    tr->dev[d].last_t = s.t;
    tr->dev[d].last_wall = wall_s();
}

static void on_head(const lcm_recv_buf_t *rb, const char *channel, void *user)
{
    (void)channel;
    take(user, VR_DEVICE_HEAD, rb);
}

static void on_hand(const lcm_recv_buf_t *rb, const char *channel, void *user)
{
    (void)channel;
    take(user, VR_DEVICE_HAND, rb);
}

int vrTrackers_Open(vrTrackers **out, vrWorld *w, const char *url, char *err, size_t n)
{
    vrTrackers *tr = calloc(1, sizeof *tr);
    *out = NULL;
    if (!tr) return snprintf(err, n, "out of memory"), -1;
    tr->lcm = lcm_create(url);
    if (!tr->lcm) {
        free(tr);
        snprintf(err, n, "cannot open LCM URL %s (for udpm: is there a multicast route?)", url);
        return -1;
    }
    snprintf(tr->url, sizeof tr->url, "%s", url);
    tr->w = w;
    tr->t0 = vrWorld_Time(w);
    tr->sub[0] = lcm_subscribe(tr->lcm, VR_CH_HEAD, on_head, tr);
    tr->sub[1] = lcm_subscribe(tr->lcm, VR_CH_HAND, on_hand, tr);
    *out = tr;
    return 0;
}

void vrTrackers_Close(vrTrackers *tr)
{
    int i;
    if (!tr) return;
    for (i = 0; i < 2; i++)
        if (tr->sub[i]) lcm_unsubscribe(tr->lcm, tr->sub[i]);
    lcm_destroy(tr->lcm);
    free(tr);
}

static int handle(vrTrackers *tr, double wait)
{
    int ms = wait > 0 ? (int)ceil(wait * 1e3) : 0;
    return lcm_handle_timeout(tr->lcm, ms);
}

static void drain(vrTrackers *tr)
{
    int guard = 100000;   /* a flood cannot keep a frame from starting */
    while (guard-- > 0 && handle(tr, 0) > 0) continue;
}

/* a device still sending that has not reached T */
static int waiting_for(vrTrackers *tr, double T, double deadline, double now, double *wait)
{
    int d, any = 0;
    *wait = deadline;
    for (d = 0; d < 2; d++) {
        Device *v = &tr->dev[d];
        double left;
        if (!v->active || v->last_t >= T) continue;
        left = v->last_wall + deadline - now;
        if (left <= 0) {
            v->active = 0;   /* it stopped: the run goes on with its last pose */
            continue;
        }
        any = 1;
        if (left < *wait) *wait = left;
    }
    return any;
}

int vrTrackers_Poll(vrTrackers *tr, double T, double deadline)
{
    double wait;
    drain(tr);
    while (deadline > 0 && waiting_for(tr, T, deadline, wall_s(), &wait))
        if (handle(tr, wait) > 0) drain(tr);
    return tr->dev[0].active || tr->dev[1].active;
}

int vrTrackers_WaitFirst(vrTrackers *tr, double deadline)
{
    double end = wall_s() + deadline;
    drain(tr);
    while (!tr->dev[0].active && !tr->dev[1].active) {
        double left = end - wall_s();
        if (left <= 0) return 0;
        handle(tr, left);
    }
    return 1;
}

long long vrTrackers_Refused(const vrTrackers *tr) { return tr->refused; }

/* Workers on the same network URL publish the sounds themselves
 * (parallel/sgp.c): a listener there would hear each event twice. */
int vrTrackers_PublishSounds(vrTrackers *tr, const vrSoundEvent *ev, int n, const char *sound)
{
    const vrSettings *s = vrWorld_Settings(tr->w);
    if (s->gps > 0 && strncmp(s->lcm_url, "memq://", 7) != 0 && strcmp(s->lcm_url, tr->url) == 0) return 0;
    return vrSounds_Publish(tr->lcm, ev, n, sound);
}
