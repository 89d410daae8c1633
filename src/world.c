/* world.c — objects, settings and the frame loop: the coordinator of
 * ARCHITECTURE "the loop, once" (thesis 3.4.2 and 3.5.2).
 *
 * Per frame [t, T]: the owners run their pairs through the span on the
 * grid computed here from the global state; the earliest event by (time,
 * pair order) is taken; every clock advances to it; its owner responds;
 * the new states go to every holder; the next span starts at the event.
 * At the frame end, rest is decided from the bodies' states.
 */
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "grow.h"
#include "off.h"
#include "primitives.h"
#include "world.h"

#define MAX_REPORTED_OVERLAPS 8

/* ---- defaults --------------------------------------------------------------------- */

vrObjectDef vrObjectDef_Default(vrObjectType type)
{
    vrObjectDef d;
    memset(&d, 0, sizeof d);
    d.type = type;
    d.elasticity = 1.0;
    d.mass = 1.0;
    d.volume = 1.0;
    d.rotate_axis[2] = 1.0;
    d.color[0] = 255;
    d.radius = 1.0;
    d.ures = d.vres = 10;
    d.size[0] = d.size[1] = d.size[2] = 1.0;
    d.exp1 = d.exp2 = 1.0;
    d.a1 = d.a2 = d.a3 = 1.0;
    return d;
}

