/* mass.c — mass properties of a convex polyhedron for uniform density (SPEC 2).
 *
 * Volume integrals by the divergence theorem, done as a sum of signed
 * tetrahedra (apex at a reference point, base a triangle of a fan over each
 * face): exact for any closed, consistently oriented polyhedron.  For the
 * second moments of a tetrahedron with one corner at the origin and the
 * others a, b, c (Tonon 2004, "Explicit exact formulas for the 3-D
 * tetrahedron inertia tensor"):
 *     int x_i x_j dV = V/20 * (sum_k p_k,i p_k,j + s_i s_j),  s = a + b + c.
 * Principal axes by cyclic Jacobi rotations (Golub & Van Loan, sec. 8.5).
 */
#include "mass.h"

/* calls fn(a, b, c, ctx) for every triangle of a fan over every face */
typedef void (*TriangleFn)(vec3 a, vec3 b, vec3 c, void *ctx);

static void for_each_triangle(const vrPolyhedron *p, vec3 origin, TriangleFn fn, void *ctx)
{
    int f, k;
    for (f = 0; f < p->nf; f++) {
        int s = p->face_start[f], e = p->face_start[f + 1];
        vec3 a = vec3_sub(p->vert[p->face_vert[s]], origin);
        for (k = s + 1; k + 1 < e; k++)
            fn(a, vec3_sub(p->vert[p->face_vert[k]], origin),
               vec3_sub(p->vert[p->face_vert[k + 1]], origin), ctx);
    }
}

static double det3(vec3 a, vec3 b, vec3 c) { return vec3_dot(a, vec3_cross(b, c)); }

typedef struct Moments {
    double v6;      /* 6 x volume */
    vec3 first;     /* 24 x first moment */
    mat33 second;   /* 120 x second moments int x_i x_j dV */
} Moments;

static void add_tetrahedron(vec3 a, vec3 b, vec3 c, void *ctx)
{
    Moments *m = ctx;
    double d = det3(a, b, c), p[3][3] = {{a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}};
    double s[3] = {a.x + b.x + c.x, a.y + b.y + c.y, a.z + b.z + c.z};
    int i, j;
    m->v6 += d;
    m->first = vec3_madd(m->first, d, vec3_make(s[0], s[1], s[2]));
    for (i = 0; i < 3; i++)
        for (j = i; j < 3; j++) {
            double pp = p[0][i] * p[0][j] + p[1][i] * p[1][j] + p[2][i] * p[2][j];
            m->second.m[i][j] += d * (pp + s[i] * s[j]);
        }
}

static Moments moments_about(const vrPolyhedron *p, vec3 origin)
{
    Moments m;
    m.v6 = 0;
    m.first = vec3_zero();
    m.second = mat33_zero();
    for_each_triangle(p, origin, add_tetrahedron, &m);
    m.second.m[1][0] = m.second.m[0][1]; /* symmetric: the upper half was summed */
    m.second.m[2][0] = m.second.m[0][2];
    m.second.m[2][1] = m.second.m[1][2];
    return m;
}

void vrMass_VolumeCentroid(const vrPolyhedron *p, double *volume, vec3 *centroid)
{
    /* a vertex as the apex keeps the sums free of the cancellation a far
     * origin would bring */
    vec3 ref = p->nv > 0 ? p->vert[0] : vec3_zero();
    Moments m = moments_about(p, ref);
    if (volume) *volume = m.v6 / 6.0;
    if (centroid) /* tetrahedron centroid (0+a+b+c)/4, weighted by volume */
        *centroid = m.v6 != 0 ? vec3_madd(ref, 1.0 / (4.0 * m.v6), m.first) : ref;
}

void vrMass_Compute(vrPolyhedron *p)
{
    Moments m = moments_about(p, vec3_zero());
    double tr;
    int i, j, f, v;

    p->volume = m.v6 / 6.0;
    /* per unit mass: int x_i x_j dV / V = second / (120 V) = second / (20 v6) */
    tr = m.second.m[0][0] + m.second.m[1][1] + m.second.m[2][2];
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            p->inertia_unit.m[i][j] = m.v6 != 0 ? ((i == j ? tr : 0) - m.second.m[i][j]) / (20.0 * m.v6) : 0;

    /* thesis 3.3.1.1: inscribed radius is the nearest face plane, the
     * circumscribed one the farthest vertex */
    p->r_in = p->nf > 0 ? p->face_offset[0] : 0;
    for (f = 1; f < p->nf; f++)
        if (p->face_offset[f] < p->r_in) p->r_in = p->face_offset[f];
    p->r_out = 0;
    for (v = 0; v < p->nv; v++)
        if (vec3_len(p->vert[v]) > p->r_out) p->r_out = vec3_len(p->vert[v]);
}

/* ---- principal axes ------------------------------------------------------ */

/* one Jacobi rotation in the (i, j) plane that zeroes a[i][j]; v collects
 * the rotations (Rutishauser's stable form of the angle) */
static void jacobi_rotate(double a[3][3], double v[3][3], int i, int j)
{
    double theta, t, c, s;
    int k;
    if (a[i][j] == 0) return;
    theta = (a[j][j] - a[i][i]) / (2.0 * a[i][j]);
    t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
    c = 1.0 / sqrt(t * t + 1.0);
    s = t * c;
    for (k = 0; k < 3; k++) { /* a <- a J */
        double aki = a[k][i], akj = a[k][j];
        a[k][i] = c * aki - s * akj;
        a[k][j] = s * aki + c * akj;
    }
    for (k = 0; k < 3; k++) { /* a <- J^T a */
        double aik = a[i][k], ajk = a[j][k];
        a[i][k] = c * aik - s * ajk;
        a[j][k] = s * aik + c * ajk;
    }
    for (k = 0; k < 3; k++) {
        double vki = v[k][i], vkj = v[k][j];
        v[k][i] = c * vki - s * vkj;
        v[k][j] = s * vki + c * vkj;
    }
}

static double off_diagonal(double a[3][3]) { return fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]); }

static void swap_columns(double a[3][3], double v[3][3], int i, int j)
{
    int k;
    double t = a[i][i];
    a[i][i] = a[j][j];
    a[j][j] = t;
    for (k = 0; k < 3; k++) {
        t = v[k][i];
        v[k][i] = v[k][j];
        v[k][j] = t;
    }
}

void vrMass_Principal(const mat33 *inertia, vec3 *moments, mat33 *axes)
{
    double a[3][3], v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, scale = 0;
    int i, j, sweep;
    mat33 r;

    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            a[i][j] = 0.5 * (inertia->m[i][j] + inertia->m[j][i]); /* symmetric part */
            scale += fabs(a[i][j]);
        }
    /* quadratic convergence: a handful of sweeps reach rounding level */
    for (sweep = 0; sweep < 50 && off_diagonal(a) > 1e-300 + 1e-17 * scale; sweep++) {
        jacobi_rotate(a, v, 0, 1);
        jacobi_rotate(a, v, 0, 2);
        jacobi_rotate(a, v, 1, 2);
    }
    for (i = 0; i < 2; i++) /* ascending: three elements, selection sort */
        for (j = i + 1; j < 3; j++)
            if (a[j][j] < a[i][i]) swap_columns(a, v, i, j);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) r.m[i][j] = v[i][j];
    if (mat33_det(&r) < 0) /* a proper rotation: flip the last axis */
        for (i = 0; i < 3; i++) r.m[i][2] = -r.m[i][2];
    if (moments) *moments = vec3_make(a[0][0], a[1][1], a[2][2]);
    if (axes) *axes = r;
}
