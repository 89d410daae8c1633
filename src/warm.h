/* warm.h — the last island step's impulses, kept by pair to start the
 * next step's solve from (warm.c; SPEC 7).  A resting stack's impulses
 * hardly change from one step to the next: started from them, the
 * Gauss-Seidel sweeps of island.c end in a few sweeps instead of dozens
 * (Box2D and Bullet warm start the same way).  A guess only: the solve's
 * answer is the same law whatever it starts from. */
#ifndef VROC_WARM_H
#define VROC_WARM_H

#include "island.h"

typedef struct vrWarmContact {
    int a, b;                 /* object ids, a < b */
    double h;                 /* the step it was solved for */
    vec3 n;
    int npoints;
    vec3 p[VR_ISLAND_POINTS];
    double lambda[VR_ISLAND_POINTS];
    vec3 friction;
    double twist;
} vrWarmContact;

typedef struct vrWarm {
    int n, cap;
    vrWarmContact *c;         /* sorted by pair once vrWarm_Sort has run */
    long structure;           /* the world's structure count they belong to */
} vrWarm;

void vrWarm_Free(vrWarm *w);
/* to becomes a copy of from (its list and structure); -1 when out of
 * memory, to then empty and of no structure */
int vrWarm_Copy(vrWarm *to, const vrWarm *from);
/* keeps contact c of pair (a, b), solved for a step of h; -1 when out of memory */
int vrWarm_Keep(vrWarm *w, int a, int b, double h, const vrIslandContact *c);
void vrWarm_Sort(vrWarm *w);
/* c (of pair a, b, for a step of h) warm from the kept contact of its
 * pair: each point takes the impulse of the kept point within `match` of
 * it (shared among the points that take the same one), scaled by the
 * steps' ratio; friction and twist likewise.  Cold when nothing matches. */
void vrWarm_Start(const vrWarm *w, int a, int b, double h, double match, vrIslandContact *c);

#endif
