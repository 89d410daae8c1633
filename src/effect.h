/* effect.h — what an event does to its bodies: the bodies' new states (SPEC 3.1, 3.4) */
#ifndef VROC_RESPOND_H
#define VROC_RESPOND_H

#include "event.h"
#include "response.h"

#define VR_V_EPS 1e-3          /* m/s: slower approaches inside the envelope need no impulse */
#define VR_PUSHOUT_GAP 1e-6    /* m: a push-out leaves this gap (MPR is good to 1e-9) */

/* Adds to up the states of the bodies (by id in body) that ev changes:
 * velocities after an impulse (ev->e and ev->mu, at ev->c along ev->n, spin
 * clamped at flight->max_angular), positions after a push-out.  -1 when the
 * impulse solve fails or memory runs out. */
int vrEffect_Compute(vrBody **body, vrResponder *responder, const vrFlight *flight, double v_rest, const vrEvent *ev,
                     vrUpdate *up);

#endif
