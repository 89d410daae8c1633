/* brute_distance.c — the tests' reference distance (brute_distance.h).
 *
 * World-space vertices, faces as triangle fans, closest point on a triangle
 * by the triangle's Voronoi regions, segment-segment distance as the minimum
 * over its candidates; bounding spheres of edges and fan triangles skip the
 * pairs that cannot beat the best so far.
 *   bf_closest_on_triangle   closest point of a triangle (Ericson 5.1.5)
 *   bf_point_segment         distance of a point to a segment
 *   bf_segment_segment       distance of two segments
 *   bf_segment_hits_triangle does a segment cross a triangle
 *   bf_body, bf_body_free    a polyhedron in world space with edge spheres
 *   bf_one_way               vertices of one over faces of the other
 *   bf_edges                 every edge pair
 *   bf_inside                a point inside a polyhedron
 */
#include <stdlib.h>

#include "brute_distance.h"

static vec3 bf_closest_on_triangle(vec3 x, vec3 a, vec3 b, vec3 c)
{
    vec3 ab = vec3_sub(b, a), ac = vec3_sub(c, a), ax = vec3_sub(x, a), bx, cx;
    double d1 = vec3_dot(ab, ax), d2 = vec3_dot(ac, ax), d3, d4, d5, d6, va, vb, vc, den;
    if (d1 <= 0 && d2 <= 0) return a;
    bx = vec3_sub(x, b);
    d3 = vec3_dot(ab, bx);
    d4 = vec3_dot(ac, bx);
    if (d3 >= 0 && d4 <= d3) return b;
    vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return vec3_madd(a, d1 / (d1 - d3), ab);
    cx = vec3_sub(x, c);
    d5 = vec3_dot(ab, cx);
    d6 = vec3_dot(ac, cx);
    if (d6 >= 0 && d5 <= d6) return c;
    vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return vec3_madd(a, d2 / (d2 - d6), ac);
    va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return vec3_madd(b, (d4 - d3) / ((d4 - d3) + (d5 - d6)), vec3_sub(c, b));
    den = 1.0 / (va + vb + vc);
    return vec3_add(a, vec3_add(vec3_scale(ab, vb * den), vec3_scale(ac, vc * den)));
}

static double bf_point_segment(vec3 x, vec3 a, vec3 b)
{
    vec3 d = vec3_sub(b, a);
    double t = vec3_dot(vec3_sub(x, a), d) / vec3_len2(d);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return vec3_dist(x, vec3_madd(a, t, d));
}

static double bf_segment_segment(vec3 a, vec3 b, vec3 c, vec3 d)
{
    vec3 u = vec3_sub(b, a), v = vec3_sub(d, c), w0 = vec3_sub(a, c);
    double uu = vec3_dot(u, u), uv = vec3_dot(u, v), vv = vec3_dot(v, v);
    double uw = vec3_dot(u, w0), vw = vec3_dot(v, w0), den = uu * vv - uv * uv;
    double best = bf_point_segment(a, c, d), m;
    if ((m = bf_point_segment(b, c, d)) < best) best = m;
    if ((m = bf_point_segment(c, a, b)) < best) best = m;
    if ((m = bf_point_segment(d, a, b)) < best) best = m;
    if (den > 0) { /* the interior critical point of the two lines */
        double s = (uv * vw - vv * uw) / den, t = (uu * vw - uv * uw) / den;
        if (s > 0 && s < 1 && t > 0 && t < 1) {
            m = vec3_dist(vec3_madd(a, s, u), vec3_madd(c, t, v));
            if (m < best) best = m;
        }
    }
    return best;
}

/* segment pq through triangle abc of normal n = (b - a) x (c - a) */
static int bf_segment_hits_triangle(vec3 p, vec3 q, vec3 a, vec3 b, vec3 c, vec3 n)
{
    vec3 x;
    double dp = vec3_dot(n, vec3_sub(p, a)), dq = vec3_dot(n, vec3_sub(q, a));
    if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return 0;
    x = vec3_lerp(p, q, dp / (dp - dq));
    return vec3_dot(n, vec3_cross(vec3_sub(b, a), vec3_sub(x, a))) >= 0
        && vec3_dot(n, vec3_cross(vec3_sub(c, b), vec3_sub(x, b))) >= 0
        && vec3_dot(n, vec3_cross(vec3_sub(a, c), vec3_sub(x, c))) >= 0;
}

/* a polyhedron in world space, with bounding spheres of its edges that let
 * the search skip pairs that cannot beat the best so far */
typedef struct BfBody {
    const vrPolyhedron *p;
    vec3 *w;        /* nv world vertices */
    vec3 *mid;      /* ne edge midpoints */
    double *half;   /* ne half lengths */
} BfBody;

