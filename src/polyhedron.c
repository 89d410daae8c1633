/* polyhedron.c — the feature graph of a convex polyhedron, built from its
 * faces (SPEC 2).
 *
 * Every builder (primitives.c, hull.c, off.c) ends in vrPolyhedron_FromFaces:
 * vertices plus the counter-clockwise boundary loop of each face.  From the
 * loops it derives everything the closest-feature walk needs (the
 * conventions are in feature.h): half-edge twins, edges with their
 * left/right faces, the edges about each vertex counter-clockwise, and the
 * face planes; it checks the surface and fills the mass properties (mass.c).
 *   poly_alloc, vrPolyhedron_Free    the arrays
 *   HalfEdges, bucket_by_tail        the half-edges of the loops, by tail vertex
 *   match_twins                      twins and edges, left and right faces
 *   order_vertex_edges               the edges about each vertex
 *   compute_planes, compute_margins  face planes, smooth normals, and how far
 *                                    a face stands out (contact's support rule)
 *   check_convex, check_loops        the refusals
 *   centre, from_faces               the centre of mass to the origin; the whole
 *   vrPolyhedron_Climb               the top vertex along a direction
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "face_groups.h"
#include "mass.h"
#include "polyhedron.h"
#include "progress.h"

int vrGeom_Fail(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (err && errlen > 0) {
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return -1;
}

double vrGeom_Size(const vec3 *pts, int n)
{
    vec3 lo, hi;
    int i;
    if (n <= 0) return 0;
    lo = hi = pts[0];
    for (i = 1; i < n; i++) {
        lo = vec3_min(lo, pts[i]);
        hi = vec3_max(hi, pts[i]);
    }
    return vec3_dist(lo, hi);
}

void vrPolyhedron_Free(vrPolyhedron *p)
{
    if (!p) return;
    free(p->vert);
    free(p->vert_normal);
    free(p->edge_v);
    free(p->edge_f);
    free(p->vert_edge_start);
    free(p->vert_edge);
    free(p->face_start);
    free(p->face_vert);
    free(p->face_edge);
    free(p->face_normal);
    free(p->face_offset);
    free(p->face_spread);
    free(p->face_drop);
    vrFaceGroups_Free(p->groups);
    free(p);
}

/* nh: total length of the face loops (the number of half-edges) */
static vrPolyhedron *poly_alloc(int nv, int nf, int nh)
{
    vrPolyhedron *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->nv = nv;
    p->nf = nf;
    p->ne = nh / 2;
    p->vert = malloc(sizeof *p->vert * nv);
    p->vert_normal = calloc(nv, sizeof *p->vert_normal);
    p->edge_v = malloc(sizeof *p->edge_v * (p->ne + 1));
    p->edge_f = malloc(sizeof *p->edge_f * (p->ne + 1));
    p->vert_edge_start = calloc(nv + 1, sizeof *p->vert_edge_start);
    p->vert_edge = malloc(sizeof *p->vert_edge * nh);
    p->face_start = malloc(sizeof *p->face_start * (nf + 1));
    p->face_vert = malloc(sizeof *p->face_vert * nh);
    p->face_edge = malloc(sizeof *p->face_edge * nh);
    p->face_normal = malloc(sizeof *p->face_normal * nf);
    p->face_offset = malloc(sizeof *p->face_offset * nf);
    p->face_spread = malloc(sizeof *p->face_spread * nf);
    p->face_drop = malloc(sizeof *p->face_drop * nf);
    if (!p->vert || !p->vert_normal || !p->edge_v || !p->edge_f || !p->vert_edge_start || !p->vert_edge
        || !p->face_start || !p->face_vert || !p->face_edge || !p->face_normal || !p->face_offset
        || !p->face_spread || !p->face_drop) {
        vrPolyhedron_Free(p);
        return NULL;
    }
    return p;
}

/* ---- half-edges ----------------------------------------------------------
 * Half-edge h is position h of face_vert: it runs from face_vert[h] to the
 * next vertex of the same loop. */
