/* simulate.c — time: `step`, `start` and `stop` (SPEC 1.2), `restart`.
 *
 * A script's `start` runs frames until everything rests or max_frames
 * frames have run, then reads on, so a script never hangs.  At the prompt
 * `start` only sets a clock: the input loop (interactive.c) runs one frame
 * each time_step of wall time while the prompt stays live.  Frames run one
 * at a time so that each is drawn and a long run can be interrupted.
 */
#include <stdio.h>
#include <time.h>
#include "commands.h"

volatile sig_atomic_t sh_interrupted;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* The speed caps (max_linear 8 m/s, max_angular 4 rad/s by default, the
 * thesis's) take energy and spin away silently; the first clamp of a
 * session that never set a cap says so, once (stats clamps counts them
 * all). */
static void note_first_clamp(Shell *sh)
{
    vrStats s;
    const vrSettings *set = vrWorld_Settings(sh->world);
    char lin[32], ang[32];
    if (sh->clamp_noted) return;
    vrWorld_GetStats(sh->world, &s);
    if (s.clamps == 0) return;
    sh->clamp_noted = 1;
    vrFormatDouble(lin, set->max_linear);
    vrFormatDouble(ang, set->max_angular);
    sh_note(sh, "a speed cap cut a velocity at frame %ld (max_linear = %s m/s, max_angular = %s rad/s): "
                "the energy and spin above them are lost; raise them to keep it (stats: clamps)",
            s.frames, lin, ang);
}

static int one_frame(Shell *sh, char *err, size_t n)
{
    sh_trackers_before_frame(sh);
    if (vrWorld_Step(sh->world, 1, err, n) != 0) return -1;
    if (sh_sound_frame(sh, err, n) != 0) return -1;
    note_first_clamp(sh);
    return sh_display_draw(sh, err, n);
}

static int interrupted(long done, long of, char *err, size_t n)
{
    if (!sh_interrupted) return 0;
    sh_interrupted = 0;
    snprintf(err, n, "interrupted after %ld of %ld frames", done, of);
    return 1;
}

/* frames, one at a time, as long as the run has some left; the tool
 * panel's presses after each may end it, lengthen it or make it a start */
static int advance(Shell *sh, long frames, int until_rest, char *err, size_t n)
{
    ShRun run;
    long done = 0;
    run.left = frames, run.until_rest = until_rest;
    while (run.left > 0) {
        if (run.until_rest && vrWorld_AllAtRest(sh->world)) break;
        if (interrupted(done, frames, err, n) || one_frame(sh, err, n) != 0) return -1;
        done++, run.left--;
        sh_panel_requests(sh, &run);
    }
    return 0;
}

int run_step(Shell *sh, const Stmt *st, char *err, size_t n)
{
    sh_interrupted = 0;
    return advance(sh, st->has_value ? (long)st->v[0] : 1, 0, err, n);
}

/* real time: one frame per time_step of wall time; time_step 0 halts
 * simulated time, but frames still come (the head may move) */
static double frame_period(const Shell *sh)
{
    double ts = vrWorld_Settings(sh->world)->time_step;
    return ts > 0 ? ts : 0.1;
}

int run_start(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)st;
    if (vrWorld_Start(sh->world, err, n) != 0) return -1;   /* interpenetration refuses it */
    if (!sh->interactive) {
        sh_interrupted = 0;
        return advance(sh, vrWorld_Settings(sh->world)->max_frames, 1, err, n);
    }
    if (sh_run_realtime(sh, err, n) != 0) return -1;
    sh_location(sh, sh->run_origin, sizeof sh->run_origin);
    return 0;
}

int sh_run_realtime(Shell *sh, char *err, size_t n)
{
    if (vrWorld_Start(sh->world, err, n) != 0) return -1;
    if (!sh->running) sh->next_frame = now_s() + frame_period(sh);
    sh->running = 1;
    return 0;
}

int run_stop(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)st, (void)err, (void)n;
    sh->running = 0;   /* silent when nothing runs */
    return 0;
}

int run_restart(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)st, (void)err, (void)n;
    vrWorld_Restart(sh->world);
    sh->selected = VR_NO_OBJECT;
    sh->running = 0;
    return 0;
}

double sh_frame_wait(const Shell *sh)
{
    double wait;
    if (!sh->running) return -1;
    wait = sh->next_frame - now_s();
    return wait > 0 ? wait : 0;
}

int sh_tick(Shell *sh, char *err, size_t n)
{
    double now;
    ShRun run;
    run.left = 0, run.until_rest = 0;
    if (one_frame(sh, err, n) != 0) {
        sh->running = 0;
        return -1;
    }
    sh_panel_requests(sh, &run);   /* the panel's step: one frame more, time stopped */
    if (run.left > 0 && advance(sh, run.left, 0, err, n) != 0) return -1;
    now = now_s();
    sh->next_frame += frame_period(sh);
    if (sh->next_frame < now) sh->next_frame = now;   /* late: go on, do not burst to catch up */
    return 0;
}
