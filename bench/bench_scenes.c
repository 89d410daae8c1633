/* bench_scenes.c — thesis chapter 5 on this machine (issue 7, make bench).
 *
 * Runs the release shell (shell_run.h: pinned to one core) on scripts
 * that `read` the thesis's scenes (scenes/NAME.cmd) and the peers' scenes
 * of ../shared/bench/, and reads the figures from `stats`
 * deltas: frames / sim_ms (simulation only) and frames / (sim_ms +
 * render_ms) (stereo, 640x512, `frames =` before `display`: drawn, not
 * written), never process wall time.  Every run is a fresh process; each
 * figure is the median of several runs (the counts are deterministic, only
 * the times vary).  A scene's closing `start` runs no frame: `max_frames = 0`
 * comes before its `read`, and the frames are stepped here.
 *
 *   table 5.2  each thesis scene, 600 frames (its 6 s story), heap on
 *   table 5.3  the same with `heap = 0`, and the ratio heap on / off
 *   table 5.6  scenes/random.cmd with `random N` (restart, then N objects in
 *              its room) for N = 20 ... 100, and 1000 (5 frames only)
 *   rates      distance queries (`checks`) and responses (`collisions`) per
 *              second of simulation, against the thesis's 98 per GP
 *   peers      peer-random-100.cmd and peer-random-1000.cmd as they are
 *              (their own `step 600` / `step 60`, one `stats` added before
 *              it for the energy at frame 0); the 1000 one once
 *
 * Prints the machine, the renderer, tables with the thesis's figures and
 * the targets beside ours (met or not), and `csv,` lines; asserts
 * nothing.
 */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "vroc.h"
#include "figures.h"
#include "shell_run.h"

#define FRAMES 600          /* a thesis scene's story: 6 s at 0.01 s */
#define STEREO_FRAMES 200
#define RUNS 7
#define STEREO_RUNS 3
#define MAX_RUNS 8

typedef BenchStats Stats;

/* one measurement: deltas between the first and last `stats` of a script */
typedef struct Run {
    int ok;
    int n;                 /* stats lines read */
    Stats first, last;     /* the first and last stats lines */
    double frames, sim_ms, render_ms, checks, collisions;
    double subframes;      /* sum of `subframes` over the stats lines after the first */
} Run;

static BenchShell shell;

/* ---- running vroc ---------------------------------------------------------- */
static void take_stats(void *ctx, const BenchStats *s)
{
    Run *r = ctx;
    if (r->n++ == 0) r->first = *s;
    else r->subframes += s->subframes;
    r->last = *s;
}

/* runs the script text through vroc; fills r from its stats lines */
static Run run_script(const char *text)
{
    Run r;
    BenchLines out;
    memset(&r, 0, sizeof r);
    out.stats = take_stats, out.line = NULL, out.ctx = &r;
    r.ok = bench_shell_run(&shell, text, &out) && r.n >= 2;
    r.frames = r.last.frames - r.first.frames;
    r.sim_ms = r.last.sim_ms - r.first.sim_ms;
    r.render_ms = r.last.render_ms - r.first.render_ms;
    r.checks = r.last.checks - r.first.checks;
    r.collisions = r.last.collisions - r.first.collisions;
    if (!r.ok) fprintf(stderr, "bench_scenes: vroc failed on:\n%.400s\n", text);
    return r;
}

/* the script: settings, optional display, the scene read with its `start`
 * running no frame, extra lines, then `stats`, `frames` steps (all at once,
 * or one at a time with stats after each: census), `stats` */
static char *scene_script(const char *scene, int heap, int stereo, const char *extra, int frames, int census)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    int i;
    if (!f) return NULL;
    fprintf(f, "heap = %d\n%smax_frames = 0\nread %s\n%sstats\n", heap, stereo ? "frames =\ndisplay\n" : "", scene,
            extra ? extra : "");
    if (census)
        for (i = 0; i < frames; i++) fputs("step 1\nstats\n", f);
    else
        fprintf(f, "step %d\nstats\n", frames);
    fclose(f);
    return buf;
}

static Run run_scene(const char *scene, int heap, int stereo, const char *extra, int frames, int census)
{
    char *text = scene_script(scene, heap, stereo, extra, frames, census);
    Run r;
    memset(&r, 0, sizeof r);
    if (text) r = run_script(text);
    free(text);
    return r;
}

