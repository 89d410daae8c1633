/* bench_broadphase.c — the sorted sweep against the box trees (issue 26:
 * "sweep-and-prune with insertion sort as I-COLLIDE does, or a dynamic
 * AABB tree as Box2D/Bullet do: measure both on these scenes and keep the
 * faster"), make bench.
 *
 * Each scene is a shell script run by the release shell (shell_run.h:
 * pinned to one core) with `broadphase = sweep` or `broadphase = tree` put
 * first.  The
 * runs of the two structures alternate (sweep first in odd rounds, tree in
 * even ones), RUNS rounds, and the figure is each one's median frames per
 * second from the `sim_ms` between two stats lines (the simulation alone:
 * not the build, not the first frame's pair making).  The two runs of a
 * scene must end with the same collisions and resting objects: the same
 * run, only the structure differs (the checks, printed for both, may
 * differ by about 0.1 %: README, Status).
 *   random2000/5000/10000   SPEC 10's room (bench_scale.c): no gravity, no
 *                           caps, 35, 47.6 and 60 m rooms (one density)
 *   peer1000                ../shared/bench/peer-random-1000.cmd (the
 *                           peers' room; $VROC_PEER_BENCH for the folder)
 *   pile                    bench_contact.c's pile: 100 objects in a 4 m
 *                           room, gravity, mu 0.5, e 0.5, 0.01 s frames
 * `bench_broadphase NAME...` runs only the scenes named.  Prints a table and
 * `csv,` lines; asserts nothing but that the counts agree. */
#define _DEFAULT_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "figures.h"
#include "shell_run.h"

#define RUNS 5

/* the first and last stats lines of a run, and how many there were */
typedef struct Ends { BenchStats first, last; int n; } Ends;

static BenchShell shell;
static const char *peer_dir;
static int failures;

static void take_stats(void *ctx, const BenchStats *s)
{
    Ends *e = ctx;
    if (e->n++ == 0) e->first = *s;
    e->last = *s;
}

/* the first and the last stats line of the script's run */
static int run(const char *kind, const char *script, Ends *e)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    BenchLines out;
    int ok = 0;
    memset(e, 0, sizeof *e);
    out.stats = take_stats, out.line = NULL, out.ctx = e;
    if (f) {
        fprintf(f, "broadphase = %s\n%s", kind, script);
        fclose(f);
        ok = bench_shell_run(&shell, text, &out) && e->n >= 1;
    }
    free(text);
    if (!ok) fprintf(stderr, "bench_broadphase: vroc failed on:\n%.300s\n", script);
    return ok;
}

/* frames per second between the first stats line and the last (from the
 * start when there is only one) */
static double fps(const Ends *e)
{
    const BenchStats *a = &e->first, *b = &e->last;
    double frames = e->n > 1 ? b->frames - a->frames : b->frames, ms = e->n > 1 ? b->sim_ms - a->sim_ms : b->sim_ms;
    return ms > 0 ? 1000 * frames / ms : 0;
}

static void scene(const char *name, const char *script)
{
    static const char *const kinds[2] = {"sweep", "tree"};
    double f[2][RUNS], m[2];
    Ends e;
    BenchStats end[2];
    int r, i;
    for (r = 0; r < RUNS; r++)
        for (i = 0; i < 2; i++) {
            int k = r % 2 ? 1 - i : i;
            if (!run(kinds[k], script, &e)) {
                failures++;
                return;
            }
            f[k][r] = fps(&e);
            end[k] = e.last;
        }
    m[0] = bench_median(f[0], RUNS), m[1] = bench_median(f[1], RUNS);
    /* checks (distance queries) may differ a little: the pairs are met,
     * so their records made and looked at, in another order */
    if (end[0].collisions != end[1].collisions || end[0].resting != end[1].resting) {
        printf("  %-12s COUNTS DIFFER: sweep %.0f collisions %.0f resting, tree %.0f, %.0f\n", name, end[0].collisions,
               end[0].resting, end[1].collisions, end[1].resting);
        failures++;
    }
    printf("  %-12s %10.1f %10.1f %8.2f %12.0f %12.0f %12.0f\n", name, m[0], m[1], m[0] > 0 ? m[1] / m[0] : 0,
           end[0].collisions, end[0].checks, end[1].checks);
    printf("csv,broadphase,%s,%.2f,%.2f,%.0f,%.0f,%.0f\n", name, m[0], m[1], end[0].collisions, end[0].checks,
           end[1].checks);
    fflush(stdout);
}

static void room_scene(const char *name, int n, double side, int frames)
{
    char s[512];
    snprintf(s, sizeof s,
             "time_step = 0.05\ncollision_dist = 0.01\nmax_linear = 1000\nmax_angular = 10000\nseed = 1993\n"
             "max_frames = 0\nroom = %.17g\nrandom %d\nstep 1\nstats\nstep %d\nstats\n",
             side, n, frames);
    scene(name, s);
}

static void peer_scene(void)
{
    char file[600], s[700];
    snprintf(file, sizeof file, "%s/peer-random-1000.cmd", peer_dir);
    if (access(file, R_OK)) {
        printf("  %-12s (no %s: set VROC_PEER_BENCH)\n", "peer1000", file);
        return;
    }
    snprintf(s, sizeof s, "read %s\n", file);
    scene("peer1000", s);
}

static void pile_scene(void)
{
    scene("pile", "time_step = 0.01\ncollision_dist = 0.01\ngravity\ndefault_friction = 0.5\n"
                  "default_elasticity = 0.5\nmax_frames = 0\nroom = 4\nrandom 100\nstep 1\nstats\nstep 3000\nstats\n");
}

int main(int argc, char **argv)
{
    if (bench_shell_open(&shell, "bench_broadphase") != 0) return 1;
    peer_dir = getenv("VROC_PEER_BENCH");
    if (!peer_dir || !*peer_dir) peer_dir = "../shared/bench";
    printf("sweep against tree: median frames/s of %d interleaved runs each (%s)\n", RUNS, bench_shell_pinning(&shell));
    printf("  %-12s %10s %10s %8s %12s %12s %12s\n", "scene", "sweep fps", "tree fps", "tree/sw", "collisions",
           "sweep checks", "tree checks");
    if (bench_wanted(argc, argv, "random2000")) room_scene("random2000", 2000, 35, 20);
    if (bench_wanted(argc, argv, "random5000")) room_scene("random5000", 5000, 47.6, 20);
    if (bench_wanted(argc, argv, "random10000")) room_scene("random10000", 10000, 60, 20);
    if (bench_wanted(argc, argv, "peer1000")) peer_scene();
    if (bench_wanted(argc, argv, "pile")) pile_scene();
    return failures ? 1 : 0;
}
