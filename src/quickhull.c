/* quickhull.c — the triangulated convex hull of a point set (SPEC 2).
 *
 * Quickhull (Barber, Dobkin & Huhdanpaa 1996, "The Quickhull algorithm for
 * convex hulls"): a triangulated hull whose faces keep the points above them
 * (conflict lists); each step takes a face's farthest point, removes the
 * faces that point sees and cones the horizon to it.  Whether the eye sees a
 * face is decided exactly (orient.c), so the triangulation stays exactly
 * convex and the horizon one cycle whatever duplicates or coplanar clusters
 * come in.  A point within 1e-3 of the tolerance of the hull is dropped (it
 * changes nothing worth a vertex).
 *   push, push_horizon       growing arrays (out of memory: h->oom)
 *   new_face, set_plane      a triangle with its normal and height filter
 *   height, assign           a point's height over a face; its conflict list
 *   sees, find_horizon       the faces the eye sees, and their horizon
 *   build_cone, add_point    one step
 *   initial_simplex          the first tetrahedron, from extreme points
 *   collect_triangles        the live faces, renumbered: the result
 */
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "orient.h"
#include "polyhedron.h"
#include "quickhull.h"

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

static void push(Hull *h, IntVec *v, int x)
{
    if (vrGrow((void **)&v->a, &v->cap, v->n + 1, sizeof *v->a) != 0) {
        h->oom = 1;
        return;
    }
    v->a[v->n++] = x;
}

static void push_horizon(Hull *h, int a, int b, int out)
{
    if (vrGrow((void **)&h->hz, &h->caphz, h->nhz + 1, sizeof *h->hz) != 0) {
        h->oom = 1;
        return;
    }
    h->hz[h->nhz].a = a;
    h->hz[h->nhz].b = b;
    h->hz[h->nhz++].out = out;
}

static void set_plane(Face *f, vec3 a, vec3 b, vec3 c)
{
    vec3 u = vec3_sub(b, a), v = vec3_sub(c, a);
    f->n = vec3_cross(u, v);
    f->nabs = vec3_make(fabs(u.y * v.z) + fabs(u.z * v.y), fabs(u.z * v.x) + fabs(u.x * v.z),
                        fabs(u.x * v.y) + fabs(u.y * v.x));
}

/* a face (a, b, c) with no neighbours yet; -1 when out of memory */
static int new_face(Hull *h, int a, int b, int c)
{
    Face *f;
    int id;
    if (h->freeface.n > 0) {
        id = h->freeface.a[--h->freeface.n];
    } else {
        if (vrGrow((void **)&h->face, &h->capface, h->nface + 1, sizeof *h->face) != 0) {
            h->oom = 1;
            return -1;
        }
        id = h->nface++;
    }
    f = &h->face[id];
    f->v[0] = a;
    f->v[1] = b;
    f->v[2] = c;
    f->nb[0] = f->nb[1] = f->nb[2] = -1;
    f->head = f->far = -1;
    f->fardist = 0;
    set_plane(f, h->pts[a], h->pts[b], h->pts[c]);
    f->minout = h->drop * vec3_len(f->n);
    f->stamp = 0;
    f->state = FACE_ALIVE;
    return id;
}

static double face_orient(const Hull *h, int f, int pt)
{
    const int *v = h->face[f].v;
    return vrOrient(h->pts[v[0]], h->pts[v[1]], h->pts[v[2]], h->pts[pt]);
}

/* n.(p - v0): orient() from the face's stored normal, with *eb bounding its
 * error (each of the eight roundings on the way is at most u relative to
 * the magnitudes summed in nabs.|p - v0|; 16u leaves room) */
static double height(const Hull *h, const Face *F, int pt, double *eb)
{
    vec3 d = vec3_sub(h->pts[pt], h->pts[F->v[0]]);
    *eb = 8 * DBL_EPSILON * (F->nabs.x * fabs(d.x) + F->nabs.y * fabs(d.y) + F->nabs.z * fabs(d.z));
    return vec3_dot(F->n, d);
}

static void add_conflict(Hull *h, int f, int pt, double d)
{
    Face *F = &h->face[f];
    h->next[pt] = F->head;
    F->head = pt;
    if (F->far < 0 || d > F->fardist) {
        F->far = pt;
        F->fardist = d;
    }
}

/* does pt, seen along the normal of face F, fall on its triangle?  A
 * sliver's normal is mostly rounding (its products cancel): no answer */
