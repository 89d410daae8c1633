/* bench_scale.c — SPEC 10 (issue 26): "n can be 10,000" (make bench).
 *
 * SPEC 10's room: N objects (`random N`, spheres and cubes, e = 1) flying in
 * a room without gravity and without speed clamps, N = 2,000, 5,000 and
 * 10,000 in rooms of 35, 47.6 and 60 m (the same density).  Each size runs
 * in a fresh child process (fork from this small one), so that its peak
 * resident set (VmHWM, tests/peak_mem.h) is its own: built, started, then
 * FRAMES frames timed by the world's own sim_ms (simulation only, not the
 * build).  The figure is the median of RUNS children (the counts are
 * deterministic, only the times vary).
 *
 *   scale     frames/s, peak memory, live pairs (records) against the
 *             logical n(n-1)/2, bytes per object; goal >= 20 frames/s and
 *             <= 2 GB at 10,000
 *   workers   `random 10000` in the 60 m room with gps = 1 and 2, in the
 *             process (memq://) and forked over UDP multicast (udpm, in a
 *             private network namespace, tests/netns.h), against serial,
 *             interleaved runs: frames/s, peak memory of the SGP (with
 *             memq://, of the process and its workers) and of a forked
 *             worker, messages per frame.  The workers are forked while
 *             the world is empty (a start before the room is built), so a
 *             worker's peak is its own, not the room it would inherit.
 *
 *   floor     N cubes of 0.2 m on one static floor, 0.5 m apart (each its
 *             own island, as a user's 10,000 blocks on a table), let go
 *             0.5 mm above it: the landing (the first FLOOR_FRAMES frames,
 *             every cube in contact, then put to rest) and as many frames
 *             after, all at rest; frames/s of each and peak memory
 *
 * Prints tables and `csv,` lines; asserts nothing. */
#define _DEFAULT_SOURCE
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "vroc.h"
#include "../tests/netns.h"
#include "in_child.h"
#include "figures.h"
#include "../tests/peak_mem.h"

#define FRAMES 20
#define RUNS 3
/* the workers' room: SPEC 10's 10,000 */
#define WORKER_N 10000
#define WORKER_ROOM 60.0
#define WORKER_FRAMES 10
#define UDPM "udpm://239.255.76.67:7667?ttl=0"

typedef struct Result {
    int ok;
    double fps, peak_mb, gp_peak_mb, sim_ms, frames;
    long long live_pairs, messages, collisions;
    long pairs;
    int objects;
} Result;

static vrWorld *room(int n, double side, int gps, const char *url)
{
    vrWorld *w = vrWorld_Create();
    vrSettings s = *vrWorld_Settings(w);
    char err[256] = "";
    int failed;
    s.room = side;
    s.seed = 1993;
    s.collision_dist = 0.01;
    s.time_step = 0.05;
    s.max_linear = 1000;
    s.max_angular = 10000;
    s.gps = gps;
    snprintf(s.lcm_url, sizeof s.lcm_url, "%s", url);
    failed = vrWorld_SetSettings(w, &s, err, sizeof err) != 0;
    if (!failed && gps > 0) failed = vrWorld_Start(w, err, sizeof err) != 0;   /* the workers, forked small */
    if (failed || vrWorld_AddRandom(w, n, err, sizeof err) != 0 || vrWorld_Start(w, err, sizeof err) != 0) {
        fprintf(stderr, "bench_scale: room of %d: %s\n", n, err);
        vrWorld_Destroy(w);
        return NULL;
    }
    return w;
}

/* the largest peak resident set (kB) of this process's children: its
 * forked workers, still running */
static long children_peak_kb(void)
{
    DIR *d = opendir("/proc");
    struct dirent *e;
    long most = 0;
    while (d && (e = readdir(d))) {
        char path[300], line[512];
        FILE *f;
        long pid = strtol(e->d_name, NULL, 10), ppid = -1;
        if (pid <= 0) continue;
        snprintf(path, sizeof path, "/proc/%ld/stat", pid);
        if (!(f = fopen(path, "r"))) continue;
        /* pid (comm) state ppid: the comm may hold spaces, so after the last ')' */
        if (fgets(line, sizeof line, f) && strrchr(line, ')')) sscanf(strrchr(line, ')') + 1, " %*c %ld", &ppid);
        fclose(f);
        if (ppid == (long)getpid() && vrPeakMem_Kb((pid_t)pid) > most) most = vrPeakMem_Kb((pid_t)pid);
    }
    if (d) closedir(d);
    return most;
}

