/* distribution.h — which worker owns which pair (thesis 3.5.1 and 6.4,
 * SPEC 5, 10): the `distribution` setting's round robin or improved deal,
 * as a function of the pair's two ids, so that neither the SGP nor a
 * worker lists the n(n-1)/2 pairs.  The SGP makes the deal at a setup and
 * sends it to the workers (setup_t.lcm); each worker's lazy owner asks it
 * "is this pair mine" before making a pair's record (pair_life.c). */
#ifndef VROC_DISTRIBUTION_H
#define VROC_DISTRIBUTION_H

#include <stdint.h>
#include "config.h"
#include "table.h"

/* the improved deal's groups: the fewest with a block for every worker, at
 * most 12 for VR_MAX_GPS = 64 (12 * 11 / 2 >= 64) */
#define VR_DEAL_GROUPS 16
#define VR_DEAL_BLOCKS (VR_DEAL_GROUPS * (VR_DEAL_GROUPS + 1) / 2)

typedef struct vrDeal {
    int improved;             /* 0: round robin */
    int nalive;               /* round robin: pair (a, b), a < b, is worker */
    int32_t alive[VR_MAX_GPS];   /* alive[(b(b-1)/2 + a) % nalive]'s (its index in the triangle) */
    int per, groups;          /* improved: object i is in group i / per, of `groups` */
    int32_t block_gp[VR_DEAL_BLOCKS];   /* improved: the worker of each block of pairs between two groups */
} vrDeal;

/* deals the table's live pairs among the workers alive[0..nalive) */
void vrDistribution_Deal(vrDeal *d, const vrTable *t, vrDistribution kind, const int *alive, int nalive);
/* the worker that owns pair (a, b), a < b: exactly one for every pair */
int vrDeal_Owner(const vrDeal *d, int a, int b);
/* the number of the table's live pairs (vrTable_LivePair) worker g owns;
 * need (t->n bytes, or NULL) marks the objects it needs copies of: those
 * of its pairs */
long long vrDeal_Share(const vrDeal *d, const vrTable *t, int g, unsigned char *need);
/* 0 when a received deal is whole: every pair has an owner below ngps */
int vrDeal_Check(const vrDeal *d, int ngps);

#endif