static int over_triangle(const Hull *h, const Face *F, int pt)
{
    vec3 p = h->pts[pt];
    int i;
    if (vec3_maxabs(F->n) <= 1e-6 * vec3_maxabs(F->nabs)) return 0;
    for (i = 0; i < 3; i++) {
        vec3 a = h->pts[F->v[i]], b = h->pts[F->v[i == 2 ? 0 : i + 1]];
        if (vec3_dot(vec3_cross(vec3_sub(b, a), vec3_sub(p, a)), F->n) < 0) return 0;
    }
    return 1;
}

/* Puts pt in the conflict list of one of faces[0..n) (the new faces of a
 * step, trying faces[*hint] first: neighbouring points share faces) or drops
 * it.  It is dropped when it is above none of them (Barber et al.: then it
 * is inside), or when it lies within drop of one of their triangles (then it
 * is within drop of the hull: a small height alone would not say so, the
 * point may be far out along the face's plane).  So points on a flat within
 * rounding go at once, without exact arithmetic. */
static void assign(Hull *h, int pt, const int *faces, int n, int *hint)
{
    int k, above = -1;
    double dabove = 0;
    for (k = 0; k < n; k++) {
        int at = *hint + k < n ? *hint + k : *hint + k - n, f = faces[at];
        const Face *F = &h->face[f];
        double eb, d = height(h, F, pt, &eb);
        if (d - F->minout > eb) {
            add_conflict(h, f, pt, d);
            *hint = at;
            return;
        }
        if (fabs(d) <= F->minout + eb && over_triangle(h, F, pt)) return;
        if (d > eb && above < 0) {
            above = f;
            dabove = d;
        }
    }
    for (k = 0; k < n && above < 0; k++) { /* the sign too close to call: exactly */
        double eb, d = height(h, &h->face[faces[k]], pt, &eb);
        if (fabs(d) <= eb && face_orient(h, faces[k], pt) > 0) above = faces[k];
    }
    if (above >= 0) add_conflict(h, above, pt, dabove);
}

/* the index of the edge of face f whose neighbour is g */
static int edge_to(const Hull *h, int f, int g)
{
    const int *nb = h->face[f].nb;
    return nb[0] == g ? 0 : nb[1] == g ? 1 : 2;
}

static int sees(Hull *h, int f, int eye)
{
    Face *F = &h->face[f];
    double d, eb;
    if (F->state == FACE_VISIBLE) return 1;
    if (F->stamp == h->step) return 0; /* tested this step: not visible */
    F->stamp = h->step;
    d = height(h, F, eye, &eb);
    if (d > eb || (d >= -eb && face_orient(h, f, eye) > 0)) {
        F->state = FACE_VISIBLE;
        push(h, &h->visible, f);
        return 2; /* newly seen */
    }
    return 0;
}

/* Depth-first over the faces the eye sees, each face's edges taken
 * counter-clockwise from the one it was entered by: the unseen neighbours
 * are met in order round the horizon (as in Lloyd's QuickHull3D). */
static void find_horizon(Hull *h, int f0, int eye)
{
    h->dfs.n = h->nhz = h->visible.n = 0;
    h->face[f0].state = FACE_VISIBLE;
    push(h, &h->visible, f0);
    push(h, &h->dfs, f0);
    push(h, &h->dfs, -1); /* entered by: none, so all three edges */
    push(h, &h->dfs, 0);  /* edges done */
    while (h->dfs.n > 0 && !h->oom) {
        int *fr = &h->dfs.a[h->dfs.n - 3];
        int f = fr[0], entry = fr[1], i, g, seen;
        if (fr[2] == (entry < 0 ? 3 : 2)) {
            h->dfs.n -= 3;
            continue;
        }
        i = entry < 0 ? fr[2] : (entry + 1 + fr[2]) % 3;
        fr[2]++;
        g = h->face[f].nb[i];
        seen = sees(h, g, eye);
        if (seen == 2) {
            push(h, &h->dfs, g);
            push(h, &h->dfs, edge_to(h, g, f));
            push(h, &h->dfs, 0);
        } else if (seen == 0) {
            push_horizon(h, h->face[f].v[i], h->face[f].v[(i + 1) % 3], g);
        }
    }
}

