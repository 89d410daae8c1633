/* scene.h — the scene builders the tests share (Box2D's shared/ is the
 * model): a world with the step, envelope and gravity a test names, spheres
 * and boxes placed and set going, an object's state after n frames, and
 * dumps compared or hashed; and, for the tests below the world (the keys,
 * the distance bounds), a sphere or polyhedron body on its own.
 *
 * A builder that fails prints why (`    add NAME: ...`, `    step: ...`)
 * and returns VR_NO_OBJECT or -1, so the test's ENSURE names the line. */
#ifndef VROC_TEST_SCENE_H
#define VROC_TEST_SCENE_H

#include "vroc.h"
#include "vec.h"

struct vrBody;
struct vrPolyhedron;

/* ---- a world and its settings ---------------------------------------------- */

/* a world stepping time_step, envelope d, gravity g down z, speeds capped at 50 */
vrWorld *vrScene_World(double time_step, double d, double g);
/* the world's settings changed by edit */
void vrScene_Set(vrWorld *w, void (*edit)(vrSettings *));
void vrScene_HeapOff(vrSettings *s);
/* the shell's speed caps (SPEC 3.2, the thesis's): max_linear 8 m/s, max_angular 4 rad/s */
void vrScene_ShellCaps(vrSettings *s);
/* a world of settings s and n random objects (vrWorld_AddRandom, named
 * r0..); NULL, with the error printed, when either is refused */
vrWorld *vrScene_RandomRoom(const vrSettings *s, int n);
/* mid-run edits: every stride-th random object from `first` deleted, and in
 * the place of the first `born` of them a ball of 0.1 m named TAG0.. (inside
 * the deleted object's own bounding sphere, so clear of the others), flying
 * at v; -1 when an object is missing or refused */
int vrScene_ReplaceSome(vrWorld *w, int n, int first, int stride, int born, const char *tag, vec3 v);

/* ---- objects ------------------------------------------------------------------ */

/* a new object of definition d */
vrObjectId vrScene_Add(vrWorld *w, const char *name, vrObjectType type, const vrObjectDef *d);
/* a ball of radius r at `at` moving at v; mass -1: static; e its elasticity */
vrObjectId vrScene_Sphere(vrWorld *w, const char *name, double r, vec3 at, vec3 v, double mass, double e);
/* a box of half extents `half` at `at`, still */
vrObjectId vrScene_Box(vrWorld *w, const char *name, vec3 half, vec3 at, double mass, double e);
/* the object's definition changed by f(def, arg) */
void vrScene_Edit(vrWorld *w, vrObjectId id, void (*f)(vrObjectDef *, const void *), const void *arg);
/* editors for vrScene_Edit: arg is {axis x, y, z, angle}, or a vector of 3 */
void vrScene_SetRotation(vrObjectDef *d, const void *axis_angle);
void vrScene_SetSpin(vrObjectDef *d, const void *omega);
void vrScene_SetVelocity(vrObjectDef *d, const void *v);

/* ---- running and looking ------------------------------------------------------- */

/* n frames: 0, or -1 and the error printed */
int vrScene_Step(vrWorld *w, long n);
vrObjectState vrScene_State(const vrWorld *w, vrObjectId id);
vrStats vrScene_Stats(const vrWorld *w);
vec3 vrScene_Position(const vrObjectState *s);
vec3 vrScene_LinearVel(const vrObjectState *s);
/* the world's dump (vrWorld_WriteDump) in a string the caller frees */
char *vrScene_Dump(vrWorld *w);
/* 1 when a and b dump the same bits (both printed when not) */
int vrScene_SameDumps(vrWorld *a, vrWorld *b);
/* runs of one scene in several modes (serial, heap off, workers ...):
 * each stepped n frames; 0, or -1 when one is missing or fails (printed) */
int vrScene_StepRuns(vrWorld **w, int nw, long n);
/* 1 when every run dumps the first's bits (printed when not); the worlds
 * are destroyed either way */
int vrScene_SameRunsFreed(vrWorld **w, int nw);
/* the FNV-1a hash of the world's dump */
unsigned long long vrScene_DumpHash(vrWorld *w);

/* ---- bodies without a world ------------------------------------------------------ */

/* a ball of radius r, mass 1 (is_static: -1) */
void vrScene_SphereBody(struct vrBody *b, int id, double r, int is_static);
/* a box of half extents `half` whose polyhedron is p, mass 1 (is_static: -1) */
void vrScene_BoxBody(struct vrBody *b, int id, struct vrPolyhedron *p, vec3 half, int is_static);

/* ---- tracker samples and saved files -------------------------------------------- */

/* a tracker sample at t: position p, orientation q, the buttons */
vrTrackerSample vrScene_Sample(double t, vec3 p, quat q, unsigned buttons);
/* vrWorld_WriteSave's definition writer: `object ID`, which vrScene_ReadSave copies */
void vrScene_DefLine(void *ctx, FILE *out, vrObjectId id);
/* b, a fresh world, given a's settings and definitions, then the saved text's
 * state lines (text is cut into lines in place): 0, or -1 and the error printed */
int vrScene_ReadSave(vrWorld *a, vrWorld *b, char *text);

#endif
