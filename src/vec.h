/* vec.h — 3D math in doubles: vectors, Hamilton quaternions, 3x3 matrices.
 *
 * Everything is static inline and allocation-free.  The operations are
 * written out so that the same inputs always give the same bits on every
 * process (no FMA contraction under -std=c99, no reordering): determinism
 * between serial and parallel runs depends on it.
 */
#ifndef VROC_VEC_H
#define VROC_VEC_H

#include <math.h>

#define VR_PI 3.14159265358979323846

typedef struct vec3 { double x, y, z; } vec3;
typedef struct quat { double w, x, y, z; } quat;       /* unit: rotation */
typedef struct mat33 { double m[3][3]; } mat33;         /* row-major */

/* the smaller and larger of two numbers that are not NaN: libm's fmin and
 * fmax are calls (they must handle NaN), these inline */
static inline double vr_min(double a, double b) { return a < b ? a : b; }
static inline double vr_max(double a, double b) { return a > b ? a : b; }

/* ---- vectors ---------------------------------------------------------- */
static inline vec3 vec3_make(double x, double y, double z) { vec3 r = {x, y, z}; return r; }
static inline vec3 vec3_zero(void) { vec3 r = {0, 0, 0}; return r; }
static inline vec3 vec3_add(vec3 a, vec3 b) { return vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 vec3_sub(vec3 a, vec3 b) { return vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 vec3_neg(vec3 a) { return vec3_make(-a.x, -a.y, -a.z); }
static inline vec3 vec3_scale(vec3 a, double s) { return vec3_make(a.x * s, a.y * s, a.z * s); }
/* a + s*b */
static inline vec3 vec3_madd(vec3 a, double s, vec3 b) { return vec3_make(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z); }
static inline double vec3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 vec3_cross(vec3 a, vec3 b)
{
    return vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double vec3_len2(vec3 a) { return vec3_dot(a, a); }
static inline double vec3_len(vec3 a) { return sqrt(vec3_dot(a, a)); }
static inline double vec3_dist(vec3 a, vec3 b) { return vec3_len(vec3_sub(a, b)); }
/* unit vector; the zero vector stays zero */
static inline vec3 vec3_normalize(vec3 a)
{
    double l = vec3_len(a);
    return l > 0 ? vec3_scale(a, 1.0 / l) : a;
}
static inline vec3 vec3_lerp(vec3 a, vec3 b, double t) { return vec3_madd(a, t, vec3_sub(b, a)); }
static inline double vec3_get(vec3 a, int i) { return i == 0 ? a.x : i == 1 ? a.y : a.z; }
static inline int vec3_isfinite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
static inline vec3 vec3_min(vec3 a, vec3 b) { return vec3_make(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
static inline vec3 vec3_max(vec3 a, vec3 b) { return vec3_make(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }
static inline double vec3_maxabs(vec3 a)
{
    double m = fabs(a.x);
    if (fabs(a.y) > m) m = fabs(a.y);
    if (fabs(a.z) > m) m = fabs(a.z);
    return m;
}

/* A unit vector orthogonal to unit n, chosen by a fixed rule (so every
 * process picks the same tangent frame). */
static inline vec3 vec3_orthogonal(vec3 n)
{
    vec3 a = fabs(n.x) <= fabs(n.y) && fabs(n.x) <= fabs(n.z) ? vec3_make(1, 0, 0)
           : fabs(n.y) <= fabs(n.z) ? vec3_make(0, 1, 0) : vec3_make(0, 0, 1);
    return vec3_normalize(vec3_cross(n, a));
}

/* ---- quaternions (Hamilton, w first; q takes body to world) ------------ */
static inline quat quat_make(double w, double x, double y, double z) { quat q = {w, x, y, z}; return q; }
static inline quat quat_identity(void) { return quat_make(1, 0, 0, 0); }
static inline quat quat_mul(quat a, quat b)
{
    return quat_make(a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
                     a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                     a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                     a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w);
}
static inline quat quat_conj(quat q) { return quat_make(q.w, -q.x, -q.y, -q.z); }
static inline double quat_norm(quat q) { return sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z); }
static inline quat quat_normalize(quat q)
{
    double n = quat_norm(q);
    return n > 0 ? quat_make(q.w / n, q.x / n, q.y / n, q.z / n) : quat_identity();
}
/* rotation of `angle` radians about unit `axis` */
static inline quat quat_from_axis_angle(vec3 axis, double angle)
{
    double s = sin(0.5 * angle);
    return quat_make(cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s);
}
/* exp of a rotation vector r (angle |r| about r/|r|); exact for small |r| */
static inline quat quat_from_rotvec(vec3 r)
{
    double a = vec3_len(r);
    if (a < 1e-8) { /* sin(a/2)/a by its series, cos(a/2) likewise */
        double s = 0.5 - a * a / 48.0;
        return quat_normalize(quat_make(1.0 - a * a / 8.0, r.x * s, r.y * s, r.z * s));
    }
    return quat_from_axis_angle(vec3_scale(r, 1.0 / a), a);
}
static inline vec3 quat_rotate(quat q, vec3 v)
{
    /* v + 2w (u x v) + 2 u x (u x v), u = vector part */
    vec3 u = vec3_make(q.x, q.y, q.z);
    vec3 t = vec3_scale(vec3_cross(u, v), 2.0);
    return vec3_add(vec3_madd(v, q.w, t), vec3_cross(u, t));
}
static inline vec3 quat_unrotate(quat q, vec3 v) { return quat_rotate(quat_conj(q), v); }
/* angle of the rotation taking a to b, in [0, pi] */
static inline double quat_angle_between(quat a, quat b)
{
    quat d = quat_mul(b, quat_conj(a));
    double v = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return 2.0 * atan2(v, fabs(d.w));
}
/* the canonical sign: w >= 0, and if w == 0 the first non-zero part > 0 */
static inline quat quat_canonical(quat q)
{
    double c[4] = {q.w, q.x, q.y, q.z};
    int i;
    for (i = 0; i < 4; i++)
        if (c[i] != 0) break;
    if (i < 4 && c[i] < 0) q = quat_make(-q.w, -q.x, -q.y, -q.z);
    return q;
}

/* ---- 3x3 matrices ------------------------------------------------------ */
static inline mat33 mat33_zero(void) { mat33 r = {{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}}; return r; }
static inline mat33 mat33_identity(void) { mat33 r = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; return r; }
static inline mat33 mat33_diag(double a, double b, double c)
{
    mat33 r = {{{a, 0, 0}, {0, b, 0}, {0, 0, c}}};
    return r;
}
static inline vec3 mat33_mulv(const mat33 *a, vec3 v)
{
    return vec3_make(a->m[0][0] * v.x + a->m[0][1] * v.y + a->m[0][2] * v.z,
                     a->m[1][0] * v.x + a->m[1][1] * v.y + a->m[1][2] * v.z,
                     a->m[2][0] * v.x + a->m[2][1] * v.y + a->m[2][2] * v.z);
}
/* a^T v */
static inline vec3 mat33_tmulv(const mat33 *a, vec3 v)
{
    return vec3_make(a->m[0][0] * v.x + a->m[1][0] * v.y + a->m[2][0] * v.z,
                     a->m[0][1] * v.x + a->m[1][1] * v.y + a->m[2][1] * v.z,
                     a->m[0][2] * v.x + a->m[1][2] * v.y + a->m[2][2] * v.z);
}
static inline mat33 mat33_mul(const mat33 *a, const mat33 *b)
{
    mat33 r;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            r.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] + a->m[i][2] * b->m[2][j];
    return r;
}
static inline mat33 mat33_transpose(const mat33 *a)
{
    mat33 r;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) r.m[i][j] = a->m[j][i];
    return r;
}
static inline mat33 mat33_scale(const mat33 *a, double s)
{
    mat33 r;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) r.m[i][j] = a->m[i][j] * s;
    return r;
}
static inline mat33 mat33_add(const mat33 *a, const mat33 *b)
{
    mat33 r;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) r.m[i][j] = a->m[i][j] + b->m[i][j];
    return r;
}
/* the matrix of v x . */
static inline mat33 mat33_cross(vec3 v)
{
    mat33 r = {{{0, -v.z, v.y}, {v.z, 0, -v.x}, {-v.y, v.x, 0}}};
    return r;
}
static inline vec3 mat33_row(const mat33 *a, int i) { return vec3_make(a->m[i][0], a->m[i][1], a->m[i][2]); }
static inline vec3 mat33_col(const mat33 *a, int j) { return vec3_make(a->m[0][j], a->m[1][j], a->m[2][j]); }
static inline double mat33_det(const mat33 *a)
{
    return a->m[0][0] * (a->m[1][1] * a->m[2][2] - a->m[1][2] * a->m[2][1])
         - a->m[0][1] * (a->m[1][0] * a->m[2][2] - a->m[1][2] * a->m[2][0])
         + a->m[0][2] * (a->m[1][0] * a->m[2][1] - a->m[1][1] * a->m[2][0]);
}
/* inverse by the adjugate; caller guarantees det != 0 */
static inline mat33 mat33_inverse(const mat33 *a)
{
    mat33 r;
    double id = 1.0 / mat33_det(a);
    r.m[0][0] = (a->m[1][1] * a->m[2][2] - a->m[1][2] * a->m[2][1]) * id;
    r.m[0][1] = (a->m[0][2] * a->m[2][1] - a->m[0][1] * a->m[2][2]) * id;
    r.m[0][2] = (a->m[0][1] * a->m[1][2] - a->m[0][2] * a->m[1][1]) * id;
    r.m[1][0] = (a->m[1][2] * a->m[2][0] - a->m[1][0] * a->m[2][2]) * id;
    r.m[1][1] = (a->m[0][0] * a->m[2][2] - a->m[0][2] * a->m[2][0]) * id;
    r.m[1][2] = (a->m[0][2] * a->m[1][0] - a->m[0][0] * a->m[1][2]) * id;
    r.m[2][0] = (a->m[1][0] * a->m[2][1] - a->m[1][1] * a->m[2][0]) * id;
    r.m[2][1] = (a->m[0][1] * a->m[2][0] - a->m[0][0] * a->m[2][1]) * id;
    r.m[2][2] = (a->m[0][0] * a->m[1][1] - a->m[0][1] * a->m[1][0]) * id;
    return r;
}
/* rotation matrix of unit quaternion q (body to world) */
static inline mat33 mat33_from_quat(quat q)
{
    mat33 r;
    double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    r.m[0][0] = 1 - 2 * (yy + zz); r.m[0][1] = 2 * (xy - wz);     r.m[0][2] = 2 * (xz + wy);
    r.m[1][0] = 2 * (xy + wz);     r.m[1][1] = 1 - 2 * (xx + zz); r.m[1][2] = 2 * (yz - wx);
    r.m[2][0] = 2 * (xz - wy);     r.m[2][1] = 2 * (yz + wx);     r.m[2][2] = 1 - 2 * (xx + yy);
    return r;
}
/* R A R^T: a body-frame tensor in the world frame */
static inline mat33 mat33_rotate_tensor(const mat33 *rot, const mat33 *a)
{
    mat33 t = mat33_mul(rot, a), rt = mat33_transpose(rot);
    return mat33_mul(&t, &rt);
}

/* unit quaternion of a proper rotation matrix (Shepperd's method: pick the
 * largest of w, x, y, z to divide by, so it stays accurate) */
static inline quat quat_from_mat33(const mat33 *r)
{
    double tr = r->m[0][0] + r->m[1][1] + r->m[2][2], s;
    quat q;
    if (tr >= r->m[0][0] && tr >= r->m[1][1] && tr >= r->m[2][2]) {
        s = 2.0 * sqrt(1.0 + tr);
        q = quat_make(0.25 * s, (r->m[2][1] - r->m[1][2]) / s, (r->m[0][2] - r->m[2][0]) / s, (r->m[1][0] - r->m[0][1]) / s);
    } else if (r->m[0][0] >= r->m[1][1] && r->m[0][0] >= r->m[2][2]) {
        s = 2.0 * sqrt(1.0 + r->m[0][0] - r->m[1][1] - r->m[2][2]);
        q = quat_make((r->m[2][1] - r->m[1][2]) / s, 0.25 * s, (r->m[0][1] + r->m[1][0]) / s, (r->m[0][2] + r->m[2][0]) / s);
    } else if (r->m[1][1] >= r->m[2][2]) {
        s = 2.0 * sqrt(1.0 + r->m[1][1] - r->m[0][0] - r->m[2][2]);
        q = quat_make((r->m[0][2] - r->m[2][0]) / s, (r->m[0][1] + r->m[1][0]) / s, 0.25 * s, (r->m[1][2] + r->m[2][1]) / s);
    } else {
        s = 2.0 * sqrt(1.0 + r->m[2][2] - r->m[0][0] - r->m[1][1]);
        q = quat_make((r->m[1][0] - r->m[0][1]) / s, (r->m[0][2] + r->m[2][0]) / s, (r->m[1][2] + r->m[2][1]) / s, 0.25 * s);
    }
    return quat_normalize(q);
}

/* ---- poses -------------------------------------------------------------- */
/* x_world = R x_body + p; R is kept beside q so a query rotates by a matrix */
typedef struct vrPose { vec3 p; quat q; mat33 R; } vrPose;

static inline vrPose vrPose_make(vec3 p, quat q)
{
    vrPose r;
    r.p = p;
    r.q = q;
    r.R = mat33_from_quat(q);
    return r;
}
static inline vec3 vrPose_apply(const vrPose *t, vec3 x) { return vec3_add(mat33_mulv(&t->R, x), t->p); }
static inline vec3 vrPose_invapply(const vrPose *t, vec3 x) { return mat33_tmulv(&t->R, vec3_sub(x, t->p)); }
static inline vec3 vrPose_rotate(const vrPose *t, vec3 v) { return mat33_mulv(&t->R, v); }

#endif