/* the horizon must be one cycle (exact predicates make it so) */
static int horizon_is_cycle(const Hull *h)
{
    int k;
    if (h->nhz < 3) return 0;
    for (k = 0; k < h->nhz; k++)
        if (h->hz[k].b != h->hz[(k + 1) % h->nhz].a) return 0;
    return 1;
}

/* replaces the seen faces with a cone of new faces from the horizon to eye */
static void build_cone(Hull *h, int eye)
{
    int k, j, nh = h->nhz;
    h->cone.n = 0;
    for (k = 0; k < nh; k++) {
        Horizon z = h->hz[k];
        int f = new_face(h, z.a, z.b, eye);
        Face *out;
        if (f < 0) return;
        push(h, &h->cone, f);
        h->face[f].nb[0] = z.out;
        out = &h->face[z.out];
        for (j = 0; j < 3; j++)
            if (out->v[j] == z.b && out->v[(j + 1) % 3] == z.a) out->nb[j] = f;
    }
    if (h->oom) return;
    for (k = 0; k < nh; k++) {
        h->face[h->cone.a[k]].nb[1] = h->cone.a[(k + 1) % nh];
        h->face[h->cone.a[k]].nb[2] = h->cone.a[(k + nh - 1) % nh];
    }
}

/* one quickhull step: the farthest point above face f0 joins the hull;
 * -1 out of memory, VR_HULL_RETRY when the horizon is not one cycle */
static int add_point(Hull *h, int f0)
{
    int eye = h->face[f0].far, k, hint = 0;
    h->step++;
    find_horizon(h, f0, eye);
    if (h->oom) return -1;
    if (!horizon_is_cycle(h)) return VR_HULL_RETRY;
    h->orphans.n = 0;
    for (k = 0; k < h->visible.n; k++) {
        int f = h->visible.a[k], pt;
        for (pt = h->face[f].head; pt >= 0; pt = h->next[pt])
            if (pt != eye) push(h, &h->orphans, pt);
        h->face[f].state = FACE_FREE;
        push(h, &h->freeface, f);
    }
    build_cone(h, eye);
    if (h->oom) return -1;
    for (k = 0; k < h->orphans.n; k++) assign(h, h->orphans.a[k], h->cone.a, h->cone.n, &hint);
    for (k = 0; k < h->cone.n; k++)
        if (h->face[h->cone.a[k]].head >= 0) push(h, &h->pending, h->cone.a[k]);
    return h->oom ? -1 : 0;
}

/* ---- the first tetrahedron ------------------------------------------------- */

static double dist_to_plane(vec3 a, vec3 b, vec3 c, vec3 q)
{
    vec3 n = vec3_normalize(vec3_cross(vec3_sub(b, a), vec3_sub(c, a)));
    return fabs(vec3_dot(n, vec3_sub(q, a)));
}

/* the two farthest apart of the six axis-extreme points */
static void farthest_pair(const vec3 *p, int n, int *i0, int *i1)
{
    int ext[6] = {0, 0, 0, 0, 0, 0}, i, j, ax;
    double best = -1;
    for (i = 1; i < n; i++)
        for (ax = 0; ax < 3; ax++) {
            if (vec3_get(p[i], ax) < vec3_get(p[ext[2 * ax]], ax)) ext[2 * ax] = i;
            if (vec3_get(p[i], ax) > vec3_get(p[ext[2 * ax + 1]], ax)) ext[2 * ax + 1] = i;
        }
    *i0 = *i1 = 0;
    for (i = 0; i < 6; i++)
        for (j = i + 1; j < 6; j++)
            if (vec3_dist(p[ext[i]], p[ext[j]]) > best) {
                best = vec3_dist(p[ext[i]], p[ext[j]]);
                *i0 = ext[i];
                *i1 = ext[j];
            }
}

