/* setup.h — a setup round: every live worker is given the objects of its
 * pairs and its pairs (SPEC 5), after the world's objects, shapes or
 * settings changed, or a worker died; and the bookkeeping around it. */
#ifndef VROC_SETUP_H
#define VROC_SETUP_H

#include "sgp_state.h"

/* deals the pairs among the live workers and sets each up, again when one
 * dies on the way; the world's pending states count as delivered */
int vrSgp_Setup(vrWorld *w, vrSgp *s, char *err, size_t n);
/* all that worker g's owners counted */
vrGpCounts vrSgp_Counts(const vrSgp *s, int g);
/* appends b's anchor as it is, to be restored bit for bit */
int vrSgp_AddAnchor(vrUpdate *up, vrBody *b);
/* the world's pending states went out: kept for redoing the frame */
int vrSgp_Delivered(vrWorld *w, vrSgp *s);

#endif
