/* warm.c — the last island step's impulses by pair (warm.h).
 *   vrWarm_Keep, vrWarm_Sort, find   the list, by pair
 *   vrWarm_Start                     a contact started from its pair's
 */
#include <stdlib.h>
#include <string.h>
#include "warm.h"
#include "grow.h"

/* normals closer than this (cosine) are the same contact */
#define SAME_NORMAL 0.999

void vrWarm_Free(vrWarm *w)
{
    free(w->c);
    w->c = NULL;
    w->n = w->cap = 0;
}

int vrWarm_Copy(vrWarm *to, const vrWarm *from)
{
    to->n = 0;
    to->structure = -1;
    if (vrGrow((void **)&to->c, &to->cap, from->n, sizeof *to->c) != 0) return -1;
    if (from->n > 0) memcpy(to->c, from->c, (size_t)from->n * sizeof *to->c);
    to->n = from->n;
    to->structure = from->structure;
    return 0;
}

int vrWarm_Keep(vrWarm *w, int a, int b, double h, const vrIslandContact *c)
{
    vrWarmContact *k;
    int i;
    if (w->n == w->cap) {
        int cap = w->cap ? 2 * w->cap : 64;
        vrWarmContact *m = realloc(w->c, (size_t)cap * sizeof *m);
        if (!m) return -1;
        w->c = m, w->cap = cap;
    }
    k = &w->c[w->n++];
    k->a = a, k->b = b, k->h = h, k->n = c->n, k->npoints = c->npoints;
    for (i = 0; i < c->npoints; i++) k->p[i] = c->p[i], k->lambda[i] = c->lambda[i];
    k->friction = c->friction;
    k->twist = c->twist;
    return 0;
}

static int by_pair(const void *x, const void *y)
{
    const vrWarmContact *a = x, *b = y;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    return a->b < b->b ? -1 : a->b > b->b;
}

void vrWarm_Sort(vrWarm *w)
{
    if (w->n > 1) qsort(w->c, (size_t)w->n, sizeof *w->c, by_pair);
}

static const vrWarmContact *find(const vrWarm *w, int a, int b)
{
    vrWarmContact key;
    key.a = a, key.b = b;
    /* cppcheck-suppress uninitvar ; by_pair reads a and b only */
    return w->n ? bsearch(&key, w->c, (size_t)w->n, sizeof *w->c, by_pair) : NULL;
}

void vrWarm_Start(const vrWarm *w, int a, int b, double h, double match, vrIslandContact *c)
{
    const vrWarmContact *k = find(w, a, b);
    int near[VR_ISLAND_POINTS], takers[VR_ISLAND_POINTS] = {0}, i, j, any = 0;
    double scale;
    c->warm = 0;
    if (!k || !(k->h > 0) || vec3_dot(k->n, c->n) < SAME_NORMAL) return;
    scale = h / k->h;
    for (i = 0; i < c->npoints; i++) {
        double best = match;
        near[i] = -1;
        for (j = 0; j < k->npoints; j++)
            if (vec3_dist(c->p[i], k->p[j]) <= best) best = vec3_dist(c->p[i], k->p[j]), near[i] = j;
        if (near[i] >= 0) takers[near[i]]++, any = 1;
    }
    if (!any) return;
    for (i = 0; i < c->npoints; i++) c->lambda[i] = near[i] < 0 ? 0 : scale * k->lambda[near[i]] / takers[near[i]];
    c->friction = vec3_scale(k->friction, scale);
    c->twist = scale * k->twist;
    c->warm = 1;
}
