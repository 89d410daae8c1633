/* distribution.c — the pair distribution (thesis 3.5.1, 6.4; SPEC 5).
 *
 * Round robin (3.5.1) deals the pairs in order.  The improved distribution
 * (6.4) cuts the objects into m groups and gives each worker whole blocks
 * of pairs between groups, so a worker holds copies of few groups (the
 * thesis's 6 objects on 3 workers: at most 4 objects each).
 *
 *   groups_for     the fewest groups with a block for every worker
 *   block_of       the index of the block of pairs between groups g1 <= g2
 *   assign_blocks  the blocks to the workers, greedily
 *   deal_improved  the pairs to the workers by their blocks
 *   list_pairs     the live pairs in order
 */
#include <stdlib.h>
#include "config.h"
#include "distribution.h"

static int groups_for(int workers, int objects)
{
    int m = 1;
    while (m * (m - 1) / 2 < workers && m < objects) m++;
    return m;
}

static int block_of(int g1, int g2, int m) { return g1 * m - g1 * (g1 - 1) / 2 + (g2 - g1); }

/* Greedy, biggest block first: among the workers that can take the block
 * without going past a fair share (+20 %), the one it adds fewest new
 * groups to, then the least loaded; if none can, the least loaded.  For the
 * thesis's example this is its figure 6.3: 4 objects and 5 pairs each. */
static void assign_blocks(const long long *size, int m, int nalive, int *owner)
{
    long long total = 0, cap, load[VR_MAX_GPS] = {0};
    char uses[VR_MAX_GPS][VR_MAX_GPS * 2] = {{0}};
    int blocks = m * (m + 1) / 2, b, k, g1, g2;
    for (b = 0; b < blocks; b++) {
        total += size[b];
        owner[b] = -1;
    }
    cap = (total * 12 + nalive * 10 - 1) / (nalive * 10);
    for (;;) {
        int best = -1, bg1 = 0, bg2 = 0, who = -1, wc = 0;
        for (g1 = 0; g1 < m; g1++)
            for (g2 = g1; g2 < m; g2++) {
                b = block_of(g1, g2, m);
                if (owner[b] < 0 && (best < 0 || size[b] > size[best])) { best = b; bg1 = g1; bg2 = g2; }
            }
        if (best < 0) return;
        for (k = 0; k < nalive; k++) {
            int c = !uses[k][bg1] + (bg2 != bg1 && !uses[k][bg2]);
            if (load[k] + size[best] > cap) continue;
            if (who < 0 || c < wc || (c == wc && load[k] < load[who])) { who = k; wc = c; }
        }
        for (k = 0; who < 0 && k < nalive; k++)
            if (who < 0 || load[k] < load[who]) who = k;
        if (who < 0) who = 0;
        owner[best] = who;
        load[who] += size[best];
        uses[who][bg1] = uses[who][bg2] = 1;
    }
}

static void deal_improved(const vrTable *t, const int *alive, int nalive, vrDeal *d)
{
    int m = groups_for(nalive, t->n), per = (t->n + m - 1) / m, k;
    long long *size = calloc((size_t)(m * (m + 1) / 2), sizeof *size);
    int *owner = malloc((size_t)(m * (m + 1) / 2) * sizeof *owner);
    if (!size || !owner || m > 2 * VR_MAX_GPS) {
        for (k = 0; k < d->npairs; k++) d->gp_of[k] = alive[k % nalive];
    } else {
        for (k = 0; k < d->npairs; k++) size[block_of(d->a[k] / per, d->b[k] / per, m)]++;
        assign_blocks(size, m, nalive, owner);
        for (k = 0; k < d->npairs; k++) d->gp_of[k] = alive[owner[block_of(d->a[k] / per, d->b[k] / per, m)]];
    }
    free(size);
    free(owner);
}

static int list_pairs(vrDeal *d, const vrTable *t)
{
    int i, j, k = 0, cap = 64;
    d->a = malloc((size_t)cap * sizeof *d->a);
    d->b = malloc((size_t)cap * sizeof *d->b);
    for (i = 0; d->a && d->b && i < t->n; i++)
        for (j = i + 1; j < t->n; j++) {
            if (!vrTable_LivePair(t, i, j)) continue;
            if (k == cap) {
                int *a = realloc(d->a, (size_t)(cap *= 2) * sizeof *a), *b;
                if (a) d->a = a;
                b = realloc(d->b, (size_t)cap * sizeof *b);
                if (b) d->b = b;
                if (!a || !b) return -1;
            }
            d->a[k] = i;
            d->b[k++] = j;
        }
    d->npairs = k;
    return d->a && d->b ? 0 : -1;
}

int vrDistribution_Deal(vrDeal *d, const vrTable *t, vrDistribution kind, const int *alive, int nalive)
{
    int k;
    d->a = d->b = d->gp_of = NULL;
    d->npairs = 0;
    if (list_pairs(d, t) != 0 || !(d->gp_of = malloc((size_t)(d->npairs ? d->npairs : 1) * sizeof *d->gp_of))) {
        vrDistribution_Free(d);
        return -1;
    }
    if (kind == VR_DIST_IMPROVED) deal_improved(t, alive, nalive, d);
    else
        for (k = 0; k < d->npairs; k++) d->gp_of[k] = alive[k % nalive];
    return 0;
}

void vrDistribution_Free(vrDeal *d)
{
    free(d->a);
    free(d->b);
    free(d->gp_of);
    d->a = d->b = d->gp_of = NULL;
    d->npairs = 0;
}
