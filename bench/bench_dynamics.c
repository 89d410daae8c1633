/* bench_dynamics.c — the simulation's speed (issue 4): frames per second
 * from sim_ms, checks and heap pops per frame, collisions, with the heap
 * and without it (the thesis's table 5.3 ablation), on
 *   - a desk: 30 static blocks (a table, monitors, cases) and 10 falling
 *     objects, the shape of the thesis's Desks and Office;
 *   - random 100 in a 10 m room (SPEC 1.2's draw, elastic, no gravity: the
 *     thesis's table 5.6 environment, collisions spread over time), the
 *     issue's target;
 *   - the same draw in a 6 m room under gravity (a pile on the floor, dense
 *     collisions: a harder case, no target);
 *   - random 1000 in a 12 m room, a few frames.
 * Each figure is the median of REPEATS runs.  Prints a table and csv lines. */
#include <stdlib.h>
#include <string.h>
#include "vroc.h"

#define REPEATS 3

typedef struct {
    const char *name;
    void (*build)(vrWorld *);
    long frames;
    int ablation;
    double room, gravity;
} vrBench;

static void settings(vrWorld *w, const vrBench *b, unsigned seed, int heap)
{
    vrSettings s = *vrWorld_Settings(w);
    s.time_step = 0.05;
    s.collision_dist = 0.01;
    s.force_mag = b->gravity;
    s.max_linear = 16;
    s.max_angular = 20;
    s.room = b->room;
    s.seed = seed;
    s.heap = heap;
    vrWorld_SetSettings(w, &s, NULL, 0);
}

static void box(vrWorld *w, const char *name, double hx, double hy, double hz, double x, double y, double z, double mass)
{
    vrObjectId id;
    vrObjectDef d = vrObjectDef_Default(VR_CUBE);
    d.size[0] = hx; d.size[1] = hy; d.size[2] = hz;
    d.translate[0] = x; d.translate[1] = y; d.translate[2] = z;
    d.mass = mass;
    d.mass_set = 1;
    d.elasticity = 0.5;
    vrWorld_CreateObject(w, name, VR_CUBE, &id, NULL, 0);
    vrWorld_SetObjectDef(w, id, &d, NULL, 0);
}

static void desk(vrWorld *w)
{
    char name[32];
    int i;
    box(w, "table", 3, 1, 0.05, 0, 0, 0.7, -1);
    for (i = 0; i < 29; i++) {           /* monitors, cases, keyboards in a row */
        snprintf(name, sizeof name, "block%d", i);
        box(w, name, 0.08, 0.15 + 0.05 * (i % 3), 0.1 + 0.05 * (i % 4), -2.8 + 0.2 * i, (i % 2) * 0.4 - 0.2,
            0.75 + 0.1 + 0.05 * (i % 4), -1);
    }
    for (i = 0; i < 10; i++) {           /* what falls on them */
        vrObjectId id;
        vrObjectDef d = vrObjectDef_Default(i % 2 ? VR_CUBE : VR_SPHERE);
        snprintf(name, sizeof name, "falling%d", i);
        d.radius = 0.08;
        d.size[0] = d.size[1] = d.size[2] = 0.07;
        d.translate[0] = -2.5 + 0.55 * i;
        d.translate[1] = 0.1 * (i % 3) - 0.1;
        d.translate[2] = 1.6 + 0.15 * i;
        d.elasticity = 0.6;
        vrWorld_CreateObject(w, name, d.type, &id, NULL, 0);
        vrWorld_SetObjectDef(w, id, &d, NULL, 0);
    }
}

static void random100(vrWorld *w) { vrWorld_AddRandom(w, 100, NULL, 0); }
static void random1000(vrWorld *w) { vrWorld_AddRandom(w, 1000, NULL, 0); }

typedef struct { double fps, checks, pops, collisions, energy; } vrFigures;

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static vrFigures run(const vrBench *b, int heap)
{
    double fps[REPEATS];
    vrFigures f;
    int r;
    memset(&f, 0, sizeof f);
    for (r = 0; r < REPEATS; r++) {
        vrWorld *w = vrWorld_Create();
        vrStats s;
        char err[256];
        settings(w, b, 42, heap);
        b->build(w);
        if (vrWorld_Step(w, b->frames, err, sizeof err) != 0) printf("%s: %s\n", b->name, err);
        vrWorld_GetStats(w, &s);
        fps[r] = s.sim_ms > 0 ? 1000.0 * (double)s.frames / s.sim_ms : 0;
        f.checks = (double)s.checks / (double)s.frames;
        f.pops = (double)s.heap_pops / (double)s.frames;
        f.collisions = (double)s.collisions;
        vrWorld_Destroy(w);
    }
    qsort(fps, REPEATS, sizeof fps[0], cmp);
    f.fps = fps[REPEATS / 2];
    return f;
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    static const vrBench benches[] = {
        {"desk 40 (30 static)", desk, 200, 1, 0, 9.8},
        {"random 100, room 10 m", random100, 200, 1, 10, 0},
        {"random 100, 6 m, gravity", random100, 200, 1, 6, 9.8},
        /* without the heap: 500,000 pairs at every internal step, hours */
        {"random 1000, room 12 m", random1000, 10, 0, 12, 9.8},
    };
    vrFigures on[4], off[4];
    int i;
    printf("dynamics, one core, median of %d runs; fps from sim_ms\n", REPEATS);
    printf("%-24s %10s %10s %10s %9s %10s %10s %9s\n", "scene", "fps heap", "checks/fr", "pops/fr",
           "events", "fps no-heap", "checks/fr", "heap/none");
    for (i = 0; i < 4; i++) {
        on[i] = run(&benches[i], 1);
        memset(&off[i], 0, sizeof off[i]);
        if (benches[i].ablation) off[i] = run(&benches[i], 0);
        printf("%-24s %10.0f %10.0f %10.0f %9.0f %10.0f %10.0f %8.1fx\n", benches[i].name, on[i].fps,
               on[i].checks, on[i].pops, on[i].collisions, off[i].fps, off[i].checks,
               off[i].fps > 0 ? on[i].fps / off[i].fps : 0);
        printf("csv,dynamics,%s,%ld,%.1f,%.1f,%.1f,%.0f,%.1f,%.1f\n", benches[i].name, benches[i].frames, on[i].fps,
               on[i].checks, on[i].pops, on[i].collisions, off[i].fps, off[i].checks);
    }
    printf("targets: random 100 in a room >= 2000 fps: %s (%.0f); heap on >= 20x heap off on the Office-like "
           "desk: %s (%.1fx) (thesis: 20x Office, 4x Desks)\n", on[1].fps >= 2000 ? "met" : "NOT met", on[1].fps,
           on[0].fps >= 20 * off[0].fps ? "met" : "NOT met", off[0].fps > 0 ? on[0].fps / off[0].fps : 0);
    return 0;
}
