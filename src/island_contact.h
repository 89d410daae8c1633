/* island_contact.h — one contact of an island's solve (island_contact.c),
 * for island.c's sweeps and ground-up pass: the solve's state, a contact
 * made ready (with either body held still), its impulses so far applied,
 * and one Gauss-Seidel step at it. */
#ifndef VROC_ISLAND_CONTACT_H
#define VROC_ISLAND_CONTACT_H

#include "island.h"

/* what one point of a contact needs through the sweeps: its lever arms
 * and the inverse effective mass along the normal (both bodies free, or
 * the lower one held still in the shock pass) */
typedef struct vrSolvePoint {
    vec3 ra, rb;
    double kn;                /* n.K n: normal velocity per unit normal impulse */
} vrSolvePoint;

/* Friction acts on the contact as a whole (a patch, as PhysX does): a
 * tangential impulse at the points' centroid within mu times the points'
 * normal impulses together, and a twist about the normal within that times
 * the patch's mean radius.  Per point, the points' coupling through the
 * body's turning sets their impulses against each other and wastes the
 * cone: a box on a slope below atan mu crept down it. */
typedef struct vrSolvePatch {
    vrSolvePoint at;                 /* the centroid */
    vec3 t1, t2;
    double kt[2][2];          /* K in the tangent plane, inverted (0 when singular) */
    double ktw;               /* twist about n per unit angular impulse, inverted (0: none) */
    double radius;            /* mean distance of the points from the centroid */
} vrSolvePatch;

/* an island's solve under way (island.c) */
typedef struct vrIslandSolve {
    vrIslandBody *body;
    vrIslandContact *c;
    vrSolvePoint *pt;                /* VR_ISLAND_POINTS per contact */
    vrSolvePatch *patch;             /* one per contact */
    double *m;                /* per contact: its points' normal block, VR_LCP_MAX^2 (block_normal_step) */
    int ncontact;
    int frictionless;         /* the energy check's second try */
} vrIslandSolve;

/* point i of contact ci */
static inline vrSolvePoint *vrSolve_Point(const vrIslandSolve *s, int ci, int i) { return &s->pt[ci * VR_ISLAND_POINTS + i]; }
/* the relative velocity at the point, b's minus a's */
vec3 vrSolve_RelativeVelocity(const vrIslandBody *A, const vrIslandBody *B, const vrSolvePoint *pt);
/* contact ci's points, patch and normal block made for its bodies as they
 * are, with a or b held still (a held body takes no impulse) */
void vrSolve_Hold(vrIslandSolve *s, int ci, int hold_a, int hold_b);
/* contact ci's impulses so far (a warm start) applied to its bodies */
void vrSolve_ApplyImpulses(vrIslandSolve *s, int ci);
/* one Gauss-Seidel step at contact ci: its points' normal impulses
 * together, then its friction; the largest change of normal velocity made */
double vrSolve_ContactStep(vrIslandSolve *s, int ci, int hold_a, int hold_b);

#endif
