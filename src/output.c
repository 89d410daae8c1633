/* output.c — the machine-readable outputs of SPEC 1.3: `dump` and `stats`.
 * Tests and benchmarks read these lines: keys are added, never renamed. */
#include <stdlib.h>
#include <string.h>
#include "vroc.h"

void vrFormatDouble(char buf[32], double x)
{
    static const char *const forms[] = {"%.15g", "%.16g", "%.17g"};
    int i;
    if (x == 0) x = 0;   /* -0 prints as 0 */
    for (i = 0; i < 3; i++) {
        snprintf(buf, 32, forms[i], x);
        if (strtod(buf, NULL) == x) return;
    }
}

static const vrWorld *sort_world;
static int by_name(const void *a, const void *b)
{
    return strcmp(vrWorld_ObjectName(sort_world, *(const int *)a), vrWorld_ObjectName(sort_world, *(const int *)b));
}

static const char *state_name(vrMotionState s)
{
    static const char *const names[] = {"static", "moving", "supported", "rest"};
    return names[s];
}

static void put_numbers(FILE *out, const double *v, int n)
{
    char buf[32];
    int i;
    for (i = 0; i < n; i++) {
        vrFormatDouble(buf, v[i]);
        fprintf(out, ",%s", buf);
    }
}

int vrWorld_WriteDump(const vrWorld *w, FILE *out)
{
    int n = vrWorld_ObjectCount(w), i;
    int *ids = malloc((size_t)(n ? n : 1) * sizeof *ids);
    if (!ids) return -1;
    vrWorld_ObjectList(w, ids, n);
    sort_world = w;
    qsort(ids, (size_t)n, sizeof *ids, by_name);
    fprintf(out, "# name,t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,state\n");
    for (i = 0; i < n; i++) {
        vrObjectState st;
        if (vrWorld_GetObjectState(w, ids[i], &st) != 0) continue;
        fputs(vrWorld_ObjectName(w, ids[i]), out);
        put_numbers(out, &st.t, 1);
        put_numbers(out, st.position, 3);
        put_numbers(out, st.orientation, 4);
        put_numbers(out, st.linear_vel, 3);
        put_numbers(out, st.angular_vel, 3);
        fprintf(out, ",%s\n", state_name(st.state));
    }
    free(ids);
    return ferror(out) ? -1 : 0;
}

/* " key=a/b/c", one number per worker */
static void put_list(FILE *out, const char *key, const long long *v, int n)
{
    int i;
    fprintf(out, " %s=", key);
    for (i = 0; i < n && i < 64; i++) fprintf(out, "%s%lld", i ? "/" : "", v[i]);
}

int vrWorld_WriteStats(const vrWorld *w, FILE *out)
{
    vrStats s;
    char e[32], t[32];
    vrWorld_GetStats(w, &s);
    vrFormatDouble(e, s.energy);
    vrFormatDouble(t, s.time);
    fprintf(out, "frames=%ld time=%s objects=%d dynamic=%d resting=%d pairs=%ld subframes=%ld "
            "subframes_thesis=%ld checks=%lld heap_pops=%lld collisions=%lld klu_solves=%lld "
            "klu_refactors=%lld klu_factors=%lld energy=%s frame_ms=%.3f sim_ms=%.3f render_ms=%.3f",
            s.frames, t, s.objects, s.dynamic, s.resting, s.pairs, s.subframes, s.subframes_thesis,
            s.checks, s.heap_pops, s.collisions, s.klu_solves, s.klu_refactors, s.klu_factors, e,
            s.frame_ms, s.sim_ms, s.render_ms);
    fprintf(out, " island_steps=%lld island_contacts=%lld", s.island_steps, s.island_contacts);
    if (s.gps > 0) {
        fprintf(out, " gps=%d messages=%lld copies=%lld", s.gps, s.messages, s.copies);
        put_list(out, "gp_checks", s.gp_checks, s.gps);
        put_list(out, "gp_copies", s.gp_copies, s.gps);
        put_list(out, "gp_pairs", s.gp_pairs, s.gps);
        fprintf(out, " foreign=%lld malformed=%lld", s.foreign, s.malformed);
    }
    fprintf(out, " clamps=%lld", s.clamps);
    fprintf(out, " live_pairs=%lld\n", s.live_pairs);   /* keys are only ever added at the end */
    return ferror(out) ? -1 : 0;
}