static int initial_simplex(Hull *h, double tolabs, char *err, size_t errlen)
{
    /* faces (a b c) (b a d) (c b d) (a c d) and their neighbours, edge by edge */
    static const int nb[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    const vec3 *p = h->pts;
    int a, b, c = 0, d = 0, i, f, hint = 0, all[4];
    double best = 0;
    farthest_pair(p, h->n, &a, &b);
    if (!(vec3_dist(p[a], p[b]) > tolabs)) return vrGeom_Fail(err, errlen, "all points coincide");
    for (i = 0; i < h->n; i++) {
        double dl = vrGeom_DistToLine(p[a], p[b], p[i]);
        if (dl > best) {
            best = dl;
            c = i;
        }
    }
    if (!(best > tolabs)) return vrGeom_Fail(err, errlen, "all points are collinear");
    for (best = 0, i = 0; i < h->n; i++) {
        double dp = dist_to_plane(p[a], p[b], p[c], p[i]);
        if (dp > best) {
            best = dp;
            d = i;
        }
    }
    if (!(best > tolabs)) return vrGeom_Fail(err, errlen, "all points are coplanar (within %g)", tolabs);
    if (vrOrient(p[a], p[b], p[c], p[d]) > 0) { /* d must be below abc */
        i = b;
        b = c;
        c = i;
    }
    all[0] = new_face(h, a, b, c);
    all[1] = new_face(h, b, a, d);
    all[2] = new_face(h, c, b, d);
    all[3] = new_face(h, a, c, d);
    if (h->oom) return vrGeom_Fail(err, errlen, "out of memory");
    for (f = 0; f < 4; f++) memcpy(h->face[all[f]].nb, nb[f], sizeof nb[f]);
    for (i = 0; i < h->n; i++)
        if (i != a && i != b && i != c && i != d) assign(h, i, all, 4, &hint);
    for (f = 0; f < 4; f++)
        if (h->face[f].head >= 0) push(h, &h->pending, f);
    return 0;
}

static void hull_free(Hull *h)
{
    free(h->next);
    free(h->face);
    free(h->freeface.a);
    free(h->pending.a);
    free(h->visible.a);
    free(h->orphans.a);
    free(h->cone.a);
    free(h->dfs.a);
    free(h->hz);
}

static int quickhull(Hull *h, double tolabs, char *err, size_t errlen)
{
    h->next = malloc(sizeof *h->next * h->n);
    if (!h->next) return vrGeom_Fail(err, errlen, "out of memory");
    if (initial_simplex(h, tolabs, err, errlen) != 0) return -1;
    while (h->pending.n > 0) {
        int f = h->pending.a[--h->pending.n], rc;
        if (h->face[f].state != FACE_ALIVE || h->face[f].head < 0) continue;
        rc = add_point(h, f);
        if (rc == -1) return vrGeom_Fail(err, errlen, "out of memory");
        if (rc == VR_HULL_RETRY) {
            vrGeom_Fail(err, errlen, "the horizon of point %d is not a cycle", h->face[f].far);
            return VR_HULL_RETRY;
        }
    }
    return h->oom ? vrGeom_Fail(err, errlen, "out of memory") : 0;
}

/* the live faces of the quickhull, renumbered 0..n-1 */
static int collect_triangles(const Hull *h, vrHullMesh *t)
{
    int *id = malloc(sizeof *id * (h->nface + 1)), f, i;
    t->n = 0;
    if (!id) return -1;
    for (f = 0; f < h->nface; f++) id[f] = h->face[f].state == FACE_ALIVE ? t->n++ : -1;
    t->v = malloc(sizeof *t->v * t->n);
    t->nb = malloc(sizeof *t->nb * t->n);
    if (!t->v || !t->nb) {
        free(id);
        return -1;
    }
    for (f = 0; f < h->nface; f++) {
        if (id[f] < 0) continue;
        for (i = 0; i < 3; i++) {
            t->v[id[f]][i] = h->face[f].v[i];
            /* NOLINTNEXTLINE(clang-analyzer-core.uninitialized.Assign): a face's neighbours are faces < nface, all given an id */
            t->nb[id[f]][i] = id[h->face[f].nb[i]];
        }
    }
    free(id);
    return 0;
}

void vrHullMesh_Free(vrHullMesh *t)
{
    free(t->v);
    free(t->nb);
    t->v = NULL;
    t->nb = NULL;
    t->n = 0;
}

int vrQuickhull(const vec3 *pts, int n, double tolabs, vrHullMesh *out, char *err, size_t errlen)
{
    Hull h;
    int rc;
    memset(&h, 0, sizeof h);
    memset(out, 0, sizeof *out);
    h.pts = pts;
    h.n = n;
    h.drop = 1e-3 * tolabs;
    rc = quickhull(&h, tolabs, err, errlen);
    if (rc == 0 && collect_triangles(&h, out) != 0) rc = vrGeom_Fail(err, errlen, "out of memory");
    if (rc != 0) vrHullMesh_Free(out);
    hull_free(&h);
    return rc;
}
