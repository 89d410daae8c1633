/* test_parallel_sound.c — collision sounds with workers (SPEC 8, issue
 * 27): the workers' events carry the approach speed and the impulse's
 * point, so that 1 and 2 workers, in this process (memq://) and forked
 * over UDP multicast, make the serial run's sound events bit for bit; with
 * workers on udpm each frame's events go out on VROC_SOUND, where a
 * subscriber decodes exactly them (and once each when the live trackers
 * listen on the same URL).  The scene's impacts are checked against the
 * closed form of a dropped ball, so that equal events are right ones.
 * Marked netns: the runner makes a private network namespace first. */
#include <stdlib.h>
#include <string.h>
#include <lcm/lcm.h>
#include "test.h"
#include "vroc.h"
#include "scene.h"
#include "vroc_sound_t.h"

#define UDPM "udpm://239.255.76.70:7670?ttl=0"
#define FRAMES 150
#define MAX_EV 256

typedef struct Heard { int n; vroc_sound_t m[MAX_EV]; char name[MAX_EV][16]; } Heard;

static void on_sound(const lcm_recv_buf_t *rb, const char *ch, const vroc_sound_t *m, void *user)
{
    Heard *h = user;
    (void)rb, (void)ch;
    if (h->n >= MAX_EV) return;
    h->m[h->n] = *m;   /* its string is the decoder's: copied */
    snprintf(h->name[h->n], sizeof h->name[0], "%s", m->sound);
    h->m[h->n].sound = h->name[h->n];
    h->n++;
}

/* a ball dropped 1 m onto a floor (its first impact at the closed form:
 * it sounds at the contact gap, 1 mm, min(d, 1 mm) as in test_sound.c),
 * two balls thrown at each other, two more dropped from other heights */
static vrWorld *balls(int gps, const char *url)
{
    vrWorld *w = vrScene_World(0.01, 0.01, 9.8);
    vrSettings s = *vrWorld_Settings(w);
    s.gps = gps;
    snprintf(s.lcm_url, sizeof s.lcm_url, "%s", url);
    vrWorld_SetSettings(w, &s, NULL, 0);
    vrScene_Box(w, "floor", vec3_make(2, 2, 0.05), vec3_zero(), -1, 0.9);
    vrScene_Sphere(w, "drop", 0.1, vec3_make(-1, -1, 0.15 + 1e-3 + 1), vec3_zero(), 1, 0.8);
    vrScene_Sphere(w, "left", 0.1, vec3_make(-0.5, 1, 1), vec3_make(1.6, 0, 0), 1, 0.9);
    vrScene_Sphere(w, "right", 0.1, vec3_make(0.5, 1, 1), vec3_make(-1.6, 0, 0), 1, 0.9);
    vrScene_Sphere(w, "low", 0.08, vec3_make(1, -1, 0.6), vec3_zero(), 1, 0.85);
    vrScene_Sphere(w, "high", 0.12, vec3_make(0, -1, 1.4), vec3_zero(), 2, 0.7);
    return w;
}

typedef struct Sounds { int n; vrSoundEvent ev[MAX_EV]; long frame[MAX_EV]; } Sounds;

/* FRAMES frames; each frame's events kept; with a subscriber, what it
 * hears after each frame (tr: the live trackers publish too, as the shell
 * does) */
static int run(vrWorld *w, Sounds *out, lcm_t *sub, vrTrackers *tr)
{
    long f;
    out->n = 0;
    for (f = 0; f < FRAMES; f++) {
        const vrSoundEvent *e;
        int k, m;
        if (vrScene_Step(w, 1) != 0) return -1;
        m = vrWorld_FrameSounds(w, &e);
        if (tr && vrTrackers_PublishSounds(tr, e, m, VR_SOUND_DEFAULT) != 0) return -1;
        for (k = 0; k < m && out->n < MAX_EV; k++) {
            out->frame[out->n] = f;
            out->ev[out->n++] = e[k];
        }
        while (sub && lcm_handle_timeout(sub, m ? 20 : 0) > 0) continue;
    }
    return 0;
}

static int same_bits(const vrSoundEvent *x, const vrSoundEvent *y)
{
    return memcmp(&x->t, &y->t, sizeof x->t) == 0 && memcmp(&x->volume, &y->volume, sizeof x->volume) == 0
           && memcmp(x->position, y->position, sizeof x->position) == 0
           && memcmp(&x->speed, &y->speed, sizeof x->speed) == 0 && x->a == y->a && x->b == y->b;
}

static Sounds serial;

/* the serial run, and the drop's first impact at t = sqrt(2 h / g), speed sqrt(2 g h) */
static int setup(void)
{
    vrWorld *w = balls(0, "memq://");
    vrObjectId drop = vrWorld_FindObject(w, "drop");
    int k, found = 0;
    if (run(w, &serial, NULL, NULL) != 0) return -1;
    for (k = 0; k < serial.n && !found; k++)
        if (serial.ev[k].a == drop || serial.ev[k].b == drop) {
            found = 1;
            if (fabs(serial.ev[k].t - sqrt(2 / 9.8)) > 1e-9 || fabs(serial.ev[k].speed - sqrt(2 * 9.8)) > 1e-9) {
                printf("    the drop's first sound at %.12g s, %.12g m/s\n", serial.ev[k].t, serial.ev[k].speed);
                return -1;
            }
        }
    vrWorld_Destroy(w);
    if (!found || serial.n < 10) printf("    %d serial sounds, drop's %s\n", serial.n, found ? "found" : "missing");
    return found && serial.n >= 10 ? 0 : -1;
}

