/* schedule.h — when to look (thesis 3.2.3 and 3.3.1.1, SPEC 3.2 and 3.3):
 * the internal-step grid of a span, and a pair's expected earliest event. */
#ifndef VROC_SCHEDULE_H
#define VROC_SCHEDULE_H

#include "body.h"

/* The grid of a span [t0, T]: points a + (k0 + k) h, k = 1..n, the last
 * one exactly T, anchored at a, the start of the contact step the span is
 * in (a <= t0 < a + (k0 + 1) h), so that a span started by an event has
 * the points its step had before it: a pair whose bodies the event did not
 * change looks at the same instants, over the same brackets, whatever
 * events came before (see vrGrid_Before).  frame_T is the frame's end (>=
 * T: a span ends at the next island step, SPEC 7). */
typedef struct vrGrid { double t0, T, h; long n; double frame_T; double a; long k0; } vrGrid;

static inline double vrGrid_Point(const vrGrid *g, long k)
{
    return k >= g->n ? g->T : k <= 0 ? g->t0 : g->a + (double)(g->k0 + k) * g->h;
}
/* the anchored point before point k >= 1 (at or before t0 for k = 1): the
 * bracket a look at point k bisects starts there, or later where either
 * body's motion starts (the look-ahead's vrOwner_FirstEvent) */
static inline double vrGrid_Before(const vrGrid *g, long k)
{
    return g->a + (double)(g->k0 + k - 1) * g->h;
}

/* SPEC 3.2: h_max = d / (2 max_i (s_i + w_i R_i)) over the free bodies;
 * internal_step > 0 forces h */
void vrSchedule_Grid(vrBody *const *bodies, int nbodies, double ts, double T, double d,
                     double internal_step, const vrFlight *f, vrGrid *g);
/* the largest of the free bodies' reach over [ts, T] (0 with a forced step) */
double vrSchedule_Fastest(vrBody *const *bodies, int nbodies, double ts, double T, double internal_step,
                          const vrFlight *f);
/* a body's s_i + w_i R_i for the span [ts, T] (0 when not free) */
double vrSchedule_Reach(const vrBody *b, double ts, double T, const vrFlight *f);
/* its w_i R_i alone (a true sphere's turning moves no surface point) */
static inline double vrSchedule_SpinReach(const vrBody *b)
{
    return vrBody_SpinBound(b) * (b->shape.kind == VR_SHAPE_SPHERE ? 0.0 : b->r_out);
}
/* time left after t before b's speed stops growing at the cap (0 once it
 * has; INFINITY when it never will, or b is not free) */
static inline double vrSchedule_CapLeft(const vrBody *b, double t)
{
    double left = b->m.tcap - (t - b->m.t0);
    return vrBody_IsFree(b) ? (left > 0 ? left : 0) : INFINITY;
}
/* the grid of [ts, T] depends on the bodies' reach (no forced step, time left) */
static inline int vrSchedule_NeedsReach(double ts, double T, double internal_step)
{
    return internal_step <= 0 && T > ts;
}
/* the grid of [ts, T] given the largest reach over the free bodies */
void vrSchedule_GridFor(double fastest, double ts, double T, double d, double internal_step, vrGrid *g);
/* The grid of the span [ts, T] of the contact step [a, T], on the step's
 * anchored points: *steps (0 at the step's first span) is how many the
 * step is cut into, doubled until the fastest reach fits (a refined grid
 * keeps every point it had), never halved within the step. */
void vrSchedule_AnchoredGrid(double fastest, double a, double ts, double T, double d, double internal_step,
                             long *steps, vrGrid *g);
/* the first k >= 1 whose grid point is at or after time t (n + 1 if none) */
long vrSchedule_FirstPointAtOrAfter(const vrGrid *g, double t);

/* SPEC 3.3: the earliest time after t at which the pair, dist apart at t,
 * could come within d: (R - r) dropped for bodies that cannot rotate, the
 * closing speed bounded piecewise and split at the speed cap (thesis eq. 5).
 * With n, the unit normal from a toward b at t, the bound also uses the
 * direction of motion (thesis 6.3): a pair moving apart is not checked
 * again until the speed caps could turn it round; and for turning boxes
 * (constant spin) the support of each along n vertex by vertex
 * (distbound.h).  Each bound holds, so the latest does.  Returns t when
 * the pair is due now, INFINITY when it can never close. */
double vrSchedule_Key(vrBody *a, vrBody *b, double t, double dist, vec3 n, double d, const vrFlight *f);
/* The same, for a caller that needs no key past `enough`: any time not
 * before it once the key is surely that late (the vertex bounds stop there) */
double vrSchedule_KeyUpTo(vrBody *a, vrBody *b, double t, double dist, vec3 n, double d, const vrFlight *f,
                          double enough);
/* two bodies' centres at t and their distance: what a look by the
 * bounding spheres measures, and the sphere key reads again */
typedef struct vrCentres { vec3 xa, xb; double len; } vrCentres;
void vrCentres_At(const vrBody *a, const vrBody *b, double t, vrCentres *c);
/* The same from the bounding spheres about the centres (a sphere's own),
 * which do not change as the bodies turn: c the centres at t, dist the
 * distance between the spheres and n the direction between the centres. */
double vrSchedule_SphereKey(vrBody *a, vrBody *b, double t, const vrCentres *c, double dist, vec3 n, double d,
                            const vrFlight *f);

#endif
