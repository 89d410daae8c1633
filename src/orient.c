/* orient.c — the exact orientation predicate of four points (Shewchuk
 * 1997, "Adaptive precision floating-point arithmetic and fast robust
 * geometric predicates"): a floating-point filter with a proven error
 * bound, then long double, then expansion arithmetic.  The hull (quickhull.c,
 * coplanar.c) decides with it whether a point sees a face, so that its
 * triangulation stays exactly convex.
 *   two_sum, two_product     a sum and a product with their rounding errors
 *   exp_sum, exp_scale,      expansion arithmetic (Shewchuk sec. 2)
 *   exp_mul
 *   exact_diff, det_exact    the 3x3 determinant of exact differences
 */
#include <float.h>
#include <string.h>

#include "orient.h"

/* ---- exact orientation ----------------------------------------------------
 * An expansion is a sum of doubles, ordered by increasing magnitude and
 * non-overlapping (Shewchuk sec. 2); its sign is that of its last term. */
#define EXP_MAX 192 /* the 3x3 determinant of exact differences needs <= 192 terms */

/* gcc 12's -fanalyzer does not follow the expansions through the loops
 * that fill them (every h[k] and d[r][i] is written before it is read, and
 * two_sum and two_product are given only those): a false positive, on
 * this section only (make lint) */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wanalyzer-use-of-uninitialized-value"
#endif

static void two_sum(double a, double b, double *x, double *y)
{
    double s = a + b, bv = s - a, av = s - bv;
    *x = s;
    *y = (a - av) + (b - bv);
}

static void two_product(double a, double b, double *x, double *y)
{
    double p = a * b;
    *x = p;
    *y = fma(a, b, -p); /* the rounding error of a*b, exactly */
}

/* h = e + f (Shewchuk's FAST-EXPANSION-SUM, zeros dropped); returns length */
static int exp_sum(int ne, const double *e, int nf, const double *f, double *h)
{
    double g[EXP_MAX], q, t;
    int i = 0, j = 0, n = 0, k = 0;
    while (i < ne || j < nf) g[n++] = j >= nf || (i < ne && fabs(e[i]) < fabs(f[j])) ? e[i++] : f[j++];
    if (n == 0) {
        h[0] = 0;
        return 1;
    }
    q = g[0];
    for (i = 1; i < n; i++) {
        two_sum(q, g[i], &q, &t);
        if (t != 0) h[k++] = t;
    }
    if (q != 0 || k == 0) h[k++] = q;
    return k;
}

/* h = e * b (Shewchuk's SCALE-EXPANSION, zeros dropped) */
static int exp_scale(int ne, const double *e, double b, double *h)
{
    double q, t, hi, lo, s;
    int i, k = 0;
    two_product(e[0], b, &q, &t);
    if (t != 0) h[k++] = t;
    for (i = 1; i < ne; i++) {
        two_product(e[i], b, &hi, &lo);
        two_sum(q, lo, &s, &t);
        if (t != 0) h[k++] = t;
        two_sum(hi, s, &q, &t);
        if (t != 0) h[k++] = t;
    }
    if (q != 0 || k == 0) h[k++] = q;
    return k;
}

/* h = e * f, f short */
static int exp_mul(int ne, const double *e, int nf, const double *f, double *h)
{
    double part[EXP_MAX], acc[EXP_MAX];
    int n = exp_scale(ne, e, f[0], h), j, m;
    for (j = 1; j < nf; j++) {
        m = exp_scale(ne, e, f[j], part);
        memcpy(acc, h, sizeof *h * n);
        n = exp_sum(n, acc, m, part, h);
    }
    return n;
}

typedef struct Diff { int n; double c[2]; } Diff; /* a - b, exactly */

static Diff exact_diff(double a, double b)
{
    Diff d;
    double x, y;
    two_sum(a, -b, &x, &y);
    d.n = y != 0 ? 2 : 1;
    d.c[0] = y != 0 ? y : x;
    d.c[1] = x;
    return d;
}

/* det[a-p; b-p; c-p], exactly; returns its largest term (its sign is exact) */
static double det_exact(vec3 a, vec3 b, vec3 c, vec3 p)
{
    Diff d[3][3];
    const vec3 *row[3] = {&a, &b, &c};
    double acc[EXP_MAX], old[EXP_MAX];
    int r, i, n = 0;
    for (r = 0; r < 3; r++)
        for (i = 0; i < 3; i++) d[r][i] = exact_diff(vec3_get(*row[r], i), vec3_get(p, i));
    for (i = 0; i < 3; i++) { /* d0_i (d1_j d2_k - d1_k d2_j), (i j k) cyclic */
        int j = (i + 1) % 3, k = (i + 2) % 3, n1, n2, nm, nt, q;
        double m1[8], m2[8], minor[16], term[64];
        n1 = exp_mul(d[1][j].n, d[1][j].c, d[2][k].n, d[2][k].c, m1);
        n2 = exp_mul(d[1][k].n, d[1][k].c, d[2][j].n, d[2][j].c, m2);
        for (q = 0; q < n2; q++) m2[q] = -m2[q];
        nm = exp_sum(n1, m1, n2, m2, minor);
        nt = exp_mul(nm, minor, d[0][i].n, d[0][i].c, term);
        /* cppcheck-suppress uninitvar ; n is 0 the first time round: nothing of acc is read */
        memcpy(old, acc, sizeof *acc * n);
        n = exp_sum(n, old, nt, term, acc);
    }
    return acc[n - 1];
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

/* First in long double with Shewchuk's error bound (o3derrboundA) for its
 * precision, which settles all but (nearly) exact zeros; those exactly. */
double vrOrient(vec3 a, vec3 b, vec3 c, vec3 p)
{
    static const long double u = LDBL_EPSILON / 2, bound = (7 + 56 * u) * u;
    long double adx = (long double)a.x - p.x, ady = (long double)a.y - p.y, adz = (long double)a.z - p.z;
    long double bdx = (long double)b.x - p.x, bdy = (long double)b.y - p.y, bdz = (long double)b.z - p.z;
    long double cdx = (long double)c.x - p.x, cdy = (long double)c.y - p.y, cdz = (long double)c.z - p.z;
    long double bc = bdx * cdy, cb = cdx * bdy, ca = cdx * ady, ac = adx * cdy, ab = adx * bdy, ba = bdx * ady;
    long double det = adz * (bc - cb) + bdz * (ca - ac) + cdz * (ab - ba);
    long double perm = (fabsl(bc) + fabsl(cb)) * fabsl(adz) + (fabsl(ca) + fabsl(ac)) * fabsl(bdz)
                     + (fabsl(ab) + fabsl(ba)) * fabsl(cdz);
    if (fabsl(det) > bound * perm) return (double)-det;
    return -det_exact(a, b, c, p);
}
