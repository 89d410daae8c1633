/* closest_exhaustive.c — the exhaustive search that answers a closest-
 * feature query when the walk (closest.c) hits its step cap or ends on a
 * pair whose plane does not separate the bodies: the same features and
 * points the walk would end on, from every pair of features.
 *
 *   pair_points      a final pair's closest points: vertex-anything or edge-edge
 *   cull_*           the features that can matter: those in a slab between the bodies
 *   find_piercing    an edge of one side piercing a face of the other
 *   find_contained   one polyhedron inside the other
 *   nearest_pair     the separated minimum: a vertex over a face, or two edges
 *   vrWalk_Exhaustive   the search, in that order
 *
 * Every feature against every other is O(E F): two superquadrics of 150 x
 * 150 points touching in a pile took tens of seconds a search (the walk
 * ended on two edges a hair apart and a hair off parallel, whose plane
 * could not be shown to separate them).  So the search skips the
 * features that cannot be part of its answer.  Along a unit direction u
 * (frame 0) side 0 reaches at most hi0 and side 1 starts at lo1; the walk
 * holds a point of each body, g apart.  A vertex of side 0 below lo1 - g
 * is more than g from every point of side 1, and a vertex of side 1 above
 * hi0 + g more than g from side 0; so is a feature whose vertices all are
 * (u.x is linear).  Such a feature is in no pair nearer than g, the
 * minimum is at most g, and an edge crossing a face does so at a point of
 * both bodies, inside [lo1, hi0]: the search finds what it found over every
 * feature, the first pair in its order, among far fewer when the bodies
 * are close along u.  u is the best separating of a few candidates: the
 * walk's closest-points direction and the faces beside its features.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "closest_exhaustive.h"
#include "polyhedron.h"
#include "segment.h"
#include "voronoi.h"

enum { GO = VR_WALK_GO, DONE = VR_WALK_DONE };

/* closest points (frame 0) of a final pair: vertex-anything or edge-edge */
static void pair_points(const vrWalk *w, vec3 *c0, vec3 *c1)
{
    vec3 c[2];
    int i, j;
    if (w->f[0].type == VR_EDGE && w->f[1].type == VR_EDGE) {
        const int *e0 = w->p[0]->edge_v[w->f[0].index], *e1 = w->p[1]->edge_v[w->f[1].index];
        vec3 a0 = w->p[0]->vert[e0[0]], a1 = w->p[0]->vert[e0[1]];
        vec3 b0 = vert_in_other(w, 1, e1[0]), b1 = vert_in_other(w, 1, e1[1]);
        double s, t;
        vrSegment_ClosestParams(a0, a1, b0, b1, &s, &t);
        *c0 = vec3_lerp(a0, a1, s);
        *c1 = vec3_lerp(b0, b1, t);
        return;
    }
    i = w->f[0].type == VR_VERTEX ? 0 : 1;
    j = 1 - i;
    c[i] = in_frame0(w, i, w->p[i]->vert[w->f[i].index]);
    c[j] = in_frame0(w, j, vrVoronoi_ClosestOnFeature(w->p[j], w->f[j], vert_in_other(w, i, w->f[i].index)));
    *c0 = c[0];
    *c1 = c[1];
}

/* a vertex's height along u past the slab's edge is this far, by rounding
 * alone, at most (per metre of the bodies' size) */
#define CULL_TOL 1e-9

/* which features of each side can be in the answer (NULL: all) */
typedef struct Cull { unsigned char *edge[2], *face[2], *vert[2]; void *mem; } Cull;

static vec3 vert0(const vrWalk *w, int i, int v) { return in_frame0(w, i, w->p[i]->vert[v]); }

/* a point of each body the walk holds, and their distance: a vertex of
 * each feature, or, with no face among them, the features' closest
 * points (pair_points takes a vertex's foot on a face's plane, which may
 * lie off the face: no point of the body) */
static double walk_gap(const vrWalk *w)
{
    double g = vec3_dist(vert0(w, 0, vrFeature_Vertex(w->p[0], w->f[0])), vert0(w, 1, vrFeature_Vertex(w->p[1], w->f[1])));
    vec3 c0, c1;
    if (w->f[0].type != VR_FACE && w->f[1].type != VR_FACE) {
        pair_points(w, &c0, &c1);
        g = fmin(g, vec3_dist(c0, c1));
    }
    return g;
}

