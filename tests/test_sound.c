/* test_sound.c — collision sounds (SPEC 8) against the closed forms of a
 * dropped ball: one event per impact at the analytic bounce times and
 * speeds, the volume law, none once the speed is below sound_min_speed or
 * the ball rests, one per pair per 0.1 s; and tools' vroc-sound renders a
 * log into a WAV whose sounds start at the events' samples. */
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "scene.h"
#include "sound.h"
#define TEST_LCG_SEED 8080
#include "test_lcg.h"

static double contact_gap(double d) { return d < 1e-3 ? d : 1e-3; }

/* a table top at z = 0.05; the ball touches it at 0.15 + g_c */
static vrWorld *drop(double e, double h, double g, double vol, vrObjectId *ball)
{
    vrWorld *w = vrScene_World(0.01, 0.01, g);
    vrSettings s = *vrWorld_Settings(w);
    s.collision_vol = vol;
    vrWorld_SetSettings(w, &s, NULL, 0);
    vrScene_Box(w, "table", vec3_make(2, 2, 0.05), vec3_make(0, 0, 0), -1, 1.0);
    *ball = vrScene_Sphere(w, "ball", 0.1, vec3_make(0, 0, 0.15 + contact_gap(0.01) + h), vec3_zero(), 1, e);
    return w;
}

/* the events of n frames, appended to ev (at most max) */
static int run(vrWorld *w, long frames, vrSoundEvent *ev, int max, int *n)
{
    long f;
    for (f = 0; f < frames; f++) {
        const vrSoundEvent *e;
        int k, m;
        if (vrScene_Step(w, 1) != 0) return -1;
        m = vrWorld_FrameSounds(w, &e);
        for (k = 0; k < m; k++)
            if (*n < max) ev[(*n)++] = e[k];
            else return -1;
    }
    return 0;
}

/* A ball dropped from h: impacts at t1 = sqrt(2h/g), then every 2 e^k v1/g,
 * at speeds e^k v1; each faster than 0.5 m/s sounds once, at volume
 * collision_vol v/10, at the contact point; then nothing, resting or not */
static int test_sound_events_come_at_the_analytic_bounce_times(void)
{
    double h = 1, g = 9.8, e = 0.8, vol = 0.5, v1 = sqrt(2 * g * h), t = sqrt(2 * h / g), v = v1;
    vrSoundEvent ev[64];
    vrObjectId ball;
    vrWorld *w = drop(e, h, g, vol, &ball);
    int n = 0, k;
    ENSURE(run(w, 600, ev, 64, &n) == 0);
    for (k = 0; v > 0.5; k++) {
        ENSURE_MSG(k < n, "%d events, the analytic bounce %d at %.9g s (%.4g m/s) missing", n, k, t, v);
        ENSURE_NEAR(ev[k].t, t, 1e-9);
        ENSURE_NEAR(ev[k].speed, v, 1e-9);
        ENSURE_NEAR(ev[k].volume, vol * v / 10, 1e-10);
        ENSURE_NEAR(ev[k].position[2], 0.05 + contact_gap(0.01) / 2, 1e-3);
        ENSURE(ev[k].a == vrWorld_FindObject(w, "ball") || ev[k].b == vrWorld_FindObject(w, "ball"));
        t += 2 * e * v / g;
        v *= e;
    }
    ENSURE_MSG(n == k, "%d events, %d bounces faster than 0.5 m/s", n, k);
    vrWorld_Destroy(w);
    return 0;
}

/* faster than 10 m/s the volume is collision_vol itself */
static int test_fast_impact_sounds_at_collision_vol(void)
{
    vrSoundEvent ev[4];
    vrObjectId ball;
    vrWorld *w = drop(0.5, 8, 9.8, 0.7, &ball);   /* sqrt(2 g 8) = 12.5 m/s */
    int n = 0;
    ENSURE(run(w, 140, ev, 4, &n) == 0);
    ENSURE(n >= 1);
    ENSURE_NEAR(ev[0].speed, sqrt(2 * 9.8 * 8), 1e-9);
    ENSURE(ev[0].volume == 0.7);
    vrWorld_Destroy(w);
    return 0;
}