vrSettings vrSettings_Default(void)
{
    vrSettings s;
    memset(&s, 0, sizeof s);
    s.time_step = 0.1;
    s.collision_dist = 0.25;
    s.max_linear = 8.0;
    s.max_angular = 4.0;
    s.force_dir[2] = -1.0;
    s.heap = 1;
    s.max_frames = 600;
    s.distribution = VR_DIST_ROUND_ROBIN;
    strcpy(s.lcm_url, "udpm://239.255.76.67:7667?ttl=0");
    s.collision_vol = 1.0;
    return s;
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static vec3 v3(const double a[3]) { return vec3_make(a[0], a[1], a[2]); }

static int fail(char *err, size_t n, const char *fmt, const char *what, double v)
{
    if (err && n) snprintf(err, n, fmt, what, v);
    return -1;
}

static int fail_msg(char *err, size_t n, const char *msg)
{
    if (err && n) snprintf(err, n, "%s", msg);
    return -1;
}

/* ---- settings ------------------------------------------------------------------------ */

static int bad_range(double v, double lo, double hi, int lo_open)
{
    return !isfinite(v) || v > hi || v < lo || (lo_open && v == lo);
}

static int check_settings(const vrSettings *s, char *err, size_t n)
{
    vec3 f = v3(s->force_dir);
    if (bad_range(s->time_step, 0, 1e9, 0)) return fail(err, n, "%s must be >= 0 (got %g)", "time_step", s->time_step);
    if (bad_range(s->collision_dist, 0, 1e9, 1)) return fail(err, n, "%s must be > 0 (got %g)", "collision_dist", s->collision_dist);
    if (bad_range(s->internal_step, 0, 1e9, 0)) return fail(err, n, "%s must be >= 0 (got %g)", "internal_step", s->internal_step);
    if (bad_range(s->max_linear, 0, 1e9, 1)) return fail(err, n, "%s must be > 0 (got %g)", "max_linear", s->max_linear);
    if (bad_range(s->max_angular, 0, 1e9, 1)) return fail(err, n, "%s must be > 0 (got %g)", "max_angular", s->max_angular);
    if (!vec3_isfinite(f) || vec3_len2(f) == 0) return fail_msg(err, n, "force direction must be a non-zero vector");
    if (bad_range(s->force_mag, 0, 1e9, 0)) return fail(err, n, "%s magnitude must be >= 0 (got %g)", "force", s->force_mag);
    if (s->heap != 0 && s->heap != 1) return fail(err, n, "%s must be 0 or 1 (got %g)", "heap", s->heap);
    if (s->max_frames < 0) return fail(err, n, "%s must be >= 0 (got %g)", "max_frames", (double)s->max_frames);
    if (bad_range(s->room, 0, 1e6, 0)) return fail(err, n, "%s must be >= 0 (got %g)", "room", s->room);
    if (s->gps < 0 || s->gps > 64) return fail(err, n, "%s must be 0..64 (got %g)", "gps", s->gps);
    if (bad_range(s->collision_vol, 0, 1, 0)) return fail(err, n, "%s must be 0..1 (got %g)", "collision_vol", s->collision_vol);
    return 0;
}

/* What a change of settings does: the pair owners take the new parameters
 * (PARAMS_OWNERS: every pair is looked at afresh), and where free flight
 * changes every body is re-anchored at the frame start (PARAMS_MOTION).
 * The heap changes no motion: re-anchoring for it would round poses
 * differently from a run that never switched it (SPEC 3.2: heap on and off
 * give the same bits, and so does switching between them). */
enum { PARAMS_OWNERS = 1, PARAMS_MOTION = 2 };

static int params_changed(const vrSettings *a, const vrSettings *b)
{
    if (a->collision_dist != b->collision_dist || a->max_linear != b->max_linear
        || a->max_angular != b->max_angular || a->force_mag != b->force_mag
        || a->force_dir[0] != b->force_dir[0] || a->force_dir[1] != b->force_dir[1]
        || a->force_dir[2] != b->force_dir[2])
        return PARAMS_OWNERS | PARAMS_MOTION;
    return a->heap != b->heap ? PARAMS_OWNERS : 0;
}

const vrSettings *vrWorld_Settings(const vrWorld *w) { return &w->s; }

int vrWorld_SetSettings(vrWorld *w, const vrSettings *s, char *err, size_t n)
{
    if (check_settings(s, err, n) != 0) return -1;
    w->params_dirty |= params_changed(&w->s, s);
    if (s->time_step != w->s.time_step) {
        w->t_base = w->t;
        w->frames_base = w->frames;
    }
    if (s->seed != w->s.seed) {
        w->s.seed = s->seed;
        vrRandom_Seed(w);
    }
    w->s = *s;
    return 0;
}

vrFlight vrWorld_Flight(const vrWorld *w)
{
    vrFlight f;
    f.accel = vec3_scale(vec3_normalize(v3(w->s.force_dir)), w->s.force_mag);
    f.max_linear = w->s.max_linear;
    f.max_angular = w->s.max_angular;
    return f;
}

vrParams vrWorld_Params(const vrWorld *w)
{
    vrParams p;
    p.d = w->s.collision_dist;
    p.flight = vrWorld_Flight(w);
    p.use_heap = w->s.heap;
    return p;
}

/* ---- life cycle ---------------------------------------------------------------------- */

vrWorld *vrWorld_Create(void)
{
    vrWorld *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    w->s = vrSettings_Default();
    w->instant_t = -INFINITY;
    vrUpdate_Init(&w->update);
    vrUpdate_Init(&w->pending);
    vrRandom_Seed(w);
    return w;
}

static void free_object(vrObject *o)
{
    if (!o) return;
    vrPolyhedron_Free(o->poly);
    vrPolyhedron_Free(o->off);
    free(o->off_text);
    free(o->draw_verts);
    free(o->draw_normals);
    free(o->draw_face_start);
    free(o->draw_face_verts);
    free(o);
}

static void clear_objects(vrWorld *w)
{
    int i;
    for (i = 0; i < w->nobj; i++) free_object(w->obj[i]);
    w->nobj = 0;
    w->ndyn = 0;
    vrOwner_Free(w->owner);
    w->owner = NULL;
    w->started = 0;
    w->pending.n = 0;
    w->structure++;
}

void vrWorld_Destroy(vrWorld *w)
{
    if (!w) return;
    clear_objects(w);
    vrSgp_Free(w->sgp);
    free(w->obj);
    free(w->dyn);
    free(w->dyn_slot);
    vrReach_Free(&w->reach);
    free(w->changed);
    vrUpdate_Free(&w->update);
    vrUpdate_Free(&w->pending);
    free(w);
}

void vrWorld_Restart(vrWorld *w)
{
    clear_objects(w);
    w->t = w->t_base = 0;
    w->frames = w->frames_base = 0;
    w->subframes = 0;
    w->collisions = 0;
    w->frame_ms = w->sim_ms = w->render_ms = 0;
    memset(&w->retired, 0, sizeof w->retired);
    w->random_next = 0;
    w->params_dirty = 0;
    w->instant = 0;
    w->instant_t = -INFINITY;
    vrRandom_Seed(w);
}

/* ---- objects --------------------------------------------------------------------------- */

vrObject *vrWorld_Object(const vrWorld *w, vrObjectId id)
{
    return id >= 0 && id < w->nobj ? w->obj[id] : NULL;
}

static int valid_name(const char *s)
{
    size_t i, n = strlen(s);
    if (n == 0 || n > VR_NAME_MAX) return 0;
    for (i = 0; i < n; i++) {
        char c = s[i];
        int alpha = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
        int digit = c >= '0' && c <= '9';
        if (!(alpha || (i > 0 && (digit || c == '.' || c == '-')))) return 0;
    }
    return 1;
}

vrObjectId vrWorld_FindObject(const vrWorld *w, const char *name)
{
    int i;
    for (i = 0; i < w->nobj; i++)
        if (w->obj[i] && strcmp(w->obj[i]->name, name) == 0) return i;
    return VR_NO_OBJECT;
}

/* the object table has a free slot at w->nobj */
static int room_for_one_more(vrWorld *w, char *err, size_t n)
{
    int cap;
    vrObject **no;
    if (w->nobj < w->objcap) return 0;
    cap = w->objcap ? 2 * w->objcap : 64;
    no = realloc(w->obj, (size_t)cap * sizeof *no);
    if (!no) return fail_msg(err, n, "out of memory");
    w->obj = no;
    w->objcap = cap;
    return 0;
}

int vrWorld_CreateObject(vrWorld *w, const char *name, vrObjectType type, vrObjectId *id, char *err, size_t n)
{
    vrObject *o;
    if (!valid_name(name)) {
        if (err && n) snprintf(err, n, "bad object name '%.80s' (letters, digits, _ . -, at most %d bytes)", name, VR_NAME_MAX);
        return -1;
    }
    if (vrWorld_FindObject(w, name) != VR_NO_OBJECT) {
        if (err && n) snprintf(err, n, "object '%s' exists", name);
        return -1;
    }
    if (room_for_one_more(w, err, n) != 0) return -1;
    o = calloc(1, sizeof *o);
    if (!o) return fail_msg(err, n, "out of memory");
    strcpy(o->name, name);
    o->def = vrObjectDef_Default(type);
    o->alive = 1;
    o->body.id = w->nobj;
    w->obj[w->nobj] = o;
    if (id) *id = w->nobj;
    w->nobj++;
    return 0;
}

const char *vrWorld_ObjectName(const vrWorld *w, vrObjectId id)
{
    vrObject *o = vrWorld_Object(w, id);
    return o ? o->name : NULL;
}

int vrWorld_GetObjectDef(const vrWorld *w, vrObjectId id, vrObjectDef *def)
{
    vrObject *o = vrWorld_Object(w, id);
    if (!o) return -1;
    *def = o->def;
    return 0;
}

int vrWorld_ObjectCount(const vrWorld *w)
{
    int i, n = 0;
    for (i = 0; i < w->nobj; i++) n += w->obj[i] != NULL;
    return n;
}

int vrWorld_ObjectList(const vrWorld *w, vrObjectId *ids, int max)
{
    int i, n = 0;
    for (i = 0; i < w->nobj; i++)
        if (w->obj[i]) {
            if (n < max) ids[n] = i;
            n++;
        }
    return n;
}

/* a polyhedron from OFF text (a worker gets the text, not the file) */
static int off_from_text(const char *text, vrPolyhedron **p, char *err, size_t n)
{
    char path[] = "/tmp/vroc-off-XXXXXX";
    int fd = mkstemp(path), r;
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) return fail_msg(err, n, "cannot write a temporary OFF file");
    r = fputs(text, f) < 0;
    r |= fclose(f) != 0;
    r = r ? fail_msg(err, n, "cannot write a temporary OFF file") : vrPolyhedron_FromOFF(path, p, err, n);
    unlink(path);
    return r;
}

