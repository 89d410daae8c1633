/* closest_exhaustive.c — the exhaustive search that answers a closest-
 * feature query when the walk (closest.c) hits its step cap or ends on a
 * pair whose plane does not separate the bodies: the same features and
 * points the walk would end on, from every pair of features.
 *
 *   pair_points      a final pair's closest points: vertex-anything or edge-edge
 *   find_piercing    an edge of one side piercing a face of the other
 *   find_contained   one polyhedron inside the other
 *   nearest_pair     the separated minimum: a vertex over a face, or two edges
 *   vrWalk_Exhaustive   the search, in that order
 */
#include <math.h>

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

/* an edge of side i piercing a face of side 1-i */
static int find_piercing(vrWalk *w, int i)
{
    int j = 1 - i, e, f;
    const vrPolyhedron *p = w->p[i], *q = w->p[j];
    for (e = 0; e < p->ne; e++) {
        vec3 t = vert_in_other(w, i, p->edge_v[e][0]), h = vert_in_other(w, i, p->edge_v[e][1]);
        for (f = 0; f < q->nf; f++) {
            double lo, hi, dl, du;
            if (!vrVoronoi_ClipToFace(q, f, t, h, &lo, &hi)) continue;
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
static void nearest_pair(vrWalk *w)
{
    double best = HUGE_VAL;
    int i, v, f, e0, e1;
    for (i = 0; i < 2; i++) {
        const vrPolyhedron *q = w->p[1 - i];
        for (v = 0; v < w->p[i]->nv; v++) {
            vec3 x = vert_in_other(w, i, v);
            for (f = 0; f < q->nf; f++) {
                double h = vrPolyhedron_FaceHeight(q, f, x);
                if (h < 0 || h >= best || !vrVoronoi_InPrism(q, f, x)) continue;
                best = h;
                w->f[i] = vrFeature_Make(VR_VERTEX, v);
                w->f[1 - i] = vrFeature_Make(VR_FACE, f);
            }
        }
    }
    for (e0 = 0; e0 < w->p[0]->ne; e0++)
        for (e1 = 0; e1 < w->p[1]->ne; e1++) {
            vec3 a0 = w->p[0]->vert[w->p[0]->edge_v[e0][0]], a1 = w->p[0]->vert[w->p[0]->edge_v[e0][1]];
            vec3 b0 = vert_in_other(w, 1, w->p[1]->edge_v[e1][0]), b1 = vert_in_other(w, 1, w->p[1]->edge_v[e1][1]);
            double s, t, d;
            vrSegment_ClosestParams(a0, a1, b0, b1, &s, &t);
            d = vec3_dist(vec3_lerp(a0, a1, s), vec3_lerp(b0, b1, t));
            if (d >= best) continue;
            best = d;
            w->f[0] = vrFeature_Make(VR_EDGE, e0);
            w->f[1] = vrFeature_Make(VR_EDGE, e1);
        }
}

int vrWalk_Exhaustive(vrWalk *w)
{
    int i, r;
    for (i = 0; i < 2; i++)
        if ((r = find_piercing(w, i)) != GO || (r = find_contained(w, i)) != GO) return r;
    nearest_pair(w);
    pair_points(w, &w->c[0], &w->c[1]);
    return DONE;
}
