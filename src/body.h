/* body.h — a simulated rigid body: what its shape and mass give, and its
 * motion since its last event (SPEC 3.2, ARCHITECTURE "objects move lazily").
 *
 * A body stores its state at its last event time t0; its pose at any later
 * time is computed on demand by motion.c, as a pure function of that state
 * and of t - t0.  Every process holding a copy of the body computes the same
 * bits from the same anchor, which is what makes serial and parallel runs
 * identical.
 */
#ifndef VROC_BODY_H
#define VROC_BODY_H

#include "contact.h"

/* the anchor of free flight (thesis 3.2.3, SPEC 3.2) */
typedef struct vrMotion {
    double t0;
    vec3 x0, v0;   /* centre of mass position and velocity at t0 */
    vec3 a;        /* acceleration: the global force; none in an island's contact
                      step, whose gravity is in the velocity already (SPEC 7) */
    quat q0;       /* orientation at t0, body to world */
    vec3 L;        /* angular momentum, world frame, constant in free flight */
    double tcap;   /* time after t0 when |v| reaches max_linear (INFINITY: never) */
    int over_cap;  /* |v0| above max_linear: a throw (SPEC 8), flying uncapped to its next event */
    double spin;   /* |L| / I_min, the bound on |omega| (vrBody_SpinBound) */
} vrMotion;

/* how torque-free rotation is computed */
typedef enum {
    VR_ROT_NONE,      /* static, or L = 0: the orientation never changes */
    VR_ROT_ISOTROPIC, /* I1 = I2 = I3: omega constant, exact */
    VR_ROT_SYMMETRIC, /* two equal moments: regular precession, exact */
    VR_ROT_GENERAL,   /* asymmetric: L-preserving splitting integrator */
    VR_ROT_KINEMATIC  /* held by the hand (grab.h): constant world omega, kept in m.L */
} vrRotKind;

#define VR_ROT_CHECKPOINTS 32

/* integrator state at a whole number of steps after t0 (principal frame);
 * motion.c keeps steps after the first "open" (see open_step) */
typedef struct vrRotState { long step; quat Q; vec3 Pi; } vrRotState;

typedef struct vrRotCache {
    double h;                       /* fixed sub-step of this anchor */
    vrRotState anchor;              /* step 0: the state at t0 */
    vrRotState last;                /* where the last query stopped */
    vrRotState ring[VR_ROT_CHECKPOINTS]; /* every 64th step, newest last */
    int nring;
} vrRotCache;

typedef struct vrBody {
    int id;
    int is_static;
    double mass, inv_mass;          /* static: inv_mass = 0 */
    mat33 inertia;                  /* about the centre, body frame (kg m^2) */
    mat33 inv_inertia;
    vec3 moments;                   /* principal moments, ascending */
    quat principal;                 /* principal frame -> body frame */
    int sym_axis;                   /* VR_ROT_SYMMETRIC: index of the distinct moment */
    double i_min;                   /* smallest principal moment */
    double r_in, r_out;             /* about the centre (thesis 3.3.1.1) */
    double elasticity;
    double friction;                /* Coulomb coefficient; a pair uses sqrt(mu1 mu2) (SPEC 7) */
    vrShape shape;

    vrMotion m;
    vrRotKind rot;
    vrRotCache rc;
    int resting;                    /* SPEC 3.5 rest state */
    int contact;                    /* in an island's contact step until the next island
                                       step: flies without the global force (island.h) */
    int island;                     /* its island at the last island step or rest (the
                                       island's lowest body id), -1 none */
    int hit;                        /* an impulse jolted it in the current frame (vrBody_Jolted) */
    int kinematic;                  /* held by the hand (SPEC 8, grab.h): it follows the hand,
                                       infinite mass to others, no force, never rests; m.L
                                       holds its world angular velocity, not a momentum */
    /* the last pose asked for: a body in several pairs is asked again and
     * again at the same grid point (the same bits either way) */
    double pose_t;
    vrPose pose;
    int pose_valid;
    int still;                      /* no velocity, acceleration or spin: one pose for every t */
} vrBody;

/* settings that shape free flight */
typedef struct vrFlight {
    vec3 accel;          /* global force as an acceleration */
    double max_linear, max_angular;
} vrFlight;

/* SPEC 3.2's caps: a speed above its cap by rounding only is at the cap,
 * neither cut nor counted (stats clamps).  A spin the cap cut, recomputed
 * from L at the next anchor (omega = I^-1 L), comes out a few ulps over:
 * counted, one cut was two, and a ball spinning at the cap on a
 * frictionless floor was "cut" again at one island step in five. */