/* in this (child) process: the room built, `frames` frames timed */
static Result measure(int n, double side, int gps, const char *url, int frames)
{
    Result r;
    vrWorld *w = room(n, side, gps, url);
    vrStats a, b;
    char err[256];
    memset(&r, 0, sizeof r);
    if (!w) return r;
    vrWorld_GetStats(w, &a);
    if (vrWorld_Step(w, frames, err, sizeof err) != 0) {
        fprintf(stderr, "bench_scale: %s\n", err);
        vrWorld_Destroy(w);
        return r;
    }
    vrWorld_GetStats(w, &b);
    r.ok = 1;
    r.frames = (double)(b.frames - a.frames);
    r.sim_ms = b.sim_ms - a.sim_ms;
    r.fps = r.sim_ms > 0 ? 1000.0 * r.frames / r.sim_ms : 0;
    r.peak_mb = (double)vrPeakMem_Kb(0) / 1024.0;
    r.gp_peak_mb = (double)children_peak_kb() / 1024.0;
    r.live_pairs = b.live_pairs;
    r.pairs = b.pairs;
    r.objects = b.objects;
    r.messages = b.messages - a.messages;
    r.collisions = b.collisions - a.collisions;
    vrWorld_Destroy(w);
    return r;
}

/* ---- floor ---- */
#define FLOOR_FRAMES 40

/* n cubes on a grid over a static floor, started; NULL when refused */
static vrWorld *floor_of_cubes(int n)
{
    vrWorld *w = vrWorld_Create();
    vrSettings s = *vrWorld_Settings(w);
    char err[256] = "", name[32];
    int side = 1, i, failed;
    while (side * side < n) side++;
    s.time_step = 0.05;
    s.collision_dist = 0.01;
    s.force_dir[0] = 0, s.force_dir[1] = 0, s.force_dir[2] = -1;
    s.force_mag = 9.8;
    s.default_friction = 0.5;
    s.default_elasticity = 0;
    failed = vrWorld_SetSettings(w, &s, err, sizeof err) != 0;
    for (i = -1; i < n && !failed; i++) {
        vrObjectDef d = vrObjectDef_Default(VR_CUBE);
        vrObjectId id;
        snprintf(name, sizeof name, i < 0 ? "floor" : "c%d", i);
        d.size[0] = d.size[1] = d.size[2] = i < 0 ? 0.5 * side + 1.0 : 0.1;
        if (i < 0) d.translate[2] = -d.size[2], d.mass = -1, d.mass_set = 1;
        else d.translate[0] = 0.5 * (i % side), d.translate[1] = 0.5 * (i / side), d.translate[2] = 0.1005;
        if (i < 0) d.translate[0] = d.translate[1] = 0.25 * side;
        failed = vrWorld_CreateObject(w, name, VR_CUBE, &id, err, sizeof err) != 0
                 || vrWorld_SetObjectDef(w, id, &d, err, sizeof err) != 0;
    }
    if (failed || vrWorld_Start(w, err, sizeof err) != 0) {
        fprintf(stderr, "bench_scale: floor of %d: %s\n", n, err);
        vrWorld_Destroy(w);
        return NULL;
    }
    return w;
}

/* frames/s of the landing (out[0]), at rest (out[1]); the cubes at rest
 * at the end (out[2]); peak MB (out[3]) */
static void floor_child(const void *ctx, void *out)
{
    double *r = out;
    vrWorld *w = floor_of_cubes(*(const int *)ctx);
    vrStats a, b, c;
    char err[256];
    if (!w) return;
    vrWorld_GetStats(w, &a);
    if (vrWorld_Step(w, FLOOR_FRAMES, err, sizeof err) == 0) {
        vrWorld_GetStats(w, &b);
        if (vrWorld_Step(w, FLOOR_FRAMES, err, sizeof err) == 0) {
            vrWorld_GetStats(w, &c);
            r[0] = 1000.0 * FLOOR_FRAMES / (b.sim_ms - a.sim_ms);
            r[1] = 1000.0 * FLOOR_FRAMES / (c.sim_ms - b.sim_ms);
            r[2] = c.resting;
            r[3] = (double)vrPeakMem_Kb(0) / 1024.0;
        }
    }
    vrWorld_Destroy(w);
}

static void floor_table(void)
{
    static const int sizes[] = {2500, 10000};
    size_t k;
    printf("\ncubes on a floor, each its own island: %d frames of 0.05 s landing, %d at rest, median of %d children\n",
           FLOOR_FRAMES, FLOOR_FRAMES, RUNS);
    printf("%8s %14s %14s %10s %10s\n", "cubes", "landing fps", "at rest fps", "resting", "peak MB");
    for (k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        double r[RUNS][4], land[RUNS], rest[RUNS], ml, mr;
        int i;
        for (i = 0; i < RUNS; i++) {
            bench_in_child(floor_child, &sizes[k], r[i], sizeof r[i]);
            land[i] = r[i][0], rest[i] = r[i][1];
        }
        ml = bench_median(land, RUNS), mr = bench_median(rest, RUNS);
        printf("%8d %14.1f %14.1f %10.0f %10.1f\n", sizes[k], ml, mr, r[0][2], r[0][3]);
        printf("csv,floor,%d,%.2f,%.2f,%.0f,%.1f\n", sizes[k], ml, mr, r[0][2], r[0][3]);
    }
}

