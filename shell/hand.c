/* hand.c — the mouse as the hand (hand.h).
 *
 *   hand_press     the ray cast that picks, the plane facing the view
 *   hand_move      the pointer's ray on that plane: the hand point
 *   hand_velocity  the motion over the last HAND_VELOCITY_S seconds
 *   hand_send      the one place the samples leave (see below)
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "hand.h"

/* The one function to connect to SPEC 8's hand (issue 27): a trigger-down
 * sample at the grabbed point, the moves, a trigger-up sample with the
 * throw's velocity.  Until then it writes the samples as a track file
 * (SPEC 8's lines, the orientation the identity, button 1 the trigger)
 * into $VROC_HAND_LOG when that is set: what the window would tell the
 * hand, and what the window tests read. */
static void hand_send(ShHand *h, const HandSample *s)
{
    if (!h->log) return;
    if (s->phase == HAND_DOWN) fprintf(h->log, "# grab %s\n", s->name);
    fprintf(h->log, "%.6f hand %.9g %.9g %.9g 1 0 0 0 %d\n", s->t, s->pos[0], s->pos[1], s->pos[2],
            s->phase == HAND_UP ? 0 : 1);
    if (s->phase == HAND_UP) fprintf(h->log, "# throw %.9g %.9g %.9g\n", s->vel[0], s->vel[1], s->vel[2]);
    fflush(h->log);
}

void hand_init(ShHand *h, double t0)
{
    const char *path = getenv("VROC_HAND_LOG");
    memset(h, 0, sizeof *h);
    h->t0 = t0;
    if (path && path[0]) h->log = fopen(path, "w");
}

void hand_done(ShHand *h)
{
    if (h->log) fclose(h->log);
    h->log = NULL;
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
 * the oldest): a mean over a few polls, not one poll's jitter */
static void hand_velocity(const ShHand *h, double v[3])
{
    int last = h->count - 1, k = last, i;
    double dt;
    while (k > 0 && h->t[last] - h->t[k] < HAND_VELOCITY_S) k--;
    dt = h->t[last] - h->t[k];
    for (i = 0; i < 3; i++) v[i] = dt > 0 ? (h->p[last][i] - h->p[k][i]) / dt : 0;
}

static void send(ShHand *h, HandPhase phase, const double p[3], double t)
{
    HandSample s;
    memset(&s, 0, sizeof s);
    s.phase = phase;
    s.t = t - h->t0;
    memcpy(s.pos, p, sizeof s.pos);
    if (phase != HAND_DOWN) hand_velocity(h, s.vel);
    s.object = h->object;
    s.name = h->name;
    hand_send(h, &s);
}

int hand_press(ShHand *h, vrWorld *w, const double o[3], const double d[3], const double f[3], double t)
{
    vrObjectId id;
    double dist, p[3];
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
    send(h, HAND_DOWN, p, t);
    return 1;
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

void hand_move(ShHand *h, const double o[3], const double d[3], double t)
{
    double p[3];
    if (!h->held) return;
    on_plane(h, o, d, p);
    keep(h, p, t);
    send(h, HAND_MOVE, p, t);
}

void hand_release(ShHand *h, const double o[3], const double d[3], double t)
{
    double p[3];
    if (!h->held) return;
    on_plane(h, o, d, p);
    keep(h, p, t);
    send(h, HAND_UP, p, t);
    h->held = 0;
}
