/* libdump.c — the scene of libdump.in, built with the library directly
 * (include/vroc.h only), stepped and dumped.  tests/shell.sh compares its
 * output with vroc's on libdump.in: the shell must apply every statement
 * exactly as the API does (numbers, vectors, mass over volume, rotate). */
#include <stdio.h>
#include <stdlib.h>
#include "vroc.h"

static char err[1024];

static void check(int r)
{
    if (r != 0) {
        fprintf(stderr, "libdump: %s\n", err);
        exit(1);
    }
}

static void set3(double v[3], double x, double y, double z)
{
    v[0] = x, v[1] = y, v[2] = z;
}

static vrObjectDef *create(vrWorld *w, const char *name, vrObjectType type, vrObjectId *id)
{
    static vrObjectDef d;
    check(vrWorld_CreateObject(w, name, type, id, err, sizeof err));
    d = vrObjectDef_Default(type);
    return &d;
}

static void settings(vrWorld *w)
{
    vrSettings s = *vrWorld_Settings(w);
    s.time_step = 0.05;
    s.collision_dist = 0.02;
    set3(s.force_dir, 0, 0, -1);
    s.force_mag = 9.8;
    check(vrWorld_SetSettings(w, &s, err, sizeof err));
}

static void table_and_spheres(vrWorld *w)
{
    vrObjectId id;
    vrObjectDef *d = create(w, "table", VR_CUBE, &id);
    set3(d->size, 2, 2, 0.1);
    set3(d->translate, 0, 0, -0.1);
    d->mass = -1, d->mass_set = 1;
    check(vrWorld_SetObjectDef(w, id, d, err, sizeof err));
    d = create(w, "a", VR_SPHERE, &id);
    d->radius = 0.25;
    set3(d->translate, -1, 0, 0.5);
    set3(d->linear_vel, 2, 0, 0);
    d->elasticity = 0.5;
    check(vrWorld_SetObjectDef(w, id, d, err, sizeof err));
    d = create(w, "b", VR_SPHERE, &id);
    d->radius = 0.25;
    set3(d->translate, 1, 0, 0.5);
    set3(d->linear_vel, -2, 0, 0);
    d->volume = 2;
    check(vrWorld_SetObjectDef(w, id, d, err, sizeof err));
}

static void box_and_superquadric(vrWorld *w)
{
    vrObjectId id;
    vrObjectDef *d = create(w, "box", VR_CUBE, &id);
    set3(d->size, 0.2, 0.1, 0.15);
    set3(d->translate, 0, 1, 1);
    set3(d->rotate_axis, 1, 1, 0);
    d->rotate_angle = 0.5, d->rotate_set = 1;
    set3(d->angular_vel, 0, 0, 1);
    d->elasticity = 0.25;
    check(vrWorld_SetObjectDef(w, id, d, err, sizeof err));
    d = create(w, "sq", VR_SUPERQUADRIC, &id);
    d->exp1 = 0.5;
    d->a3 = 0.5;
    d->ures = 12;
    set3(d->translate, 0, -1, 1.5);
    d->mass = 3, d->mass_set = 1;
    check(vrWorld_SetObjectDef(w, id, d, err, sizeof err));
}

int main(void)
{
    vrWorld *w = vrWorld_Create();
    if (!w) return 1;
    settings(w);
    table_and_spheres(w);
    box_and_superquadric(w);
    check(vrWorld_Step(w, 20, err, sizeof err));
    vrWorld_WriteDump(w, stdout);
    vrWorld_Destroy(w);
    return 0;
}
