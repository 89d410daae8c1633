/* scene.c — the scene builders the tests share (scene.h says what each
 * gives).  Worlds through the public API (vroc.h); bodies through body.h,
 * for the tests that measure pairs without a world.
 *
 *   place  — a definition put at a point with its mass and elasticity (spheres, boxes)
 *   fnv    — the FNV-1a hash of n bytes (vrScene_DumpHash)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene.h"
#include "body.h"

/* ---- a world and its settings ---------------------------------------------- */

vrWorld *vrScene_World(double time_step, double d, double g)
{
    vrWorld *w = vrWorld_Create();
    vrSettings s = *vrWorld_Settings(w);
    s.time_step = time_step;
    s.collision_dist = d;
    s.force_mag = g;
    s.max_linear = 50;
    s.max_angular = 50;
    vrWorld_SetSettings(w, &s, NULL, 0);
    return w;
}

void vrScene_Set(vrWorld *w, void (*edit)(vrSettings *))
{
    vrSettings s = *vrWorld_Settings(w);
    edit(&s);
    vrWorld_SetSettings(w, &s, NULL, 0);
}

void vrScene_HeapOff(vrSettings *s) { s->heap = 0; }

void vrScene_ShellCaps(vrSettings *s)
{
    s->max_linear = 8;
    s->max_angular = 4;
}

vrWorld *vrScene_RandomRoom(const vrSettings *s, int n)
{
    vrWorld *w = vrWorld_Create();
    char err[256] = "";
    if (!w) return NULL;
    if (vrWorld_SetSettings(w, s, err, sizeof err) != 0 || vrWorld_AddRandom(w, n, err, sizeof err) != 0) {
        printf("    room of %d: %s\n", n, err);
        vrWorld_Destroy(w);
        return NULL;
    }
    return w;
}

int vrScene_ReplaceSome(vrWorld *w, int n, int first, int stride, int born, const char *tag, vec3 v)
{
    char name[32];
    int k, made = 0;
    for (k = first; k < n; k += stride) {
        vrObjectId id;
        vrObjectState st;
        snprintf(name, sizeof name, "r%d", k);
        id = vrWorld_FindObject(w, name);
        if (vrWorld_GetObjectState(w, id, &st) != 0 || vrWorld_DeleteObject(w, id) != 0) return -1;
        if (made >= born) continue;
        snprintf(name, sizeof name, "%s%d", tag, made++);
        if (vrScene_Sphere(w, name, 0.1, vec3_make(st.position[0], st.position[1], st.position[2]), v, 1, 1)
            == VR_NO_OBJECT) return -1;
    }
    return 0;
}

/* ---- objects ------------------------------------------------------------------ */

vrObjectId vrScene_Add(vrWorld *w, const char *name, vrObjectType type, const vrObjectDef *d)
{
    vrObjectId id;
    char err[256];
    if (vrWorld_CreateObject(w, name, type, &id, err, sizeof err) != 0 || vrWorld_SetObjectDef(w, id, d, err, sizeof err) != 0) {
        printf("    add %s: %s\n", name, err);
        return VR_NO_OBJECT;
    }
    return id;
}

/* d placed at `at`, of the given mass and elasticity, in the world */
static vrObjectId place(vrWorld *w, const char *name, vrObjectDef *d, vec3 at, double mass, double e)
{
    d->translate[0] = at.x; d->translate[1] = at.y; d->translate[2] = at.z;
    d->mass = mass;
    d->mass_set = 1;
    d->elasticity = e;
    return vrScene_Add(w, name, d->type, d);
}

vrObjectId vrScene_Sphere(vrWorld *w, const char *name, double r, vec3 at, vec3 v, double mass, double e)
{
    vrObjectDef d = vrObjectDef_Default(VR_SPHERE);
    d.radius = r;
    d.linear_vel[0] = v.x; d.linear_vel[1] = v.y; d.linear_vel[2] = v.z;
    return place(w, name, &d, at, mass, e);
}

vrObjectId vrScene_Box(vrWorld *w, const char *name, vec3 half, vec3 at, double mass, double e)
{
    vrObjectDef d = vrObjectDef_Default(VR_CUBE);
    d.size[0] = half.x; d.size[1] = half.y; d.size[2] = half.z;
    return place(w, name, &d, at, mass, e);
}

void vrScene_Edit(vrWorld *w, vrObjectId id, void (*f)(vrObjectDef *, const void *), const void *arg)
{
    vrObjectDef d;
    vrWorld_GetObjectDef(w, id, &d);
    f(&d, arg);
    vrWorld_SetObjectDef(w, id, &d, NULL, 0);
}

void vrScene_SetRotation(vrObjectDef *d, const void *axis_angle)
{
    const double *a = axis_angle;
    d->rotate_set = 1;
    d->rotate_axis[0] = a[0]; d->rotate_axis[1] = a[1]; d->rotate_axis[2] = a[2];
    d->rotate_angle = a[3];
}

void vrScene_SetSpin(vrObjectDef *d, const void *omega)
{
    const double *a = omega;
    d->angular_vel[0] = a[0]; d->angular_vel[1] = a[1]; d->angular_vel[2] = a[2];
}

void vrScene_SetVelocity(vrObjectDef *d, const void *v)
{
    const double *a = v;
    d->linear_vel[0] = a[0]; d->linear_vel[1] = a[1]; d->linear_vel[2] = a[2];
}

