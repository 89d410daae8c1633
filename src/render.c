/* render.c — the render module (vroc-render.so): OSMesa stereo frames.
 *
 * SPEC 4 and thesis 3.4.1: one view per eye from matrices the caller
 * computed; flat or Gouraud shading under a headlight (ambient 0.2 +
 * diffuse 0.8, no specular), depth test, black background.  Lighting is
 * computed here on the CPU, in world space, once per frame: the light is
 * the same for both eyes, a face toward it shows exactly its colour, and
 * the bytes do not depend on the GL's lighting code.  All objects go into
 * one vertex buffer in world coordinates, uploaded once and drawn twice
 * (one draw call per eye and style): the cost per frame is a few calls,
 * not a few per object.
 *
 * Built alone (render.c + render.h) with -lOSMesa and dlopen()ed by
 * display.c; see render.h for the contract.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render.h"

/* one vertex as the GL reads it: world position and lit colour */
typedef struct Vertex {
    float pos[3];
    unsigned char rgba[4];
} Vertex;

/* growable arrays: `n` used, `cap` allocated */
typedef struct VertexArray { Vertex *v; size_t n, cap; } VertexArray;
typedef struct IndexArray { GLuint *v; size_t n, cap; } IndexArray;

struct vrRenderContext {
    OSMesaContext gl;
    unsigned char *rgba;       /* the colour buffer OSMesa draws into */
    int width, height;
    GLuint buffers[2];         /* vertex buffer, index buffer */
    VertexArray verts;
    IndexArray solid, phantom, lines;   /* triangles, triangles, line pairs */
    char renderer[128];
};

enum { FRAME_MAX_VERTS = 0x7fffffff };

/* ---- growable arrays --------------------------------------------------- */
static int grow(void **p, size_t *cap, size_t need, size_t elem)
{
    size_t c = *cap ? *cap : 1024;
    void *q;
    if (need <= *cap) return 0;
    while (c < need) {
        if (c > SIZE_MAX / 2 / elem) return -1;
        c *= 2;
    }
    q = realloc(*p, c * elem);
    if (!q) return -1;
    *p = q;
    *cap = c;
    return 0;
}

static int reserve_verts(VertexArray *a, size_t more)
{
    return grow((void **)&a->v, &a->cap, a->n + more, sizeof *a->v);
}

static int reserve_index(IndexArray *a, size_t more)
{
    return grow((void **)&a->v, &a->cap, a->n + more, sizeof *a->v);
}

/* ---- geometry ---------------------------------------------------------- */
/* p' = M p for a column-major rigid matrix; w = 0 rotates only (normals) */
static void transform(const double m[16], const double p[3], double w, double out[3])
{
    int i;
    for (i = 0; i < 3; i++)
        out[i] = m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i] * w;
}

static unsigned char shade(unsigned char c, double intensity)
{
    double v = floor(c * intensity + 0.5);
    return (unsigned char)(v > 255 ? 255 : v < 0 ? 0 : v);
}

/* headlight: ambient + diffuse * cos(angle to the light), back faces ambient */
static double lighting(const double n[3], const double light[3])
{
    double c = n[0] * light[0] + n[1] * light[1] + n[2] * light[2];
    return VR_RENDER_AMBIENT + VR_RENDER_DIFFUSE * (c > 0 ? c : 0);
}

static void set_vertex(Vertex *v, const double p[3], const unsigned char rgb[3], double intensity)
{
    int i;
    for (i = 0; i < 3; i++) {
        v->pos[i] = (float)p[i];
        v->rgba[i] = shade(rgb[i], intensity);
    }
    v->rgba[3] = 255;
}

/* Newell's method: robust for any planar polygon, needs no particular
 * three vertices to be non-collinear */
