/* hull.c — the convex hull of a point set, as a polyhedron (SPEC 2).
 *
 * The hull is triangulated (quickhull.c), its coplanar triangles merged into
 * polygons (coplanar.c), and the vertices left on fewer than three faces
 * (on an edge or inside a face: not extreme) dropped; vrPolyhedron_FromFaces
 * builds the graph from the polygons and checks it.  Should points closer
 * than the tolerance make the merge inconsistent (VR_HULL_RETRY), the whole
 * is done again with such points merged first, at growing distances.
 *   drop_flat_vertices       the corners that are not extreme
 *   make_polyhedron          the polygons as a polyhedron
 *   hull_attempt             one attempt over a point set
 *   Grid, snap_points        points closer than r merged into the first of them
 *   snapped_attempt          an attempt after such a merge
 */
#include <stdlib.h>
#include <string.h>

#include "coplanar.h"
#include "progress.h"
#include "hull.h"

/* Drops the vertices that lie on fewer than three polygons (inside an edge
 * or a face: not extreme) and renumbers the rest 0..nv-1 in input order.
 * keep[] maps input index to new index (-1: dropped). */
static int drop_flat_vertices(vrLoops *l, int npts, int *keep, int *nv)
{
    int i, f, k = 0, n = 0;
    for (i = 0; i < npts; i++) keep[i] = 0;
    for (i = 0; i < l->len; i++) keep[l->vert[i]]++;
    for (i = 0; i < npts; i++) keep[i] = keep[i] >= 3 ? n++ : -1;
    *nv = n;
    for (f = 0; f < l->n; f++) {
        int s = l->start[f], e = l->start[f + 1];
        l->start[f] = k;
        for (i = s; i < e; i++)
            if (keep[l->vert[i]] >= 0) l->vert[k++] = keep[l->vert[i]];
        if (k - l->start[f] < 3) return -1;
    }
    l->start[l->n] = l->len = k;
    return 0;
}

static int check_points(const vec3 *pts, int n, char *err, size_t errlen)
{
    int i;
    if (!pts || n < 4) return vrGeom_Fail(err, errlen, "a hull needs at least 4 points, got %d", pts ? n : 0);
    for (i = 0; i < n; i++)
        if (!vec3_isfinite(pts[i])) return vrGeom_Fail(err, errlen, "point %d is not finite", i);
    return 0;
}

/* the polygons of the hull and the input index of each vertex (orig maps
 * the points hulled to the input; NULL: the same) */
static int make_polyhedron(const vec3 *pts, int n, vrLoops *l, const int *orig, double tol, int **src,
                           vrPolyhedron **out, char *err, size_t errlen)
{
    int *keep = malloc(sizeof *keep * n), nv = 0, i, rc = VR_HULL_RETRY;
    vec3 *v = malloc(sizeof *v * n);
    int *map = malloc(sizeof *map * n);
    if (!keep || !v || !map) {
        rc = vrGeom_Fail(err, errlen, "out of memory");
    } else if (drop_flat_vertices(l, n, keep, &nv) != 0) {
        vrGeom_Fail(err, errlen, "a merged face lost its corners");
    } else {
        vrProgress_Now();
        for (i = 0; i < n; i++)
            if (keep[i] >= 0) {
                v[keep[i]] = pts[i];
                map[keep[i]] = orig ? orig[i] : i;
            }
        if (vrPolyhedron_FromFaces(v, nv, l->start, l->vert, l->n, tol, out, err, errlen) == 0) rc = 0;
    }
    if (rc == 0 && src) {
        *src = map;
        map = NULL;
    }
    free(keep);
    free(v);
    free(map);
    return rc;
}

/* one attempt over the points pts[0..n) (orig: their input indices) */
static int hull_attempt(const vec3 *pts, int n, const int *orig, double tol, double tolabs, int **src,
                        vrPolyhedron **out, char *err, size_t errlen)
{
    vrHullMesh mesh = {0};
    vrLoops loops = {0};
    int rc = vrQuickhull(pts, n, tolabs, &mesh, err, errlen);
    vrProgress_Now();
    if (rc == 0) rc = vrCoplanar_Merge(&mesh, pts, n, tolabs, &loops, err, errlen);
    vrProgress_Now();
    if (rc == 0) rc = make_polyhedron(pts, n, &loops, orig, tol, src, out, err, errlen);
    vrHullMesh_Free(&mesh);
    vrLoops_Free(&loops);
    return rc;
}

/* ---- merging points closer than r (the retries) ---------------------------- */

typedef struct Grid {  /* cells of side r, hashed; each lists its representatives */
    long long (*key)[3];
    int *head, *link;
    int cap;
    vec3 lo;
    double r;
} Grid;

static void cell_of(const Grid *g, vec3 p, long long c[3])
{
    c[0] = (long long)floor((p.x - g->lo.x) / g->r);
    c[1] = (long long)floor((p.y - g->lo.y) / g->r);
    c[2] = (long long)floor((p.z - g->lo.z) / g->r);
}

