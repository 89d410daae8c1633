/* distribution.c — the pair distribution (thesis 3.5.1, 6.4; SPEC 5, 10),
 * a function of the pair's two ids, never a list of the pairs.
 *
 * Round robin (3.5.1) deals the pairs in the order of their index in the
 * triangle of ids, b(b-1)/2 + a: the k-th to the (k mod n)-th live worker.
 * The improved distribution (6.4) cuts the objects into groups of `per`
 * consecutive ids and gives each worker whole blocks of pairs between two
 * groups, so a worker holds copies of few groups (the thesis's 6 objects
 * on 3 workers: at most 4 objects each).  Either way each pair has exactly
 * one owner among the live workers, whatever was deleted or created: the
 * deal is made anew at every setup, from the table as it is then.
 *
 *   groups_for     the fewest groups with a block for every worker
 *   block_of       the index of the block of pairs between groups g1 <= g2
 *   count_groups   live and dynamic objects per group; block_size from them
 *   assign_blocks  the blocks to the workers, greedily
 *   vrDistribution_Deal, vrDeal_Owner   the deal, and a pair's owner
 *   share_*        a worker's pairs counted, and the objects it needs
 */
#include <string.h>
#include "distribution.h"

static int groups_for(int workers, int objects)
{
    int m = 1;
    while (m * (m - 1) / 2 < workers && m < objects && m < VR_DEAL_GROUPS) m++;
    return m;
}

static int block_of(int g1, int g2, int m) { return g1 * m - g1 * (g1 - 1) / 2 + (g2 - g1); }

static int group_of(const vrDeal *d, int id)
{
    int g = id / d->per;
    return g < d->groups ? g : d->groups - 1;   /* (an id past the table's, in a malformed setup) */
}

/* per group: its live objects, and the dynamic ones among them */
static void count_groups(const vrDeal *d, const vrTable *t, long long *all, long long *dyn)
{
    int i;
    memset(all, 0, VR_DEAL_GROUPS * sizeof *all);
    memset(dyn, 0, VR_DEAL_GROUPS * sizeof *dyn);
    for (i = 0; i < t->n; i++)
        if (t->obj[i] && t->obj[i]->live) {
            all[group_of(d, i)]++;
            dyn[group_of(d, i)] += !t->obj[i]->body.is_static;
        }
}

/* the live pairs between groups g1 <= g2: not both static (vrTable_LivePair) */
static long long block_size(const long long *all, const long long *dyn, int g1, int g2)
{
    long long s1 = all[g1] - dyn[g1], s2 = all[g2] - dyn[g2];
    if (g1 == g2) return all[g1] * (all[g1] - 1) / 2 - s1 * (s1 - 1) / 2;
    return all[g1] * all[g2] - s1 * s2;
}

/* Greedy, biggest block first: among the workers that can take the block
 * without going past a fair share (+20 %), the one it adds fewest new
 * groups to, then the least loaded; if none can, the least loaded.  For the
 * thesis's example this is its figure 6.3: 4 objects and 5 pairs each. */
