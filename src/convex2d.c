/* convex2d.c — 2-D convex geometry in the contact plane: the hull of a
 * point set, and the intersection of two hulls (SPEC 2: a face-face pair's
 * region is the clipped overlap of the faces), with the region's
 * tolerances.
 *   p2_sort, p2_apart, p2_dedup  sorting, and points closer than VR_REGION_DEDUP
 *   side                         signed distance from a line
 *   thin_to_segment              a hull too thin to clip with, as its segment
 *   clip_halfplane               Sutherland-Hodgman against one edge
 *   intersect_segments           two segments (or points)
 */
#include <string.h>

#include "convex2d.h"

static void p2_sort(P2 *p, int n)
{
    int i, j;
    for (i = 1; i < n; i++) {
        P2 x = p[i];
        for (j = i; j > 0 && p2_less(x, p[j - 1]); j--) p[j] = p[j - 1];
        p[j] = x;
    }
}

/* a and b lie more than VR_REGION_DEDUP apart (squared: a root is slow) */
static int p2_apart(P2 a, P2 b)
{
    P2 d = p2_sub(a, b);
    return p2_dot(d, d) > VR_REGION_DEDUP * VR_REGION_DEDUP;
}

/* drop points within VR_REGION_DEDUP of their predecessor (cyclically) */
static int p2_dedup(P2 *p, int n)
{
    int i, m = 0;
    for (i = 0; i < n; i++)
        if (m == 0 || p2_apart(p[i], p[m - 1])) p[m++] = p[i];
    while (m > 1 && !p2_apart(p[m - 1], p[0])) m--;
    return m;
}

int vrP2_Chain(const P2 *p, int n, P2 *h)
{
    int i, k = 0, lower;
    for (i = 0; i < n; i++) {
        while (k >= 2 && p2_turn(h[k - 2], h[k - 1], p[i]) <= 0) k--;
        h[k++] = p[i];
    }
    for (i = n - 2, lower = k + 1; i >= 0; i--) {
        while (k >= lower && p2_turn(h[k - 2], h[k - 1], p[i]) <= 0) k--;
        h[k++] = p[i];
    }
    return k;
}

int vrP2_Hull(P2 *p, int n, P2 *tmp)
{
    int k;
    p2_sort(p, n);
    n = p2_dedup(p, n);
    if (n < 3) return n;
    k = vrP2_Chain(p, n, tmp);
    k--; /* the first point closes the loop */
    memcpy(p, tmp, (size_t)k * sizeof *p);
    return p2_dedup(p, k);
}

/* signed distance of x to the left of line a->b (metres) */
static double side(P2 a, P2 b, P2 x) { return p2_cross(p2_sub(b, a), p2_sub(x, a)) / p2_len(p2_sub(b, a)); }

/* The point, segment or polygon `in` clipped to the left of a->b, with the
 * containment tolerance; crossings are cut on the line itself. */
static int clip_halfplane(const P2 *in, int n, P2 a, P2 b, P2 *out)
{
    int i, m = 0;
    if (n == 2) { /* a segment is not a closed loop */
        double s0 = side(a, b, in[0]), s1 = side(a, b, in[1]);
        if (s0 < -VR_REGION_SLACK && s1 < -VR_REGION_SLACK) return 0;
        out[0] = s0 < -VR_REGION_SLACK ? p2_lerp(in[0], in[1], s0 / (s0 - s1)) : in[0];
        out[1] = s1 < -VR_REGION_SLACK ? p2_lerp(in[0], in[1], s0 / (s0 - s1)) : in[1];
        return 2;
    }
    for (i = 0; i < n; i++) { /* Sutherland-Hodgman */
        P2 c = in[i], d = in[(i + 1) % n];
        double sc = side(a, b, c), sd = side(a, b, d);
        int ic = sc >= -VR_REGION_SLACK, id = sd >= -VR_REGION_SLACK;
        if (ic) out[m++] = c;
        if (ic != id && n > 1) {
            double t = sc / (sc - sd);
            out[m++] = p2_lerp(c, d, t < 0 ? 0 : t > 1 ? 1 : t);
        }
    }
    return m;
}

