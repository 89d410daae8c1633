/* bench_render.c — stereo frames per second of the display (SPEC 4).
 *
 * Two scenes at the default 640x512: an Office-sized one (thesis 5.2: 43
 * objects; here 13 boxes, 25 spheres of 10x10, 5 superquadrics) and 1000
 * objects (spheres and boxes on a grid), each drawn with and without
 * writing the PPM pair.  Prints a table, CSV lines (`csv,...`) and the
 * GL_RENDERER string; asserts nothing.  The target is 60 stereo frames/s
 * for the Office scene on llvmpipe.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "vroc.h"
#define BENCH_NAME "bench_render"
#include "render_scenes.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec / 1e9;
}

/* stereo frames per second over `frames` renders (and writes, when dir) */
static double rate(vrDisplay *d, vrWorld *w, const vrView *v, int frames, const char *dir)
{
    double t0 = now_s();
    int i;
    for (i = 0; i < frames; i++) {
        if (vrDisplay_Render(d, w, v, err, sizeof err) ||
            (dir && vrDisplay_WriteFrames(d, dir, i % 4, VR_FRAMES_PPM, err, sizeof err))) {
            fprintf(stderr, "bench_render: %s\n", err);
            return 0;
        }
    }
    return frames / (now_s() - t0);
}

static void run(vrDisplay *d, const char *scene, vrWorld *w, int frames, const char *dir)
{
    vrView v = vrView_Default();
    double draw, write;
    v.eye[1] = -6, v.eye[2] = 3;        /* the whole scene in view */
    v.look[2] = 0.8;
    rate(d, w, &v, 3, NULL);            /* warm-up: shaders compile on first use */
    draw = rate(d, w, &v, frames, NULL);
    write = rate(d, w, &v, frames, dir);
    printf("%-8s %8d %12.1f %18.1f\n", scene, vrWorld_ObjectCount(w), draw, write);
    printf("csv,render,%s,%d,%dx%d,%.2f,%.2f\n", scene, vrWorld_ObjectCount(w), v.width, v.height, draw, write);
}

int main(void)
{
    char dir[] = "/tmp/vroc-bench-XXXXXX", cmd[64];
    vrDisplay *d = NULL;
    vrWorld *w;
    if (!mkdtemp(dir) || vrDisplay_Open(&d, err, sizeof err)) {
        fprintf(stderr, "bench_render: %s\n", d ? "" : err);
        return 1;
    }
    printf("renderer: %s\n", vrDisplay_RendererName(d));
    printf("stereo frames/s at 640x512 (two eyes per frame; writing: + two PPM files in %s)\n", dir);
    printf("%-8s %8s %12s %18s\n", "scene", "objects", "draw", "draw+write");
    w = office();
    run(d, "office", w, 200, dir);
    vrWorld_Destroy(w);
    w = crowd();
    run(d, "crowd", w, 20, dir);
    vrWorld_Destroy(w);
    vrDisplay_Close(d);
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : 1;
}
