/* world.h — the world's insides, shared by the modules that coordinate it
 * (world.c, rest.c, random.c, output.c, parallel/).  The shell never sees
 * this: it uses include/vroc.h. */
#ifndef VROC_WORLD_H
#define VROC_WORLD_H

#include "vroc.h"
#include "gp.h"

typedef struct vrObject {
    char name[VR_NAME_MAX + 1];
    vrObjectDef def;
    int alive;
    int built;               /* shape and mass made from def */
    int live;                /* in the simulation: edits now act on its motion */
    vrPolyhedron *poly;      /* hull (cube, superquadric, OFF) or the sphere's drawing mesh */
    vrPolyhedron *off;       /* OFF file loaded by SetObjectDef, waiting to be built */
    double *draw_verts, *draw_normals;
    int *draw_face_start, *draw_face_verts;
    vrBody body;
    vrPose frame_pose;       /* at the end of the last frame (SPEC 3.5) */
    int have_frame_pose;
} vrObject;

struct vrWorld {
    vrSettings s;
    vrObject **obj;          /* by id (creation order); deleted ones stay NULL */
    int nobj, objcap;
    double t;
    long frames;
    int started;             /* the pair set exists */
    int params_dirty;        /* settings changed: re-anchor all at the next frame */
    vrOwner *owner;          /* serial: one owner of every pair */
    vrBody **dyn;            /* live dynamic bodies, for the grid */
    int ndyn, dyncap;
    vrUpdate update;
    int *changed;            /* scratch: ids changed by an update */
    int nchanged, changedcap;
    /* statistics (SPEC 1.3) */
    long subframes;
    long long collisions;
    double frame_ms, sim_ms, render_ms;
    /* `random` */
    int random_next;
    unsigned long long rng;
};

vrParams vrWorld_Params(const vrWorld *w);
vrFlight vrWorld_Flight(const vrWorld *w);
vrObject *vrWorld_Object(const vrWorld *w, vrObjectId id);
/* applies an update: wakes what rests on changed bodies, re-anchors, tells the owners */
int vrWorld_ApplyUpdate(vrWorld *w, vrUpdate *up);

/* rest.c */
/* bodies resting on a changed body wake, transitively (SPEC 3.5) */
int vrRest_WakeDependents(vrWorld *w, vrUpdate *up, double t);
/* frame end: puts to rest what qualifies; fills up with the new states */
int vrRest_FrameEnd(vrWorld *w, vrUpdate *up);
void vrRest_RememberFramePoses(vrWorld *w);

/* random.c */
void vrRandom_Seed(vrWorld *w);

#endif
