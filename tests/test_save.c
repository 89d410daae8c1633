/* test_save.c — SPEC 11's saved state through the library alone: numbers
 * that read back to their bits, and a world saved mid-run and read into a
 * fresh one that goes on bit for bit.  (tests/save.sh runs the shell's
 * `save` on every scene the issue names.)
 */
#define _XOPEN_SOURCE 700   /* open_memstream */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include "test.h"
#include "scene.h"
#include "save_line.h"

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

static int test_saved_numbers_read_back_to_the_same_bits(void)
{
    double fixed[] = {0.1, 1.0 / 3.0, -0.0, 0.0, 5e-324, DBL_MIN, DBL_MAX, -1e-300, 1e22, 2.5, -7.25e-5};
    unsigned long long s = 12345;
    int i;
    for (i = 0; i < 2000; i++) {
        double x;
        char b[32];
        if (i < (int)(sizeof fixed / sizeof fixed[0])) x = fixed[i];
        else {
            unsigned long long bits;
            s ^= s << 13, s ^= s >> 7, s ^= s << 17;   /* xorshift64: every bit pattern */
            bits = s;
            memcpy(&x, &bits, sizeof x);
            if (isnan(x)) continue;
        }
        vrFormatExact(b, x);
        ENSURE_MSG(same_bits(strtod(b, NULL), x), "%s does not read back to %a", b, x);
    }
    return 0;
}

static int test_a_state_line_reads_vectors_hex_floats_and_refuses_nan(void)
{
    const char *text = " x=(0x1.8p+1, -0, 5e-324) t=inf";
    vrSaveLine l;
    double v[3], t;
    char err[200];
    ENSURE(vrSaveLine_Parse(&l, "test", text, strlen(text), err, sizeof err) == 0);
    ENSURE(vrSaveLine_Numbers(&l, "x", v, 3, 0, err, sizeof err) == 0);
    ENSURE(v[0] == 3.0 && same_bits(v[1], -0.0) && v[2] == 5e-324);
    ENSURE(vrSaveLine_Numbers(&l, "t", &t, 1, 0, err, sizeof err) != 0);   /* inf only where allowed */
    ENSURE(vrSaveLine_Numbers(&l, "t", &t, 1, 1, err, sizeof err) == 0 && isinf(t));
    text = " x=(1, nan, 2)";
    ENSURE(vrSaveLine_Parse(&l, "test", text, strlen(text), err, sizeof err) == 0);
    ENSURE(vrSaveLine_Numbers(&l, "x", v, 3, 0, err, sizeof err) != 0 && strstr(err, "x must be"));
    return 0;
}

static void set_friction(vrObjectDef *d, const void *mu) { d->friction = *(const double *)mu; }

static int test_a_pile_saved_mid_run_goes_on_bit_for_bit_in_a_fresh_world(void)
{
    const double mu = 0.6;
    vrWorld *a = vrScene_World(0.02, 0.02, 9.8), *b = vrWorld_Create(), *c = NULL;
    vrStats sa, sb;
    char *text = NULL, *bad = NULL, *in_island = NULL;
    size_t len = 0;
    FILE *out = open_memstream(&text, &len);
    vrObjectId gone;
    vrSettings set = *vrWorld_Settings(a);
    char err[200], name[16];
    int k;
    set.default_friction = 0.6;
    ENSURE(vrWorld_SetSettings(a, &set, err, sizeof err) == 0);
    vrScene_Edit(a, vrScene_Box(a, "floor", vec3_make(2, 2, 0.1), vec3_make(0, 0, 0), -1, 0.2), set_friction, &mu);
    for (k = 0; k < 4; k++) {   /* with friction: frictionless, the stack's slight tilts let it slide apart */
        snprintf(name, sizeof name, "b%d", k);
        vrScene_Edit(a, vrScene_Box(a, name, vec3_make(0.1, 0.1, 0.1), vec3_make(0.01 * k, 0, 0.2 + 0.21 * k), 1, 0.2), set_friction, &mu);
    }
    gone = vrScene_Sphere(a, "gone", 0.1, vec3_make(1, 0, 0.5), vec3_make(0, 0, 0), 1, 0.5);
    vrScene_Sphere(a, "ball", 0.1, vec3_make(-1, 0, 0.5), vec3_make(0.5, 0, 0), 1, 0.5);
    ENSURE(vrScene_Step(a, 30) == 0);
    ENSURE(vrScene_State(a, gone).state == VR_STATE_REST);   /* deleting a resting body crashed once */
    ENSURE(vrWorld_DeleteObject(a, gone) == 0);
    ENSURE(vrScene_Step(a, 5) == 0);
    ENSURE(out && vrWorld_WriteSave(a, out, vrScene_DefLine, NULL) == 0);
    fclose(out);
    ENSURE(strstr(text, "state gap") && strstr(text, "state warm") && strstr(text, " rest=1"));
    ENSURE((bad = strdup(text)) && (in_island = strstr(bad, " contact=1 island=")) && (c = vrWorld_Create()));
    in_island[9] = '0';          /* a body in an island out of contact: refused, with the line's words */
    ENSURE(vrScene_ReadSave(a, c, bad) != 0);
    free(bad);
    vrWorld_Destroy(c);
    ENSURE(vrScene_ReadSave(a, b, text) == 0);
    ENSURE(vrScene_Step(a, 40) == 0 && vrScene_Step(b, 40) == 0);
    ENSURE(vrScene_SameDumps(a, b));
    sa = vrScene_Stats(a), sb = vrScene_Stats(b);
    ENSURE(sa.frames == 75 && sb.frames == 75 && sa.time == sb.time);
    ENSURE(sa.collisions == sb.collisions && sa.checks == sb.checks && sa.heap_pops == sb.heap_pops);
    ENSURE(sa.klu_solves == sb.klu_solves && sa.island_steps == sb.island_steps && sa.energy == sb.energy);
    free(text);
    vrWorld_Destroy(a);
    vrWorld_Destroy(b);
    return 0;
}

