/* world.h — the world's insides, shared by the modules that coordinate it
 * (world.c, rest.c, random.c, output.c, parallel/).  The shell never sees
 * this: it uses include/vroc.h. */
#ifndef VROC_WORLD_H
#define VROC_WORLD_H

#include "vroc.h"
#include "owner.h"
#include "reach.h"

typedef struct vrSgp vrSgp;

/* an owner-set operation's answer: a worker died, the frame starts over */
#define VR_RESTART_FRAME 2

typedef struct vrObject {
    char name[VR_NAME_MAX + 1];
    vrObjectDef def;
    int alive;
    int built;               /* shape and mass made from def */
    int live;                /* in the simulation: edits now act on its motion */
    vrPolyhedron *poly;      /* hull (cube, superquadric, OFF) or the sphere's drawing mesh */
    vrPolyhedron *off;       /* OFF file loaded by SetObjectDef, waiting to be built */
    char *off_text;          /* that file's text, for workers to build the same polyhedron */
    double *draw_verts, *draw_normals;
    int *draw_face_start, *draw_face_verts;
    vrBody body;
    int overlap_owed;        /* added, or moved by an edit, since the last start that
                                checked: its pairs are checked at the next (SPEC 1.4) */
    vrPose frame_pose;       /* at the end of the last frame (SPEC 3.5) */
    int have_frame_pose;
} vrObject;

struct vrWorld {
    vrSettings s;
    vrObject **obj;          /* by id (creation order); deleted ones stay NULL */
    int nobj, objcap;
    double t;
    long frames;
    double t_base;           /* frame times are t_base + k time_step, k frames since */
    long frames_base;        /* (summing time_step frame by frame would drift) */
    int started;             /* the pair set exists */
    int instant;             /* responses at instant_t, the last event's time (SPEC 3.1's cap) */
    double instant_t;
    int params_dirty;        /* settings changed (world.c's PARAMS_*): for the next frame */
    long structure;          /* bumped when objects, shapes, masses or settings change */
    vrOwner *owner;          /* serial: one owner of every pair (NULL while workers run) */
    struct vrSgp *sgp;       /* parallel: the workers (parallel/sgp.c) */
    vrUpdate pending;        /* states changed since the owners last heard */
    vrOwnerStats retired;    /* statistics of owners that are gone */
    int may_rest;            /* resting bodies, or more: 0 means none (rest begins only at
                                frame ends, where they are counted) */
    vrBody **dyn;            /* live dynamic bodies, for the grid */
    int ndyn, dyncap;
    int *dyn_slot;           /* by object id below ndyn_slot: its index in dyn, or -1 */
    int ndyn_slot, dyn_slotcap;
    vrReach reach;           /* the grid's largest reach, from bounds on dyn */
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

/* What the coordinator asks of the pair owners (ARCHITECTURE "the loop,
 * once"): the local owner, or the workers through LCM (parallel/sgp.c).
 * first_event first delivers the states in w->pending. */
typedef struct vrOwnerSet {
    int (*first_event)(vrWorld *w, const vrGrid *g, int allow_instant, vrEvent *ev, char *err, size_t n);
    /* every clock moves to ev->t; the responder's new states */
    int (*respond)(vrWorld *w, const vrEvent *ev, vrUpdate *up, char *err, size_t n);
    void (*end_frame)(vrWorld *w, double T);
    /* the pairs of the bodies ids[0..nids) overlapping deeper than tol */
    int (*overlapping)(vrWorld *w, double tol, const int *ids, int nids, int (*out)[2], int max, char *err,
                       size_t n);
    /* frame end T: contacts that could carry the bodies with want[id] */
    int (*support_candidates)(vrWorld *w, double T, const unsigned char *want, vrCandidates *out,
                              char *err, size_t n);
} vrOwnerSet;

vrParams vrWorld_Params(const vrWorld *w);
vrFlight vrWorld_Flight(const vrWorld *w);
vrObject *vrWorld_Object(const vrWorld *w, vrObjectId id);
/* applies an update: wakes what rests on changed bodies, re-anchors, tells the owners */
int vrWorld_ApplyUpdate(vrWorld *w, vrUpdate *up);

/* an object at a given id (workers hold a subset of the SGP's objects);
 * off_text: the OFF file's text for polyhedra, or NULL */
int vrWorld_PutObject(vrWorld *w, int id, const vrObjectDef *def, const char *off_text, char *err, size_t n);
/* builds what changed and places new objects; no pairs */
int vrWorld_Ready(vrWorld *w, char *err, size_t n);
/* by body id (nobj + 1 bytes, to free; NULL when out of memory): 1 when
 * its state is pending, or an overlap check is owed, so that a pair of it
 * is evaluated afresh */
unsigned char *vrWorld_PendingMarks(const vrWorld *w);
/* frees the SGP and its workers, their counts kept in the stats */
void vrWorld_RetireSgp(vrWorld *w);

/* parallel/sgp.c */
extern const vrOwnerSet vrSgp_Owners;
/* starts or re-sets the workers as the settings and objects require */
int vrSgp_Sync(vrWorld *w, char *err, size_t n);
void vrSgp_Free(struct vrSgp *s);
void vrSgp_Stats(const struct vrSgp *s, vrStats *st);

/* rest.c */
/* bodies resting on a changed body wake, transitively (SPEC 3.5) */
int vrRest_WakeDependents(vrWorld *w, vrUpdate *up, double t);
/* frame end: puts to rest what qualifies; fills up with the new states */
int vrRest_FrameEnd(vrWorld *w, vrUpdate *up);
/* frame end T: bodies carried by several contacts together become
 * supported by all of them; -1 (err) or VR_RESTART_FRAME from the owners */
int vrRest_SeveralSupports(vrWorld *w, double T, const vrOwnerSet *owners, vrUpdate *up, char *err, size_t n);
void vrRest_RememberFramePoses(vrWorld *w);

/* random.c */
void vrRandom_Seed(vrWorld *w);

#endif