/* ---- figures --------------------------------------------------------------- */
/* median over `runs` runs of frames per second; *one keeps a run's counts */
typedef struct Rate { double fps, sim_ms; Run one; int runs; } Rate;

static Rate rate(const char *scene, int heap, int stereo, const char *extra, int frames, int runs)
{
    double fps[MAX_RUNS], ms[MAX_RUNS];
    Rate out;
    int i, n = 0;
    memset(&out, 0, sizeof out);
    for (i = 0; i < runs && i < MAX_RUNS; i++) {
        Run r = run_scene(scene, heap, stereo, extra, frames, 0);
        double t = r.sim_ms + (stereo ? r.render_ms : 0);
        if (!r.ok || t <= 0) continue;
        out.one = r;
        fps[n] = 1000 * r.frames / t, ms[n] = r.sim_ms, n++;
    }
    out.runs = n;
    out.fps = bench_median(fps, n);
    out.sim_ms = bench_median(ms, n);
    return out;
}

/* Heap on and off in turns (on, off, on, off, ...), so that a slow spell of
 * this shared machine falls on both: the medians of each, and the median of
 * the ratios of the pairs. */
static double paired(const char *scene, int frames, int runs, Rate *on, Rate *off)
{
    double fon[MAX_RUNS], foff[MAX_RUNS], ratio[MAX_RUNS], mson[MAX_RUNS], msoff[MAX_RUNS];
    int i, n = 0;
    memset(on, 0, sizeof *on);
    memset(off, 0, sizeof *off);
    for (i = 0; i < runs && i < MAX_RUNS; i++) {
        Run a = run_scene(scene, 1, 0, NULL, frames, 0), b = run_scene(scene, 0, 0, NULL, frames, 0);
        if (!a.ok || !b.ok || a.sim_ms <= 0 || b.sim_ms <= 0) continue;
        on->one = a, off->one = b;
        fon[n] = 1000 * a.frames / a.sim_ms, foff[n] = 1000 * b.frames / b.sim_ms;
        ratio[n] = fon[n] / foff[n];
        mson[n] = a.sim_ms, msoff[n] = b.sim_ms;
        n++;
    }
    on->runs = off->runs = n;
    on->fps = bench_median(fon, n);
    off->fps = bench_median(foff, n);
    on->sim_ms = bench_median(mson, n);
    off->sim_ms = bench_median(msoff, n);
    return bench_median(ratio, n);
}

/* mean internal steps per frame over the run (deterministic: one run) */
static double subframes_per_frame(const char *scene, const char *extra, int frames)
{
    Run r = run_scene(scene, 1, 0, extra, frames, 1);
    return r.ok && r.frames > 0 ? r.subframes / r.frames : 0;
}

static const char *num(char *buf, double v)
{
    if (v >= 100) snprintf(buf, 24, "%.0f", v);
    else if (v >= 1) snprintf(buf, 24, "%.1f", v);
    else snprintf(buf, 24, "%.2f", v);
    return buf;
}

static const char *yes(int met) { return met ? "yes" : "NO"; }

/* ---- the thesis's environments: tables 5.2, 5.3 and the rates --------------- */
typedef struct Scene {
    const char *name;
    double hp750_fps, hp750_noheap_fps;   /* thesis tables 5.2, 5.3 */
} Scene;

static const Scene scenes[] = {{"simple", 34, 23}, {"desks", 4, 1}, {"basketball", 22, 5}, {"office", 4, 0.2},
                               {"bounce", 4, 0.4}};
#define NSCENES (int)(sizeof scenes / sizeof scenes[0])

typedef struct Measured {
    Rate on, off, on_stereo, off_stereo;
    double ratio;             /* median of the paired runs' on/off */
    double sub_ours;
} Measured;

static Measured measured[NSCENES];

static void measure_scene(const Scene *sc, Measured *s)
{
    char path[256];
    snprintf(path, sizeof path, "scenes/%s.cmd", sc->name);
    s->ratio = paired(path, FRAMES, RUNS, &s->on, &s->off);
    s->on_stereo = rate(path, 1, 1, NULL, STEREO_FRAMES, STEREO_RUNS);
    s->off_stereo = rate(path, 0, 1, NULL, STEREO_FRAMES, STEREO_RUNS);
    s->sub_ours = subframes_per_frame(path, NULL, FRAMES);
}

