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

static char err[512];

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec / 1e9;
}

static int add(vrWorld *w, const char *name, vrObjectDef *d)
{
    vrObjectId id;
    if (vrWorld_CreateObject(w, name, d->type, &id, err, sizeof err) ||
        vrWorld_SetObjectDef(w, id, d, err, sizeof err)) {
        fprintf(stderr, "bench_render: %s: %s\n", name, err);
        return -1;
    }
    return 0;
}

static void place(vrObjectDef *d, double x, double y, double z)
{
    d->translate[0] = x, d->translate[1] = y, d->translate[2] = z;
}

static void paint(vrObjectDef *d, int i)
{
    d->color[0] = (37 * i) % 256, d->color[1] = (91 * i + 80) % 256, d->color[2] = (53 * i + 160) % 256;
}

/* a floor, two walls, two desks on four legs each: 13 static boxes */
static int office_boxes(vrWorld *w)
{
    static const double box[13][6] = {
        {0, 0, -0.05, 4, 4, 0.05}, {0, 4, 1.5, 4, 0.05, 1.5}, {-4, 0, 1.5, 0.05, 4, 1.5},
        {-1.5, 1, 0.75, 1, 0.5, 0.03}, {1.5, 1, 0.75, 1, 0.5, 0.03},
        {-2.4, 0.6, 0.36, 0.03, 0.03, 0.36}, {-0.6, 0.6, 0.36, 0.03, 0.03, 0.36},
        {-2.4, 1.4, 0.36, 0.03, 0.03, 0.36}, {-0.6, 1.4, 0.36, 0.03, 0.03, 0.36},
        {0.6, 0.6, 0.36, 0.03, 0.03, 0.36}, {2.4, 0.6, 0.36, 0.03, 0.03, 0.36},
        {0.6, 1.4, 0.36, 0.03, 0.03, 0.36}, {2.4, 1.4, 0.36, 0.03, 0.03, 0.36}};
    char name[32];
    int i;
    for (i = 0; i < 13; i++) {
        vrObjectDef d = vrObjectDef_Default(VR_CUBE);
        place(&d, box[i][0], box[i][1], box[i][2]);
        d.size[0] = box[i][3], d.size[1] = box[i][4], d.size[2] = box[i][5];
        d.mass = -1, d.mass_set = 1;
        paint(&d, i);
        snprintf(name, sizeof name, "box%d", i);
        if (add(w, name, &d)) return -1;
    }
    return 0;
}

static vrWorld *office(void)
{
    vrWorld *w = vrWorld_Create();
    char name[32];
    int i;
    if (office_boxes(w)) return w;
    for (i = 0; i < 25; i++) {
        vrObjectDef d = vrObjectDef_Default(VR_SPHERE);
        place(&d, -2.4 + 0.2 * (i % 5) + 2.4 * (i % 2), 0.6 + 0.2 * (i / 5), 0.9);
        d.radius = 0.08;
        paint(&d, 20 + i);
        snprintf(name, sizeof name, "ball%d", i);
        if (add(w, name, &d)) return w;
    }
    for (i = 0; i < 5; i++) {
        vrObjectDef d = vrObjectDef_Default(VR_SUPERQUADRIC);
        place(&d, -2 + i, -1, 0.3);
        d.a1 = d.a2 = d.a3 = 0.25;
        d.exp1 = 0.3 + 0.3 * i, d.exp2 = 0.5 + 0.2 * i;
        paint(&d, 50 + i);
        snprintf(name, sizeof name, "sq%d", i);
        if (add(w, name, &d)) return w;
    }
    return w;
}

/* 1000 objects, alternately spheres of 10x10 and boxes, on a 10x10x10 grid */
static vrWorld *crowd(void)
{
    vrWorld *w = vrWorld_Create();
    char name[32];
    int i;
    for (i = 0; i < 1000; i++) {
        vrObjectDef d = vrObjectDef_Default(i % 2 ? VR_CUBE : VR_SPHERE);
        place(&d, -2.25 + 0.5 * (i % 10), -2.25 + 0.5 * (i / 10 % 10), 0.5 * (i / 100));
        d.radius = 0.2;
        d.size[0] = d.size[1] = d.size[2] = 0.15;
        paint(&d, i);
        snprintf(name, sizeof name, "r%d", i);
        if (add(w, name, &d)) break;
    }
    return w;
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