static void face_normal(const vrRenderObject *o, int f, double n[3])
{
    int a = o->face_start[f], b = o->face_start[f + 1], k;
    double len, body[3] = {0, 0, 0};
    for (k = a; k < b; k++) {
        const double *p = o->verts + 3 * o->face_verts[k];
        const double *q = o->verts + 3 * o->face_verts[k + 1 < b ? k + 1 : a];
        body[0] += (p[1] - q[1]) * (p[2] + q[2]);
        body[1] += (p[2] - q[2]) * (p[0] + q[0]);
        body[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    len = sqrt(body[0] * body[0] + body[1] * body[1] + body[2] * body[2]);
    if (len > 0) for (k = 0; k < 3; k++) body[k] /= len;
    transform(o->model, body, 0, n);
}

/* a convex polygon as a fan of triangles: corner k is vertex base + idx[k],
 * or base + k when idx is NULL */
static void add_fan(IndexArray *a, GLuint base, const int *idx, int count)
{
    int k, j;
    for (k = 0; k + 2 < count; k++) {
        int corner[3];
        corner[0] = 0, corner[1] = k + 1, corner[2] = k + 2;
        for (j = 0; j < 3; j++)
            a->v[a->n++] = base + (GLuint)(idx ? idx[corner[j]] : corner[j]);
    }
}

static size_t corner_count(const vrRenderObject *o)
{
    return o->nfaces ? (size_t)o->face_start[o->nfaces] : 0;
}

static int check_object(const vrRenderObject *o, char *err, size_t errlen)
{
    int k;
    if (o->nverts < 0 || o->nfaces < 0 || (o->nverts && !o->verts) ||
        (o->nfaces && (!o->face_start || !o->face_verts || o->face_start[0] != 0)) ||
        (o->smooth && o->nverts && !o->normals)) {
        vrRender_Error(err, errlen, "render: malformed mesh");
        return -1;
    }
    for (k = 0; k < o->nfaces; k++)
        if (o->face_start[k + 1] - o->face_start[k] < 3) {
            vrRender_Error(err, errlen, "render: a face with fewer than 3 vertices");
            return -1;
        }
    for (k = 0; k < (int)corner_count(o); k++)
        if (o->face_verts[k] < 0 || o->face_verts[k] >= o->nverts) {
            vrRender_Error(err, errlen, "render: face vertex index out of range");
            return -1;
        }
    return 0;
}

/* shared vertices: smooth shading, or the edges and depth of a real object */
static void add_shared_verts(VertexArray *va, const vrRenderObject *o, const double light[3])
{
    int i;
    for (i = 0; i < o->nverts; i++) {
        double p[3], n[3];
        transform(o->model, o->verts + 3 * i, 1, p);
        if (o->style == VR_STYLE_SOLID) {
            transform(o->model, o->normals + 3 * i, 0, n);
            set_vertex(&va->v[va->n + i], p, o->color, lighting(n, light));
        } else {
            set_vertex(&va->v[va->n + i], p, o->color, 1.0);   /* lines: unlit colour */
        }
    }
}

static void add_shared_polys(vrRenderContext *c, const vrRenderObject *o, GLuint base)
{
    IndexArray *tris = o->style == VR_STYLE_SOLID ? &c->solid : &c->phantom;
    int f, k;
    for (f = 0; f < o->nfaces; f++) {
        const int *fv = o->face_verts + o->face_start[f];
        int count = o->face_start[f + 1] - o->face_start[f];
        add_fan(tris, base, fv, count);
        if (o->style != VR_STYLE_WIRE) continue;
        for (k = 0; k < count; k++) {
            c->lines.v[c->lines.n++] = base + (GLuint)fv[k];
            c->lines.v[c->lines.n++] = base + (GLuint)fv[(k + 1) % count];
        }
    }
}

/* flat shading: every face gets its own vertices, lit by the face normal */
static void add_flat_faces(vrRenderContext *c, const vrRenderObject *o, const double light[3])
{
    int f, k;
    for (f = 0; f < o->nfaces; f++) {
        int a = o->face_start[f], count = o->face_start[f + 1] - a;
        GLuint base = (GLuint)c->verts.n;
        double n[3], intensity;
        face_normal(o, f, n);
        intensity = lighting(n, light);
        for (k = 0; k < count; k++) {
            double p[3];
            transform(o->model, o->verts + 3 * o->face_verts[a + k], 1, p);
            set_vertex(&c->verts.v[c->verts.n++], p, o->color, intensity);
        }
        add_fan(&c->solid, base, NULL, count);
    }
}

static int add_object(vrRenderContext *c, const vrRenderObject *o, const double light[3],
                      char *err, size_t errlen)
{
    size_t corners = corner_count(o), nv = corners > (size_t)o->nverts ? corners : (size_t)o->nverts;
    if (check_object(o, err, errlen)) return -1;
    if (c->verts.n + nv > FRAME_MAX_VERTS || reserve_verts(&c->verts, nv) ||
        reserve_index(&c->solid, 3 * corners) || reserve_index(&c->phantom, 3 * corners) ||
        reserve_index(&c->lines, 2 * corners)) {
        vrRender_Error(err, errlen, "render: out of memory for the scene's vertices");
        return -1;
    }
    if (o->style == VR_STYLE_SOLID && !o->smooth) {
        add_flat_faces(c, o, light);
    } else {
        GLuint base = (GLuint)c->verts.n;
        add_shared_verts(&c->verts, o, light);
        c->verts.n += (size_t)o->nverts;
        add_shared_polys(c, o, base);
    }
    return 0;
}

static int build_scene(vrRenderContext *c, const vrRenderFrame *f, char *err, size_t errlen)
{
    int i;
    c->verts.n = c->solid.n = c->phantom.n = c->lines.n = 0;
    for (i = 0; i < f->nobjects; i++)
        if (add_object(c, &f->objects[i], f->light, err, errlen)) return -1;
    return 0;
}

/* ---- GL ------------------------------------------------------------------ */
static void setup_state(vrRenderContext *c)
{
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);      /* edges drawn over their own depth-only faces */
    glDisable(GL_LIGHTING);      /* lit on the CPU, see the top of the file */
    glDisable(GL_DITHER);        /* exact colours */
    glShadeModel(GL_SMOOTH);
    glEnable(GL_CULL_FACE);      /* closed convex polyhedra: back faces never show */
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glPolygonOffset(1.0f, 1.0f); /* depth-only faces lie just behind their edges */
    glClearColor(0, 0, 0, 1);
    glClearDepth(1.0);
    glGenBuffers(2, c->buffers);
    glBindBuffer(GL_ARRAY_BUFFER, c->buffers[0]);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, c->buffers[1]);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
}