static inline int vrFlight_OverCap(double speed, double cap) { return speed > cap * (1 + 1e-12); }

/* An impulse hits a body (its `hit`, which keeps it from resting that
 * frame, rest.c) when it changes the speed of some point of it by v_rest
 * (SPEC 7: the speed of a fall through g_c) or more: |dv| + |dw| r_out
 * bounds that change.  A slower tap is how the contacts of a pile hold
 * it between contact steps: counted as a hit, the taps of mm/s that a
 * settled pile of 300 takes every frame somewhere kept its one island
 * awake for ever.  A bounce, or a body stopped from v_rest or faster,
 * is a hit; without gravity v_rest is 0 and every impulse is one. */
static inline int vrBody_Jolted(vec3 dv, vec3 dw, double r_out, double v_rest)
{
    return vec3_len(dv) + vec3_len(dw) * r_out >= v_rest;
}

/* motion.c */
void vrBody_SetMassProperties(vrBody *b, double mass, const mat33 *inertia_unit, double r_in, double r_out);
/* (re)anchors b at time t with the given state; clamps |v| and |omega|
 * (SPEC 3.2: at the start and at every event), recomputes the acceleration
 * (none in a contact step) and the cap time */
int vrBody_Anchor(vrBody *b, double t, vec3 x, vec3 v, quat q, vec3 L, const vrFlight *f);
/* sets the anchor exactly as given (one captured with vrBody_CaptureAnchor):
 * no clamping, no normalising; what derives from it is recomputed */
void vrBody_Restore(vrBody *b, double t0, vec3 x0, vec3 v0, quat q0, vec3 L, const vrFlight *f);
/* re-anchor at t keeping the motion (after a change of settings) */
void vrBody_Reanchor(vrBody *b, double t, const vrFlight *f);
void vrBody_Pose(vrBody *b, double t, vrPose *pose);
/* the pose a distance or a region needs: a sphere collides as a true
 * sphere, so only its centre is computed (the identity stands in for its
 * turning); what needs a sphere's spin takes vrBody_Pose */
void vrBody_ShapePose(vrBody *b, double t, vrPose *pose);
/* 1 when b's flight, as anchored, reaches max_linear within (from, to]
 * after its anchor: the force sped it up to the cap, and it flies on at
 * it (SPEC 3.2), a cut that stats clamps counts (a cap at the anchor
 * itself is the anchor's own, counted where it was cut) */
int vrBody_CapReached(const vrBody *b, double from, double to);
void vrBody_Position(const vrBody *b, double t, vec3 *x);
void vrBody_Velocity(const vrBody *b, double t, vec3 *v);
/* world angular velocity at t (needs the orientation at t) */
vec3 vrBody_Omega(const vrBody *b, const vrPose *pose);
/* velocity of the material point p (world) given the pose at t */
vec3 vrBody_PointVelocity(const vrBody *b, double t, const vrPose *pose, vec3 p);
/* the same from the body's velocity v and spin w (taken once for many
 * points), its centre at c */
static inline vec3 vrRigid_PointVelocity(vec3 v, vec3 w, vec3 c, vec3 p)
{
    return vec3_add(v, vec3_cross(w, vec3_sub(p, c)));
}
/* world inverse inertia at the pose */
mat33 vrBody_InvInertiaWorld(const vrBody *b, const vrPose *pose);
mat33 vrBody_InertiaWorld(const vrBody *b, const vrPose *pose);
/* the box the centre of mass sweeps over [t1, t2] (t1 <= t2): exact
 * extremes of the parabola and of the line after the speed cap */
void vrBody_PathBox(const vrBody *b, double t1, double t2, vec3 *lo, vec3 *hi);
/* speed bound over [t, t + span] for the internal-step grid (SPEC 3.2) */
double vrBody_SpeedBound(const vrBody *b, double t, double span, double accel, double max_linear);
/* |L| / I_min: a bound on |omega| in free flight */
double vrBody_SpinBound(const vrBody *b);
/* dynamic and not resting */
static inline int vrBody_IsFree(const vrBody *b) { return !b->is_static && !b->resting; }
/* infinite mass in a response or an island solve: static, or held (kinematic) */
static inline int vrBody_Immovable(const vrBody *b) { return b->is_static || b->kinematic; }
/* what an island step of length h pays into the body's velocity before its
 * solve (island_step.c; the owners' touches allow for it): the force's
 * g h for a body that can move, none for an immovable one */
static inline vec3 vrBody_StepGravity(const vrBody *b, vec3 accel, double h)
{
    return vrBody_Immovable(b) ? vec3_zero() : vec3_scale(accel, h);
}
double vrBody_Energy(vrBody *b, double t, vec3 g);

#endif