/* an elastic ball bouncing every 2 v/g = 1/15 s under g = 30: the pair
 * sounds at most once per 0.1 s, so every other impact, 2/15 s apart */
static int test_one_sound_per_pair_per_tenth_of_a_second(void)
{
    double g = 30, v = 1, h = v * v / (2 * g), period = 2 * v / g;
    vrSoundEvent ev[64];
    vrObjectId ball;
    vrWorld *w = drop(1, h, g, 1, &ball);
    int n = 0, k;
    ENSURE(run(w, 200, ev, 64, &n) == 0);
    ENSURE_MSG(n >= 14 && n <= 16, "%d sounds in 2 s (expected 15)", n);
    for (k = 1; k < n; k++) ENSURE_NEAR(ev[k].t - ev[k - 1].t, 2 * period, 1e-9);
    ENSURE(vrScene_Stats(w).collisions >= 2 * n - 1);
    vrWorld_Destroy(w);
    return 0;
}

/* the refractory rule as it reads (sound.h), by a look at every earlier
 * sound: did pair `order` sound within VR_SOUND_REFRACTORY before t? */
static int sounded_within(const long long *order, const double *t, int n, long long pair, double at)
{
    int i;
    for (i = 0; i < n; i++)
        if (order[i] == pair && at - t[i] < VR_SOUND_REFRACTORY) return 1;
    return 0;
}

/* 20,000 impacts of 2,500 pairs, some 1,000 in any 0.1 s (the peers' 1,000
 * room's rate), against the rule read by a look at every sound before:
 * the same sounds, one for one, through the batches in which sound.c
 * drops the pairs past their refractory time and remakes its table */
static int test_refractory_time_at_a_thousand_impacts_a_tenth(void)
{
    static long long order[20000];
    static double when[20000];
    vrSettings set = vrSettings_Default();
    vrSounds s;
    int k, n = 0, kept = 0;
    double t = 0;
    memset(&s, 0, sizeof s);
    for (k = 0; k < 20000; k++) {
        vrEvent ev;
        int want;
        memset(&ev, 0, sizeof ev);
        t += 2e-4 * uni();
        ev.kind = VR_EV_IMPACT;
        ev.t = t;
        ev.a = (int)(50 * uni());
        ev.b = ev.a + 1 + (int)(50 * uni());
        ev.order = (long long)ev.a << 32 | ev.b;
        ev.approach = -1;
        want = !sounded_within(order, when, n, ev.order, t);
        ENSURE(vrSounds_Note(&s, &ev, &set) == 0);
        ENSURE_MSG(s.n == kept + want, "impact %d at %g: %s", k, t, want ? "no sound" : "a sound in the refractory time");
        kept = s.n;
        if (want) order[n] = ev.order, when[n++] = t;
    }
    printf("    %d sounds of 20000 impacts\n", n);
    ENSURE(n > 10000 && n < 19900);   /* both rules at work */
    vrSounds_Free(&s);
    return 0;
}

/* ---- tools' vroc-sound ----------------------------------------------------------- */

static unsigned le(const unsigned char *p, int bytes)
{
    unsigned v = 0;
    int i;
    for (i = bytes - 1; i >= 0; i--) v = v << 8 | p[i];
    return v;
}

typedef struct Wav { int rate, channels, bits; long frames; short *s; } Wav;

/* a RIFF WAVE file's fmt and data chunks */
static int read_wav(const char *path, Wav *wav)
{
    static unsigned char buf[1 << 22];
    FILE *f = fopen(path, "rb");
    size_t len, at = 12;
    if (!f) return -1;
    len = fread(buf, 1, sizeof buf, f);
    fclose(f);
    if (len < 12 || memcmp(buf, "RIFF", 4) || memcmp(buf + 8, "WAVE", 4)) return -1;
    memset(wav, 0, sizeof *wav);
    while (at + 8 <= len) {
        unsigned size = le(buf + at + 4, 4);
        if (!memcmp(buf + at, "fmt ", 4) && le(buf + at + 8, 2) == 1) {
            wav->channels = (int)le(buf + at + 10, 2);
            wav->rate = (int)le(buf + at + 12, 4);
            wav->bits = (int)le(buf + at + 22, 2);
        } else if (!memcmp(buf + at, "data", 4) && at + 8 + size <= len) {
            wav->frames = size / 2;
            wav->s = (short *)(void *)(buf + at + 8);
        }
        at += 8 + size + (size & 1);
    }
    return wav->s && wav->rate ? 0 : -1;
}