typedef struct Args { int n, gps, frames; double side; const char *url; } Args;

static void measure_child(const void *ctx, void *out)
{
    const Args *a = ctx;
    *(Result *)out = measure(a->n, a->side, a->gps, a->url, a->frames);
}

/* measure() in a fresh child, its result through a pipe */
static Result in_child(int n, double side, int gps, const char *url, int frames)
{
    Args a = {n, gps, frames, side, url};
    Result r;
    bench_in_child(measure_child, &a, &r, sizeof r);
    return r;
}

static int by_fps(const void *x, const void *y)
{
    double a = ((const Result *)x)->fps, b = ((const Result *)y)->fps;
    return a < b ? -1 : a > b;
}

static void scale_table(void)
{
    static const struct { int n; double side; } sizes[] = {{2000, 35.0}, {5000, 47.6}, {10000, 60.0}};
    size_t k;
    printf("SPEC 10 room, no gravity, no clamps, %d frames of 0.05 s, median of %d children\n", FRAMES, RUNS);
    printf("%8s %8s %10s %10s %12s %14s %10s %12s\n", "objects", "room m", "frames/s", "peak MB", "live pairs",
           "logical pairs", "B/object", "goal");
    for (k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        Result r[RUNS], m;
        int i;
        for (i = 0; i < RUNS; i++) r[i] = in_child(sizes[k].n, sizes[k].side, 0, "memq://", FRAMES);
        qsort(r, RUNS, sizeof r[0], by_fps);
        m = r[RUNS / 2];
        if (!m.ok) {
            printf("%8d  failed\n", sizes[k].n);
            continue;
        }
        printf("%8d %8.1f %10.1f %10.1f %12lld %14ld %10.0f %12s\n", sizes[k].n, sizes[k].side, m.fps, m.peak_mb,
               m.live_pairs, m.pairs, m.peak_mb * 1048576.0 / sizes[k].n,
               sizes[k].n == 10000 ? (m.fps >= 20 && m.peak_mb <= 2048 ? "met" : "NOT met") : "-");
        printf("csv,scale,%d,%.1f,%.2f,%.1f,%lld,%ld\n", sizes[k].n, sizes[k].side, m.fps, m.peak_mb, m.live_pairs,
               m.pairs);
    }
}

/* serial, gps = 1 and 2 in the process and forked over udpm, interleaved
 * (the machine's load shifts) */
static void workers_table(void)
{
    static const struct { int gps; const char *url; } mode[] = {
        {0, "memq://"}, {1, "memq://"}, {2, "memq://"}, {1, UDPM}, {2, UDPM}};
    enum { MODES = sizeof mode / sizeof mode[0] };
    Result r[MODES][RUNS];
    int i, g;
    for (i = 0; i < RUNS; i++)
        for (g = 0; g < MODES; g++) r[g][i] = in_child(WORKER_N, WORKER_ROOM, mode[g].gps, mode[g].url, WORKER_FRAMES);
    printf("\nworkers on `random %d` in the %.0f m room, %d frames, interleaved, median of %d\n", WORKER_N,
           WORKER_ROOM, WORKER_FRAMES, RUNS);
    printf("%6s %8s %10s %10s %12s %12s %16s %12s\n", "gps", "link", "frames/s", "vs serial", "SGP peak MB",
           "GP peak MB", "messages/frame", "events/frame");
    for (g = 0; g < MODES; g++) qsort(r[g], RUNS, sizeof r[g][0], by_fps);
    for (g = 0; g < MODES; g++) {
        Result m = r[g][RUNS / 2], s = r[0][RUNS / 2];
        const char *link = mode[g].gps == 0 ? "-" : strncmp(mode[g].url, "memq", 4) == 0 ? "memq" : "udpm";
        if (!m.ok || !s.ok) {
            printf("%6d %8s  failed\n", mode[g].gps, link);
            continue;
        }
        printf("%6d %8s %10.1f %10.2f %12.1f %12.1f %16.1f %12.1f\n", mode[g].gps, link, m.fps, m.fps / s.fps,
               m.peak_mb, m.gp_peak_mb, m.messages / m.frames, m.collisions / m.frames);
        printf("csv,workers,%d,%s,%.2f,%.3f,%.1f,%.1f,%.1f\n", mode[g].gps, link, m.fps, m.fps / s.fps, m.peak_mb,
               m.gp_peak_mb, m.messages / m.frames);
    }
    printf("(memq://: the workers live in the SGP's process, its peak holds theirs; udpm: forked, each its own)\n");
}

int main(int argc, char **argv)
{
    enter_namespace(argc, argv);    /* udpm stays inside a private network namespace */
    setvbuf(stdout, NULL, _IOLBF, 0);
    if (argc < 2 || strcmp(argv[1], "scale") == 0) scale_table();
    if (argc < 2 || strcmp(argv[1], "floor") == 0) floor_table();
    if (argc < 2 || strcmp(argv[1], "workers") == 0) workers_table();
    return 0;
}