/* st: the run's stats, when not NULL */
static int matches_serial(int gps, const char *url, vrStats *st)
{
    static Sounds s;
    vrWorld *w = balls(gps, url);
    int k;
    ENSURE(run(w, &s, NULL, NULL) == 0);
    if (st) vrWorld_GetStats(w, st);
    vrWorld_Destroy(w);
    ENSURE_MSG(s.n == serial.n, "%d workers on %s: %d sounds, serial %d", gps, url, s.n, serial.n);
    for (k = 0; k < s.n; k++)
        ENSURE_MSG(s.frame[k] == serial.frame[k] && same_bits(&s.ev[k], &serial.ev[k]),
                   "%d workers on %s: sound %d (t %.17g) differs from the serial one (t %.17g)", gps, url, k,
                   s.ev[k].t, serial.ev[k].t);
    return 0;
}

static int test_workers_make_the_serial_sounds_bit_for_bit(void)
{
    return matches_serial(1, "memq://", NULL) || matches_serial(2, "memq://", NULL)
           || matches_serial(1, UDPM, NULL) || matches_serial(2, UDPM, NULL);
}

/* A worker killed in the middle of a frame that sounds twice (the thrown
 * balls landing together), at the frame's second advance, after its first
 * sound: the frame is done again from its start by the other worker, and
 * its sounds are neither lost nor made twice. */
static int test_a_killed_worker_changes_no_sound(void)
{
    char kill[32];
    vrStats st;
    int k, r;
    for (k = 1; k < serial.n && serial.frame[k] != serial.frame[k - 1]; k++) continue;
    ENSURE_MSG(k < serial.n, "no frame of the serial run sounds twice");
    snprintf(kill, sizeof kill, "1:%ld:2", serial.frame[k] + 1);   /* a worker counts frames from 1 */
    setenv("VROC_FAULT_KILL", kill, 1);
    r = matches_serial(2, UDPM, &st);
    unsetenv("VROC_FAULT_KILL");
    if (r) return r;
    ENSURE_MSG(st.gp_copies[1] == 0 && st.gp_copies[0] > 0, "worker 1 (killed at %s) still holds %lld copies", kill,
               (long long)st.gp_copies[1]);
    return 0;
}

/* what the subscriber heard is the events, in order, bit for bit */
static int heard_all(const Heard *h, const Sounds *s)
{
    int k;
    ENSURE_MSG(h->n == s->n, "heard %d VROC_SOUND messages for %d sounds", h->n, s->n);
    for (k = 0; k < s->n; k++) {
        vrSoundEvent e = s->ev[k];
        e.t = h->m[k].t, e.volume = h->m[k].volume, e.speed = h->m[k].speed;
        memcpy(e.position, h->m[k].position, sizeof e.position);
        ENSURE_MSG(same_bits(&e, &s->ev[k]) && strcmp(h->m[k].sound, VR_SOUND_DEFAULT) == 0,
                   "message %d: t %.17g, sound %s; the event's t %.17g", k, h->m[k].t, h->m[k].sound, s->ev[k].t);
    }
    return 0;
}

static int publishes(int with_trackers)
{
    static Heard h;
    static Sounds s;
    lcm_t *sub = lcm_create(UDPM);
    vrWorld *w = balls(2, UDPM);
    vrTrackers *tr = NULL;
    vroc_sound_t_subscription_t *hears;
    char err[256];
    int r;
    ENSURE_MSG(sub != NULL, "cannot open %s", UDPM);
    h.n = 0;
    ENSURE((hears = vroc_sound_t_subscribe(sub, "VROC_SOUND", on_sound, &h)) != NULL);
    ENSURE(!with_trackers || vrTrackers_Open(&tr, w, UDPM, err, sizeof err) == 0);
    r = run(w, &s, sub, tr);
    vrTrackers_Close(tr);
    vrWorld_Destroy(w);
    while (lcm_handle_timeout(sub, 100) > 0) continue;
    vroc_sound_t_unsubscribe(sub, hears);
    lcm_destroy(sub);
    ENSURE(r == 0);
    ENSURE(s.n == serial.n);
    return heard_all(&h, &s);
}

static int test_workers_on_udpm_publish_the_sounds(void) { return publishes(0); }

static int test_trackers_on_the_workers_url_do_not_repeat_them(void) { return publishes(1); }

static const vrTest tests[] = {
    TEST(test_workers_make_the_serial_sounds_bit_for_bit),
    TEST(test_a_killed_worker_changes_no_sound),
    TEST(test_workers_on_udpm_publish_the_sounds),
    TEST(test_trackers_on_the_workers_url_do_not_repeat_them),
};

const vrTestSuite vrSuite_ParallelSound = {"parallel_sound", tests, TEST_COUNT(tests), setup, NULL, 1};