/* the slot of cell c: where it is, or the empty one where it would go */
static int grid_slot(const Grid *g, const long long c[3])
{
    unsigned long long hsh = (unsigned long long)c[0] * 0x9E3779B97F4A7C15ULL
                           ^ (unsigned long long)c[1] * 0xC2B2AE3D27D4EB4FULL
                           ^ (unsigned long long)c[2] * 0x165667B19E3779F9ULL;
    int s = (int)((hsh ^ (hsh >> 29)) & (unsigned long long)(g->cap - 1));
    while (g->head[s] >= 0 && memcmp(g->key[s], c, sizeof g->key[s]) != 0) s = (s + 1) & (g->cap - 1);
    return s;
}

/* an earlier representative within r of p, or -1 */
static int grid_near(const Grid *g, const vec3 *pts, vec3 p)
{
    long long c[3], d[3];
    int i, j;
    cell_of(g, p, c);
    for (i = 0; i < 27; i++) {
        int s;
        d[0] = c[0] + i % 3 - 1;
        d[1] = c[1] + i / 3 % 3 - 1;
        d[2] = c[2] + i / 9 - 1;
        s = grid_slot(g, d);
        for (j = g->head[s]; j >= 0; j = g->link[j])
            if (vec3_dist(pts[j], p) <= g->r) return j;
    }
    return -1;
}

static void grid_free(Grid *g)
{
    free(g->key);
    free(g->head);
    free(g->link);
}

static int grid_alloc(Grid *g, const vec3 *pts, int n, double r)
{
    int i;
    g->cap = 1;
    while (g->cap < 2 * n) g->cap <<= 1;
    g->key = malloc(sizeof *g->key * g->cap);
    g->head = malloc(sizeof *g->head * g->cap);
    g->link = malloc(sizeof *g->link * n);
    if (!g->key || !g->head || !g->link) return -1;
    for (i = 0; i < g->cap; i++) g->head[i] = -1;
    g->r = r;
    g->lo = pts[0];
    for (i = 1; i < n; i++)
        g->lo = vec3_min(g->lo, pts[i]);
    return 0;
}

/* Each point goes to the first earlier representative within r, or
 * becomes one: rep[0..*m) lists the representatives, in input order. */
static int snap_points(const vec3 *pts, int n, double r, int *rep, int *m)
{
    Grid g = {0};
    int i;
    *m = 0;
    if (grid_alloc(&g, pts, n, r) != 0) {
        grid_free(&g);
        return -1;
    }
    for (i = 0; i < n; i++) {
        long long c[3];
        int s;
        if (grid_near(&g, pts, pts[i]) >= 0) continue;
        cell_of(&g, pts[i], c);
        s = grid_slot(&g, c);
        memcpy(g.key[s], c, sizeof c);
        g.link[i] = g.head[s];
        g.head[s] = i;
        rep[(*m)++] = i;
    }
    grid_free(&g);
    return 0;
}

/* the attempt with the points closer than r merged into the first of them */
static int snapped_attempt(const vec3 *pts, int n, double r, double tol, double tolabs, int **src,
                           vrPolyhedron **out, char *err, size_t errlen)
{
    int *rep = malloc(sizeof *rep * n), m = 0, i, rc;
    vec3 *q = malloc(sizeof *q * n);
    if (!rep || !q || snap_points(pts, n, r, rep, &m) != 0) {
        rc = vrGeom_Fail(err, errlen, "out of memory");
    } else {
        for (i = 0; i < m; i++) q[i] = pts[rep[i]];
        rc = m < 4 ? VR_HULL_RETRY : hull_attempt(q, m, rep, tol, tolabs, src, out, err, errlen);
    }
    free(rep);
    free(q);
    return rc;
}

int vrPolyhedron_HullTol(const vec3 *pts, int n, double tol, int **src, vrPolyhedron **out, char *err,
                         size_t errlen)
{
    /* a triangulation exact for points closer than the tolerance may not
     * merge consistently (slivers, corners blurred at the tolerance's
     * scale): then such points are merged, at growing distances */
    static const double snap[] = {0, 1, 10, 100, 1000};
    double tolabs;
    int k, rc;
    char why[256] = "";
    *out = NULL;
    if (src) *src = NULL;
    if (check_points(pts, n, err, errlen) != 0) return -1;
    tolabs = tol * vrGeom_Size(pts, n);
    rc = hull_attempt(pts, n, NULL, tol, tolabs, src, out, why, sizeof why);
    for (k = 1; rc == VR_HULL_RETRY && k < 5; k++)
        rc = snapped_attempt(pts, n, snap[k] * tolabs, tol, tolabs, src, out, why, sizeof why);
    if (rc == VR_HULL_RETRY)
        return vrGeom_Fail(err, errlen, "hull: numerically inconsistent (%s) even with points within %g merged", why,
                           snap[4] * tolabs);
    if (rc != 0) return vrGeom_Fail(err, errlen, "%s", why);
    return 0;
}

int vrPolyhedron_Hull(const vec3 *pts, int n, vrPolyhedron **out, char *err, size_t errlen)
{
    return vrPolyhedron_HullTol(pts, n, VR_COPLANAR_TOL, NULL, out, err, errlen);
}