static void assign_blocks(const long long *size, int m, int nalive, int *owner)
{
    long long total = 0, cap, load[VR_MAX_GPS] = {0};
    char uses[VR_MAX_GPS][VR_DEAL_GROUPS] = {{0}};
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

static void deal_improved(vrDeal *d, const vrTable *t)
{
    long long all[VR_DEAL_GROUPS], dyn[VR_DEAL_GROUPS], size[VR_DEAL_BLOCKS];
    int owner[VR_DEAL_BLOCKS], m, g1, g2, b;
    d->groups = m = groups_for(d->nalive, t->n);
    d->per = (t->n + m - 1) / m;
    if (d->per < 1) d->per = 1;
    count_groups(d, t, all, dyn);
    for (g1 = 0; g1 < m; g1++)
        for (g2 = g1; g2 < m; g2++) size[block_of(g1, g2, m)] = block_size(all, dyn, g1, g2);
    assign_blocks(size, m, d->nalive, owner);
    for (b = 0; b < m * (m + 1) / 2; b++) d->block_gp[b] = d->alive[owner[b]];
}

void vrDistribution_Deal(vrDeal *d, const vrTable *t, vrDistribution kind, const int *alive, int nalive)
{
    memset(d, 0, sizeof *d);
    d->nalive = nalive;
    memcpy(d->alive, alive, (size_t)nalive * sizeof *alive);
    d->per = d->groups = 1;
    d->improved = kind == VR_DIST_IMPROVED;
    if (d->improved) deal_improved(d, t);
}

int vrDeal_Owner(const vrDeal *d, int a, int b)
{
    if (d->improved) return d->block_gp[block_of(group_of(d, a), group_of(d, b), d->groups)];
    return d->alive[((long long)b * (b - 1) / 2 + a) % d->nalive];
}

int vrDeal_Check(const vrDeal *d, int ngps)
{
    int i;
    if (d->nalive < 1 || d->nalive > VR_MAX_GPS) return -1;
    for (i = 0; i < d->nalive; i++)
        if (d->alive[i] < 0 || d->alive[i] >= ngps) return -1;
    if (!d->improved) return 0;
    if (d->groups < 1 || d->groups > VR_DEAL_GROUPS || d->per < 1) return -1;
    for (i = 0; i < d->groups * (d->groups + 1) / 2; i++)
        if (d->block_gp[i] < 0 || d->block_gp[i] >= ngps) return -1;
    return 0;
}

/* ---- a worker's share ------------------------------------------------------------- */

/* Round robin: row b of the triangle (the pairs (a, b), a < b) starts at
 * index b(b-1)/2, so worker g's pairs in it are those with a in one
 * residue class mod nalive: counted from the live (and dynamic) objects
 * before b in each class, O(n) for the table */
static long long count_round_robin(const vrDeal *d, const vrTable *t, int g)
{
    long long all[VR_MAX_GPS] = {0}, dyn[VR_MAX_GPS] = {0}, n = 0;
    int G = d->nalive, rank = -1, b;
    for (b = 0; b < G; b++)
        if (d->alive[b] == g) rank = b;
    for (b = 0; rank >= 0 && b < t->n; b++) {
        const vrObject *o = t->obj[b];
        int c;
        if (!o || !o->live) continue;
        c = (int)(((rank - ((long long)b * (b - 1) / 2) % G) % G + G) % G);
        n += o->body.is_static ? dyn[c] : all[c];
        all[b % G]++;
        dyn[b % G] += !o->body.is_static;
    }
    return n;
}

/* object i has a pair of g's: its partners are looked at until one is g's
 * (among many objects one of the first nalive is) */
static int round_robin_needs(const vrDeal *d, const vrTable *t, int g, int i)
{
    int j;
    for (j = 0; j < t->n; j++)
        if (j != i && vrTable_LivePair(t, i, j) && vrDeal_Owner(d, i < j ? i : j, i < j ? j : i) == g) return 1;
    return 0;
}

/* Improved: the blocks of g, and an object needed when a block of g's
 * joins its group to one that holds a partner of it */
static long long share_improved(const vrDeal *d, const vrTable *t, int g, unsigned char *need)
{
    long long all[VR_DEAL_GROUPS], dyn[VR_DEAL_GROUPS], n = 0;
    int g1, g2, i;
    count_groups(d, t, all, dyn);
    for (g1 = 0; g1 < d->groups; g1++)
        for (g2 = g1; g2 < d->groups; g2++)
            if (d->block_gp[block_of(g1, g2, d->groups)] == g) n += block_size(all, dyn, g1, g2);
    for (i = 0; need && i < t->n; i++) {
        int gi = group_of(d, i), mobile;
        need[i] = 0;
        if (!t->obj[i] || !t->obj[i]->live) continue;
        mobile = !t->obj[i]->body.is_static;
        for (g2 = 0; g2 < d->groups && !need[i]; g2++) {
            long long partners = (mobile ? all[g2] : dyn[g2]) - (g2 == gi && mobile);
            int b = gi <= g2 ? block_of(gi, g2, d->groups) : block_of(g2, gi, d->groups);
            need[i] = d->block_gp[b] == g && partners > 0;
        }
    }
    return n;
}

long long vrDeal_Share(const vrDeal *d, const vrTable *t, int g, unsigned char *need)
{
    int i;
    if (d->improved) return share_improved(d, t, g, need);
    for (i = 0; need && i < t->n; i++) need[i] = t->obj[i] && t->obj[i]->live && round_robin_needs(d, t, g, i);
    return count_round_robin(d, t, g);
}