typedef struct HalfEdges {
    int *face;       /* the face each half-edge belongs to */
    int *next, *prev; /* the following and preceding half-edge of the same loop */
    int *twin;       /* the opposite half-edge, in the neighbouring face */
    int *edge;       /* the edge it is a side of */
    int *out_start;  /* nv+1: half-edges leaving v are out[out_start[v] ..) */
    int *out, *out_head; /* ... and the vertices they lead to */
} HalfEdges;

static int h_head(const vrPolyhedron *p, const HalfEdges *he, int h) { return p->face_vert[he->next[h]]; }

static void halfedges_free(HalfEdges *he)
{
    free(he->face);
    free(he->next);
    free(he->prev);
    free(he->twin);
    free(he->edge);
    free(he->out_start);
    free(he->out);
    free(he->out_head);
}

static int halfedges_alloc(HalfEdges *he, int nv, int nh)
{
    he->face = malloc(sizeof *he->face * nh);
    he->next = malloc(sizeof *he->next * nh);
    he->prev = malloc(sizeof *he->prev * nh);
    he->twin = malloc(sizeof *he->twin * nh);
    he->edge = malloc(sizeof *he->edge * nh);
    he->out_start = calloc(nv + 2, sizeof *he->out_start);
    he->out = malloc(sizeof *he->out * nh);
    he->out_head = malloc(sizeof *he->out_head * nh);
    return he->face && he->next && he->prev && he->twin && he->edge && he->out_start && he->out && he->out_head
         ? 0 : -1;
}

/* links each loop and buckets the half-edges by their tail vertex */
static void bucket_by_tail(const vrPolyhedron *p, HalfEdges *he, int nh)
{
    int f, h, v;
    for (f = 0; f < p->nf; f++)
        for (h = p->face_start[f]; h < p->face_start[f + 1]; h++) {
            he->face[h] = f;
            he->next[h] = h + 1 < p->face_start[f + 1] ? h + 1 : p->face_start[f];
            he->prev[h] = h > p->face_start[f] ? h - 1 : p->face_start[f + 1] - 1;
        }
    for (h = 0; h < nh; h++) he->out_start[p->face_vert[h] + 2]++;
    for (v = 0; v < p->nv; v++) he->out_start[v + 2] += he->out_start[v + 1];
    for (h = 0; h < nh; h++) {
        int k = he->out_start[p->face_vert[h] + 1]++;
        he->out[k] = h;
        he->out_head[k] = h_head(p, he, h);
    }
}

/* pairs every half-edge a->b with the only b->a; numbers the edges */
static int match_twins(vrPolyhedron *p, HalfEdges *he, int nh, char *err, size_t errlen)
{
    int h, k, ne = 0;
    for (h = 0; h < nh; h++) {
        int a = p->face_vert[h], b = h_head(p, he, h), found = 0;
        vrProgress_Tick();           /* a fine hull's million half-edges: a worker's heartbeat */
        for (k = he->out_start[b]; k < he->out_start[b + 1]; k++)
            if (he->out_head[k] == a) {
                he->twin[h] = he->out[k];
                found++;
            }
        if (found != 1)
            return vrGeom_Fail(err, errlen, "edge %d-%d of face %d is in %d other faces (not a closed surface)",
                               a, b, he->face[h], found);
    }
    for (h = 0; h < nh; h++) {
        if (he->twin[h] < h) continue;
        /* the left face is the one whose loop runs tail -> head */
        p->edge_v[ne][0] = p->face_vert[h];
        p->edge_v[ne][1] = h_head(p, he, h);
        p->edge_f[ne][0] = he->face[h];
        p->edge_f[ne][1] = he->face[he->twin[h]];
        he->edge[h] = he->edge[he->twin[h]] = ne;
        p->face_edge[h] = p->face_edge[he->twin[h]] = ne;
        ne++;
    }
    return 0;
}