/* makes c current on a colour buffer of this size (several displays may
 * take turns); OSMesa resizes its depth buffer to match */
static int bind_buffer(vrRenderContext *c, int width, int height, char *err, size_t errlen)
{
    if (c->width != width || c->height != height) {
        unsigned char *p = realloc(c->rgba, (size_t)width * (size_t)height * 4);
        if (!p) {
            vrRender_Error(err, errlen, "render: out of memory for a %dx%d frame", width, height);
            return -1;
        }
        c->rgba = p;
        c->width = c->height = 0;   /* bound to nothing until MakeCurrent succeeds */
    } else if (OSMesaGetCurrentContext() == c->gl) {
        return 0;
    }
    if (!OSMesaMakeCurrent(c->gl, c->rgba, GL_UNSIGNED_BYTE, width, height)) {
        vrRender_Error(err, errlen, "render: OSMesa cannot draw a %dx%d frame", width, height);
        return -1;
    }
    OSMesaPixelStore(OSMESA_Y_UP, 0);    /* row 0 is the top, as in a PPM */
    c->width = width, c->height = height;
    return 0;
}

static vrRenderContext *create(char *err, size_t errlen)
{
    vrRenderContext *c = calloc(1, sizeof *c);
    const char *name;
    if (!c) {
        vrRender_Error(err, errlen, "render: out of memory");
        return NULL;
    }
    c->gl = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!c->gl) {
        vrRender_Error(err, errlen, "render: OSMesaCreateContextExt (RGBA, 24-bit depth) failed");
        free(c);
        return NULL;
    }
    if (bind_buffer(c, 16, 16, err, errlen)) {
        OSMesaDestroyContext(c->gl);
        free(c->rgba);
        free(c);
        return NULL;
    }
    name = (const char *)glGetString(GL_RENDERER);
    snprintf(c->renderer, sizeof c->renderer, "%s", name ? name : "unknown");
    setup_state(c);
    return c;
}

