/* display.c — the library side of the display (SPEC 4, thesis 3.4.1).
 *
 * The head pose becomes two eyes, each with an off-axis frustum; the world
 * becomes a list of meshes with body-to-world matrices; the render module
 * (render.h) draws them; the pixels are written as binary PPM.  No OSMesa
 * symbol is referenced here: the module is dlopen()ed on the first
 * vrDisplay_Open, so that a run without a display never loads OSMesa and
 * the LLVM it pulls in (a cost at every process start).
 *
 * Where the module is looked for: module.h.
 */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "vroc.h"
#include "vec.h"
#include "render.h"
#include "image.h"
#include "module.h"
#include "panel_draw.h"

#define MODULE_FILE "vroc-render.so"
#define RES_MIN 16
#define RES_MAX 8192

struct vrDisplay {
    const vrRenderApi *api;
    vrRenderContext *ctx;
    unsigned char *pixels[2];  /* RGB, eye 0 left, 1 right */
    int width, height;         /* of the last successful render; 0: none */
    vrRenderObject *objects;   /* scratch for the scene handed to the module */
    int objects_cap;
    vrObjectId *ids;
    vrPanelParts panel;        /* the tool panel's boxes (SPEC 8), drawn after the objects */
};

/* ---- the module ---------------------------------------------------------- */
static const vrRenderApi *module_api;    /* loaded once per process */

static int load_module(char *err, size_t errlen)
{
    const vrRenderApi *api;
    if (module_api) return 0;
    api = vrModule_Load("render module", MODULE_FILE, "VROC_RENDER_MODULE", VR_RENDER_SYMBOL, err, errlen);
    if (api && api->abi != VR_RENDER_ABI) {
        vrRender_Error(err, errlen, "the render module " MODULE_FILE " is another interface version; rebuild it");
        api = NULL;
    }
    module_api = api;
    return api ? 0 : -1;
}

/* ---- open and close ------------------------------------------------------ */
vrView vrView_Default(void)
{
    vrView v;
    memset(&v, 0, sizeof v);
    v.width = 640, v.height = 512;   /* the HP-750's (thesis 5.2) */
    v.eye[1] = -8, v.eye[2] = 3;
    v.look[2] = 1;
    v.up[2] = 1;
    v.ipd = 0.064;
    v.focal = 0;
    v.fov = 45;
    v.see_through = 0;
    return v;
}

int vrDisplay_Open(vrDisplay **out, char *err, size_t errlen)
{
    vrDisplay *d;
    *out = NULL;
    if (load_module(err, errlen)) return -1;
    d = calloc(1, sizeof *d);
    if (!d) {
        vrRender_Error(err, errlen, "out of memory");
        return -1;
    }
    d->api = module_api;
    d->ctx = d->api->create(err, errlen);
    if (!d->ctx) {
        free(d);
        return -1;
    }
    *out = d;
    return 0;
}

void vrDisplay_Close(vrDisplay *d)
{
    if (!d) return;
    d->api->destroy(d->ctx);
    free(d->pixels[0]);
    free(d->pixels[1]);
    free(d->objects);
    free(d->ids);
    free(d);
}

const char *vrDisplay_RendererName(const vrDisplay *d)
{
    return d ? d->api->renderer_name(d->ctx) : "";
}

const unsigned char *vrDisplay_Pixels(const vrDisplay *d, int eye, int *width, int *height)
{
    if (width) *width = d && d->width ? d->width : 0;
    if (height) *height = d && d->width ? d->height : 0;
    if (!d || !d->width || eye < 0 || eye > 1) return NULL;
    return d->pixels[eye];
}