/* The edges about each vertex, counter-clockwise seen from outside: from
 * v->w in face F, the next is v->u where u->v precedes v->w in F's loop. */
static int order_vertex_edges(vrPolyhedron *p, const HalfEdges *he, char *err, size_t errlen)
{
    int v;
    for (v = 0; v < p->nv; v++) {
        int start = he->out_start[v], deg = he->out_start[v + 1] - start, n = 0;
        int h0 = he->out[start], h = h0;
        vrProgress_Tick();
        p->vert_edge_start[v] = start;
        do {
            p->vert_edge[start + n++] = he->edge[h];
            h = he->twin[he->prev[h]];
        } while (h != h0 && n < deg);
        if (h != h0 || n != deg)
            return vrGeom_Fail(err, errlen, "the faces about vertex %d do not form one fan (not a manifold)", v);
    }
    p->vert_edge_start[p->nv] = he->out_start[p->nv];
    return 0;
}

static int build_graph(vrPolyhedron *p, char *err, size_t errlen)
{
    HalfEdges he = {0};
    int nh = p->face_start[p->nf], rc;
    if (halfedges_alloc(&he, p->nv, nh) != 0) {
        halfedges_free(&he);
        return vrGeom_Fail(err, errlen, "out of memory");
    }
    vrProgress_Now();
    bucket_by_tail(p, &he, nh);
    vrProgress_Now();
    rc = match_twins(p, &he, nh, err, errlen);
    vrProgress_Now();
    if (rc == 0) rc = order_vertex_edges(p, &he, err, errlen);
    if (rc == 0 && p->nv - p->ne + p->nf != 2)
        rc = vrGeom_Fail(err, errlen, "V - E + F = %d, not 2 (not a sphere-like surface)", p->nv - p->ne + p->nf);
    halfedges_free(&he);
    return rc;
}

/* ---- planes, normals, checks --------------------------------------------- */

/* Newell's normal of a loop (about its centroid, against cancellation):
 * twice the area times the unit normal */
static vec3 loop_area_normal(const vrPolyhedron *p, int f)
{
    int s = p->face_start[f], e = p->face_start[f + 1], k;
    vec3 c = vec3_zero(), n = vec3_zero();
    for (k = s; k < e; k++) c = vec3_add(c, p->vert[p->face_vert[k]]);
    c = vec3_scale(c, 1.0 / (e - s));
    for (k = s; k < e; k++) {
        vec3 a = vec3_sub(p->vert[p->face_vert[k]], c);
        vec3 b = vec3_sub(p->vert[p->face_vert[k + 1 < e ? k + 1 : s]], c);
        n = vec3_add(n, vec3_cross(a, b));
    }
    return n;
}

static int compute_planes(vrPolyhedron *p, char *err, size_t errlen)
{
    int f, k, v;
    for (f = 0; f < p->nf; f++) {
        vec3 an = loop_area_normal(p, f);
        double sum = 0;
        if (!(vec3_len(an) > 0)) return vrGeom_Fail(err, errlen, "face %d has no area", f);
        p->face_normal[f] = vec3_normalize(an);
        for (k = p->face_start[f]; k < p->face_start[f + 1]; k++) {
            sum += vec3_dot(p->face_normal[f], p->vert[p->face_vert[k]]);
            /* smooth normals for drawing: incident face normals, area weighted */
            v = p->face_vert[k];
            p->vert_normal[v] = vec3_add(p->vert_normal[v], an);
        }
        p->face_offset[f] = sum / vrPolyhedron_FaceSize(p, f);
        if (!(p->face_offset[f] > 0))
            return vrGeom_Fail(err, errlen, "face %d does not face away from the centre (flat or inside-out)", f);
    }
    for (v = 0; v < p->nv; v++) p->vert_normal[v] = vec3_normalize(p->vert_normal[v]);
    return 0;
}

static int on_face(const vrPolyhedron *p, int f, int v)
{
    int k;
    for (k = p->face_start[f]; k < p->face_start[f + 1]; k++)
        if (p->face_vert[k] == v) return 1;
    return 0;
}