static void table_5_2(void)
{
    char a[24], b[24], c[24];
    int i;
    printf("\nTable 5.2 analogue: heap on; %d frames a run (the 6 s story), median of %d runs (simulation)"
           " and of %d runs of %d frames (stereo)\n", FRAMES, RUNS, STEREO_RUNS, STEREO_FRAMES);
    printf("%-11s %4s %5s %9s %9s %10s %10s %12s | %7s %9s %8s %4s\n", "scene", "objs", "pairs", "sub/frame",
           "(ours)", "sim fps", "stereo fps", "subframes/s", "HP-750", "x HP-750", "target", "met");
    for (i = 0; i < NSCENES; i++) {
        const Scene *sc = &scenes[i];
        const Measured *s = &measured[i];
        double x = s->on.fps / sc->hp750_fps;
        printf("%-11s %4.0f %5.0f %9.0f %9.2f %10s %10s %12s | %7.0f %8.0fx %8s %4s\n", sc->name,
               s->on.one.first.objects, s->on.one.first.pairs, s->on.one.first.subframes_thesis, s->sub_ours,
               num(a, s->on.fps), num(b, s->on_stereo.fps), num(c, s->on.fps * s->sub_ours), sc->hp750_fps, x,
               ">=1000x", yes(x >= 1000));
        printf("csv,table5.2,%s,%.0f,%.0f,%.0f,%.3f,%.1f,%.1f,%.0f,%g,%.0f\n", sc->name, s->on.one.first.objects,
               s->on.one.first.pairs, s->on.one.first.subframes_thesis, s->sub_ours, s->on.fps, s->on_stereo.fps,
               s->on.fps * s->sub_ours, sc->hp750_fps, x);
    }
    printf("(sub/frame: the thesis's rule ceil(time_step*2*max_linear/collision_dist), = table 5.1; (ours): the mean"
           " internal steps vroc took; subframes/s = sim fps x ours)\n");
}

static void table_5_3(void)
{
    char a[24], b[24], c[24];
    int i;
    printf("\nTable 5.3 analogue: heap = 0 (every pair of the pair set at every internal step); runs in turns with"
           " table 5.2's, on/off the median of the %d pairs' ratios\n", RUNS);
    printf("%-11s %10s %10s %12s %10s | %8s %8s %13s %4s\n", "scene", "sim fps", "stereo fps", "subframes/s",
           "checks", "on/off", "(stereo)", "thesis on/off", "met");
    for (i = 0; i < NSCENES; i++) {
        const Scene *sc = &scenes[i];
        const Measured *s = &measured[i];
        double ratio = s->ratio;
        double ratio_st = s->off_stereo.fps > 0 ? s->on_stereo.fps / s->off_stereo.fps : 0;
        double thesis = sc->hp750_fps / sc->hp750_noheap_fps;
        printf("%-11s %10s %10s %12s %10.0f | %7.1fx %7.2fx %12.1fx %4s\n", sc->name, num(a, s->off.fps),
               num(b, s->off_stereo.fps), num(c, s->off.fps * s->sub_ours), s->off.one.checks, ratio, ratio_st,
               thesis, yes(ratio >= thesis));
        printf("csv,table5.3,%s,%.1f,%.1f,%.0f,%.0f,%.0f,%.2f,%.2f,%.2f\n", sc->name, s->off.fps, s->off_stereo.fps,
               s->off.fps * s->sub_ours, s->off.one.checks, s->on.one.checks, ratio, ratio_st, thesis);
    }
    printf("(the issue's targets: desks >= 4x and office >= 20x, simulation only; heap on checks:");
    for (i = 0; i < NSCENES; i++) printf(" %s %.0f", scenes[i].name, measured[i].on.one.checks);
    printf(")\n");
}

static void rates(void)
{
    double checks = 0, responses = 0, ms = 0;
    int i;
    printf("\nDistance queries and collision responses per second of simulation (heap on, the table 5.2 runs)\n");
    printf("%-11s %10s %12s %12s %14s\n", "scene", "checks", "responses", "checks/s", "responses/s");
    for (i = 0; i < NSCENES; i++) {
        const Scene *sc = &scenes[i];
        const Measured *s = &measured[i];
        double t = s->on.sim_ms / 1000;
        printf("%-11s %10.0f %12.0f %12.0f %14.0f\n", sc->name, s->on.one.checks, s->on.one.collisions,
               t > 0 ? s->on.one.checks / t : 0, t > 0 ? s->on.one.collisions / t : 0);
        printf("csv,rates,%s,%.0f,%.0f,%.3f\n", sc->name, s->on.one.checks, s->on.one.collisions, s->on.sim_ms);
        checks += s->on.one.checks, responses += s->on.one.collisions, ms += s->on.sim_ms;
    }
    printf("%-11s %10.0f %12.0f %12.0f %14.0f   (thesis: one GP ~ 98 responses/s, detection included)\n", "all",
           checks, responses, ms > 0 ? 1000 * checks / ms : 0, ms > 0 ? 1000 * responses / ms : 0);
}

