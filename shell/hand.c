/* hand.c — the mouse as the hand (hand.h).
 *
 *   hand_time      a wall-clock moment in simulation time (HandClock)
 *   hand_press     the ray cast that picks, the plane facing the view
 *   hand_move      the pointer's ray on that plane: the hand point
 *   hand_release   the trigger up, and the motion run on (see there)
 *   velocity       the motion over the last HAND_VELOCITY_S seconds
 *   moment         hand_time, after a restart too
 *   push           the one place the samples leave: the world, the log
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "hand.h"

void hand_init(ShHand *h)
{
    const char *path = getenv("VROC_HAND_LOG");
    memset(h, 0, sizeof *h);
    h->object = VR_NO_OBJECT;
    if (path && path[0]) h->log = fopen(path, "w");
}

void hand_done(ShHand *h)
{
    if (h->log) fclose(h->log);
    h->log = NULL;
}

double hand_time(const ShHand *h, const HandClock *c, double tw)
{
    double s = c->next - c->rate * (c->wall_next - tw);
    if (s > c->next) s = c->next;         /* read late: the frame to come has not run yet */
    if (s < c->now) s = c->now;           /* taken while the last frame was computed */
    if (h->pushed && s < h->last_t) s = h->last_t;
    return s;
}

/* the moment in simulation time; a world that forgot the hand (restart)
 * no longer holds our last sample's time */
static double moment(ShHand *h, const vrWorld *w, const HandClock *c, double tw)
{
    vrTrackerSample now;
    if (vrWorld_TrackerPose(w, VR_DEVICE_HAND, &now) != 0) h->pushed = 0;
    return hand_time(h, c, tw);
}

/* The sample into the world (SPEC 8's hand: the orientation the identity,
 * button 1 the trigger) and, as a track file line, into $VROC_HAND_LOG */
static int push(ShHand *h, vrWorld *w, const double p[3], double t, unsigned buttons)
{
    vrTrackerSample s = {0, {0, 0, 0}, {1, 0, 0, 0}, 0};
    s.t = t, s.buttons = buttons;
    memcpy(s.position, p, sizeof s.position);
    if (vrWorld_PushSample(w, VR_DEVICE_HAND, &s, h->error, sizeof h->error) != 0) return -1;
    h->pushed = 1;
    h->last_t = t;
    memcpy(h->last_p, p, sizeof h->last_p);
    if (h->log) {   /* what the world took, not what it refused */
        fprintf(h->log, "%.17g hand %.17g %.17g %.17g 1 0 0 0 %u\n", t, p[0], p[1], p[2], buttons);
        fflush(h->log);
    }
    return 0;
}

static void keep(ShHand *h, const double p[3], double t)
{
    if (h->count == HAND_SAMPLES) {
        memmove(h->t, h->t + 1, (HAND_SAMPLES - 1) * sizeof h->t[0]);
        memmove(h->p, h->p + 1, (HAND_SAMPLES - 1) * sizeof h->p[0]);
        h->count--;
    }
    h->t[h->count] = t;
    memcpy(h->p[h->count], p, sizeof h->p[0]);
    h->count++;
}

/* from the newest sample back to the first one HAND_VELOCITY_S older (or
 * the oldest): a mean over a few polls, not one poll's jitter.  0 when
 * the drag took no simulated time (time stopped): then there is none. */
static int velocity(const ShHand *h, double v[3])
{
    int last = h->count - 1, k = last, i;
    double dt;
    while (k > 0 && h->t[last] - h->t[k] < HAND_VELOCITY_S) k--;
    dt = h->t[last] - h->t[k];
    for (i = 0; i < 3; i++) v[i] = dt > 0 ? (h->p[last][i] - h->p[k][i]) / dt : 0;
    return dt > 0;
}

int hand_press(ShHand *h, vrWorld *w, const double o[3], const double d[3], const double f[3],
               const HandClock *c, double tw)
{
    vrObjectId id;
    double dist, p[3], t = moment(h, w, c, tw);
    int i;
    if (vrWorld_RayCast(w, o, d, &id, &dist) != 0) return 0;
    for (i = 0; i < 3; i++) p[i] = o[i] + dist * d[i];
    h->held = 1;
    h->object = id;
    snprintf(h->name, sizeof h->name, "%s", vrWorld_ObjectName(w, id));
    memcpy(h->point, p, sizeof p);
    memcpy(h->normal, f, sizeof h->normal);
    h->count = 0;
    keep(h, p, t);
    if (h->log) fprintf(h->log, "# grab %s\n", h->name);
    return push(h, w, p, t, VR_BUTTON_TRIGGER) == 0 ? 1 : -1;
}

/* where the ray meets the plane; the last point when it runs parallel to it
 * or meets it behind the eye */
static void on_plane(const ShHand *h, const double o[3], const double d[3], double p[3])
{
    double num = 0, den = 0, s;
    int i;
    for (i = 0; i < 3; i++) {
        num += h->normal[i] * (h->point[i] - o[i]);
        den += h->normal[i] * d[i];
    }
    s = fabs(den) > 1e-9 ? num / den : -1;
    if (s <= 0) {
        memcpy(p, h->p[h->count - 1], 3 * sizeof p[0]);
        return;
    }
    for (i = 0; i < 3; i++) p[i] = o[i] + s * d[i];
}

int hand_move(ShHand *h, vrWorld *w, const double o[3], const double d[3], const HandClock *c, double tw)
{
    double p[3], t = moment(h, w, c, tw);
    if (!h->held) return 0;
    on_plane(h, o, d, p);
    keep(h, p, t);
    return push(h, w, p, t, VR_BUTTON_TRIGGER);
}

/* The trigger goes up where the pointer is, put on the drag's line.  The
 * throw is the velocity of the interpolated motion at that instant, so
 * both segments that meet there move at the drag's velocity: the one
 * that ends there (the release point is the last sample's plus v dt) and
 * the one that starts there (the hand runs on for HAND_VELOCITY_S at v):
 * the throw is the drag's, not the one poll's step before the release.  A drag that took no
 * simulated time (time stopped) has no velocity: the hand stays, and what
 * it held is let go at rest. */
int hand_release(ShHand *h, vrWorld *w, const double o[3], const double d[3], const HandClock *c, double tw)
{
    double p[3], v[3], run[3], t = moment(h, w, c, tw);
    int i, moving;
    if (!h->held) return 0;
    h->held = 0;
    on_plane(h, o, d, p);
    keep(h, p, t);
    moving = velocity(h, v);
    /* on the drag's line from the last sample, so that the segment that
     * ends at the release moves at v too: select mode throws with the
     * motion that brought the hand there (man vroc, SELECT MODE) */
    if (moving && h->pushed && t > h->last_t)
        for (i = 0; i < 3; i++) p[i] = h->last_p[i] + v[i] * (t - h->last_t);
    if (push(h, w, p, t, 0) != 0) return -1;
    if (h->log) fprintf(h->log, "# throw %.17g %.17g %.17g\n", v[0], v[1], v[2]), fflush(h->log);
    if (!moving) return 0;
    for (i = 0; i < 3; i++) run[i] = p[i] + v[i] * HAND_VELOCITY_S;
    return push(h, w, run, t + HAND_VELOCITY_S, 0);
}