/* two segments (a point is a segment of equal ends), within the tolerance */
static int intersect_segments(const P2 *p, const P2 *q, P2 *out)
{
    P2 d1 = p2_sub(p[1], p[0]), d2 = p2_sub(q[1], q[0]), r = p2_sub(q[0], p[0]);
    double den = p2_cross(d1, d2), l1 = p2_len(d1), l2 = p2_len(d2), u0, u1, lo, hi;
    if (fabs(den) > 1e-12 * l1 * l2) { /* crossing lines */
        double s = p2_cross(r, d2) / den, t = p2_cross(r, d1) / den;
        double ts = VR_REGION_SLACK / l1, tt = VR_REGION_SLACK / l2;
        if (s < -ts || s > 1 + ts || t < -tt || t > 1 + tt) return 0;
        out[0] = p2_lerp(p[0], p[1], s < 0 ? 0 : s > 1 ? 1 : s);
        return 1;
    }
    if (l1 < l2) { /* parallel or points: measure along the longer one, p */
        const P2 *x = p;
        p = q;
        q = x;
        d1 = d2;
        l1 = l2;
    }
    if (l1 <= VR_REGION_DEDUP) { /* two points */
        if (p2_len(p2_sub(q[0], p[0])) > VR_REGION_SLACK) return 0;
        out[0] = p2_lerp(p[0], q[0], 0.5);
        return 1;
    }
    if (fabs(side(p[0], p[1], q[0])) > VR_REGION_SLACK || fabs(side(p[0], p[1], q[1])) > VR_REGION_SLACK) return 0;
    u0 = p2_dot(p2_sub(q[0], p[0]), d1) / (l1 * l1);
    u1 = p2_dot(p2_sub(q[1], p[0]), d1) / (l1 * l1);
    lo = u0 < u1 ? u0 : u1;
    hi = u0 < u1 ? u1 : u0;
    if (lo < 0) lo = 0;
    if (hi > 1) hi = 1;
    if (lo > hi + VR_REGION_SLACK / l1) return 0;
    if (lo > hi) lo = hi = 0.5 * (lo + hi);
    out[0] = p2_lerp(p[0], p[1], lo);
    out[1] = p2_lerp(p[0], p[1], hi);
    return p2_dedup(out, 2);
}

/* A hull no wider than VR_REGION_SLACK about the line through its two
 * farthest points is that segment.  As a polygon its edges lie along the
 * line, and their half-planes, each taken within VR_REGION_SLACK, let the
 * whole line through: a superquadric's edge on a wall made a region as
 * long as the wall, whose far points' bounce floors were 80 m/s. */
static int thin_to_segment(P2 *p, int n)
{
    int i, a = 0, b = 0;
    double far = -1;
    P2 x, y;
    if (n < 3) return n;
    for (i = 1; i < n; i++)
        if (p2_len(p2_sub(p[i], p[0])) > far) far = p2_len(p2_sub(p[i], p[0])), b = i;
    for (i = 0, far = -1; i < n; i++)
        if (p2_len(p2_sub(p[i], p[b])) > far) far = p2_len(p2_sub(p[i], p[b])), a = i;
    if (!(far > VR_REGION_DEDUP)) return n;
    for (i = 0; i < n; i++)
        if (fabs(side(p[a], p[b], p[i])) > VR_REGION_SLACK) return n;
    x = p[a], y = p[b];
    p[0] = x, p[1] = y;
    return 2;
}

/* clip the other by the polygon's edges */
int vrP2_IntersectHulls(P2 *p, int np, P2 *q, int nq, P2 *out, P2 *buf)
{
    int k, n;
    P2 *cur = out, *next = buf, *swap;
    np = thin_to_segment(p, np);
    nq = thin_to_segment(q, nq);
    if (np < 3 && nq < 3) {
        P2 ps[2], qs[2];
        ps[0] = p[0], ps[1] = p[np - 1], qs[0] = q[0], qs[1] = q[nq - 1];
        return intersect_segments(ps, qs, out);
    }
    if (nq < 3) { /* the clipper must be the polygon */
        swap = p, p = q, q = swap;
        k = np, np = nq, nq = k;
    }
    memcpy(cur, p, (size_t)np * sizeof *p);
    n = np;
    for (k = 0; k < nq && n > 0; k++) {
        n = clip_halfplane(cur, n, q[k], q[(k + 1) % nq], next);
        if (n > 2) n = p2_dedup(next, n);
        swap = cur, cur = next, next = swap;
    }
    if (cur != out) memcpy(out, cur, (size_t)n * sizeof *out);
    return n;
}