/* ---- the view ------------------------------------------------------------ */
static int vec_finite(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

static int check_view(const vrView *v, char *err, size_t errlen)
{
    vec3 f = vec3_sub(vec3_make(v->look[0], v->look[1], v->look[2]),
                      vec3_make(v->eye[0], v->eye[1], v->eye[2]));
    vec3 up = vec3_make(v->up[0], v->up[1], v->up[2]);
    const char *bad = NULL;
    if (v->width < RES_MIN || v->width > RES_MAX || v->height < RES_MIN || v->height > RES_MAX) {
        vrRender_Error(err, errlen, "resolution %dx%d out of range (%d..%d each)", v->width, v->height,
                RES_MIN, RES_MAX);
        return -1;
    }
    if (!vec_finite(v->eye) || !vec_finite(v->look) || !vec_finite(v->up)) bad = "eye, look and up must be finite";
    else if (vec3_len(f) == 0) bad = "look must differ from eye";
    else if (vec3_len(vec3_cross(f, up)) <= 1e-9 * vec3_len(f) * vec3_len(up)) bad = "up must not be parallel to look - eye";
    else if (!(v->ipd >= 0) || !isfinite(v->ipd)) bad = "ipd must be finite and >= 0";
    else if (!(v->focal >= 0) || !isfinite(v->focal)) bad = "focal must be finite and >= 0 (0: |look - eye|)";
    else if (!(v->fov >= 10 && v->fov <= 120)) bad = "fov out of range (10..120 degrees)";
    else if (v->see_through < 0 || v->see_through > 2) bad = "see_through must be 0, 1 or 2";
    if (bad) vrRender_Error(err, errlen, "%s", bad);
    return bad ? -1 : 0;
}

/* world to eye, column-major: the eye at p looking along f, r right, u up */
static void look_matrix(vec3 p, vec3 r, vec3 u, vec3 f, double m[16])
{
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = r.x, m[4] = r.y, m[8] = r.z, m[12] = -vec3_dot(r, p);
    m[1] = u.x, m[5] = u.y, m[9] = u.z, m[13] = -vec3_dot(u, p);
    m[2] = -f.x, m[6] = -f.y, m[10] = -f.z, m[14] = vec3_dot(f, p);
    m[15] = 1;
}

/* glFrustum's matrix, column-major */
static void frustum(double l, double r, double b, double t, double n, double f, double m[16])
{
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = 2 * n / (r - l);
    m[5] = 2 * n / (t - b);
    m[8] = (r + l) / (r - l);
    m[9] = (t + b) / (t - b);
    m[10] = -(f + n) / (f - n);
    m[11] = -1;
    m[14] = -2 * f * n / (f - n);
}

/* SPEC 4: the eyes ipd apart along the head's right axis, axes parallel,
 * each frustum shifted so that both frame the same window at the focal
 * distance (off-axis stereo): a point nearer than that window lands further
 * right in the left eye (crossed disparity), one beyond it further left. */
static void stereo_eyes(const vrView *v, vrRenderFrame *fr)
{
    vec3 eye = vec3_make(v->eye[0], v->eye[1], v->eye[2]);
    vec3 to = vec3_sub(vec3_make(v->look[0], v->look[1], v->look[2]), eye);
    vec3 f = vec3_normalize(to);
    vec3 r = vec3_normalize(vec3_cross(f, vec3_make(v->up[0], v->up[1], v->up[2])));
    vec3 u = vec3_cross(r, f);
    double focal = v->focal > 0 ? v->focal : vec3_len(to);
    double n = VR_RENDER_NEAR, top = n * tan(v->fov * VR_PI / 360.0);
    double half_w = top * v->width / v->height;
    int e;
    for (e = 0; e < 2; e++) {
        double side = e == 0 ? -0.5 : 0.5;           /* left eye at -ipd/2 */
        double shift = -side * v->ipd * n / focal;   /* window centre, at the near plane */
        look_matrix(vec3_madd(eye, side * v->ipd, r), r, u, f, fr->view[e]);
        frustum(-half_w + shift, half_w + shift, -top, top, n, VR_RENDER_FAR, fr->proj[e]);
    }
    /* the headlight shines along the line of sight, the same for both eyes */
    fr->light[0] = -f.x, fr->light[1] = -f.y, fr->light[2] = -f.z;
}

/* ---- the scene ----------------------------------------------------------- */
static void pose_matrix(const vrObjectState *st, double m[16])
{
    mat33 R = mat33_from_quat(quat_make(st->orientation[0], st->orientation[1],
                                        st->orientation[2], st->orientation[3]));
    int i, j;
    for (j = 0; j < 3; j++)
        for (i = 0; i < 3; i++) m[4 * j + i] = R.m[i][j];
    m[3] = m[7] = m[11] = 0;
    for (i = 0; i < 3; i++) m[12 + i] = st->position[i];
    m[15] = 1;
}

static int reserve_objects(vrDisplay *d, int n)
{
    vrRenderObject *o;
    vrObjectId *ids;
    int cap = d->objects_cap ? d->objects_cap : 64;
    if (n <= d->objects_cap) return 0;
    while (cap < n) cap *= 2;
    o = realloc(d->objects, (size_t)cap * sizeof *o);
    if (o) d->objects = o;
    ids = realloc(d->ids, (size_t)cap * sizeof *ids);
    if (ids) d->ids = ids;
    if (!o || !ids) return -1;
    d->objects_cap = cap;
    return 0;
}

static vrRenderStyle style_of(const vrObjectDef *def, int see_through)
{
    if (!def->real || see_through == 0) return VR_STYLE_SOLID;
    return see_through == 1 ? VR_STYLE_WIRE : VR_STYLE_PHANTOM;
}

static int describe_object(vrWorld *w, vrObjectId id, int see_through, vrRenderObject *o)
{
    vrObjectDef def;
    vrObjectState st;
    vrMesh mesh;
    int i;
    if (vrWorld_GetObjectDef(w, id, &def) || vrWorld_GetObjectState(w, id, &st) ||
        vrWorld_GetMesh(w, id, &mesh))
        return -1;
    o->nverts = mesh.nverts, o->verts = mesh.verts, o->normals = mesh.normals;
    o->nfaces = mesh.nfaces, o->face_start = mesh.face_start, o->face_verts = mesh.face_verts;
    o->smooth = mesh.smooth;
    pose_matrix(&st, o->model);
    for (i = 0; i < 3; i++) o->color[i] = (unsigned char)def.color[i];
    o->style = style_of(&def, see_through);
    return 0;
}

static int gather_scene(vrDisplay *d, vrWorld *w, int see_through, vrRenderFrame *fr,
                        char *err, size_t errlen)
{
    int n = vrWorld_ObjectCount(w), i;
    if (reserve_objects(d, n + VR_PANEL_PARTS)) {
        vrRender_Error(err, errlen, "out of memory for %d objects", n);
        return -1;
    }
    n = vrWorld_ObjectList(w, d->ids, n);
    for (i = 0; i < n; i++)
        if (describe_object(w, d->ids[i], see_through, &d->objects[i])) {
            vrRender_Error(err, errlen, "cannot draw object '%s'", vrWorld_ObjectName(w, d->ids[i]));
            return -1;
        }
    fr->nobjects = n + vrPanelDraw_Parts(w, &d->panel, d->objects + n);
    fr->objects = d->objects;
    return 0;
}

/* ---- render -------------------------------------------------------------- */
static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static int size_pixels(vrDisplay *d, int width, int height, char *err, size_t errlen)
{
    size_t bytes = (size_t)width * (size_t)height * 3;
    int e;
    if (d->width == width && d->height == height) return 0;
    d->width = d->height = 0;
    for (e = 0; e < 2; e++) {
        unsigned char *p = realloc(d->pixels[e], bytes);
        if (!p) {
            vrRender_Error(err, errlen, "out of memory for %dx%d frames", width, height);
            return -1;
        }
        d->pixels[e] = p;
    }
    return 0;
}

int vrDisplay_Render(vrDisplay *d, vrWorld *w, const vrView *view, char *err, size_t errlen)
{
    double start = now_ms();
    vrRenderFrame fr;
    if (check_view(view, err, errlen) || size_pixels(d, view->width, view->height, err, errlen))
        return -1;
    d->width = d->height = 0;          /* no valid frame until this one is complete */
    memset(&fr, 0, sizeof fr);
    fr.width = view->width, fr.height = view->height;
    stereo_eyes(view, &fr);
    if (gather_scene(d, w, view->see_through, &fr, err, errlen) ||
        d->api->render(d->ctx, &fr, d->pixels, err, errlen))
        return -1;
    d->width = view->width, d->height = view->height;
    vrWorld_NoteRenderTime(w, now_ms() - start);
    return 0;
}

/* ---- frame files --------------------------------------------------------- */
/* mkdir -p: every missing folder of the path, each an error if it cannot be made */
static int make_dirs(const char *dir, char *err, size_t errlen)
{
    char path[4096];
    size_t i, len = strlen(dir);
    struct stat sb;
    if (len == 0 || len >= sizeof path) {
        vrRender_Error(err, errlen, "bad frames folder '%s'", dir);
        return -1;
    }
    memcpy(path, dir, len + 1);
    for (i = 1; i <= len; i++) {
        if (path[i] != '/' && path[i] != '\0') continue;
        path[i] = '\0';
        if (mkdir(path, 0777) != 0 && (errno != EEXIST || stat(path, &sb) != 0 || !S_ISDIR(sb.st_mode))) {
            vrRender_Error(err, errlen, "cannot create frames folder '%s': %s", path,
                    errno == EEXIST ? "not a folder" : strerror(errno));
            return -1;
        }
        path[i] = dir[i];
    }
    return 0;
}

int vrDisplay_WriteFrames(const vrDisplay *d, const char *dir, long frame, vrFrameFormat format,
                          char *err, size_t errlen)
{
    static const char *const side[2] = {"left", "right"};
    const char *ext = format == VR_FRAMES_PNG ? "png" : "ppm";
    char path[4200];
    int e;
    if (!d || !d->width) {
        vrRender_Error(err, errlen, "no frame rendered yet");
        return -1;
    }
    if (frame < 0) {
        vrRender_Error(err, errlen, "bad frame number %ld", frame);
        return -1;
    }
    if (make_dirs(dir, err, errlen)) return -1;
    for (e = 0; e < 2; e++) {
        if ((size_t)snprintf(path, sizeof path, "%s/frame-%06ld-%s.%s", dir, frame, side[e], ext) >= sizeof path) {
            vrRender_Error(err, errlen, "frames folder path too long");
            return -1;
        }
        if ((format == VR_FRAMES_PNG ? vrImage_WritePNG : vrImage_WritePPM)(path, d->pixels[e], d->width,
                                                                            d->height, err, errlen))
            return -1;
    }
    return 0;
}
