/* island_step.h — the island step (SPEC 7), island_step.c. */
#ifndef VROC_ISLAND_STEP_H
#define VROC_ISLAND_STEP_H

#include "world_state.h"

/* At t, for a contact step of h: every pair the owners find touching is
 * solved with the others of its island (island.c), the step's gravity
 * paid into the velocities (a resting island that a touch reaches woken
 * first, its own contacts gathered again and solved with the rest); the
 * states go through vrWorld_ApplyUpdate.
 * 0, -1 (err), or VR_RESTART_FRAME from the owners. */
int vrIsland_Step(vrWorld *w, double t, double h, char *err, size_t n);
/* The contacts of an instant: the islands of bodies a and b (the pair of
 * an impulse event at t) solved at once, every touching point that comes
 * in held (no gravity to pay, no gap to close; restitution as at an
 * island step).  Counted in collisions.  1 (nothing done) when the owners
 * do not report the pair itself touching: the event is answered alone. */
int vrIsland_Instant(vrWorld *w, double t, int a, int b, char *err, size_t n);

#endif