/* A face's spread and drop along its normal (canonical.c: when they leave
 * room, a direction near the normal has exactly the face as its support
 * set).  The highest other vertex is a neighbour of the face: on a convex
 * polyhedron every vertex below the top has a higher neighbour. */
static void compute_margins(vrPolyhedron *p)
{
    int f, k, j;
    for (f = 0; f < p->nf; f++) {
        vec3 n = p->face_normal[f];
        double lo = HUGE_VAL, hi = -HUGE_VAL, other = -HUGE_VAL;
        for (k = p->face_start[f]; k < p->face_start[f + 1]; k++) {
            int v = p->face_vert[k];
            double h = vec3_dot(n, p->vert[v]);
            lo = fmin(lo, h);
            hi = fmax(hi, h);
            for (j = p->vert_edge_start[v]; j < p->vert_edge_start[v + 1]; j++) {
                int w = vrPolyhedron_OtherEnd(p, p->vert_edge[j], v);
                if (!on_face(p, f, w)) other = fmax(other, vec3_dot(n, p->vert[w]));
            }
        }
        p->face_spread[f] = hi - lo;
        p->face_drop[f] = lo - other;
    }
}

/* each face planar and convex in its plane, and the surface convex at each
 * edge (the corner after the edge behind the neighbour's plane): the local
 * conditions that make a closed surface of genus 0 convex */
static int check_convex(const vrPolyhedron *p, double lim, char *err, size_t errlen)
{
    int f, k;
    for (f = 0; f < p->nf; f++) {
        int s = p->face_start[f], n = vrPolyhedron_FaceSize(p, f);
        for (k = 0; k < n; k++) {
            int e = p->face_edge[s + k], g = p->edge_f[e][0] == f ? p->edge_f[e][1] : p->edge_f[e][0];
            int k1 = k + 1 < n ? k + 1 : 0, k2 = k1 + 1 < n ? k1 + 1 : 0, c = p->face_vert[s + k2];
            vec3 va = p->vert[p->face_vert[s + k]], vb = p->vert[p->face_vert[s + k1]];
            double len = vec3_dist(va, vb);
            double left = len > 0 ? vec3_dot(vec3_cross(vec3_sub(vb, va), vec3_sub(p->vert[c], vb)),
                                             p->face_normal[f]) / len : -INFINITY;
            if (fabs(vrPolyhedron_FaceHeight(p, f, p->vert[p->face_vert[s + k]])) > lim)
                return vrGeom_Fail(err, errlen, "face %d is not planar", f);
            if (left < -lim) return vrGeom_Fail(err, errlen, "face %d is not convex", f);
            if (vrPolyhedron_FaceHeight(p, g, p->vert[c]) > lim)
                return vrGeom_Fail(err, errlen, "the surface is not convex between faces %d and %d", f, g);
        }
    }
    return 0;
}

static int check_loops(int nv, const int *face_start, const int *face_vert, int nf, char *err, size_t errlen)
{
    int f, k, v, rc = 0;
    char *used;
    if (nv < 4 || nf < 4) return vrGeom_Fail(err, errlen, "a polyhedron needs at least 4 vertices and 4 faces");
    used = calloc(nv, 1);
    if (!used) return vrGeom_Fail(err, errlen, "out of memory");
    for (f = 0; f < nf && rc == 0; f++) {
        if (face_start[f + 1] - face_start[f] < 3)
            rc = vrGeom_Fail(err, errlen, "face %d has fewer than 3 vertices", f);
        for (k = face_start[f]; k < face_start[f + 1] && rc == 0; k++) {
            if (face_vert[k] < 0 || face_vert[k] >= nv)
                rc = vrGeom_Fail(err, errlen, "face %d: vertex index %d out of range", f, face_vert[k]);
            else
                used[face_vert[k]] = 1;
        }
    }
    for (v = 0; v < nv && rc == 0; v++)
        if (!used[v]) rc = vrGeom_Fail(err, errlen, "vertex %d is in no face", v);
    free(used);
    return rc;
}