/* head and hand samples at times and poses of arbitrary bits, every 0.037 s */
static int push_samples(vrWorld *w, int count)
{
    char err[200];
    int k, dev;
    for (k = 0; k < count; k++)
        for (dev = 0; dev < 2; dev++) {
            vrTrackerSample s;
            double a = 0.01 + 0.3 * k + dev;
            memset(&s, 0, sizeof s);
            s.t = 0.037 * k + 0.011 * dev;
            s.position[0] = 0.1 * k / 3.0, s.position[1] = -3 + dev / 7.0, s.position[2] = 1.7 - 0.01 * k;
            s.orientation[0] = cos(a / 2), s.orientation[3] = sin(a / 2);
            s.buttons = dev == VR_DEVICE_HAND ? (unsigned)(k / 5 % 2) : 0;
            if (vrWorld_PushSample(w, (vrDevice)dev, &s, err, sizeof err) != 0) return printf("    %s\n", err), -1;
        }
    return 0;
}

static int same_pose(const vrWorld *a, const vrWorld *b, vrDevice dev)
{
    vrTrackerSample x, y;
    if (vrWorld_TrackerPose(a, dev, &x) != 0 || vrWorld_TrackerPose(b, dev, &y) != 0) return 0;
    return memcmp(x.position, y.position, sizeof x.position) == 0 && x.buttons == y.buttons
           && memcmp(x.orientation, y.orientation, sizeof x.orientation) == 0 && same_bits(x.t, y.t);
}

static int same_sounds(const vrWorld *a, const vrWorld *b, int *count)
{
    const vrSoundEvent *x, *y;
    int n = vrWorld_FrameSounds(a, &x), k;
    if (n != vrWorld_FrameSounds(b, &y)) return 0;
    for (k = 0; k < n; k++)
        if (!same_bits(x[k].t, y[k].t) || !same_bits(x[k].volume, y[k].volume) || x[k].a != y[k].a || x[k].b != y[k].b)
            return 0;
    *count += n;
    return 1;
}

/* a ball between two plates, each hit every 0.0667 s (0.1 m at 3 m/s), so
 * the 0.1 s refractory time keeps every other hit quiet; head and hand
 * samples play on.  Saved at 0.35 s, between a sounded hit on lo (0.310 s)
 * and a quiet one (0.376 s): the fresh world's poses and sounds are the
 * saving world's, frame after frame, and the file holds only the samples
 * a time from 0.35 s on needs. */
static int test_tracker_samples_and_refractory_sounds_go_on_after_a_save(void)
{
    vrWorld *a = vrScene_World(0.05, 0.01, 0), *b = vrWorld_Create();
    char *text = NULL, *p;
    size_t len = 0;
    FILE *out = open_memstream(&text, &len);
    int f, lines = 0, sounds = 0;
    vrScene_Box(a, "lo", vec3_make(1, 1, 0.05), vec3_make(0, 0, 0), -1, 1);
    vrScene_Box(a, "hi", vec3_make(1, 1, 0.05), vec3_make(0, 0, 0.4), -1, 1);
    vrScene_Sphere(a, "ball", 0.1, vec3_make(0, 0, 0.2), vec3_make(0.1, 0, 3), 1, 1);
    ENSURE(push_samples(a, 60) == 0);
    ENSURE(vrScene_Step(a, 7) == 0);
    ENSURE(out && vrWorld_WriteSave(a, out, vrScene_DefLine, NULL) == 0);
    fclose(out);
    for (p = text; (p = strstr(p, "state sample ")); p++) lines++;
    /* 60 samples a device, 0.037 s apart: 10 of each (from 0 and from
     * 0.011 s) are at or before 0.35 s, all but the last of them forgotten */
    ENSURE_MSG(lines == 2 * (60 - 9), "%d sample lines", lines);
    ENSURE(strstr(text, "state sound_pair a=lo b=ball t=0.3103"));
    ENSURE(vrScene_ReadSave(a, b, text) == 0);
    for (f = 0; f < 20; f++) {
        ENSURE(vrScene_Step(a, 1) == 0 && vrScene_Step(b, 1) == 0);
        ENSURE_MSG(same_pose(a, b, VR_DEVICE_HEAD) && same_pose(a, b, VR_DEVICE_HAND), "frame %d: poses differ", f);
        ENSURE_MSG(same_sounds(a, b, &sounds), "frame %d: sounds differ", f);
    }
    ENSURE(sounds >= 8 && vrScene_SameDumps(a, b));
    free(text);
    vrWorld_Destroy(a);
    vrWorld_Destroy(b);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_saved_numbers_read_back_to_the_same_bits),
    TEST(test_a_state_line_reads_vectors_hex_floats_and_refuses_nan),
    TEST(test_a_pile_saved_mid_run_goes_on_bit_for_bit_in_a_fresh_world),
    TEST(test_tracker_samples_and_refractory_sounds_go_on_after_a_save),
};

const vrTestSuite vrSuite_Save = {"save", tests, TEST_COUNT(tests), NULL, NULL, 0};
