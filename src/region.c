/* region.c — the contact region of a pair (SPEC 2) and the containment
 * test over such regions (SPEC 3.1: a support's centre of mass over its
 * contact region).
 *
 * The region comes from the canonical features (canonical.c): the vertices
 * of each body within d of the other's support plane, projected on the
 * contact plane, hulled and intersected (convex2d.c), lifted to the plane
 * midway between the support planes.
 *   reduce                      at most VR_REGION_MAX points
 *   slab, project               the vertices near the other's plane, in 2-D
 *   at_corner, corner_gap       a region corner's gap: its vertex's height
 *   region_points               their hulls' intersection, lifted
 *   cmp_p2, seg_dist            containment's sort order; distance to a segment
 *   strictly_convex, inside_by  a region as it is; the margin of a point in it
 */
#include <stdlib.h>
#include <string.h>

#include "canonical.h"
#include "convex2d.h"
#include "region.h"

/* at most VR_REGION_MAX points: the extremes of the polygon along as many
 * evenly spread directions, in polygon order */
static int reduce(P2 *p, int n)
{
    int idx[VR_REGION_MAX], i, k, m = 0;
    if (n <= VR_REGION_MAX) return n;
    for (k = 0; k < VR_REGION_MAX; k++) {
        P2 d = p2(cos(2 * VR_PI * k / VR_REGION_MAX), sin(2 * VR_PI * k / VR_REGION_MAX));
        int best = 0;
        for (i = 1; i < n; i++)
            if (p2_dot(d, p[i]) > p2_dot(d, p[best])) best = i;
        /* cppcheck-suppress uninitvar ; idx[0..k-1] are the k written before */
        for (i = k; i > 0 && idx[i - 1] > best; i--) idx[i] = idx[i - 1];
        idx[i] = best;
    }
    for (k = 0; k < VR_REGION_MAX; k++) /* idx ascending: compaction in place is safe */
        if (k == 0 || idx[k] != idx[k - 1]) p[m++] = p[idx[k]];
    return m;
}

/* vertices of b at world height >= floor along n, searched from seed */
static int slab(const vrPosed *b, vec3 n, double floor, int seed, vrIntSet *out)
{
    return vrIntSet_Collect(b->p, mat33_tmulv(&b->pose->R, n), seed, floor - vec3_dot(n, b->pose->p), out);
}

static void project(const vrPosed *b, const vrIntSet *s, vec3 t1, vec3 t2, P2 *out)
{
    int i;
    for (i = 0; i < s->n; i++) {
        vec3 x = vrPosed_Vertex(b, s->v[i]);
        out[i] = p2(vec3_dot(t1, x), vec3_dot(t2, x));
    }
}

/* Step 5: the vertices of each body within d of the other's support plane,
 * projected on the plane normal to n, hulled, intersected, and lifted to the
 * plane midway between the support planes. */
/* is x's projection corner q, within the clipping's tolerance?  A corner
 * that is a vertex of the clipped-by polygon comes out of the clipping as
 * a crossing of lines, its last bits as the rounding fell: matched exactly,
 * a box tilted 3 mrad on a floor had two corners at 1.83 mm at one pose
 * and at 1.0 mm (the support planes' gap) at the next ulp of its turn, and
 * the island's allowance for them gave way to a contact impulse per corner
 * (pile seed 25, frame 481: 1.5e-4 J) */
static int at_corner(vec3 x, vec3 t1, vec3 t2, P2 q)
{
    return fabs(vec3_dot(t1, x) - q.x) <= VR_REGION_SLACK && fabs(vec3_dot(t2, x) - q.y) <= VR_REGION_SLACK;
}

/* the surfaces' gap along n at corner q of the region (region.h): a
 * vertex's own height where a body has one there, else its support plane */
static double corner_gap(const vrPosed *a, const vrPosed *b, const vrCanon *c, const vrIntSet *va, const vrIntSet *vb,
                         vec3 t1, vec3 t2, P2 q)
{
    double ha = c->ha, hb = c->hb;
    int i;
    for (i = 0; i < va->n; i++) {
        vec3 x = vrPosed_Vertex(a, va->v[i]);
        if (at_corner(x, t1, t2, q)) ha = vr_min(ha, vec3_dot(c->n, x));
    }
    for (i = 0; i < vb->n; i++) {
        vec3 x = vrPosed_Vertex(b, vb->v[i]);
        if (at_corner(x, t1, t2, q)) hb = vr_max(hb, vec3_dot(c->n, x));
    }
    return hb - ha;
}

static int region_points(const vrPosed *a, const vrPosed *b, const vrCanon *c, const vrIntSet *va, const vrIntSet *vb,
                         vec3 *point, double *gap, int *npoints)
{
    P2 stack[256], *buf = stack, *pa, *pb, *tmp, *res, *clip;
    int na, nb, m, i, n = va->n + vb->n;
    vec3 t1 = vec3_orthogonal(c->n), t2 = vec3_cross(c->n, t1);
    double mid = 0.5 * (c->ha + c->hb);
    /* a and b's points, the hull's chain (2n), the intersection and its scratch */
    if (5 * n + 6 > 256 && !(buf = malloc((5 * (size_t)n + 6) * sizeof *buf))) return -1;
    pa = buf, pb = pa + va->n, tmp = pb + vb->n, res = tmp + 2 * n + 2, clip = res + n + 2;
    project(a, va, t1, t2, pa);
    project(b, vb, t1, t2, pb);
    na = vrP2_Hull(pa, va->n, tmp);
    nb = vrP2_Hull(pb, vb->n, tmp);
    m = reduce(res, vrP2_IntersectHulls(pa, na, pb, nb, res, clip));
    for (i = 0; i < m; i++) {
        point[i] = vec3_madd(vec3_add(vec3_scale(t1, res[i].x), vec3_scale(t2, res[i].y)), mid, c->n);
        gap[i] = corner_gap(a, b, c, va, vb, t1, t2, res[i]);
    }
    *npoints = m;
    if (m == 0) { /* tolerance corner cases */
        *npoints = 1;
        point[0] = vec3_lerp(c->qa, c->qb, 0.5);
        gap[0] = c->dist;
    }
    if (buf != stack) free(buf);
    return 0;
}