/* side 0's highest and side 1's lowest along u (frame 0), over every vertex */
static void extents(const vrWalk *w, vec3 u, double *hi0, double *lo1)
{
    int v;
    *hi0 = -HUGE_VAL, *lo1 = HUGE_VAL;
    for (v = 0; v < w->p[0]->nv; v++) *hi0 = fmax(*hi0, vec3_dot(u, w->p[0]->vert[v]));
    for (v = 0; v < w->p[1]->nv; v++) *lo1 = fmin(*lo1, vec3_dot(u, vert0(w, 1, v)));
}

/* the faces beside side i's feature, their outward normals (frame 0,
 * pointing from side 0 to side 1): at most two */
static int beside(const vrWalk *w, int i, vec3 *n)
{
    const vrPolyhedron *p = w->p[i];
    int k, m = 0, f[2];
    if (w->f[i].type == VR_FACE) f[m++] = w->f[i].index;
    else if (w->f[i].type == VR_EDGE) f[m++] = p->edge_f[w->f[i].index][0], f[m++] = p->edge_f[w->f[i].index][1];
    for (k = 0; k < m; k++) n[k] = i ? vec3_neg(rotate_other(w, 1, p->face_normal[f[k]])) : p->face_normal[f[k]];
    return m;
}

/* the slab's masks, or none (every feature) when memory runs out */
static void cull_make(const vrWalk *w, Cull *c)
{
    vec3 cand[5], best = vec3_zero(), d = vec3_sub(vert0(w, 1, vrFeature_Vertex(w->p[1], w->f[1])),
                                                  vert0(w, 0, vrFeature_Vertex(w->p[0], w->f[0])));
    double g = walk_gap(w), most = -HUGE_VAL, hi0 = 0, lo1 = 0, size = w->p[0]->r_out + w->p[1]->r_out + vec3_len(w->t);
    size_t n = 0;
    int k, m = 0, i, v, e, f;
    unsigned char *at;
    memset(c, 0, sizeof *c);
    if (vec3_len(d) > 0) cand[m++] = vec3_normalize(d);
    m += beside(w, 0, cand + m);
    m += beside(w, 1, cand + m);
    for (k = 0; k < m; k++) {
        double hi, lo;
        extents(w, cand[k], &hi, &lo);
        if (lo - hi > most) most = lo - hi, best = cand[k], hi0 = hi, lo1 = lo;
    }
    if (m == 0 || !isfinite(g) || !isfinite(most)) return;
    for (i = 0; i < 2; i++) n += (size_t)w->p[i]->nv + (size_t)w->p[i]->ne + (size_t)w->p[i]->nf;
    if (!(c->mem = malloc(n))) return;
    at = c->mem;
    for (i = 0; i < 2; i++) {
        const vrPolyhedron *p = w->p[i];
        double edge = i ? hi0 + g + CULL_TOL * size : lo1 - g - CULL_TOL * size;
        c->vert[i] = at, c->edge[i] = at + p->nv, c->face[i] = at + p->nv + p->ne;
        at += p->nv + p->ne + p->nf;
        for (v = 0; v < p->nv; v++) {
            double h = vec3_dot(best, vert0(w, i, v));
            c->vert[i][v] = i ? h <= edge : h >= edge;
        }
        for (e = 0; e < p->ne; e++) c->edge[i][e] = c->vert[i][p->edge_v[e][0]] | c->vert[i][p->edge_v[e][1]];
        for (f = 0; f < p->nf; f++) {
            c->face[i][f] = 0;
            for (k = p->face_start[f]; k < p->face_start[f + 1] && !c->face[i][f]; k++) c->face[i][f] = c->vert[i][p->face_vert[k]];
        }
    }
}

static int cull_edge(const Cull *c, int i, int e) { return c->edge[i] && !c->edge[i][e]; }
static int cull_face(const Cull *c, int i, int f) { return c->face[i] && !c->face[i][f]; }
static int cull_vert(const Cull *c, int i, int v) { return c->vert[i] && !c->vert[i][v]; }

