/* island.h — the contacts of one instant solved together (SPEC 7).
 *
 * An island is a set of bodies and the contacts between them (and with
 * static bodies) at one instant.  Its impulses are found together, so a
 * stack's weight reaches the floor and a box landing flat on four corners
 * gets one answer.  The law, at every contact point: the normal impulse is
 * >= 0 and the relative normal velocity after it is at least the point's
 * floor (0 for a touching point; a negative floor lets a point with a gap
 * close it, speculatively; a positive one is a bounce, Newton's e times
 * the speed it came in at), one or the other binding (complementarity);
 * friction acts on the contact as a whole (a patch): the tangential
 * impulse at the points' centroid stops the sliding while it can, and is
 * at most mu times the points' normal impulses together in every direction
 * otherwise (Coulomb's round cone), against the slip; a twist about the
 * normal likewise within that times the patch's mean radius.
 *
 * Solved by projected Gauss-Seidel in a fixed order (contacts as given,
 * points in order), from the impulses given where a contact is warm (the
 * last step's, as Box2D and Bullet start) and from none elsewhere, so the
 * same island gives the same bits in every process; then, when the island rests on static bodies, one pass from the
 * ground up in which each contact's lower body is held still (shock
 * propagation, Guendelman, Bridson and Fedkiw 2003), so that whatever the
 * mass ratios no contact of a stack is left approaching.  Each step of
 * either pass lowers the kinetic energy or keeps it.
 *
 * The energy that must not rise is the step's: kinetic energy after the
 * solve plus the force's work over the step's flight (-m paid.v'), against
 * the kinetic energy before the force was paid in.  The exact answer never
 * raises it (it falls by half the impulses' |dv|^2 in the mass norm, plus
 * lambda.floor <= 0); sweeps cut short leave points pushed apart (lambda > 0
 * while separating), which it does not see in the kinetic energy alone: a
 * settling pile's 80-body islands gained up to 7e-9 of the scene's energy
 * in a step.  Such an answer has its impulses scaled back toward none (the
 * force paid alone loses m |paid|^2 / 2), just far enough (island.c).
 */
#ifndef VROC_ISLAND_H
#define VROC_ISLAND_H

#include "vec.h"

#define VR_ISLAND_POINTS 8     /* points of one contact the solve keeps */

typedef struct vrIslandBody {
    int dynamic;              /* 0: static (infinite mass, never moves) */
    double inv_mass;
    mat33 inv_inertia;        /* world frame, about the centre of mass */
    vec3 x;                   /* centre of mass */
    vec3 v, w;                /* in: velocities before; out: after the impulses */
    vec3 paid;                /* in: what the step's force added to v before the solve (g h; 0 at an
                               * instant): the step's flight at the new v does that force's work */
    int level;                /* out: contacts from the nearest static body (0 static, -1 none) */
} vrIslandBody;

typedef struct vrIslandContact {
    int a, b;                 /* body indices; n points from a toward b */
    vec3 n;
    double mu;                /* Coulomb coefficient, >= 0 */
    int npoints;              /* 1..VR_ISLAND_POINTS */
    vec3 p[VR_ISLAND_POINTS];           /* world points */
    double floor[VR_ISLAND_POINTS];     /* lowest relative normal velocity allowed */
    double e;                 /* restitution of a contact whose floors bounce (Poisson's, when Newton's gains) */
    int warm;                 /* in: 1 when lambda, friction and twist hold a guess to start from */
    double lambda[VR_ISLAND_POINTS];    /* out: normal impulses on b (on a: minus) */
    vec3 friction;            /* out: tangential impulse on b at the points' centroid */
    double twist;             /* out: angular impulse on b about n (friction against turning) */
} vrIslandContact;

/* pushed[i] = 1 when an impulse of a solved contact (normal, friction or
 * twist) acts on body i, else 0: the island step flies the others free,
 * under the force (island_step.c), and its energy check counts only these */
void vrIsland_Pushed(const vrIslandContact *c, int ncontact, unsigned char *pushed, int nbody);

typedef struct vrIslandStats {
    int sweeps;               /* Gauss-Seidel sweeps made */
    int shock;                /* 1 when the ground-up pass ran */
    int frictionless;         /* 1 when friction had to go to keep the energy (see island.c) */
    int bounceless;           /* 1 when the bounces had to go too */
    double residual;          /* largest normal velocity below a floor left, m/s */
} vrIslandStats;

/* What a solve works in, kept from one solve to the next by its caller
 * (vrIsland_SolveStep's x; NULL: a solve's own, freed after it): its arrays grow to the
 * largest island seen.  Made afresh at every solve, a pile's islands
 * mapped and unmapped them, and the page faults were a tenth of its time.
 * Zeroed, it is empty. */
typedef struct vrIslandScratch {
    struct vrSolvePoint *pt;          /* each with its capacity (grow.h) */
    struct vrSolvePatch *patch;
    struct vrLcpFactor *lcp;
    double *m;
    int *pass;
    vrIslandBody *before, *bounceless;
    mat33 *inertia;
    int *bounced;
    unsigned char *pushed;
    int pushedcap;
    int ptcap, patchcap, lcpcap, mcap, passcap, beforecap, inertiacap, bouncelesscap, bouncedcap;
} vrIslandScratch;
void vrIslandScratch_Free(vrIslandScratch *x);

/* Solves the island in place (body velocities updated, impulses in the
 * contacts).  At most `sweeps` sweeps, fewer once no impulse changes by
 * more than `tol` m/s of relative velocity.  0, or -1 on a bad argument. */
int vrIsland_Solve(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                   vrIslandStats *st);
/* vrIsland_Solve for an island step, whose solves are warm started and
 * whose cap is small: an island on a static body whose sweeps will not
 * reach tol by the cap (judged from its eighth sweep on, by the rate its
 * change falls at) goes to the ground-up pass then, not at the cap.  The
 * next step goes on from its impulses; a generous cap's last sweeps, which
 * still carry a tall stack's weight down (vrIsland_Solve), may be cut. */
int vrIsland_SolveStep(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                       vrIslandStats *st, vrIslandScratch *x);

#endif