static int check_def(const vrObjectDef *d, char *err, size_t n)
{
    int i;
    for (i = 0; i < 3; i++) {
        if (!isfinite(d->linear_vel[i]) || !isfinite(d->angular_vel[i]) || !isfinite(d->translate[i]))
            return fail_msg(err, n, "vectors must be finite");
        if (d->color[i] < 0 || d->color[i] > 255) return fail(err, n, "%s must be 0..255 (got %g)", "color", d->color[i]);
        if (bad_range(d->size[i], 0, 1e9, 1)) return fail(err, n, "%s must be > 0 (got %g)", "size", d->size[i]);
    }
    if (bad_range(d->elasticity, 0, 1, 0)) return fail(err, n, "%s must be 0..1 (got %g)", "elasticity", d->elasticity);
    if (!isfinite(d->mass) || d->mass == 0) return fail(err, n, "%s must be non-zero (got %g)", "mass", d->mass);
    if (bad_range(d->volume, 0, 1e12, 1)) return fail(err, n, "%s must be > 0 (got %g)", "volume", d->volume);
    if (d->rotate_set && (!isfinite(d->rotate_angle) || !vec3_isfinite(v3(d->rotate_axis)) || vec3_len2(v3(d->rotate_axis)) == 0))
        return fail_msg(err, n, "rotate axis must be a non-zero vector");
    if (bad_range(d->radius, 0, 1e9, 1)) return fail(err, n, "%s must be > 0 (got %g)", "radius", d->radius);
    if (d->ures < 3 || d->ures > 1000) return fail(err, n, "%s must be 3..1000 (got %g)", "ures", d->ures);
    if (d->vres < 3 || d->vres > 1000) return fail(err, n, "%s must be 3..1000 (got %g)", "vres", d->vres);
    if (bad_range(d->exp1, 0.05, 2, 0)) return fail(err, n, "%s must be 0.05..2 (got %g)", "exp1", d->exp1);
    if (bad_range(d->exp2, 0.05, 2, 0)) return fail(err, n, "%s must be 0.05..2 (got %g)", "exp2", d->exp2);
    if (bad_range(d->a1, 0, 1e9, 1)) return fail(err, n, "%s must be > 0 (got %g)", "a1", d->a1);
    if (bad_range(d->a2, 0, 1e9, 1)) return fail(err, n, "%s must be > 0 (got %g)", "a2", d->a2);
    if (bad_range(d->a3, 0, 1e9, 1)) return fail(err, n, "%s must be > 0 (got %g)", "a3", d->a3);
    return 0;
}

/* a whole file's text (NUL-terminated), or NULL */
static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t len = 0, cap = 0, got;
    if (!f) return NULL;
    do {
        if (len + 4096 + 1 > cap) {
            char *nb = realloc(buf, cap = 2 * cap + 4096 + 1);
            if (!nb) break;
            buf = nb;
        }
        got = fread(buf + len, 1, cap - len - 1, f);
        len += got;
    } while (got > 0);
    fclose(f);
    if (buf) buf[len] = 0;
    return buf;
}

static int shape_changed(const vrObjectDef *a, const vrObjectDef *b)
{
    switch (b->type) {
    case VR_SPHERE:
        return a->radius != b->radius || a->ures != b->ures || a->vres != b->vres;
    case VR_CUBE:
        return memcmp(a->size, b->size, sizeof a->size) != 0;
    case VR_SUPERQUADRIC:
        return a->exp1 != b->exp1 || a->exp2 != b->exp2 || a->a1 != b->a1 || a->a2 != b->a2 || a->a3 != b->a3
            || a->ures != b->ures || a->vres != b->vres;
    default:
        return strcmp(a->file, b->file) != 0;
    }
}

static double def_mass(const vrObjectDef *d) { return d->mass_set ? d->mass : d->volume; }

static int mass_changed(const vrObjectDef *a, const vrObjectDef *b)
{
    return def_mass(a) != def_mass(b) || a->elasticity != b->elasticity;
}

static int motion_edited(const vrObjectDef *a, const vrObjectDef *b)
{
    return memcmp(a->translate, b->translate, sizeof a->translate) != 0
        || memcmp(a->linear_vel, b->linear_vel, sizeof a->linear_vel) != 0
        || memcmp(a->angular_vel, b->angular_vel, sizeof a->angular_vel) != 0
        || a->rotate_set != b->rotate_set || a->rotate_angle != b->rotate_angle
        || memcmp(a->rotate_axis, b->rotate_axis, sizeof a->rotate_axis) != 0;
}

static int apply_live_edit(vrWorld *w, vrObject *o, const vrObjectDef *old, char *err, size_t n);

int vrWorld_SetObjectDef(vrWorld *w, vrObjectId id, const vrObjectDef *def, char *err, size_t n)
{
    vrObject *o = vrWorld_Object(w, id);
    vrObjectDef old;
    if (!o) return fail_msg(err, n, "no such object");
    if (def->type != o->def.type) return fail_msg(err, n, "an object's type cannot change");
    if (check_def(def, err, n) != 0) return -1;
    if (def->type == VR_POLYHEDRON && strcmp(def->file, o->def.file) != 0) {
        vrPolyhedron *p = NULL;
        char *text = read_text(def->file);
        if (vrPolyhedron_FromOFF(def->file, &p, err, n) != 0) {
            free(text);
            return -1;
        }
        if (!text) {
            vrPolyhedron_Free(p);
            return fail_msg(err, n, "out of memory");
        }
        vrPolyhedron_Free(o->off);
        free(o->off_text);
        o->off = p;
        o->off_text = text;
    }
    old = o->def;
    o->def = *def;
    if (shape_changed(&old, def) || mass_changed(&old, def)) o->built = 0;
    if (!o->live) return 0;
    return apply_live_edit(w, o, &old, err, n);
}

int vrWorld_PutObject(vrWorld *w, int id, const vrObjectDef *def, const char *off_text, char *err, size_t n)
{
    vrObject *o;
    if (id < 0 || check_def(def, err, n) != 0) return -1;
    while (w->nobj <= id) {
        if (room_for_one_more(w, err, n) != 0) return -1;
        w->obj[w->nobj++] = NULL;
    }
    free_object(w->obj[id]);
    w->obj[id] = o = calloc(1, sizeof *o);
    if (!o) return fail_msg(err, n, "out of memory");
    snprintf(o->name, sizeof o->name, "#%d", id);
    o->def = *def;
    o->alive = 1;
    o->body.id = id;
    if (def->type == VR_POLYHEDRON && (!off_text || off_from_text(off_text, &o->off, err, n) != 0))
        return off_text ? -1 : fail_msg(err, n, "polyhedron without its OFF text");
    return 0;
}

