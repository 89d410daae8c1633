/* motion.c — free flight between events (thesis 3.2.3, SPEC 3.2).
 *
 * Position: exact under the body's constant acceleration, the speed capped
 * at max_linear the way the thesis's eq. (5) splits it (once |v| reaches the
 * cap, v stays constant).  Rotation: torque-free, the world angular momentum
 * L constant and omega = R I^-1 R^T L following the orientation.  Isotropic
 * and symmetric bodies have exact closed forms; an asymmetric body (a box of
 * three different sides tumbles) uses the symplectic splitting of the free
 * rigid body Hamiltonian into its three principal rotations (McLachlan 1993;
 * Dullweber, Leimkuhler, McLachlan 1997), each an exact rotation, so |L| and
 * L itself are kept to rounding and energy does not drift.  It runs with a
 * fixed sub-step from the last event, so the pose at t is a pure function of
 * the anchor and t - t0; a small cache of checkpoints makes successive
 * queries cost only the steps between them (rotation.c: the orientation
 * at t - t0 of each kind).
 */
#include "body.h"
#include "mass.h"
#include "rotation.h"

#define ISOTROPY_TOL 1e-12     /* relative difference of moments taken as equal */

/* |L| / I_min: what |omega| never exceeds in free flight */
static double spin_of(const vrBody *b)
{
    if (b->kinematic) return vec3_len(b->m.L);
    return b->is_static || b->i_min <= 0 ? 0.0 : vec3_len(b->m.L) / b->i_min;
}

/* An isotropic body (a sphere, a cube) gets an exactly scalar tensor, so
 * that its world tensor R I R^T is I itself, not I plus rounding: those
 * rounding-sized off-diagonal entries gave the response matrix a new zero
 * pattern, and a new KLU factorisation, at almost every contact */
static void make_scalar(vrBody *b)
{
    mat33 id = mat33_identity();
    double c = (b->moments.x + b->moments.y + b->moments.z) / 3.0;
    b->moments = vec3_make(c, c, c);
    b->inertia = mat33_scale(&id, c);
    b->inv_inertia = b->is_static ? mat33_zero() : mat33_scale(&id, 1.0 / c);
}

void vrBody_SetMassProperties(vrBody *b, double mass, const mat33 *inertia_unit, double r_in, double r_out)
{
    mat33 axes;
    double span;
    b->r_in = r_in;
    b->r_out = r_out;
    b->pose_valid = 0;
    b->is_static = mass < 0;
    b->mass = fabs(mass);
    b->inv_mass = b->is_static ? 0.0 : 1.0 / b->mass;
    b->inertia = mat33_scale(inertia_unit, b->mass);
    b->inv_inertia = b->is_static ? mat33_zero() : mat33_inverse(&b->inertia);
    vrMass_Principal(&b->inertia, &b->moments, &axes);
    b->principal = quat_from_mat33(&axes);
    b->i_min = b->moments.x;
    span = b->moments.z * ISOTROPY_TOL;
    b->sym_axis = -1;
    if (b->moments.y - b->moments.x <= span && b->moments.z - b->moments.y <= span) {
        b->sym_axis = 3;                /* isotropic */
        make_scalar(b);
    } else if (b->moments.y - b->moments.x <= span)
        b->sym_axis = 2;                /* I1 = I2: the distinct axis is z */
    else if (b->moments.z - b->moments.y <= span)
        b->sym_axis = 0;                /* I2 = I3: the distinct axis is x */
    b->m.spin = spin_of(b);
}

/* ---- linear motion ------------------------------------------------------ */

/* time for |v0 + a t| to reach vmax (|v0| <= vmax), thesis eq. (3) solved for t */
static double cap_time(vec3 v0, vec3 a, double vmax)
{
    double A = vec3_dot(a, a), B = 2.0 * vec3_dot(v0, a), C = vec3_dot(v0, v0) - vmax * vmax, D;
    if (A == 0.0) return INFINITY;
    if (C > 0.0) C = 0.0;
    D = sqrt(B * B - 4.0 * A * C);
    return B > 0.0 ? -2.0 * C / (B + D) : (-B + D) / (2.0 * A);
}

/* SPEC 8: the speed caps do not cut a throw.  A throw is restored as the
 * hand gave it (grab.c), so its anchor may be faster than max_linear; it
 * then flies the true parabola, uncapped, to its next event, whose anchor
 * the caps cut again.  An anchor the cap cut is at the cap to rounding,
 * hence the margin; every holder decides alike from the anchor alone. */
static void set_cap(vrMotion *m, double max_linear)
{
    m->over_cap = vrFlight_OverCap(vec3_len(m->v0), max_linear);
    m->tcap = m->over_cap ? INFINITY : cap_time(m->v0, m->a, max_linear);
}

int vrBody_CapReached(const vrBody *b, double from, double to)
{
    double at = b->m.t0 + b->m.tcap;
    return b->m.tcap > 0 && at > from && at <= to;
}

