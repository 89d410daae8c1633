/* render_scenes.h — the render benchmarks' scenes (bench_render.c,
 * bench_window.c): an Office-sized one (thesis 5.2: 43 objects; here 13
 * boxes, 25 spheres of 10x10, 5 superquadrics) and 1000 objects (spheres
 * and boxes on a grid).  Static functions: each benchmark is one program
 * built from one file, so the scenes come in as a header.  Errors go to
 * stderr with the program's name, BENCH_NAME. */
#ifndef VROC_BENCH_RENDER_SCENES_H
#define VROC_BENCH_RENDER_SCENES_H

#include <stdio.h>
#include "vroc.h"

static char err[512];

static int add(vrWorld *w, const char *name, vrObjectDef *d)
{
    vrObjectId id;
    if (vrWorld_CreateObject(w, name, d->type, &id, err, sizeof err) ||
        vrWorld_SetObjectDef(w, id, d, err, sizeof err)) {
        fprintf(stderr, BENCH_NAME ": %s: %s\n", name, err);
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

#endif