/* ---- building and placing -------------------------------------------------------------- */

static int copy_draw_mesh(vrObject *o)
{
    const vrPolyhedron *p = o->poly;
    int i, nfv = p->face_start[p->nf];
    o->draw_verts = malloc((size_t)p->nv * 3 * sizeof(double));
    o->draw_normals = malloc((size_t)p->nv * 3 * sizeof(double));
    o->draw_face_start = malloc((size_t)(p->nf + 1) * sizeof(int));
    o->draw_face_verts = malloc((size_t)nfv * sizeof(int));
    if (!o->draw_verts || !o->draw_normals || !o->draw_face_start || !o->draw_face_verts) return -1;
    for (i = 0; i < p->nv; i++) {
        o->draw_verts[3 * i] = p->vert[i].x;
        o->draw_verts[3 * i + 1] = p->vert[i].y;
        o->draw_verts[3 * i + 2] = p->vert[i].z;
        o->draw_normals[3 * i] = p->vert_normal[i].x;
        o->draw_normals[3 * i + 1] = p->vert_normal[i].y;
        o->draw_normals[3 * i + 2] = p->vert_normal[i].z;
    }
    memcpy(o->draw_face_start, p->face_start, (size_t)(p->nf + 1) * sizeof(int));
    memcpy(o->draw_face_verts, p->face_vert, (size_t)nfv * sizeof(int));
    return 0;
}

static void free_shape(vrObject *o)
{
    vrPolyhedron_Free(o->poly);
    free(o->draw_verts);
    free(o->draw_normals);
    free(o->draw_face_start);
    free(o->draw_face_verts);
    o->poly = NULL;
    o->draw_verts = o->draw_normals = NULL;
    o->draw_face_start = o->draw_face_verts = NULL;
}

static int make_polyhedron(vrObject *o, char *err, size_t n)
{
    const vrObjectDef *d = &o->def;
    switch (d->type) {
    case VR_SPHERE:
        return vrPolyhedron_Sphere(d->radius, d->ures, d->vres, &o->poly, err, n);
    case VR_CUBE:
        return vrPolyhedron_Cube(v3(d->size), &o->poly, err, n);
    case VR_SUPERQUADRIC:
        return vrPolyhedron_Superquadric(d->exp1, d->exp2, vec3_make(d->a1, d->a2, d->a3), d->ures, d->vres,
                                         &o->poly, err, n);
    default:
        if (!o->off && !o->poly) {
            if (err && n) snprintf(err, n, "polyhedron '%s' has no file (file = path.off)", o->name);
            return -1;
        }
        if (o->off) {
            o->poly = o->off;
            o->off = NULL;
        }
        return 0;
    }
}

/* shape and mass properties from the definition */
static int build(vrObject *o, char *err, size_t n)
{
    static unsigned long shapes_made;
    const vrObjectDef *d = &o->def;
    vrShape *sh = &o->body.shape;
    mat33 unit;
    double rin, rout;
    if (d->type != VR_POLYHEDRON || o->off) free_shape(o);
    if (!o->poly && make_polyhedron(o, err, n) != 0) return -1;
    if (!o->draw_verts && copy_draw_mesh(o) != 0) return fail_msg(err, n, "out of memory");
    memset(sh, 0, sizeof *sh);
    if (d->type == VR_SPHERE) {
        double i = 0.4 * d->radius * d->radius;     /* a solid sphere: 2/5 m r^2 */
        sh->kind = VR_SHAPE_SPHERE;
        sh->radius = d->radius;
        unit = mat33_diag(i, i, i);
        rin = rout = d->radius;
    } else {
        sh->kind = d->type == VR_CUBE ? VR_SHAPE_BOX : VR_SHAPE_POLY;
        sh->half = v3(d->size);
        sh->poly = o->poly;
        unit = o->poly->inertia_unit;
        rin = o->poly->r_in;
        rout = o->poly->r_out;
    }
    sh->serial = ++shapes_made;
    vrBody_SetMassProperties(&o->body, def_mass(d), &unit, rin, rout);
    o->body.elasticity = d->elasticity;
    o->built = 1;
    return 0;
}

static quat def_orientation(const vrObjectDef *d)
{
    if (!d->rotate_set) return quat_identity();
    return quat_from_axis_angle(vec3_normalize(v3(d->rotate_axis)), d->rotate_angle);
}

static vec3 momentum_of(const vrBody *b, quat q, vec3 omega)
{
    vrPose p = vrPose_make(vec3_zero(), q);
    mat33 I = vrBody_InertiaWorld(b, &p);
    return mat33_mulv(&I, omega);
}

/* the initial state the definition describes, at the world's time */
static void place(vrWorld *w, vrObject *o)
{
    vrFlight f = vrWorld_Flight(w);
    quat q = def_orientation(&o->def);
    o->body.resting = 0;
    o->body.nsupport = 0;
    o->body.hit = 0;
    vrBody_Anchor(&o->body, w->t, v3(o->def.translate), v3(o->def.linear_vel), q,
                  momentum_of(&o->body, q, v3(o->def.angular_vel)), &f);
    o->have_frame_pose = 0;
}

static int ready(vrWorld *w, vrObject *o, char *err, size_t n)
{
    if (!o->built) {
        if (build(o, err, n) != 0) return -1;
        if (o->live) return 0;
    }
    if (!o->live) place(w, o);
    return 0;
}

/* ---- the pair set -------------------------------------------------------------------- */

static int rebuild_dynamic_list(vrWorld *w)
{
    int i;
    w->ndyn = 0;
    w->ndyn_slot = 0;
    if (vrGrow((void **)&w->dyn_slot, &w->dyn_slotcap, w->nobj, sizeof *w->dyn_slot) != 0) return -1;
    w->ndyn_slot = w->nobj;
    for (i = 0; i < w->nobj; i++) {
        vrObject *o = w->obj[i];
        w->dyn_slot[i] = -1;
        if (!o || !o->live || o->body.is_static) continue;
        if (vrGrow((void **)&w->dyn, &w->dyncap, w->ndyn + 1, sizeof *w->dyn) != 0) return -1;
        w->dyn_slot[i] = w->ndyn;
        w->dyn[w->ndyn++] = &o->body;
    }
    return 0;
}

