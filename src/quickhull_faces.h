/* quickhull_faces.h — the quickhull's state (quickhull.c) and its faces
 * with their conflict lists (quickhull_faces.c): a triangle's plane and
 * height filter, and which face a point waits above, or that it is dropped.
 * Whether the eye sees a face (quickhull.c) reads the same heights. */
#ifndef VROC_QUICKHULL_FACES_H
#define VROC_QUICKHULL_FACES_H

#include <float.h>
#include "orient.h"
#include "vec.h"

typedef struct IntVec { int *a; int n, cap; } IntVec;

enum { FACE_ALIVE, FACE_VISIBLE, FACE_FREE };

typedef struct Face {
    int v[3];        /* counter-clockwise seen from outside */
    int nb[3];       /* nb[i]: the face across the edge v[i] -> v[i+1] */
    int head;        /* first point of its conflict list, -1 if none */
    int far;         /* its farthest conflict point */
    double fardist;  /* orient() of far */
    double minout;   /* orient() of a point drop above it: less is not kept */
    vec3 n, nabs;    /* (v1-v0) x (v2-v0) as computed, and the sums of the
                        magnitudes of its products: the height filter */
    int stamp;       /* the step that last tested it against the eye */
    int state;
} Face;

typedef struct Horizon { int a, b, out; } Horizon; /* edge a->b of a seen face; out: the unseen face */

typedef struct Hull {
    const vec3 *pts;
    int n;
    int *next;       /* conflict lists: the next point above the same face */
    Face *face;
    int nface, capface;
    IntVec freeface, pending, visible, orphans, cone, dfs;
    Horizon *hz;
    int nhz, caphz;
    double drop;     /* points within this of the hull are dropped */
    int step, oom;
} Hull;

static inline double face_orient(const Hull *h, int f, int pt)
{
    const int *v = h->face[f].v;
    return vrOrient(h->pts[v[0]], h->pts[v[1]], h->pts[v[2]], h->pts[pt]);
}

/* n.(p - v0): orient() from the face's stored normal, with *eb bounding its
 * error (each of the eight roundings on the way is at most u relative to
 * the magnitudes summed in nabs.|p - v0|; 16u leaves room) */
static inline double height(const Hull *h, const Face *F, int pt, double *eb)
{
    vec3 d = vec3_sub(h->pts[pt], h->pts[F->v[0]]);
    *eb = 8 * DBL_EPSILON * (F->nabs.x * fabs(d.x) + F->nabs.y * fabs(d.y) + F->nabs.z * fabs(d.z));
    return vec3_dot(F->n, d);
}

/* a face (a, b, c) with no neighbours yet; -1 when out of memory (h->oom) */
int vrQuickhull_NewFace(Hull *h, int a, int b, int c);

/* Puts pt in the conflict list of one of faces[0..n) (the new faces of a
 * step, trying faces[*hint] first: neighbouring points share faces) or drops
 * it.  It is dropped when it is above none of them (Barber et al.: then it
 * is inside), or when it lies within drop of one of their triangles (then it
 * is within drop of the hull: a small height alone would not say so, the
 * point may be far out along the face's plane).  So points on a flat within
 * rounding go at once, without exact arithmetic. */
void vrQuickhull_Assign(Hull *h, int pt, const int *faces, int n, int *hint);

#endif