/* ---- running and looking ------------------------------------------------------- */

int vrScene_Step(vrWorld *w, long n)
{
    char err[512];
    if (vrWorld_Step(w, n, err, sizeof err) != 0) {
        printf("    step: %s\n", err);
        return -1;
    }
    return 0;
}

vrObjectState vrScene_State(const vrWorld *w, vrObjectId id)
{
    vrObjectState s;
    memset(&s, 0, sizeof s);
    vrWorld_GetObjectState(w, id, &s);
    return s;
}

vrStats vrScene_Stats(const vrWorld *w)
{
    vrStats s;
    vrWorld_GetStats(w, &s);
    return s;
}

vec3 vrScene_Position(const vrObjectState *s) { return vec3_make(s->position[0], s->position[1], s->position[2]); }
vec3 vrScene_LinearVel(const vrObjectState *s) { return vec3_make(s->linear_vel[0], s->linear_vel[1], s->linear_vel[2]); }

char *vrScene_Dump(vrWorld *w)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    vrWorld_WriteDump(w, f);
    fclose(f);
    return buf;
}

int vrScene_SameDumps(vrWorld *a, vrWorld *b)
{
    char *da = vrScene_Dump(a), *db = vrScene_Dump(b);
    int same = strcmp(da, db) == 0;
    if (!same) printf("%s---\n%s", da, db);
    free(da);
    free(db);
    return same;
}

int vrScene_StepRuns(vrWorld **w, int nw, long n)
{
    int i;
    for (i = 0; i < nw; i++)
        if (!w[i] || vrScene_Step(w[i], n) != 0) return printf("    run %d of %d: %s\n", i, nw, w[i] ? "step failed" : "not made"), -1;
    return 0;
}

int vrScene_SameRunsFreed(vrWorld **w, int nw)
{
    int i, same = 1;
    for (i = 1; i < nw; i++) same = same && vrScene_SameDumps(w[0], w[i]);
    for (i = 0; i < nw; i++) vrWorld_Destroy(w[i]);
    return same;
}

static unsigned long long fnv(const char *s, size_t n)
{
    unsigned long long h = 1469598103934665603ULL;
    size_t i;
    for (i = 0; i < n; i++) h = (h ^ (unsigned char)s[i]) * 1099511628211ULL;
    return h;
}

unsigned long long vrScene_DumpHash(vrWorld *w)
{
    char *dump = vrScene_Dump(w);
    unsigned long long h = fnv(dump, strlen(dump));
    free(dump);
    return h;
}

/* ---- bodies without a world ------------------------------------------------------ */

void vrScene_SphereBody(vrBody *b, int id, double r, int is_static)
{
    mat33 unit = mat33_diag(0.4 * r * r, 0.4 * r * r, 0.4 * r * r);
    memset(b, 0, sizeof *b);
    b->id = id;
    b->shape.kind = VR_SHAPE_SPHERE;
    b->shape.radius = r;
    vrBody_SetMassProperties(b, is_static ? -1 : 1, &unit, r, r);
}

void vrScene_BoxBody(vrBody *b, int id, vrPolyhedron *p, vec3 half, int is_static)
{
    memset(b, 0, sizeof *b);
    b->id = id;
    b->shape.kind = VR_SHAPE_BOX;
    b->shape.poly = p;
    b->shape.half = half;
    vrBody_SetMassProperties(b, is_static ? -1 : 1, &p->inertia_unit, p->r_in, p->r_out);
}

/* ---- tracker samples and saved files ------------------------------------------- */

vrTrackerSample vrScene_Sample(double t, vec3 p, quat q, unsigned buttons)
{
    vrTrackerSample s;
    s.t = t;
    s.position[0] = p.x, s.position[1] = p.y, s.position[2] = p.z;
    s.orientation[0] = q.w, s.orientation[1] = q.x, s.orientation[2] = q.y, s.orientation[3] = q.z;
    s.buttons = buttons;
    return s;
}

/* the definition writer: one line naming the id, which the reader copies */
void vrScene_DefLine(void *ctx, FILE *out, vrObjectId id)
{
    (void)ctx;
    fprintf(out, "object %d\n", id);
}

/* b: a fresh world given a's settings and definitions, then the save's state lines */
int vrScene_ReadSave(vrWorld *a, vrWorld *b, char *text)
{
    char err[400], *line, *next;
    vrObjectId selected = VR_NO_OBJECT;
    if (vrWorld_SetSettings(b, vrWorld_Settings(a), err, sizeof err) != 0) return -1;
    for (line = text; line && *line; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = '\0';
        while (*line == ' ') line++;
        if (strncmp(line, "object ", 7) == 0) {
            vrObjectDef d;
            int id = atoi(line + 7);
            vrWorld_GetObjectDef(a, id, &d);
            if (vrWorld_CreateObject(b, vrWorld_ObjectName(a, id), d.type, &selected, err, sizeof err) != 0
                || selected != id || vrWorld_SetObjectDef(b, id, &d, err, sizeof err) != 0)
                return printf("    %s\n", err), -1;
        } else if (strncmp(line, "state ", 6) == 0
                   && vrWorld_ReadState(b, selected, line + 6, strlen(line + 6), err, sizeof err) != 0)
            return printf("    %s\n", err), -1;
    }
    return 0;
}