static void destroy(vrRenderContext *c)
{
    if (!c) return;
    if (c->width && bind_buffer(c, c->width, c->height, NULL, 0) == 0)
        glDeleteBuffers(2, c->buffers);     /* never into another display's context */
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(c->gl);
    free(c->rgba);
    free(c->verts.v);
    free(c->solid.v);
    free(c->phantom.v);
    free(c->lines.v);
    free(c);
}

static const char *renderer_name(const vrRenderContext *c)
{
    return c ? c->renderer : "";
}

/* the three index lists go one after the other into the index buffer */
static void upload(const vrRenderContext *c)
{
    size_t isz = sizeof(GLuint), tri = c->solid.n * isz, ph = c->phantom.n * isz;
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(c->verts.n * sizeof(Vertex)), c->verts.v, GL_STREAM_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(tri + ph + c->lines.n * isz), NULL, GL_STREAM_DRAW);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, (GLsizeiptr)tri, c->solid.v);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, (GLintptr)tri, (GLsizeiptr)ph, c->phantom.v);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, (GLintptr)(tri + ph), (GLsizeiptr)(c->lines.n * isz), c->lines.v);
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), (const void *)offsetof(Vertex, pos));
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), (const void *)offsetof(Vertex, rgba));
}

static void draw_range(GLenum mode, size_t first, size_t count)
{
    if (count)
        glDrawElements(mode, (GLsizei)count, GL_UNSIGNED_INT, (const void *)(first * sizeof(GLuint)));
}

static void draw_eye(const vrRenderContext *c, const vrRenderFrame *f, int eye)
{
    glViewport(0, 0, f->width, f->height);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(f->proj[eye]);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(f->view[eye]);
    /* real objects first, depth only: they hide what is behind them (as the
     * real object does in a see-through display) but show nothing */
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    draw_range(GL_TRIANGLES, c->solid.n, c->phantom.n);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    draw_range(GL_TRIANGLES, 0, c->solid.n);
    draw_range(GL_LINES, c->solid.n + c->phantom.n, c->lines.n);
    glFinish();                  /* OSMesa's buffer is complete only now */
}

static void rgba_to_rgb(const unsigned char *src, unsigned char *dst, size_t pixels)
{
    size_t i;
    for (i = 0; i < pixels; i++) {
        dst[3 * i] = src[4 * i];
        dst[3 * i + 1] = src[4 * i + 1];
        dst[3 * i + 2] = src[4 * i + 2];
    }
}

static int render(vrRenderContext *c, const vrRenderFrame *f, unsigned char *rgb[2],
                  char *err, size_t errlen)
{
    int eye;
    if (f->width < 1 || f->height < 1 || f->nobjects < 0 || (f->nobjects && !f->objects)) {
        vrRender_Error(err, errlen, "render: bad frame (%dx%d, %d objects)", f->width, f->height, f->nobjects);
        return -1;
    }
    if (bind_buffer(c, f->width, f->height, err, errlen) || build_scene(c, f, err, errlen))
        return -1;
    upload(c);
    for (eye = 0; eye < 2; eye++) {
        draw_eye(c, f, eye);
        rgba_to_rgb(c->rgba, rgb[eye], (size_t)f->width * (size_t)f->height);
    }
    if (glGetError() != GL_NO_ERROR) {
        vrRender_Error(err, errlen, "render: OpenGL error while drawing");
        return -1;
    }
    return 0;
}

/* the module's one export (render.h) */
const vrRenderApi vroc_render_api = {VR_RENDER_ABI, create, destroy, render, renderer_name};
