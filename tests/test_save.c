/* test_save.c — SPEC 11's saved state through the library alone: numbers
 * that read back to their bits, and a world saved mid-run and read into a
 * fresh one that goes on bit for bit.  (tests/save.sh runs the shell's
 * `save` on every scene the issue names.)
 */
#define _XOPEN_SOURCE 700   /* open_memstream */
#include <float.h>
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

/* the definition writer: one line naming the id, which the reader copies */
static void def_line(void *ctx, FILE *out, vrObjectId id)
{
    (void)ctx;
    fprintf(out, "object %d\n", id);
}

/* b: a fresh world given a's settings and definitions, then the save's state lines */
static int read_save(vrWorld *a, vrWorld *b, char *text)
{
    char err[400], *line, *next;
    vrObjectId selected = VR_NO_OBJECT;
    if (vrWorld_SetSettings(b, vrWorld_Settings(a), err, sizeof err) != 0) return -1;
    for (line = text; line && *line; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = '\0';
        while (*line == ' ') line++;
        if (strncmp(line, "object ", 7) == 0) {
            vrObjectDef d;
            int id = atoi(line + 7);
            vrWorld_GetObjectDef(a, id, &d);
            if (vrWorld_CreateObject(b, vrWorld_ObjectName(a, id), d.type, &selected, err, sizeof err) != 0
                || selected != id || vrWorld_SetObjectDef(b, id, &d, err, sizeof err) != 0)
                return printf("    %s\n", err), -1;
        } else if (strncmp(line, "state ", 6) == 0
                   && vrWorld_ReadState(b, selected, line + 6, strlen(line + 6), err, sizeof err) != 0)
            return printf("    %s\n", err), -1;
    }
    return 0;
}

static int test_a_pile_saved_mid_run_goes_on_bit_for_bit_in_a_fresh_world(void)
{
    vrWorld *a = vrScene_World(0.02, 0.02, 9.8), *b = vrWorld_Create();
    vrStats sa, sb;
    char *text = NULL;
    size_t len = 0;
    FILE *out = open_memstream(&text, &len);
    vrObjectId gone;
    vrSettings set = *vrWorld_Settings(a);
    char err[200], name[16];
    int k;
    set.default_friction = 0.6;
    ENSURE(vrWorld_SetSettings(a, &set, err, sizeof err) == 0);
    vrScene_Box(a, "floor", vec3_make(2, 2, 0.1), vec3_make(0, 0, 0), -1, 0.2);
    for (k = 0; k < 4; k++) snprintf(name, sizeof name, "b%d", k), vrScene_Box(a, name, vec3_make(0.1, 0.1, 0.1), vec3_make(0.01 * k, 0, 0.2 + 0.21 * k), 1, 0.2);
    gone = vrScene_Sphere(a, "gone", 0.1, vec3_make(1, 0, 0.5), vec3_make(0, 0, 0), 1, 0.5);
    vrScene_Sphere(a, "ball", 0.1, vec3_make(-1, 0, 0.5), vec3_make(0.5, 0, 0), 1, 0.5);
    ENSURE(vrScene_Step(a, 30) == 0);
    ENSURE(vrScene_State(a, gone).state == VR_STATE_REST);   /* deleting a resting body crashed once */
    ENSURE(vrWorld_DeleteObject(a, gone) == 0);
    ENSURE(vrScene_Step(a, 5) == 0);
    ENSURE(out && vrWorld_WriteSave(a, out, def_line, NULL) == 0);
    fclose(out);
    ENSURE(strstr(text, "state gap") && strstr(text, "state warm") && strstr(text, " rest=1"));
    ENSURE(read_save(a, b, text) == 0);
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

static const vrTest tests[] = {
    TEST(test_saved_numbers_read_back_to_the_same_bits),
    TEST(test_a_state_line_reads_vectors_hex_floats_and_refuses_nan),
    TEST(test_a_pile_saved_mid_run_goes_on_bit_for_bit_in_a_fresh_world),
};

const vrTestSuite vrSuite_Save = {"save", tests, TEST_COUNT(tests), NULL, NULL, 0};