/* ---- table 5.6: random objects ------------------------------------------------- */
static void table_5_6(void)
{
    static const int n_objects[] = {20, 40, 60, 80, 100, 1000};
    static const double thesis_fps[] = {22, 17, 16, 13, 12.5, 0};
    char extra[64], a[24], b[24], c[24], d[24];
    int i;
    printf("\nTable 5.6 analogue: scenes/random.cmd (10 m room, no gravity, e = 1, time_step 0.05 s), then"
           " `restart` and `random N`;\n%d frames a run (30 s), 5 for N = 1000; medians of %d (simulation) and"
           " %d runs of %d frames (stereo; 3 frames for N = 1000)\n", FRAMES, RUNS, STEREO_RUNS, STEREO_FRAMES);
    printf("%5s %8s %7s %6s %10s %10s %9s %12s | %14s %8s %4s\n", "N", "pairs", "+walls", "frames", "sim fps",
           "stereo fps", "sub/frame", "subframes/s", "thesis 25 GPs", "target", "met");
    for (i = 0; i < (int)(sizeof n_objects / sizeof n_objects[0]); i++) {
        int n = n_objects[i], big = n >= 1000, frames = big ? 5 : FRAMES;
        Rate sim, st;
        double sub;
        snprintf(extra, sizeof extra, "restart\nrandom %d\n", n);
        sim = rate("scenes/random.cmd", 1, 0, extra, frames, big ? 3 : RUNS);
        st = rate("scenes/random.cmd", 1, 1, extra, big ? 3 : STEREO_FRAMES, STEREO_RUNS);
        sub = subframes_per_frame("scenes/random.cmd", extra, frames);
        printf("%5d %8d %7.0f %6d %10s %10s %9.1f %12s | %14s %8s %4s\n", n, n * (n - 1) / 2, sim.one.first.pairs,
               frames, num(a, sim.fps), num(b, st.fps), sub, num(c, sim.fps * sub),
               thesis_fps[i] > 0 ? num(d, thesis_fps[i]) : "-", n == 100 ? ">=2000" : "",
               n == 100 ? yes(sim.fps >= 2000) : "");
        printf("csv,table5.6,%d,%d,%.0f,%d,%.2f,%.2f,%.2f,%g\n", n, n * (n - 1) / 2, sim.one.first.pairs, frames,
               sim.fps, st.fps, sub, thesis_fps[i]);
    }
    printf("(pairs: N(N-1)/2 among the objects; +walls: the pair set with the room's 6 static walls, 6N more)\n");
}

/* ---- the peers' scenes ------------------------------------------------------------ */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    long n;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) > 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (buf = malloc(n + 1)) && fread(buf, 1, n, f) == (size_t)n)
        buf[n] = '\0';
    else
        free(buf), buf = NULL;
    fclose(f);
    return buf;
}

/* the peer file as it is, with `extra` and `stats` put before its last `step` */
static Run run_peer(const char *path, const char *extra)
{
    char *text = slurp(path), *step, *p, *script = NULL;
    size_t len = 0;
    FILE *f;
    Run r;
    memset(&r, 0, sizeof r);
    if (!text) return r;
    for (step = NULL, p = text; (p = strstr(p, "\nstep")); p++) step = p + 1;
    if (step && (f = open_memstream(&script, &len))) {
        fprintf(f, "%.*s%sstats\n%s", (int)(step - text), text, extra, step);
        fclose(f);
        r = run_script(script);
    }
    free(script);
    free(text);
    return r;
}

typedef struct Peer { const char *file; int runs; double ode, bullet, mujoco; } Peer;