static int pairable(const vrWorld *w, int i, int j)
{
    return !(w->obj[i]->body.is_static && w->obj[j]->body.is_static);
}

unsigned char *vrWorld_PendingMarks(const vrWorld *w)
{
    unsigned char *mark = calloc((size_t)w->nobj + 1, 1);
    int i;
    /* An owed overlap check (an edit since the last start, or a start
     * refused) looks at the flagged pairs of the bodies it is owed for:
     * owners made anew now, e.g. for a new pair set after an edit that only
     * changed a mass, must flag those, or an overlap the old owners had
     * flagged goes unseen. */
    for (i = 0; mark && i < w->nobj; i++)
        if (w->obj[i] && w->obj[i]->overlap_owed) mark[i] = 1;
    for (i = 0; mark && i < w->pending.n; i++)
        if (w->pending.body[i].id >= 0 && w->pending.body[i].id < w->nobj) mark[w->pending.body[i].id] = 1;
    return mark;
}

/* every dynamic–dynamic and dynamic–static pair of a new object (SPEC 3.3:
 * static–static pairs are never made), to be evaluated at the next span */
static int add_pairs_of(vrWorld *w, int id)
{
    int j;
    if (vrOwner_HoldBody(w->owner, id, &w->obj[id]->body) != 0) return -1;
    for (j = 0; j < w->nobj; j++) {
        if (j == id || !w->obj[j] || !w->obj[j]->live || !pairable(w, id, j)) continue;
        if (vrOwner_AddPair(w->owner, j < id ? j : id, j < id ? id : j) != 0) return -1;
    }
    return 0;
}

/* objects join the simulation: their states go out as changes, so their
 * pairs are evaluated at the next span start */
static int make_live(vrWorld *w, char *err, size_t n)
{
    int i;
    for (i = 0; i < w->nobj; i++) {
        vrObject *o = w->obj[i];
        if (!o || o->live) continue;
        o->live = 1;
        if (!vrUpdate_Body(&w->pending, &o->body, w->t)) return fail_msg(err, n, "out of memory");
        if (w->owner && add_pairs_of(w, i) != 0) return fail_msg(err, n, "out of memory");
        w->structure++;
        o->overlap_owed = 1;
    }
    return rebuild_dynamic_list(w) == 0 ? 0 : fail_msg(err, n, "out of memory");
}

/* re-anchor every dynamic body after a change of settings */
static int apply_params(vrWorld *w)
{
    vrParams p = vrWorld_Params(w);
    int i;
    int motion = w->params_dirty & PARAMS_MOTION;
    if (w->owner) vrOwner_SetParams(w->owner, &p);   /* flags every pair */
    w->update.n = 0;
    for (i = 0; motion && i < w->ndyn; i++)
        if (!vrUpdate_Body(&w->update, w->dyn[i], w->t)) return -1;
    w->params_dirty = 0;
    w->structure++;                                  /* workers are made anew with them */
    return vrWorld_ApplyUpdate(w, &w->update);
}

static void retire_owner(vrWorld *w)
{
    vrOwnerStats os;
    if (!w->owner) return;
    vrOwner_Stats(w->owner, &os);
    w->retired.checks += os.checks;
    w->retired.heap_pops += os.heap_pops;
    w->retired.response.solves += os.response.solves;
    w->retired.response.refactors += os.response.refactors;
    w->retired.response.factors += os.response.factors;
    vrOwner_Free(w->owner);
    w->owner = NULL;
}

/* the local owner of every pair; pairs settle from the poses at t unless a
 * body of theirs changed since the owners last heard */
static int make_serial_owner(vrWorld *w)
{
    vrParams p = vrWorld_Params(w);
    unsigned char *pending;
    int i, j, rc = 0;
    w->owner = vrOwner_Create();
    if (!w->owner) return -1;
    vrOwner_SetParams(w->owner, &p);
    for (i = 0; i < w->nobj; i++)
        if (w->obj[i] && w->obj[i]->live && vrOwner_HoldBody(w->owner, i, &w->obj[i]->body) != 0) return -1;
    if (!(pending = vrWorld_PendingMarks(w))) return -1;
    for (i = 0; i < w->nobj && rc == 0; i++)
        for (j = i + 1; j < w->nobj && rc == 0; j++) {
            if (!w->obj[i] || !w->obj[j] || !w->obj[i]->live || !w->obj[j]->live || !pairable(w, i, j)) continue;
            rc = vrOwner_AddPairAt(w->owner, i, j, w->t, pending[i] || pending[j]);
        }
    free(pending);
    return rc;
}

static const vrOwnerSet *owners(const vrWorld *w);

/* SPEC 1.4: the pairs of the bodies added or moved since the last start
 * that checked (every body at the first start; none owed: nothing to ask);
 * the other pairs were looked after by the run.  Serial and workers check
 * exactly these, so they agree whatever pairs their owners have flagged. */
static int report_overlaps(vrWorld *w, char *err, size_t n)
{
    int pairs[MAX_REPORTED_OVERLAPS][2], k, i, nids = 0;
    int *ids;
    size_t len;
    for (i = 0; i < w->nobj; i++)
        if (w->obj[i] && w->obj[i]->overlap_owed) break;
    if (i == w->nobj) return 0;
    ids = malloc((size_t)w->nobj * sizeof *ids);
    if (!ids) return fail_msg(err, n, "out of memory");
    for (i = 0; i < w->nobj; i++)
        if (w->obj[i] && w->obj[i]->live && w->obj[i]->overlap_owed) ids[nids++] = i;
    k = nids ? owners(w)->overlapping(w, VR_START_OVERLAP, ids, nids, pairs, MAX_REPORTED_OVERLAPS, err, n) : 0;
    free(ids);
    if (k < 0) return -1;
    if (k == 0) {
        for (i = 0; i < w->nobj; i++)
            if (w->obj[i]) w->obj[i]->overlap_owed = 0;
        return 0;
    }
    if (!err || !n) return -1;
    snprintf(err, n, "objects interpenetrate, not starting:");
    for (i = 0; i < k && i < MAX_REPORTED_OVERLAPS; i++) {
        len = strlen(err);
        snprintf(err + len, n - len, "%s %s and %s", i ? ";" : "", w->obj[pairs[i][0]]->name, w->obj[pairs[i][1]]->name);
    }
    if (k > MAX_REPORTED_OVERLAPS) {
        len = strlen(err);
        snprintf(err + len, n - len, "; and %d more pairs", k - MAX_REPORTED_OVERLAPS);
    }
    return -1;
}