/* an edge of side i piercing a face of side 1-i */
static int find_piercing(vrWalk *w, const Cull *c, int i)
{
    int j = 1 - i, e, f;
    const vrPolyhedron *p = w->p[i], *q = w->p[j];
    for (e = 0; e < p->ne; e++) {
        vec3 t, h;
        if (cull_edge(c, i, e)) continue;
        t = vert_in_other(w, i, p->edge_v[e][0]), h = vert_in_other(w, i, p->edge_v[e][1]);
        for (f = 0; f < q->nf; f++) {
            double lo, hi, dl, du;
            if (cull_face(c, j, f) || !vrVoronoi_ClipToFace(q, f, t, h, &lo, &hi)) continue;
            dl = vrPolyhedron_FaceHeight(q, f, vec3_lerp(t, h, lo));
            du = vrPolyhedron_FaceHeight(q, f, vec3_lerp(t, h, hi));
            if ((dl < 0 && du > 0) || (dl > 0 && du < 0)) {
                w->f[i] = vrFeature_Make(VR_EDGE, e);
                w->f[j] = vrFeature_Make(VR_FACE, f);
                return penetrating(w, 0, in_frame0(w, j, vec3_lerp(t, h, lo + (hi - lo) * dl / (dl - du))));
            }
        }
    }
    return GO;
}

/* vertex 0 of side i inside side 1-i (one polyhedron inside the other) */
static int find_contained(vrWalk *w, int i)
{
    int j = 1 - i, f;
    vec3 x = vert_in_other(w, i, 0);
    for (f = 0; f < w->p[j]->nf; f++)
        if (vrPolyhedron_FaceHeight(w->p[j], f, x) > 0) return GO;
    w->f[i] = vrFeature_Make(VR_VERTEX, 0);
    w->f[j] = vrFeature_Make(VR_FACE, 0);
    return penetrating(w, 0, in_frame0(w, j, x));
}

/* the separated minimum is attained by a vertex over a face or by two edges */
static void nearest_pair(vrWalk *w, const Cull *c)
{
    double best = HUGE_VAL;
    int i, v, f, e0, e1;
    for (i = 0; i < 2; i++) {
        const vrPolyhedron *q = w->p[1 - i];
        for (v = 0; v < w->p[i]->nv; v++) {
            vec3 x;
            if (cull_vert(c, i, v)) continue;
            x = vert_in_other(w, i, v);
            for (f = 0; f < q->nf; f++) {
                double h;
                if (cull_face(c, 1 - i, f)) continue;
                h = vrPolyhedron_FaceHeight(q, f, x);
                if (h < 0 || h >= best || !vrVoronoi_InPrism(q, f, x)) continue;
                best = h;
                w->f[i] = vrFeature_Make(VR_VERTEX, v);
                w->f[1 - i] = vrFeature_Make(VR_FACE, f);
            }
        }
    }
    for (e0 = 0; e0 < w->p[0]->ne; e0++) {
        vec3 a0 = w->p[0]->vert[w->p[0]->edge_v[e0][0]], a1 = w->p[0]->vert[w->p[0]->edge_v[e0][1]];
        if (cull_edge(c, 0, e0)) continue;
        for (e1 = 0; e1 < w->p[1]->ne; e1++) {
            vec3 b0, b1;
            double s, t, d;
            if (cull_edge(c, 1, e1)) continue;
            b0 = vert_in_other(w, 1, w->p[1]->edge_v[e1][0]), b1 = vert_in_other(w, 1, w->p[1]->edge_v[e1][1]);
            vrSegment_ClosestParams(a0, a1, b0, b1, &s, &t);
            d = vec3_dist(vec3_lerp(a0, a1, s), vec3_lerp(b0, b1, t));
            if (d >= best) continue;
            best = d;
            w->f[0] = vrFeature_Make(VR_EDGE, e0);
            w->f[1] = vrFeature_Make(VR_EDGE, e1);
        }
    }
}

static int search(vrWalk *w, const Cull *c)
{
    int i, r;
    for (i = 0; i < 2; i++)
        if ((r = find_piercing(w, c, i)) != GO || (r = find_contained(w, i)) != GO) return r;
    nearest_pair(w, c);
    pair_points(w, &w->c[0], &w->c[1]);
    return DONE;
}

int vrWalk_Exhaustive(vrWalk *w)
{
    Cull c;
    int r;
    cull_make(w, &c);
    r = search(w, &c);
    free(c.mem);
    return r;
}

int vrWalk_ExhaustiveAll(vrWalk *w)
{
    Cull none;
    memset(&none, 0, sizeof none);
    return search(w, &none);
}
