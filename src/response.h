/* response.h — single-point collision response (thesis 3.2.2, SPEC 3.4,
 * with SPEC 7's Coulomb friction): the 15x15 linear system in v1', v2',
 * w1', w2', R, solved with SuiteSparse KLU. */
#ifndef VROC_RESPONSE_H
#define VROC_RESPONSE_H

#include "vec.h"

typedef struct vrResponder vrResponder;

/* one side of a contact at the moment of impact (world frame) */
typedef struct vrImpactBody {
    int is_static;
    double mass;
    mat33 inertia, inv_inertia;   /* world frame, about the centre */
    vec3 p;                       /* contact point minus centre of mass */
    vec3 v, w;                    /* velocity and angular velocity before */
} vrImpactBody;

/* the solve's statistics, SPEC 1.3 klu_solves / klu_refactors / klu_factors */
typedef struct vrResponseStats {
    long long solves, refactors, factors;
    long long refined;            /* solves that took a step of iterative refinement */
} vrResponseStats;

vrResponder *vrResponder_Create(void);
void vrResponder_Free(vrResponder *r);
/* Solves the impulse of a contact with unit normal n (from body 1 toward
 * body 2), restitution e and friction mu (0: frictionless, the thesis's);
 * returns 0 and the velocities after, or -1 when KLU fails even after a
 * fresh factorisation. *impulse (may be NULL) gets R, the impulse on body
 * 1.  With friction a response may take two or three solves. */
int vrResponder_Solve(vrResponder *r, const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e, double mu,
                      vec3 *v1, vec3 *w1, vec3 *v2, vec3 *w2, vec3 *impulse);
vrResponseStats vrResponder_Stats(const vrResponder *r);

/* The closed form of SPEC 3.4 for the tests: the scalar j with R = -j n
 * (j > 0 pushes the bodies apart). */
double vrResponse_ClosedForm(const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e);

#endif