int vrWorld_Ready(vrWorld *w, char *err, size_t n)
{
    int i;
    for (i = 0; i < w->nobj; i++)
        if (w->obj[i] && ready(w, w->obj[i], err, n) != 0) return -1;
    return 0;
}

void vrWorld_RetireSgp(vrWorld *w)
{
    vrStats st;
    memset(&st, 0, sizeof st);
    vrSgp_Stats(w->sgp, &st);
    w->retired.checks += st.checks;
    w->retired.heap_pops += st.heap_pops;
    w->retired.response.solves += st.klu_solves;
    w->retired.response.refactors += st.klu_refactors;
    w->retired.response.factors += st.klu_factors;
    vrSgp_Free(w->sgp);
    w->sgp = NULL;
}

/* serial or parallel, as the settings say */
static int choose_owners(vrWorld *w, char *err, size_t n)
{
    if (w->s.gps > 0) {
        if (w->owner) {
            retire_owner(w);
            w->structure++;
        }
        return vrSgp_Sync(w, err, n);
    }
    if (w->sgp) vrWorld_RetireSgp(w);
    if (!w->owner && make_serial_owner(w) != 0) return fail_msg(err, n, "out of memory");
    return 0;
}

int vrWorld_Start(vrWorld *w, char *err, size_t n)
{
    if (vrWorld_Ready(w, err, n) != 0 || make_live(w, err, n) != 0) return -1;
    if (w->params_dirty && apply_params(w) != 0) return fail_msg(err, n, "out of memory");
    if (choose_owners(w, err, n) != 0) return -1;
    if (report_overlaps(w, err, n) != 0) return -1;
    w->started = 1;
    return 0;
}

/* ---- updates ------------------------------------------------------------------------- */

static int note_changed(vrWorld *w, int id)
{
    if (vrGrow((void **)&w->changed, &w->changedcap, w->nchanged + 1, sizeof *w->changed) != 0) return -1;
    w->changed[w->nchanged++] = id;
    return 0;
}

int vrWorld_ApplyUpdate(vrWorld *w, vrUpdate *up)
{
    vrFlight f = vrWorld_Flight(w);
    int i;
    if (up->n == 0) return 0;
    if (vrRest_WakeDependents(w, up, up->body[0].t) != 0) return -1;
    for (i = 0; i < up->n; i++) {
        vrBodyState *st;
        vrObject *o = w->obj[up->body[i].id];
        vrBody_Apply(&o->body, &up->body[i], &f);
        st = vrUpdate_Body(&w->pending, &o->body, up->body[i].t);
        if (!st) return -1;
        *st = up->body[i];
    }
    return 0;
}

/* ---- the local owner ------------------------------------------------------------------ */

/* the owner hears of the bodies that changed since it last looked */
static int deliver(vrWorld *w)
{
    int i;
    w->nchanged = 0;
    for (i = 0; i < w->pending.n; i++)
        if (note_changed(w, w->pending.body[i].id) != 0) return -1;
    vrOwner_BodiesChanged(w->owner, w->changed, w->nchanged);
    w->pending.n = 0;
    return 0;
}

static int serial_first_event(vrWorld *w, const vrGrid *g, int allow, vrEvent *ev, char *err, size_t n)
{
    int r;
    if (deliver(w) != 0) return fail_msg(err, n, "out of memory");
    r = vrOwner_FirstEvent(w->owner, g, allow, ev);
    return r < 0 ? fail_msg(err, n, "out of memory") : r;
}

static int serial_respond(vrWorld *w, const vrEvent *ev, vrUpdate *up, char *err, size_t n)
{
    vrOwner_Advance(w->owner, ev->t);
    if (vrOwner_Respond(w->owner, ev, up) != 0) return fail_msg(err, n, "collision response: the linear solve failed");
    return 0;
}

static void serial_end_frame(vrWorld *w, double T) { vrOwner_Advance(w->owner, T); }

static int serial_overlapping(vrWorld *w, double tol, const int *ids, int nids, int (*out)[2], int max, char *err,
                              size_t n)
{
    int k;
    if (deliver(w) != 0) return fail_msg(err, n, "out of memory");
    k = vrOwner_Overlapping(w->owner, w->t, tol, ids, nids, out, max);
    return k < 0 ? fail_msg(err, n, "out of memory") : k;
}

static int serial_candidates(vrWorld *w, double T, const unsigned char *want, vrCandidates *out, char *err, size_t n)
{
    if (deliver(w) != 0 || vrOwner_SupportCandidates(w->owner, T, want, w->nobj, out) != 0)
        return fail_msg(err, n, "out of memory");
    return 0;
}

static const vrOwnerSet serial_owners = {serial_first_event, serial_respond, serial_end_frame, serial_overlapping,
                                         serial_candidates};

static const vrOwnerSet *owners(const vrWorld *w) { return w->s.gps > 0 ? &vrSgp_Owners : &serial_owners; }

/* Adds to w->update the state of every live body that id supports, and
 * lets fn change it (j: the support on id).  The update's records move
 * as it grows: take none before. */
static int update_supported_by(vrWorld *w, int id, void (*fn)(const vrWorld *w, vrBodyState *st, int j))
{
    int i, j;
    for (i = 0; i < w->nobj; i++) {
        vrObject *x = w->obj[i];
        vrBodyState *st;
        if (!x || i == id || !x->live) continue;
        for (j = 0; j < x->body.nsupport && x->body.support[j].partner != id; j++)
            ;
        if (j == x->body.nsupport) continue;
        st = vrUpdate_Body(&w->update, &x->body, w->t);
        if (!st) return -1;
        for (j = 0; j < st->nsupport && st->support[j].partner != id; j++)
            ;
        if (j < st->nsupport) fn(w, st, j);
    }
    return 0;
}

