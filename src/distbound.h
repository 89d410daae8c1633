/* distbound.h — bounds on a pair's distance near an instant where it was
 * measured, from the free flight of its two bodies (Taylor models).
 *
 * Two users.  The impact bisection (SPEC 3.2) halves a grid step 48 times
 * (or until its ends are adjacent doubles), and each halving asks "within
 * d?".  Far from the crossing the answer is plain from one measurement
 * nearby: the bodies cannot have closed or opened the gap enough.  These
 * bounds prove it, so the bisection asks the geometry only where they
 * cannot; the bracket it ends with, and so every bit of the event time, is
 * the same.  And the schedule's key (SPEC 3.3) for turning bodies close
 * together: the lower bound says how long the pair surely stays apart,
 * following the vertices that are near rather than assuming the worst
 * point comes at |omega| R.
 *
 * From a measurement at te (unit direction n from a to b, closest points
 * pa on a and pb on b), for t = te + tau in the window given:
 *  - lower bound: the gap along the fixed direction n.  A centre moves
 *    exactly as v tau + a tau^2/2 (a line once the speed cap is reached);
 *    a body turning at constant omega moves a vertex r along n at most as
 *    n.r + n.(omega x r) tau + |omega|^2 |r| tau^2 / 2 (Taylor, with the
 *    second derivative's bound), and its support along n is the largest of
 *    these over the vertices that could be highest, and never more than R
 *    from the centre;
 *  - upper bound: the distance between the material points pa and pb,
 *    carried by their bodies: the second-order Taylor polynomial of each,
 *    plus |omega|^3 |r| |tau|^3 / 6 for what it leaves out (a sphere's
 *    point is its centre, less its radius);
 *  - and when one body is a frozen box (a wall, a table top), the height
 *    of the other's lowest point over the box's face toward it, carried
 *    the same way, while that point stays over the face: a body sliding
 *    along a wall keeps its distance to the wall's plane, where its
 *    distance to a fixed point of the wall grows with the square of the
 *    slide.
 * True spheres collide by their centres, so they count as not turning.
 * Bodies whose spin is not constant (two or three different moments of
 * inertia) or that meet the speed cap inside the window give no bounds.
 */
#ifndef VROC_DISTBOUND_H
#define VROC_DISTBOUND_H

#include "body.h"

/* support vertices a side keeps; more candidates than this and it bounds
 * their motion by |omega| R |tau| instead */
#define VR_DISTBOUND_VERTS 16

typedef struct vrBoundSide {
    vec3 v, a;            /* centre velocity at te, acceleration */
    vec3 u, acc;          /* velocity and acceleration of the material witness point at te */
    double w_len, r_out;  /* |omega|; outer radius about the centre */
    double headroom;      /* how much higher the support can ever get: R less its height at te */
    double jerk;          /* |omega|^3 |r|: bounds the witness point's third derivative */
    int nv;               /* -1: bound by |omega| R |tau|; else candidate vertices */
    double g[VR_DISTBOUND_VERTS], s[VR_DISTBOUND_VERTS]; /* height below the support, rate along n */
} vrBoundSide;

/* a moving point's height over a frozen box's face plane, h0 + h1 tau +
 * h2 tau^2 within cubic |tau|^3 (a sphere's centre: less its radius, and
 * floor = -radius is as low as it may go); it stays over the face while it
 * moves less than room, and it moves at most (move1 + move2 |tau|) |tau|
 * + cubic |tau|^3 */
typedef struct vrPlaneBound {
    double h0, h1, h2, cubic, floor;
    double move1, move2, room;
} vrPlaneBound;

typedef struct vrDistBound {
    int valid;
    double te;
    double gap_n;         /* gap between the supports along n at te */
    vec3 n;
    vec3 gap0;            /* between the witness points at te: pa, pb, or a sphere's centre */
    double shrink;        /* the radii of the spheres whose centres are witnesses */
    int has_upper;        /* the witnesses are points of the bodies (or two spheres' centres) */
    int has_plane;        /* one body is a frozen box: plane bounds from above too */
    vrPlaneBound plane;
    vrBoundSide a, b;
} vrDistBound;

/* Bounds from a measurement at te with closest points pa, pb (dist =
 * |pb - pa| > 0) and the bodies' poses at te, for times in [lo, hi]
 * (te among them).  The lower bound only takes its direction from them;
 * the upper bound needs them to be points of the bodies (a canonical
 * face-face contact's projected point need not be): on_bodies = 0 leaves
 * it out.  db->valid = 0 when the bodies' motion allows no bounds. */
void vrDistBound_Make(vrDistBound *db, vrBody *A, const vrPose *pose_a, vrBody *B, const vrPose *pose_b,
                      double te, vec3 pa, vec3 pb, int on_bodies, double lo, double hi);

/* lower bound only, along the unit direction n (a toward b) */
void vrDistBound_MakeAlong(vrDistBound *db, vrBody *A, const vrPose *pose_a, vrBody *B, const vrPose *pose_b,
                           double te, vec3 n, double lo, double hi);
/* a time up to `until` (in the window) such that the lower bound stays
 * above d from `from` (te when earlier) to it; `from` itself when the
 * bound is not above d there.  The caller knows the pair clear before
 * `from`. */
double vrDistBound_Clear(const vrDistBound *db, double d, double from, double until);

/* 1 when the distance at t (in the window) is certainly <= d, 0 when it is
 * certainly > d, -1 when the bounds come within tol of d (or are invalid). */
int vrDistBound_Decide(const vrDistBound *db, double t, double d, double tol);

/* A time up to `until` (in the window) to which the distance surely stays
 * at most level: by the witness points (upper bound) or, with one body a
 * frozen box, by the other's lowest point rising no higher over the box's
 * face and staying over it; te when the bounds say nothing. */
double vrDistBound_StaysWithin(const vrDistBound *db, double level, double until);

#endif
