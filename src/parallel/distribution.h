/* distribution.h — which worker owns which pair (thesis 3.5.1 and 6.4,
 * SPEC 5): the `distribution` setting's round robin or improved deal. */
#ifndef VROC_DISTRIBUTION_H
#define VROC_DISTRIBUTION_H

#include "table.h"

/* the live pairs in order, (a[k], b[k]) with a < b, and the worker of each */
typedef struct vrDeal { int *a, *b, *gp_of; int npairs; } vrDeal;

/* deals the table's live pairs (vrTable_LivePair) among the workers
 * alive[0..nalive); -1 when out of memory (d is then freed all the same) */
int vrDistribution_Deal(vrDeal *d, const vrTable *t, vrDistribution kind, const int *alive, int nalive);
void vrDistribution_Free(vrDeal *d);

#endif
