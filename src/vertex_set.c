/* vertex_set.c — small sets of vertex indices (vertex_set.h), and the
 * search that collects a hull's vertices above a plane.
 *   vrIntSet_*        the set: inline until it outgrows its buffer
 *   Seen, meet        which vertices a long search has met
 *   vrIntSet_Collect  the search */
#include <stdlib.h>
#include <string.h>
#include "vertex_set.h"
#include "polyhedron.h"

void vrIntSet_Init(vrIntSet *s)
{
    s->n = 0;
    s->cap = (int)(sizeof s->buf / sizeof s->buf[0]);
    s->v = s->buf;
}

void vrIntSet_Free(vrIntSet *s)
{
    if (s->v != s->buf) free(s->v);
    vrIntSet_Init(s);
}

#define VR_INTSET_SCAN 32   /* members looked up by a scan; more: by a hash */

int vrIntSet_Has(const vrIntSet *s, int x)
{
    int i;
    for (i = 0; i < s->n; i++)
        if (s->v[i] == x) return 1;
    return 0;
}

int vrIntSet_Add(vrIntSet *s, int x)
{
    if (s->n == s->cap) {
        int *v = malloc(2 * (size_t)s->cap * sizeof *v);
        if (!v) return -1;
        memcpy(v, s->v, (size_t)s->n * sizeof *v);
        if (s->v != s->buf) free(s->v);
        s->v = v;
        s->cap *= 2;
    }
    s->v[s->n++] = x;
    return 0;
}

void vrIntSet_Sort(vrIntSet *s)
{
    int i, j;
    for (i = 1; i < s->n; i++) {
        int x = s->v[i];
        for (j = i; j > 0 && s->v[j - 1] > x; j--) s->v[j] = s->v[j - 1];
        s->v[j] = x;
    }
}

/* Which vertices a search has met, once there are more than a set's
 * inline few: a hash of their indices (open addressing, at most half
 * full), so that a fine hull's slab of hundreds of vertices is not
 * scanned once for every neighbour of each (a region of two 300 x 300
 * superquadrics: a tenth of a frame). */
typedef struct Seen { int *slot; int mask; } Seen;

static void seen_put(Seen *h, int x)
{
    unsigned i = (unsigned)x * 2654435761u;
    while (h->slot[i & (unsigned)h->mask] >= 0 && h->slot[i & (unsigned)h->mask] != x) i++;
    h->slot[i & (unsigned)h->mask] = x;
}

/* the hash made or grown for the set's n members; -1 on no memory */
static int seen_ready(Seen *h, const vrIntSet *s)
{
    int i, size = 64;
    if (h->slot && 2 * s->n <= h->mask + 1) return 0;
    while (size < 4 * s->n) size *= 2;
    free(h->slot);
    if (!(h->slot = malloc((size_t)size * sizeof *h->slot))) return -1;
    h->mask = size - 1;
    for (i = 0; i < size; i++) h->slot[i] = -1;
    for (i = 0; i < s->n; i++) seen_put(h, s->v[i]);
    return 0;
}

static int seen_has(const Seen *h, int x)
{
    unsigned i = (unsigned)x * 2654435761u;
    for (;; i++) {
        int y = h->slot[i & (unsigned)h->mask];
        if (y == x) return 1;
        if (y < 0) return 0;
    }
}

/* adds w unless the search met it: 0, or -1 on no memory */
static int meet(vrIntSet *s, Seen *h, int w)
{
    if (s->n <= VR_INTSET_SCAN) return vrIntSet_Has(s, w) ? 0 : vrIntSet_Add(s, w);
    if (seen_ready(h, s) != 0) return -1;
    if (seen_has(h, w)) return 0;
    if (vrIntSet_Add(s, w) != 0) return -1;
    seen_put(h, w);
    return 0;
}

/* Breadth-first search from `seed` over the vertices with d.v >= floor (body
 * frame).  On a convex polytope this set is connected whenever it holds the
 * top vertex: every other vertex has a higher neighbour. */
int vrIntSet_Collect(const vrPolyhedron *p, vec3 d, int seed, double floor, vrIntSet *out)
{
    Seen h = {NULL, 0};
    int i, k, rc;
    if (vrIntSet_Add(out, seed)) return -1;
    for (i = 0, rc = 0; i < out->n && rc == 0; i++) {
        int v = out->v[i];
        for (k = p->vert_edge_start[v]; k < p->vert_edge_start[v + 1] && rc == 0; k++) {
            int w = vrPolyhedron_OtherEnd(p, p->vert_edge[k], v);
            if (vec3_dot(d, p->vert[w]) >= floor) rc = meet(out, &h, w);
        }
    }
    free(h.slot);
    return rc;
}