static void drop_support(const vrWorld *w, vrBodyState *st, int j)
{
    int partner = st->support[j].partner, k;
    (void)w;
    for (j = k = 0; j < st->nsupport; j++)
        if (st->support[j].partner != partner) st->support[k++] = st->support[j];
    st->nsupport = k;
    st->resting = 0;
}

/* a partner made static (or dynamic) by an edit: the support's `fixed`
 * (hold_to_supports in gp.c) follows, and a body resting on it wakes */
static void refix_support(const vrWorld *w, vrBodyState *st, int j)
{
    st->support[j].fixed = w->obj[st->support[j].partner]->body.is_static;
    st->resting = 0;
}

/* a definition edited while the simulation runs acts on the live body at
 * the world's time (the start of the next frame): a new shape or mass keeps
 * pose and velocities; an edited position or velocity replaces the current
 * one.  An edit wakes the body and what rests on it. */
static int apply_live_edit(vrWorld *w, vrObject *o, const vrObjectDef *old, char *err, size_t n)
{
    vrBodyState *st;
    vrPose pose;
    vec3 omega;
    int was_static = o->body.is_static;
    if (o->built && !motion_edited(old, &o->def)) {
        o->body.elasticity = o->def.elasticity;
        w->structure++;                  /* workers rebuild it with the new elasticity */
        return 0;
    }
    if (!o->built) w->structure++;
    o->overlap_owed = 1;
    vrBody_Pose(&o->body, w->t, &pose);
    omega = vrBody_Omega(&o->body, &pose);
    w->update.n = 0;
    st = vrUpdate_Body(&w->update, &o->body, w->t);
    if (!st) return fail_msg(err, n, "out of memory");
    if (!o->built && build(o, err, n) != 0) return -1;
    if (memcmp(old->translate, o->def.translate, sizeof old->translate) != 0) st->x = v3(o->def.translate);
    if (old->rotate_set != o->def.rotate_set || old->rotate_angle != o->def.rotate_angle
        || memcmp(old->rotate_axis, o->def.rotate_axis, sizeof old->rotate_axis) != 0)
        st->q = def_orientation(&o->def);
    if (memcmp(old->linear_vel, o->def.linear_vel, sizeof old->linear_vel) != 0) st->v = v3(o->def.linear_vel);
    if (memcmp(old->angular_vel, o->def.angular_vel, sizeof old->angular_vel) != 0) omega = v3(o->def.angular_vel);
    st->L = momentum_of(&o->body, st->q, omega);
    st->resting = 0;
    st->nsupport = 0;
    if (was_static != o->body.is_static) {
        if (w->owner) vrOwner_DropBody(w->owner, o->body.id);
        o->live = 0;
        if (make_live(w, err, n) != 0) return -1;
        if (update_supported_by(w, o->body.id, refix_support) != 0) return fail_msg(err, n, "out of memory");
    }
    return vrWorld_ApplyUpdate(w, &w->update) == 0 ? 0 : fail_msg(err, n, "out of memory");
}

static void drop_pending(vrWorld *w, int id)
{
    int i, k = 0;
    for (i = 0; i < w->pending.n; i++)
        if (w->pending.body[i].id != id) w->pending.body[k++] = w->pending.body[i];
    w->pending.n = k;
}

int vrWorld_DeleteObject(vrWorld *w, vrObjectId id)
{
    vrObject *o = vrWorld_Object(w, id);
    if (!o) return -1;
    if (o->live) {
        /* what rests on or slides over it loses that support */
        w->update.n = 0;
        if (update_supported_by(w, id, drop_support) != 0) return -1;
        if (w->owner) vrOwner_DropBody(w->owner, id);
        w->obj[id] = NULL;
        drop_pending(w, id);
        w->structure++;
        if (vrWorld_ApplyUpdate(w, &w->update) != 0) return -1;
    }
    w->obj[id] = NULL;
    free_object(o);
    return rebuild_dynamic_list(w);
}

/* ---- the frame loop -------------------------------------------------------------------- */

/* the grid of the span [ts, T] (SPEC 3.2) */
static void span_grid(const vrWorld *w, double ts, double T, const vrParams *p, vrGrid *g)
{
    if (!w->reach.valid || !(w->reach.T == T) || w->reach.n != w->ndyn) {
        vrSchedule_Grid(w->dyn, w->ndyn, ts, T, p->d, w->s.internal_step, &p->flight, g);
        return;
    }
    vrSchedule_GridFor(vrSchedule_NeedsReach(ts, T, w->s.internal_step) ? vrReach_Fastest(&w->reach, w->dyn, ts, &p->flight) : 0,
                       ts, T, p->d, w->s.internal_step, g);
}

/* the bodies an event changed have new reach bounds */
static void reach_changed(vrWorld *w, const vrUpdate *up, const vrParams *p)
{
    int k;
    for (k = 0; k < up->n; k++)
        if (up->body[k].id < w->ndyn_slot) vrReach_Changed(&w->reach, w->dyn, w->dyn_slot[up->body[k].id], up->body[k].t, &p->flight);
}

