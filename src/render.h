/* render.h — the interface between the library and the render module.
 *
 * The module (vroc-render.so, built from render.c alone) is the only code
 * that touches OSMesa; the library (display.c) dlopen()s it on first use, so
 * a run that never opens a display does not pay for loading OSMesa and the
 * LLVM it pulls in (SPEC 4).  The module knows nothing of vrWorld: it takes
 * plain arrays, polygons in a body frame with a body-to-world matrix, and
 * per-eye view and projection matrices, and gives back RGB pixels.
 *
 * The module exports one data symbol, VR_RENDER_SYMBOL, a vrRenderApi (a
 * data symbol rather than a function because ISO C has no conversion from
 * dlsym's void * to a function pointer).  Matrices are 4x4, column-major,
 * as OpenGL loads them.
 */
#ifndef VROC_RENDER_H
#define VROC_RENDER_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#define VR_RENDER_SYMBOL "vroc_render_api"
#define VR_RENDER_ABI 1             /* bumped whenever these structs change */
#define VR_RENDER_NEAR 0.05         /* clip planes, m (SPEC 4) */
#define VR_RENDER_FAR 500.0
#define VR_RENDER_AMBIENT 0.2       /* headlight: ambient + diffuse = 1, so a */
#define VR_RENDER_DIFFUSE 0.8       /* face toward the light shows its colour */

typedef enum vrRenderStyle {
    VR_STYLE_SOLID,     /* lit polygons */
    VR_STYLE_WIRE,      /* polygon edges in the object's colour (see-through 1) */
    VR_STYLE_PHANTOM    /* depth only: invisible, but hides what is behind it
                         * as the real object does in a see-through display */
} vrRenderStyle;

typedef struct vrRenderObject {
    int nverts;
    const double *verts;       /* xyz per vertex, body frame */
    const double *normals;     /* xyz per vertex, unit; used when smooth */
    int nfaces;
    const int *face_start;     /* nfaces+1 */
    const int *face_verts;     /* convex polygons, counter-clockwise from outside */
    int smooth;                /* 1: vertex normals (Gouraud); 0: one normal per face */
    double model[16];          /* body to world, rigid (rotation + translation) */
    unsigned char color[3];
    vrRenderStyle style;
} vrRenderObject;

typedef struct vrRenderFrame {
    int width, height;         /* pixels of each eye */
    int nobjects;
    const vrRenderObject *objects;
    double light[3];           /* unit world direction toward the light (a headlight) */
    double view[2][16];        /* world to eye, eye 0 left, 1 right */
    double proj[2][16];
} vrRenderFrame;

typedef struct vrRenderContext vrRenderContext;

/* a one-line message into the caller's err buffer (the library's convention,
 * vroc.h), shared by both sides because the module links nothing of ours */
static inline void vrRender_Error(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (!err || errlen == 0) return;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

typedef struct vrRenderApi {
    int abi;                   /* VR_RENDER_ABI of the module */
    /* an off-screen context (RGBA, 24-bit depth); NULL and a message on failure */
    vrRenderContext *(*create)(char *err, size_t errlen);
    void (*destroy)(vrRenderContext *c);
    /* draws both eyes; rgb[e] receives width*height*3 bytes, rows top to
     * bottom.  Deterministic: the same frame gives the same bytes. */
    int (*render)(vrRenderContext *c, const vrRenderFrame *f, unsigned char *rgb[2],
                  char *err, size_t errlen);
    /* glGetString(GL_RENDERER), e.g. "llvmpipe (LLVM 15.0.6, 256 bits)" */
    const char *(*renderer_name)(const vrRenderContext *c);
} vrRenderApi;

#endif