/* prints the peer scene's line; returns the last run's sim_ms */
static double peer(const char *dir, const Peer *pe)
{
    char path[512], a[24];
    double fps[MAX_RUNS], ratio = 0, frames = 0, last_ms = 0;
    int i, n = 0;
    snprintf(path, sizeof path, "%s/%s", dir, pe->file);
    for (i = 0; i < pe->runs; i++) {
        Run r = run_peer(path, "");
        if (!r.ok || r.sim_ms <= 0) continue;
        fps[n++] = 1000 * r.frames / r.sim_ms;
        ratio = r.last.energy / r.first.energy, frames = r.frames, last_ms = r.sim_ms;
    }
    if (!n) {
        printf("%-22s could not run (%s)\n", pe->file, path);
        return 0;
    }
    printf("%-22s %6.0f %4d %9s %9.4f | %6.0f %6.0f %6.0f", pe->file, frames, n, num(a, bench_median(fps, n)), ratio,
           pe->ode, pe->bullet, pe->mujoco);
    if (pe->ode > 500)
        printf(" | >=%.0f fps: %s, energy within 1%%: %s\n", 2 * pe->ode, yes(bench_median(fps, n) >= 2 * pe->ode),
               yes(ratio > 0.99 && ratio < 1.01));
    else
        printf(" | %.3fx ODE (reported, no target)\n", bench_median(fps, n) / pe->ode);
    printf("csv,peer,%s,%.0f,%d,%.3f,%.6f,%g\n", pe->file, frames, n, bench_median(fps, n), ratio, pe->ode);
    return last_ms;
}

static void peers(void)
{
    static const Peer list[] = {{"peer-random-100.cmd", RUNS, 1440, 860, 635},
                                {"peer-random-1000.cmd", 1, 96, 42, 52}};
    const char *dir = getenv("VROC_PEER_BENCH");
    char path[512];
    double thousand_ms;
    Run r;
    if (!dir || !*dir) dir = "../shared/bench";
    printf("\nThe peers' scenes, as they are (gravity, e = 1, 0.1 s frames, max_linear 16, max_angular 100);"
           " peers' figures from %s/README.md\n", dir);
    printf("%-22s %6s %4s %9s %9s | %6s %6s %6s\n", "scene", "frames", "runs", "sim fps", "E end/E0", "ODE",
           "Bullet", "MuJoCo");
    peer(dir, &list[0]);
    thousand_ms = peer(dir, &list[1]);
    /* why the energy goes: the scene's clamps.  The same 100 with them lifted */
    snprintf(path, sizeof path, "%s/%s", dir, list[0].file);
    r = run_peer(path, "max_linear = 100\nmax_angular = 1000\n");
    if (r.ok && r.first.energy != 0)
        printf("diagnostic: peer-random-100 with max_linear 100, max_angular 1000 (before its step): E end/E0 %.6f,"
               " %.0f fps\n", r.last.energy / r.first.energy, 1000 * r.frames / r.sim_ms);
    printf("(the 1000-object scene runs once: its 60 frames took %.1f s of simulation)\n", thousand_ms / 1000);
}

/* ---- main ------------------------------------------------------------------------- */
static void machine(void)
{
    char line[256], model[256] = "unknown", err[256];
    FILE *f = fopen("/proc/cpuinfo", "r");
    vrDisplay *d = NULL;
    while (f && fgets(line, sizeof line, f))
        if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
            snprintf(model, sizeof model, "%s", strchr(line, ':') + 2);
            model[strcspn(model, "\n")] = '\0';
            break;
        }
    if (f) fclose(f);
    printf("machine: %s, %ld cores online; vroc runs %s\n", model, sysconf(_SC_NPROCESSORS_ONLN),
           bench_shell_pinning(&shell));
    if (vrDisplay_Open(&d, err, sizeof err) == 0) {
        printf("renderer: %s (OSMesa), 640x512 stereo, frames drawn and not written\n", vrDisplay_RendererName(d));
        vrDisplay_Close(d);
    } else {
        printf("renderer: unavailable (%s)\n", err);
    }
    printf("figures: frames / sim_ms and frames / (sim_ms + render_ms) from vroc's `stats`, not wall time;"
           " medians of separate vroc processes\n");
}

int main(void)
{
    int i;
    if (bench_shell_open(&shell, "bench_scenes") != 0) return 1;
    machine();
    for (i = 0; i < NSCENES; i++) measure_scene(&scenes[i], &measured[i]);
    table_5_2();
    table_5_3();
    rates();
    table_5_6();
    peers();
    return 0;
}