/* moves the centre of mass to the origin (SPEC 2: the body frame) */
static int centre(vrPolyhedron *p, char *err, size_t errlen)
{
    double volume;
    vec3 c;
    int v;
    vrMass_VolumeCentroid(p, &volume, &c);
    if (!(volume > 0) || !vec3_isfinite(c))
        return vrGeom_Fail(err, errlen, "the faces enclose no volume (flat, or oriented inward)");
    for (v = 0; v < p->nv; v++) p->vert[v] = vec3_sub(p->vert[v], c);
    p->shift = c;
    return 0;
}

/* recentre = 0 for shapes whose centroid is the origin by symmetry: the
 * computed one would only add rounding to every vertex */
static int from_faces(const vec3 *vert, int nv, const int *face_start, const int *face_vert, int nf, double tol,
                      int recentre, vrPolyhedron **out, char *err, size_t errlen)
{
    vrPolyhedron *p;
    int nh, rc;
    *out = NULL;
    if (check_loops(nv, face_start, face_vert, nf, err, errlen) != 0) return -1;
    vrProgress_Now();
    nh = face_start[nf];
    if (nh % 2 != 0) return vrGeom_Fail(err, errlen, "odd number of face sides (not a closed surface)");
    p = poly_alloc(nv, nf, nh);
    if (!p) return vrGeom_Fail(err, errlen, "out of memory");
    memcpy(p->vert, vert, sizeof *vert * nv);
    memcpy(p->face_start, face_start, sizeof *face_start * (nf + 1));
    memcpy(p->face_vert, face_vert, sizeof *face_vert * nh);
    /* a million vertices take seconds: the progress hook hears each stage */
    vrProgress_Now();
    rc = build_graph(p, err, errlen);
    vrProgress_Now();
    if (rc == 0 && recentre) rc = centre(p, err, errlen);
    if (rc == 0) rc = compute_planes(p, err, errlen);
    vrProgress_Now();
    if (rc == 0) rc = check_convex(p, 4 * tol * vrGeom_Size(p->vert, nv), err, errlen);
    vrProgress_Now();
    if (rc != 0) {
        vrPolyhedron_Free(p);
        return -1;
    }
    compute_margins(p);
    vrProgress_Now();
    vrMass_Compute(p);
    vrProgress_Now();
    if (vrFaceGroups_Make(p) != 0) {
        vrPolyhedron_Free(p);
        return vrGeom_Fail(err, errlen, "out of memory");
    }
    vrProgress_Now();
    *out = p;
    return 0;
}

int vrPolyhedron_FromFaces(const vec3 *vert, int nv, const int *face_start, const int *face_vert, int nf,
                           double tol, vrPolyhedron **out, char *err, size_t errlen)
{
    return from_faces(vert, nv, face_start, face_vert, nf, tol, 1, out, err, errlen);
}

int vrPolyhedron_FromCentredFaces(const vec3 *vert, int nv, const int *face_start, const int *face_vert, int nf,
                                  double tol, vrPolyhedron **out, char *err, size_t errlen)
{
    return from_faces(vert, nv, face_start, face_vert, nf, tol, 0, out, err, errlen);
}

int vrPolyhedron_Climb(const vrPolyhedron *p, vec3 d, int v, double *gap)
{
    double h = vec3_dot(d, p->vert[v]), below = -HUGE_VAL;
    int k = p->vert_edge_start[v];
    while (k < p->vert_edge_start[v + 1]) {
        int w = vrPolyhedron_OtherEnd(p, p->vert_edge[k], v);
        double hw = vec3_dot(d, p->vert[w]);
        if (hw > h) { /* move up and scan the new star */
            v = w;
            h = hw;
            below = -HUGE_VAL;
            k = p->vert_edge_start[v];
            continue;
        }
        if (hw > below) below = hw;
        k++;
    }
    if (gap) *gap = h - below;
    return v;
}