/* Runs [t, t + time_step]: ARCHITECTURE "the loop, once". */
static int run_frame(vrWorld *w, char *err, size_t n)
{
    double T = w->t_base + (double)(w->frames + 1 - w->frames_base) * w->s.time_step, ts = w->t;
    vrParams p = vrWorld_Params(w);
    /* the responses at the last instant so far: a frame ending at an
     * instant that had its VR_INSTANT_MAX does not give it more */
    double instant_t = w->instant_t;
    int instant = w->instant;
    w->subframes = 0;
    vrReach_Frame(&w->reach, w->dyn, w->ndyn, ts, T, &p.flight);
    for (;;) {
        vrGrid g;
        vrEvent ev;
        int r;
        span_grid(w, ts, T, &p, &g);
        r = owners(w)->first_event(w, &g, instant < VR_INSTANT_MAX, &ev, err, n);
        if (r == VR_RESTART_FRAME) goto restart;
        if (r < 0) return -1;
        if (r == 0) {
            w->update.n = 0;
            r = vrRest_SeveralSupports(w, T, owners(w), &w->update, err, n);
            if (r == VR_RESTART_FRAME) goto restart;
            if (r != 0 || vrWorld_ApplyUpdate(w, &w->update) != 0) return -1;
            owners(w)->end_frame(w, T);
            w->subframes += g.n;
            break;
        }
        w->subframes += ev.t > ts ? vrSchedule_FirstPointAtOrAfter(&g, ev.t) : 0;
        w->update.n = 0;
        r = owners(w)->respond(w, &ev, &w->update, err, n);
        if (r == VR_RESTART_FRAME) goto restart;
        if (r != 0) return -1;
        if (ev.kind == VR_EV_IMPACT || ev.kind == VR_EV_CONTACT) w->collisions++;
        if (vrWorld_ApplyUpdate(w, &w->update) != 0) return fail_msg(err, n, "out of memory");
        reach_changed(w, &w->update, &p);
        instant = ev.t == instant_t ? instant + 1 : 1;
        instant_t = ev.t;
        ts = ev.t;
        continue;
    restart:                 /* a worker died: the frame again from its start */
        ts = w->t;
        vrReach_Frame(&w->reach, w->dyn, w->ndyn, ts, T, &p.flight);
        instant = w->instant;
        instant_t = w->instant_t;
        w->subframes = 0;
    }
    w->t = T;
    w->frames++;
    w->instant = instant;
    w->instant_t = instant_t;
    w->update.n = 0;
    if (vrRest_FrameEnd(w, &w->update) != 0 || vrWorld_ApplyUpdate(w, &w->update) != 0)
        return fail_msg(err, n, "out of memory");
    vrRest_RememberFramePoses(w);
    return 0;
}

int vrWorld_Step(vrWorld *w, long frames, char *err, size_t n)
{
    long f;
    for (f = 0; f < frames; f++) {
        double t0;
        if (vrWorld_Start(w, err, n) != 0) return -1;
        t0 = now_ms();
        if (run_frame(w, err, n) != 0) return -1;
        w->frame_ms = now_ms() - t0;
        w->sim_ms += w->frame_ms;
    }
    return 0;
}

int vrWorld_AllAtRest(const vrWorld *w)
{
    int i;
    for (i = 0; i < w->nobj; i++) {
        const vrObject *o = w->obj[i];
        if (o && !o->body.is_static && !(o->live && o->body.resting)) return 0;
    }
    return 1;
}

/* ---- state ------------------------------------------------------------------------------ */

static vrMotionState motion_state(const vrBody *b)
{
    if (b->is_static) return VR_STATE_STATIC;
    if (b->resting) return VR_STATE_REST;
    return b->nsupport > 0 ? VR_STATE_SUPPORTED : VR_STATE_MOVING;
}

int vrWorld_GetObjectState(const vrWorld *cw, vrObjectId id, vrObjectState *st)
{
    vrWorld *w = (vrWorld *)cw;   /* pose queries advance the rotation cache */
    vrObject *o = vrWorld_Object(w, id);
    vrPose p;
    vec3 v, om;
    quat q;
    if (!o || ready(w, o, NULL, 0) != 0) return -1;
    vrBody_Pose(&o->body, w->t, &p);
    vrBody_Velocity(&o->body, w->t, &v);
    om = vrBody_Omega(&o->body, &p);
    q = quat_canonical(p.q);
    st->t = w->t;
    st->position[0] = p.p.x; st->position[1] = p.p.y; st->position[2] = p.p.z;
    st->orientation[0] = q.w; st->orientation[1] = q.x; st->orientation[2] = q.y; st->orientation[3] = q.z;
    st->linear_vel[0] = v.x; st->linear_vel[1] = v.y; st->linear_vel[2] = v.z;
    st->angular_vel[0] = om.x; st->angular_vel[1] = om.y; st->angular_vel[2] = om.z;
    st->state = motion_state(&o->body);
    return 0;
}

int vrWorld_GetMesh(vrWorld *w, vrObjectId id, vrMesh *m)
{
    vrObject *o = vrWorld_Object(w, id);
    if (!o || ready(w, o, NULL, 0) != 0) return -1;
    m->nverts = o->poly->nv;
    m->verts = o->draw_verts;
    m->normals = o->draw_normals;
    m->nfaces = o->poly->nf;
    m->face_start = o->draw_face_start;
    m->face_verts = o->draw_face_verts;
    m->smooth = o->def.type == VR_SPHERE || o->def.type == VR_SUPERQUADRIC;
    return 0;
}

void vrWorld_NoteRenderTime(vrWorld *w, double ms) { w->render_ms += ms; }

void vrWorld_GetStats(const vrWorld *cw, vrStats *st)
{
    vrWorld *w = (vrWorld *)cw;
    int i;
    memset(st, 0, sizeof *st);
    st->frames = w->frames;
    st->time = w->t;
    for (i = 0; i < w->nobj; i++) {
        vrObject *o = w->obj[i];
        if (!o) continue;
        st->objects++;
        if (def_mass(&o->def) > 0) st->dynamic++;
        if (o->live && o->body.resting) st->resting++;
        if (def_mass(&o->def) > 0 && ready(w, o, NULL, 0) == 0)
            st->energy += vrBody_Energy(&o->body, w->t, vrWorld_Flight(w).accel);
    }
    /* SPEC 1.3: dynamic-dynamic plus dynamic-static pairs */
    st->pairs = (long)st->dynamic * (st->dynamic - 1) / 2 + (long)st->dynamic * (st->objects - st->dynamic);
    st->subframes = w->subframes;
    st->subframes_thesis = (long)ceil(w->s.time_step * 2.0 * w->s.max_linear / w->s.collision_dist);
    st->checks = w->retired.checks;
    st->heap_pops = w->retired.heap_pops;
    st->klu_solves = w->retired.response.solves;
    st->klu_refactors = w->retired.response.refactors;
    st->klu_factors = w->retired.response.factors;
    if (w->owner) {
        vrOwnerStats os;
        vrOwner_Stats(w->owner, &os);
        st->checks += os.checks;
        st->heap_pops += os.heap_pops;
        st->klu_solves += os.response.solves;
        st->klu_refactors += os.response.refactors;
        st->klu_factors += os.response.factors;
    }
    if (w->sgp) vrSgp_Stats(w->sgp, st);
    st->collisions = w->collisions;
    st->frame_ms = w->frame_ms;
    st->sim_ms = w->sim_ms;
    st->render_ms = w->render_ms;
}
