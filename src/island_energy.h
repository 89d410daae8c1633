/* island_energy.h — an island solve's energy check (island_energy.c), for
 * island.c's tries.  inertia[i] is the inverse of body i's inv_inertia
 * (zero for a body that does not move), found once a solve. */
#ifndef VROC_ISLAND_ENERGY_H
#define VROC_ISLAND_ENERGY_H

#include "island.h"

/* the bodies' kinetic energy */
double vrIslandEnergy_Kinetic(const vrIslandBody *b, const mat33 *inertia, int n);
/* the step's energy after the solve (body) less before the force was
 * paid in (before), when above SPEC 7's allowance, else 0; *C the step's
 * loss with no impulse at all; pushed: scratch for nbody flags */
double vrIslandEnergy_StepGain(const vrIslandBody *body, const vrIslandBody *before, const mat33 *inertia, int nbody,
                               const vrIslandContact *c, int ncontact, unsigned char *pushed, double *C);
/* the solve's impulses and velocity changes scaled back so that a step
 * that gained R (vrIslandEnergy_StepGain) gains nothing */
void vrIslandEnergy_PayBack(vrIslandBody *body, const vrIslandBody *before, int nbody, vrIslandContact *c,
                            int ncontact, double R, double C);
/* the floors cut to <= 0: the bounces go; bounced[i] = 1 for a contact
 * that had one, and with hold its every point held (floor 0) */
void vrIslandEnergy_NoBounces(vrIslandContact *c, int ncontact, int *bounced, int hold);
/* a bounceless solve's bounces given back as Poisson's, as far as they
 * keep the kinetic energy e0 before the solve (save: scratch for nbody) */
void vrIslandEnergy_Poisson(vrIslandBody *body, int nbody, const vrIslandContact *c, int ncontact, const int *bounced,
                            const mat33 *inertia, double e0, vrIslandBody *save);

#endif
