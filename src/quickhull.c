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
 *   (faces)                  a new face, its height filter, the conflict lists: quickhull_faces.c
 *   sees, find_horizon       the faces the eye sees, and their horizon
 *   build_cone, add_point    one step
 *   initial_simplex          the first tetrahedron, from extreme points
 *   collect_triangles        the live faces, renumbered: the result
 */
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "progress.h"
#include "grow.h"
#include "orient.h"
#include "polyhedron.h"
#include "quickhull.h"
#include "quickhull_faces.h"

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
        int f = vrQuickhull_NewFace(h, z.a, z.b, eye);
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
    for (k = 0; k < h->orphans.n; k++) vrQuickhull_Assign(h, h->orphans.a[k], h->cone.a, h->cone.n, &hint);
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
    all[0] = vrQuickhull_NewFace(h, a, b, c);
    all[1] = vrQuickhull_NewFace(h, b, a, d);
    all[2] = vrQuickhull_NewFace(h, c, b, d);
    all[3] = vrQuickhull_NewFace(h, a, c, d);
    if (h->oom) return vrGeom_Fail(err, errlen, "out of memory");
    for (f = 0; f < 4; f++) memcpy(h->face[all[f]].nb, nb[f], sizeof nb[f]);
    for (i = 0; i < h->n; i++)
        if (i != a && i != b && i != c && i != d) vrQuickhull_Assign(h, i, all, 4, &hint);
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
        vrProgress_Tick();
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