void vrBody_Position(const vrBody *b, double t, vec3 *x)
{
    const vrMotion *m = &b->m;
    double tau = t - m->t0;
    if (tau <= m->tcap) {
        *x = vec3_madd(vec3_madd(m->x0, tau, m->v0), 0.5 * tau * tau, m->a);
    } else {
        double c = m->tcap;
        vec3 xc = vec3_madd(vec3_madd(m->x0, c, m->v0), 0.5 * c * c, m->a);
        vec3 vc = vec3_madd(m->v0, c, m->a);
        *x = vec3_madd(xc, tau - c, vc);
    }
}

static void widen(vec3 *lo, vec3 *hi, vec3 x)
{
    *lo = vec3_min(*lo, x);
    *hi = vec3_max(*hi, x);
}

/* Along each axis the path is a parabola until the speed cap and a line
 * after it: its extremes are at t1, t2, the cap, or where that axis's
 * velocity turns round before the cap. */
void vrBody_PathBox(const vrBody *b, double t1, double t2, vec3 *lo, vec3 *hi)
{
    const vrMotion *m = &b->m;
    const double v0[3] = { m->v0.x, m->v0.y, m->v0.z }, a[3] = { m->a.x, m->a.y, m->a.z };
    double cap = m->t0 + m->tcap;
    vec3 x;
    int k;
    vrBody_Position(b, t1, lo);
    *hi = *lo;
    vrBody_Position(b, t2, &x);
    widen(lo, hi, x);
    if (cap > t1 && cap < t2) {
        vrBody_Position(b, cap, &x);
        widen(lo, hi, x);
    }
    for (k = 0; k < 3; k++) {
        double turn;
        if (a[k] == 0) continue;
        turn = m->t0 - v0[k] / a[k];
        if (turn > t1 && turn < t2 && turn < cap) {
            vrBody_Position(b, turn, &x);
            widen(lo, hi, x);
        }
    }
}

void vrBody_Velocity(const vrBody *b, double t, vec3 *v)
{
    double tau = t - b->m.t0;
    *v = vec3_madd(b->m.v0, tau < b->m.tcap ? tau : b->m.tcap, b->m.a);
}

/* ---- rotation ------------------------------------------------------------ */

static vec3 omega_at(const vrBody *b, const mat33 *R)
{
    vec3 lb = mat33_tmulv(R, b->m.L);
    vec3 wb = mat33_mulv(&b->inv_inertia, lb);
    return mat33_mulv(R, wb);
}

void vrBody_Pose(vrBody *b, double t, vrPose *pose)
{
    vec3 x;
    if (b->pose_valid && (b->pose_t == t || b->still)) {
        *pose = b->pose;
        return;
    }
    vrBody_Position(b, t, &x);
    *pose = vrPose_make(x, vrRotation_Orientation(b, t - b->m.t0));
    b->pose = *pose;
    b->pose_t = t;
    b->pose_valid = 1;
}

/* ---- anchoring ------------------------------------------------------------ */

/* the global force, but in an island's contact step: the island step paid
 * the step's gravity into the velocity at its start (semi-implicit Euler,
 * which is dissipative with inelastic contact), so the body flies on
 * straight to the next one (island.h, SPEC 7) */
static vec3 flight_accel(const vrBody *b, vec3 g)
{
    return b->is_static || b->resting || b->contact || b->kinematic ? vec3_zero() : g;
}

static void classify_rotation(vrBody *b)
{
    b->m.spin = spin_of(b);
    if (b->is_static || vec3_len2(b->m.L) == 0.0) b->rot = VR_ROT_NONE;
    else if (b->kinematic) b->rot = VR_ROT_KINEMATIC;
    else if (b->sym_axis == 3) b->rot = VR_ROT_ISOTROPIC;
    else if (b->sym_axis >= 0) b->rot = VR_ROT_SYMMETRIC;
    else b->rot = VR_ROT_GENERAL;
}

static void reset_rotation_cache(vrBody *b)
{
    vrRotCache *rc = &b->rc;
    vrRotState a;
    double w = vrBody_SpinBound(b);
    a.step = 0;
    a.Q = quat_mul(b->m.q0, b->principal);
    a.Pi = quat_unrotate(a.Q, b->m.L);
    rc->h = w > 0 ? fmin(1e-3, 0.003 / w) : 1e-3;
    rc->anchor = a;
    rc->nring = 0;
    rc->last = a;
}

/* A static or resting body, or one merely hanging still: its pose is x0,
 * q0 at any t, so the pose asked for once serves every later time (a wall
 * is in every bisection of a floor bounce: a rotation matrix each).  Only
 * +0 velocity and acceleration, and an x0 without -0, give the same bits
 * at every t (x0 + v0 tau is then x0 whatever the sign of tau). */
static int plus_zero(vec3 v)
{
    return v.x == 0 && v.y == 0 && v.z == 0 && !signbit(v.x) && !signbit(v.y) && !signbit(v.z);
}
static int no_minus_zero(vec3 v)
{
    return !(v.x == 0 && signbit(v.x)) && !(v.y == 0 && signbit(v.y)) && !(v.z == 0 && signbit(v.z));
}