static int peak(const Wav *w, long from, long to)
{
    int m = 0;
    long i;
    for (i = from; i < to && i < w->frames; i++) m = abs(w->s[i]) > m ? abs(w->s[i]) : m;
    return m;
}

static long first_sound(const Wav *w)
{
    long i;
    for (i = 0; i < w->frames; i++)
        if (w->s[i] != 0) return i;
    return -1;
}

/* two bounces, the second at half the volume: silence until the first's
 * sample, the second's peak half the first's, the file as long as the last
 * sound; a bad line is an error naming the log and the line */
static int test_vroc_sound_renders_events_at_their_samples(void)
{
    const char *build = getenv("VROC_BUILD");
    char dir[256], cmd[1400], log[300], wav[300], errf[300], want[400];
    Wav w;
    FILE *f;
    int p1, p2, st;
    ENSURE_MSG(build != NULL, "VROC_BUILD is not set: the runner needs the build folder to find vroc-sound");
    snprintf(dir, sizeof dir, "%.200s/vroc-sound-test-%ld", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp", (long)getpid());
    snprintf(log, sizeof log, "%s.log", dir);
    snprintf(wav, sizeof wav, "%s.wav", dir);
    snprintf(errf, sizeof errf, "%s.err", dir);
    f = fopen(log, "w");
    ENSURE(f != NULL);
    fputs("# t,sound,volume,x,y,z,speed\n0.5,bounce,1,0,0,0.05,10\n1.25,bounce,0.5,0,0,0.05,5\n", f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "%s/vroc-sound %s %s 2>%s", build, log, wav, errf);
    st = system(cmd);
    ENSURE_MSG(st == 0, "'%s' failed (status %d)", cmd, st);
    ENSURE(read_wav(wav, &w) == 0);
    ENSURE(w.rate == 44100 && w.channels == 1 && w.bits == 16);
    ENSURE_MSG(w.frames == lround(1.5 * 44100), "%ld frames", w.frames);
    ENSURE_MSG(labs(first_sound(&w) - 22050) <= 1, "first sound at sample %ld, the event at 22050", first_sound(&w));
    p1 = peak(&w, 22050, 22050 + 11025);
    p2 = peak(&w, 55125, 55125 + 11025);
    ENSURE_MSG(p1 > 16000 && abs(p1 - 2 * p2) <= 2, "peaks %d and %d: volume 1 and 0.5", p1, p2);
    f = fopen(log, "w");
    ENSURE(f != NULL);
    fputs("0.5,bounce,1,0,0,0,1\n0.7,bounce,1,0,0\n", f);
    fclose(f);
    st = system(cmd);
    ENSURE(st != 0 && WIFEXITED(st) && WEXITSTATUS(st) == 1);
    f = fopen(errf, "r");
    ENSURE(f != NULL && fgets(cmd, sizeof cmd, f) != NULL);
    fclose(f);
    snprintf(want, sizeof want, "%s:2: expected 7 fields", log);
    ENSURE_MSG(strstr(cmd, want) != NULL, "got: %s", cmd);
    unlink(log), unlink(wav), unlink(errf);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_sound_events_come_at_the_analytic_bounce_times),
    TEST(test_fast_impact_sounds_at_collision_vol),
    TEST(test_one_sound_per_pair_per_tenth_of_a_second),
    TEST(test_refractory_time_at_a_thousand_impacts_a_tenth),
    TEST(test_vroc_sound_renders_events_at_their_samples),
};

const vrTestSuite vrSuite_Sound = {"sound", tests, TEST_COUNT(tests), NULL, NULL, 0};