static int bf_body(BfBody *b, const vrPolyhedron *p, const vrPose *pose)
{
    int i;
    b->p = p;
    b->w = malloc((size_t)p->nv * sizeof *b->w);
    b->mid = malloc((size_t)p->ne * sizeof *b->mid);
    b->half = malloc((size_t)p->ne * sizeof *b->half);
    if (!b->w || !b->mid || !b->half) return -1;
    for (i = 0; i < p->nv; i++) b->w[i] = vrPose_apply(pose, p->vert[i]);
    for (i = 0; i < p->ne; i++) {
        vec3 t = b->w[p->edge_v[i][0]], h = b->w[p->edge_v[i][1]];
        b->mid[i] = vec3_lerp(t, h, 0.5);
        b->half[i] = 0.5 * vec3_dist(t, h);
    }
    return 0;
}

static void bf_body_free(BfBody *b)
{
    free(b->w);
    free(b->mid);
    free(b->half);
}

/* min over vertices of p over faces of q (as triangle fans), or 0 when an
 * edge of p crosses a face of q; fan triangles of no area are skipped (their
 * boundary edges are covered by the edge-edge pairs) */
static double bf_one_way(const BfBody *p, const BfBody *q)
{
    double best = HUGE_VAL;
    int v, e, f, k;
    for (f = 0; f < q->p->nf; f++)
        for (k = 1; k + 1 < vrPolyhedron_FaceSize(q->p, f); k++) {
            const int *fv = q->p->face_vert + q->p->face_start[f];
            vec3 a = q->w[fv[0]], b = q->w[fv[k]], c = q->w[fv[k + 1]];
            vec3 n = vec3_cross(vec3_sub(b, a), vec3_sub(c, a)), o = vec3_scale(vec3_add(a, vec3_add(b, c)), 1.0 / 3);
            double rho = vec3_dist(o, a), m;
            if ((m = vec3_dist(o, b)) > rho) rho = m;
            if ((m = vec3_dist(o, c)) > rho) rho = m;
            if (vec3_len2(n) <= 1e-30) continue;
            for (e = 0; e < p->p->ne; e++)
                if (vec3_dist(p->mid[e], o) <= rho + p->half[e]
                    && bf_segment_hits_triangle(p->w[p->p->edge_v[e][0]], p->w[p->p->edge_v[e][1]], a, b, c, n))
                    return 0;
            for (v = 0; v < p->p->nv; v++) {
                double d;
                if (vec3_dist(p->w[v], o) - rho >= best) continue;
                d = vec3_dist(p->w[v], bf_closest_on_triangle(p->w[v], a, b, c));
                if (d < best) best = d;
            }
        }
    return best;
}

static double bf_edges(const BfBody *a, const BfBody *b, double best)
{
    int i, j;
    for (i = 0; i < a->p->ne; i++)
        for (j = 0; j < b->p->ne; j++) {
            double d;
            if (vec3_dist(a->mid[i], b->mid[j]) - a->half[i] - b->half[j] >= best) continue;
            d = bf_segment_segment(a->w[a->p->edge_v[i][0]], a->w[a->p->edge_v[i][1]], b->w[b->p->edge_v[j][0]],
                                   b->w[b->p->edge_v[j][1]]);
            if (d < best) best = d;
        }
    return best;
}

/* world point x inside q: beneath every face plane, each plane taken from
 * the face's vertices by Newell's method */
static int bf_inside(const BfBody *q, vec3 x)
{
    int f, k;
    for (f = 0; f < q->p->nf; f++) {
        const int *fv = q->p->face_vert + q->p->face_start[f];
        int m = vrPolyhedron_FaceSize(q->p, f);
        vec3 n = vec3_zero();
        for (k = 0; k < m; k++) n = vec3_add(n, vec3_cross(q->w[fv[k]], q->w[fv[(k + 1) % m]]));
        if (vec3_dot(n, vec3_sub(x, q->w[fv[0]])) > 0) return 0;
    }
    return 1;
}

double vrClosest_BruteForce(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb)
{
    BfBody ba = {NULL, NULL, NULL, NULL}, bb = ba;
    double best = HUGE_VAL, d;
    if (bf_body(&ba, a, pa) == 0 && bf_body(&bb, b, pb) == 0) {
        if (bf_inside(&bb, ba.w[0]) || bf_inside(&ba, bb.w[0])) {
            best = 0;
        } else {
            best = bf_one_way(&ba, &bb);
            if (best > 0 && (d = bf_one_way(&bb, &ba)) < best) best = d;
            if (best > 0) best = bf_edges(&ba, &bb, best);
        }
    }
    bf_body_free(&ba);
    bf_body_free(&bb);
    return best;
}