static void note_stillness(vrBody *b)
{
    const vrMotion *m = &b->m;
    b->still = b->rot == VR_ROT_NONE && plus_zero(m->v0) && plus_zero(m->a) && no_minus_zero(m->x0);
}

int vrBody_Anchor(vrBody *b, double t, vec3 x, vec3 v, quat q, vec3 L, const vrFlight *f)
{
    vrMotion *m = &b->m;
    double s;
    int clamps = 0;
    m->t0 = t;
    m->x0 = x;
    m->q0 = quat_normalize(q);
    if (b->is_static || b->resting) {
        v = vec3_zero();
        L = vec3_zero();
    }
    s = vec3_len(v);
    if (vrFlight_OverCap(s, f->max_linear)) v = vec3_scale(v, f->max_linear / s), clamps++;
    m->v0 = v;
    m->L = L;
    if (!b->is_static && vec3_len2(L) > 0) {
        mat33 R = mat33_from_quat(m->q0);
        double w = b->kinematic ? vec3_len(L) : vec3_len(omega_at(b, &R));
        if (vrFlight_OverCap(w, f->max_angular)) m->L = vec3_scale(L, f->max_angular / w), clamps++;
    }
    m->a = flight_accel(b, f->accel);
    set_cap(m, f->max_linear);
    classify_rotation(b);
    reset_rotation_cache(b);
    note_stillness(b);
    b->pose_valid = 0;
    return clamps;
}

void vrBody_Restore(vrBody *b, double t0, vec3 x0, vec3 v0, quat q0, vec3 L, const vrFlight *f)
{
    vrMotion *m = &b->m;
    m->t0 = t0;
    m->x0 = x0;
    m->v0 = v0;
    m->q0 = q0;
    m->L = L;
    m->a = flight_accel(b, f->accel);
    set_cap(m, f->max_linear);
    classify_rotation(b);
    reset_rotation_cache(b);
    note_stillness(b);
    b->pose_valid = 0;
}

void vrBody_Reanchor(vrBody *b, double t, const vrFlight *f)
{
    vrPose p;
    vec3 v;
    vrBody_Pose(b, t, &p);
    vrBody_Velocity(b, t, &v);
    vrBody_Anchor(b, t, p.p, v, p.q, b->m.L, f);
}

/* ---- derived quantities ---------------------------------------------------- */

void vrBody_ShapePose(vrBody *b, double t, vrPose *pose)
{
    if (b->shape.kind != VR_SHAPE_SPHERE) {
        vrBody_Pose(b, t, pose);
        return;
    }
    vrBody_Position(b, t, &pose->p);
    pose->q = quat_identity();
    pose->R = mat33_identity();
}

vec3 vrBody_Omega(const vrBody *b, const vrPose *pose)
{
    if (b->rot == VR_ROT_NONE) return vec3_zero();
    if (b->rot == VR_ROT_KINEMATIC) return b->m.L;
    return omega_at(b, &pose->R);
}

vec3 vrBody_PointVelocity(const vrBody *b, double t, const vrPose *pose, vec3 p)
{
    vec3 v;
    vrBody_Velocity(b, t, &v);
    return vrRigid_PointVelocity(v, vrBody_Omega(b, pose), pose->p, p);
}

mat33 vrBody_InvInertiaWorld(const vrBody *b, const vrPose *pose)
{
    return b->sym_axis == 3 ? b->inv_inertia : mat33_rotate_tensor(&pose->R, &b->inv_inertia);
}

mat33 vrBody_InertiaWorld(const vrBody *b, const vrPose *pose)
{
    return b->sym_axis == 3 ? b->inertia : mat33_rotate_tensor(&pose->R, &b->inertia);
}

double vrBody_SpeedBound(const vrBody *b, double t, double span, double accel, double max_linear)
{
    vec3 v;
    double s;
    vrBody_Velocity(b, t, &v);
    s = vec3_len(v) + accel * span;
    return s < max_linear || b->m.over_cap ? s : max_linear;
}

double vrBody_SpinBound(const vrBody *b) { return b->m.spin; }


/* SPEC 1.3: 1/2 m v^2 + 1/2 omega.L - m g.x (a held body's L is I omega) */
double vrBody_Energy(vrBody *b, double t, vec3 g)
{
    vrPose p;
    vec3 v, w, wb;
    if (b->is_static) return 0.0;
    vrBody_Pose(b, t, &p);
    vrBody_Velocity(b, t, &v);
    w = vrBody_Omega(b, &p);
    wb = mat33_tmulv(&p.R, w);
    return 0.5 * b->mass * vec3_dot(v, v) - b->mass * vec3_dot(g, p.p)
         + 0.5 * (b->kinematic ? vec3_dot(wb, mat33_mulv(&b->inertia, wb)) : vec3_dot(w, b->m.L));
}
