/* island_group.c — which touching pairs make which island (see
 * island_group.h).  The islands' order and contents are functions of the
 * touches sorted by pair, so serial and parallel runs, heap on and off,
 * give the same islands. */
#include <stdlib.h>
#include "island_group.h"
#include "contact_set.h"

int vrIsland_Root(int *parent, int i)
{
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

/* the lower id stays the root: an island's id is its lowest body id */
static void join(int *parent, int a, int b)
{
    a = vrIsland_Root(parent, a), b = vrIsland_Root(parent, b);
    if (a < b) parent[b] = a;
    else if (b < a) parent[a] = b;
}

int vrIsland_Union(vrWorld *w, int *parent, int *in_island, int *ids)
{
    int k, n = 0;
    for (k = 0; k < w->ncontact_ids; k++) in_island[w->contact_ids[k]] = 0;
    for (k = 0; k < w->touches.n; k++) {
        const vrTouch *c = &w->touches.t[k];
        parent[c->a] = c->a, parent[c->b] = c->b;
        in_island[c->a] = in_island[c->b] = 0;
    }
    for (k = 0; k < w->touches.n; k++) {
        const vrTouch *c = &w->touches.t[k];
        int e, x[2];
        if (c->leaving > 0) continue;
        if (vrIsland_Moves(w, c->a) && vrIsland_Moves(w, c->b)) join(parent, c->a, c->b);
        x[0] = c->a, x[1] = c->b;
        for (e = 0; e < 2; e++)
            if (vrIsland_Moves(w, x[e]) && !in_island[x[e]]) {
                in_island[x[e]] = 1;
                if (ids) ids[n++] = x[e];
            }
    }
    if (ids) vrIds_Sort(ids, n);
    return n;
}

static int by_root(const void *x, const void *y)
{
    const vrRooted *a = x, *b = y;
    if (a->root != b->root) return a->root < b->root ? -1 : 1;
    return (a->k > b->k) - (a->k < b->k);
}

/* Each island once looked for its touches in all of them: 10,000 cubes
 * on a floor are 10,000 islands, and the step was quadratic (14.5 s for
 * their first 40 frames, 2.3 s now). */
vrRooted *vrIsland_Group(vrWorld *w, int *parent, int *m)
{
    vrRooted *g = malloc(((size_t)w->touches.n + 1) * sizeof *g);
    int k;
    *m = 0;
    if (!g) return NULL;
    for (k = 0; k < w->touches.n; k++) {
        const vrTouch *c = &w->touches.t[k];
        if (c->leaving > 0) continue;
        g[*m].root = vrIsland_Root(parent, vrIsland_Moves(w, c->a) ? c->a : c->b);
        g[(*m)++].k = k;
    }
    qsort(g, (size_t)*m, sizeof *g, by_root);
    return g;
}

/* the first of g's entries whose root is not below r, then its run */
const vrRooted *vrIsland_Run(const vrRooted *g, int m, int r, int *len)
{
    int lo = 0, hi = m;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (g[mid].root < r) lo = mid + 1;
        else hi = mid;
    }
    for (*len = 0; lo + *len < m && g[lo + *len].root == r; (*len)++) continue;
    return g + lo;
}