int vrRegion_Points(const vrPosed *a, const vrPosed *b, const vrCanon *c, double d, vec3 *point, double *gap,
                    int *npoints)
{
    vrIntSet va, vb;
    int rc;
    vrIntSet_Init(&va);
    vrIntSet_Init(&vb);
    rc = slab(b, vec3_neg(c->n), -(c->ha + d + VR_REGION_SLACK), c->sb.v.v[0], &vb)
      || slab(a, c->n, c->hb - d - VR_REGION_SLACK, c->sa.v.v[0], &va)
      || region_points(a, b, c, &va, &vb, point, gap, npoints);
    vrIntSet_Free(&va);
    vrIntSet_Free(&vb);
    return rc ? -1 : 0;
}

/* ---- support containment (SPEC 3.1) ------------------------------------- */

static int cmp_p2(const void *a, const void *b)
{
    const P2 *p = a, *q = b;
    return p2_less(*p, *q) ? -1 : p2_less(*q, *p);
}

/* distance from the origin to segment ab */
static double seg_dist(P2 a, P2 b)
{
    double ex = b.x - a.x, ey = b.y - a.y, l2 = ex * ex + ey * ey;
    double s = l2 > 0 ? -(a.x * ex + a.y * ey) / l2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    return hypot(a.x + s * ex, a.y + s * ey);
}

/* Does p[0..n) go once round a convex polygon counter-clockwise, every
 * corner turning left by more than rounding (sine above TURN_MIN), all
 * seen from p[0] in order within half a turn (left turns alone also let a
 * star go round twice)?  A region made by region_points does, in one
 * sense or the other; its hull is then itself, as the monotone chain
 * would find it, and the edge tests give the same bits. */
#define TURN_MIN 1e-9

static int strictly_convex(const P2 *p, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        P2 a = p[i], b = p[(i + 1) % n], c = p[(i + 2) % n], ab = p2_sub(b, a), bc = p2_sub(c, b);
        double turn = p2_turn(a, b, c);
        if (!(turn > 0 && turn * turn > TURN_MIN * TURN_MIN * p2_dot(ab, ab) * p2_dot(bc, bc))) return 0;
    }
    for (i = 2; i < n; i++)      /* left of p[0]->p[1], and turning on: within half a turn */
        if (!(p2_turn(p[0], p[1], p[i]) > 0 && p2_turn(p[0], p[i - 1], p[i]) > 0)) return 0;
    return 1;
}

/* how far the origin lies inside convex counter-clockwise polygon h */
static double inside_by(const P2 *h, int k)
{
    double margin = INFINITY;
    int i;
    for (i = 0; i < k; i++) {
        P2 a = h[i], b = h[(i + 1) % k];
        double len = p2_len(p2_sub(b, a)), in;
        if (!(len > 0)) continue;
        in = p2_turn(a, b, p2(0, 0)) / len;
        if (in < margin) margin = in;
    }
    return margin;
}

/* a contact region as it is (convex, in order), else Andrew's monotone
 * chain first; then edge tests */
double vrRegion_Margin(const vec3 *pts, int n, vec3 nrm, vec3 q)
{
    vec3 t1 = vec3_orthogonal(nrm), t2 = vec3_cross(nrm, t1);
    P2 small[VR_REGION_MAX], hsmall[2 * VR_REGION_MAX], *p = small, *h = hsmall;
    int i, k;
    double margin = INFINITY;
    if (n > VR_REGION_MAX) {       /* several supports' regions together */
        p = malloc((size_t)n * sizeof *p);
        h = malloc((size_t)(2 * n) * sizeof *h);
        if (!p || !h) {
            free(p == small ? NULL : p);
            free(h == hsmall ? NULL : h);
            return -INFINITY;
        }
    }
    for (i = 0; i < n; i++) {
        vec3 d = vec3_sub(pts[i], q);
        p[i].x = vec3_dot(d, t1);
        p[i].y = vec3_dot(d, t2);
    }
    if (n >= 3 && n <= VR_REGION_MAX) {
        if (strictly_convex(p, n)) return inside_by(p, n);
        for (i = 0; i < n; i++) h[i] = p[n - 1 - i];     /* the other sense */
        if (strictly_convex(h, n)) return inside_by(h, n);
    }
    qsort(p, (size_t)n, sizeof *p, cmp_p2);
    k = vrP2_Chain(p, n, h);
    if (k > 1) k--;                                /* the last point repeats the first */
    if (k == 1) margin = -hypot(h[0].x, h[0].y);
    else if (k == 2) margin = -seg_dist(h[0], h[1]);
    if (k > 2) margin = inside_by(h, k);
    if (p != small) free(p);
    if (h != hsmall) free(h);
    return margin;
}

int vrRegion_Contains(const vec3 *pts, int n, vec3 nrm, vec3 q, double tol)
{
    return vrRegion_Margin(pts, n, nrm, q) >= -tol;
}
