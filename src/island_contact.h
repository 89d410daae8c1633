/* island_contact.h — one contact of an island's solve (island_contact.c),
 * for island.c's sweeps and ground-up pass: the solve's state, a contact
 * made ready (with either body held still), its impulses so far applied,
 * and one Gauss-Seidel step at it. */
#ifndef VROC_ISLAND_CONTACT_H
#define VROC_ISLAND_CONTACT_H

#include "island.h"
#include "lcp.h"

/* One impulse direction d at a point, made once per solve (and again when
 * the ground-up pass holds a body): the relative velocity along d is
 * d.(vb - va) + jb.wb - ja.wa, and a unit impulse along d changes the
 * bodies' turning by wb (b) and -wa (a).  The sweeps then cost a few dot
 * products a row, not the world inverse inertia and two cross products
 * each time (the sweeps are most of a settling pile's time). */
typedef struct vrSolveRow {
    vec3 d;
    vec3 ja, jb;              /* ra x d, rb x d */
    vec3 wa, wb;              /* I_a^-1 ja, I_b^-1 jb; 0 for a held or static body */
} vrSolveRow;

/* a contact point: its normal row and the inverse effective mass along
 * the normal (both bodies free, or the lower one held still in the shock
 * pass) */
typedef struct vrSolvePoint {
    vrSolveRow n;
    double kn;                /* n.K n: normal velocity per unit normal impulse */
} vrSolvePoint;

/* Friction acts on the contact as a whole (a patch, as PhysX does): a
 * tangential impulse at the points' centroid within mu times the points'
 * normal impulses together, and a twist about the normal within that times
 * the patch's mean radius.  Per point, the points' coupling through the
 * body's turning sets their impulses against each other and wastes the
 * cone: a box on a slope below atan mu crept down it. */
typedef struct vrSolvePatch {
    int fa, fb;               /* 1: the body takes impulses (moving and not held) */
    double ma, mb;            /* inverse masses, 0 where the body takes none */
    vrSolveRow t[2];          /* the tangents t1, t2 at the centroid */
    double f[2];              /* the friction impulse so far along them */
    double kt[2][2];          /* K in the tangent plane, inverted (0 when singular) */
    vec3 twa, twb;            /* I^-1 n of each body (0 where it takes none) */
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
    int *pass;                /* per contact: its level in the ground-up pass (island.c) */
    vrLcpFactor *lcp;         /* per contact: its LCP's last factor (block_normal_step) */
    int ncontact;
    int frictionless;         /* the energy check's second try */
} vrIslandSolve;

/* point i of contact ci */
static inline vrSolvePoint *vrSolve_Point(const vrIslandSolve *s, int ci, int i) { return &s->pt[ci * VR_ISLAND_POINTS + i]; }
/* the relative normal velocity at point i of contact ci, b's minus a's */
double vrSolve_NormalVelocity(const vrIslandSolve *s, int ci, int i);
/* contact ci's points, patch and normal block made for its bodies as they
 * are, with a or b held still (a held body takes no impulse) */
void vrSolve_Hold(vrIslandSolve *s, int ci, int hold_a, int hold_b);
/* contact ci's impulses so far (a warm start) applied to its bodies */
void vrSolve_ApplyImpulses(vrIslandSolve *s, int ci);
/* one Gauss-Seidel step at contact ci, its bodies held as vrSolve_Hold
 * last made it: its points' normal impulses together, then its friction;
 * the largest change of normal velocity made */
double vrSolve_ContactStep(vrIslandSolve *s, int ci);

#endif
