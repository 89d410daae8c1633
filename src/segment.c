/* segment.c — the closest points of two segments and of a point and a
 * segment, by fixed formulas: the walk (closest.c) and the canonical contact
 * (canonical.c) both use them, so that both give the same bits and get
 * points inside each other's slab. */
#include "segment.h"

static double clamp01(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }

double vrSegment_PointParam(vec3 p0, vec3 p1, vec3 x)
{
    vec3 d = vec3_sub(p1, p0);
    double l2 = vec3_len2(d);
    return l2 > 0 ? clamp01(vec3_dot(vec3_sub(x, p0), d) / l2) : 0;
}

/* Ericson, Real-Time Collision Detection, 5.1.9, except that parallel
 * segments take the middle of their overlap */
void vrSegment_ClosestParams(vec3 p0, vec3 p1, vec3 q0, vec3 q1, double *s, double *t)
{
    vec3 d1 = vec3_sub(p1, p0), d2 = vec3_sub(q1, q0), r = vec3_sub(p0, q0);
    double a = vec3_dot(d1, d1), e = vec3_dot(d2, d2), b = vec3_dot(d1, d2);
    double c = vec3_dot(d1, r), f = vec3_dot(d2, r), den = a * e - b * b;
    double ss, tt;
    if (a <= 0 || e <= 0) { /* a point: never a polyhedron edge */
        *s = a > 0 ? clamp01(-c / a) : 0;
        *t = e > 0 ? clamp01((f + b * *s) / e) : 0;
        return;
    }
    if (den > 1e-12 * a * e) { /* sin^2 of the angle > 1e-12 */
        ss = clamp01((b * f - c * e) / den);
    } else {
        double s0 = -c / a, s1 = (b - c) / a; /* q0, q1 projected on p's line */
        double lo = s0 < s1 ? s0 : s1, hi = s0 < s1 ? s1 : s0;
        if (lo < 0) lo = 0;
        if (hi > 1) hi = 1;
        ss = lo <= hi ? 0.5 * (lo + hi) : (hi < 0 ? 0 : 1);
    }
    tt = (b * ss + f) / e;
    if (tt < 0) {
        tt = 0;
        ss = clamp01(-c / a);
    } else if (tt > 1) {
        tt = 1;
        ss = clamp01((b - c) / a);
    }
    *s = ss;
    *t = tt;
}
