/* vroc-tracker — publishes a track file in real time (SPEC 8), as a
 * tracker would: each sample on VROC_HEAD or VROC_HAND at its time after
 * the start, carrying its track time.
 *
 *   vroc-tracker FILE [URL]
 *
 * URL defaults to the workers' udpm://239.255.76.67:7667?ttl=0 (this host
 * only).  The whole file is checked first (errors name the file and line,
 * exit status 1); then the samples go out, and it exits after the last.
 * lcm-logger records such a session; lcm-logplayer plays it back.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <lcm/lcm.h>
#include "vroc.h"
#include "vroc_tracker_t.h"

typedef struct Sample { vrDevice dev; vrTrackerSample s; } Sample;
typedef struct Samples { Sample *s; long n, cap; } Samples;

static int collect(void *user, vrDevice dev, const vrTrackerSample *s, char *err, size_t n)
{
    Samples *all = user;
    if (all->n == all->cap) {
        long cap = all->cap ? 2 * all->cap : 256;
        Sample *m = realloc(all->s, (size_t)cap * sizeof *m);
        if (!m) return snprintf(err, n, "out of memory"), -1;
        all->s = m;
        all->cap = cap;
    }
    all->s[all->n].dev = dev;
    all->s[all->n++].s = *s;
    return 0;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void sleep_until(double t)
{
    double left = t - now_s();
    if (left > 0) {
        struct timespec ts;
        ts.tv_sec = (time_t)left;
        ts.tv_nsec = (long)((left - (double)ts.tv_sec) * 1e9);
        nanosleep(&ts, NULL);
    }
}

static int publish(lcm_t *lcm, const Sample *s)
{
    vroc_tracker_t m;
    int i;
    m.t = s->s.t;
    for (i = 0; i < 3; i++) m.position[i] = s->s.position[i];
    for (i = 0; i < 4; i++) m.orientation[i] = s->s.orientation[i];
    m.buttons = (int32_t)s->s.buttons;
    return vroc_tracker_t_publish(lcm, s->dev == VR_DEVICE_HEAD ? "VROC_HEAD" : "VROC_HAND", &m);
}

int main(int argc, char **argv)
{
    const char *url = argc > 2 ? argv[2] : "udpm://239.255.76.67:7667?ttl=0";
    Samples all = {NULL, 0, 0};
    char err[1200];
    lcm_t *lcm;
    double start;
    long k;
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: vroc-tracker FILE [URL]\n");
        return 2;
    }
    if (vrTrackFile_Read(argv[1], collect, &all, err, sizeof err) != 0) {
        fprintf(stderr, "vroc-tracker: %s\n", err);
        free(all.s);
        return 1;
    }
    lcm = lcm_create(url);
    if (!lcm) {
        fprintf(stderr, "vroc-tracker: cannot open LCM URL %s (for udpm: is there a multicast route?)\n", url);
        free(all.s);
        return 1;
    }
    start = now_s();
    for (k = 0; k < all.n; k++) {
        sleep_until(start + all.s[k].s.t);
        if (publish(lcm, &all.s[k]) != 0) {
            fprintf(stderr, "vroc-tracker: cannot publish on %s\n", url);
            break;
        }
    }
    lcm_destroy(lcm);
    free(all.s);
    return k == all.n ? 0 : 1;
}
