/* coplanar.c — the hull's coplanar triangles merged into polygon faces
 * (SPEC 2: "coplanar facets merged", relative tolerance 1e-9).
 *
 * Triangles whose corners lie within tol*size of one plane become one
 * polygon face; the corners left on fewer than three polygons (inside an
 * edge or a face: not extreme) are dropped later (hull.c).
 *   Tris, tris_init          the hull's triangles and the polygon each joins
 *   by_area                  the seeds, largest triangle first
 *   on_plane, grow_group     a polygon's flood fill from its seed
 *   vrLoops, trace_loop      a polygon's boundary as a loop
 *   Merge, trace_new         the loops of the polygons grown in one round
 *   loop_holds, check_loops  is a loop still convex without its flat corners
 *   regrow_bad, merge_round  the failed polygons, grown again tighter
 *   merge_triangles          the rounds until every loop holds
 */
#include <stdlib.h>
#include <string.h>

#include "coplanar.h"
#include "grow.h"
#include "orient.h"
#include "polyhedron.h"
#include "progress.h"

/* ---- merging coplanar triangles into polygons ------------------------------
 * Flood fill from the largest triangle: a neighbour joins when its third
 * corner lies within the tolerance of the seed's plane.  Tolerance is not
 * transitive, so each polygon is then checked: its boundary one simple
 * cycle, the corners it loses (those on fewer than three polygons: inside
 * an edge) within the tolerance of the straight edge that replaces them,
 * and no reflex turn.  A polygon that fails is filled again at the next
 * level, 1000 times tighter, down to exact coplanarity, where the exact
 * convexity of the triangulation makes the checks hold (but for slivers,
 * whose normals are rounding: the VR_HULL_RETRY with close points merged). */

enum { EXACT_LEVEL = 3 };
static const double level_scale[EXACT_LEVEL] = {1, 1e-3, 1e-6};

typedef struct Group {
    vec3 n, a;       /* the seed's plane: unit normal, a point */
    int seed, level;
} Group;

typedef struct Tris {
    int n;
    int (*v)[3];     /* the hull's (vrHullMesh) */
    int (*nb)[3];
    int *group;      /* the polygon each triangle joins, -1: none yet */
    int *level;      /* the level its next polygon is grown at */
    Group *g;
    int ngroup, capgroup;
} Tris;

static void tris_free(Tris *t)
{
    free(t->group);
    free(t->level);
    free(t->g);
}

/* the hull's triangles, none in a polygon yet */
static int tris_init(Tris *t, const vrHullMesh *mesh)
{
    int i;
    t->n = mesh->n;
    t->v = mesh->v;
    t->nb = mesh->nb;
    t->group = malloc(sizeof *t->group * t->n);
    t->level = calloc(t->n, sizeof *t->level);
    if (!t->group || !t->level) return -1;
    for (i = 0; i < t->n; i++) t->group[i] = -1;
    return 0;
}

static vec3 tri_cross(const Tris *t, const vec3 *p, int i)
{
    vec3 a = p[t->v[i][0]];
    return vec3_cross(vec3_sub(p[t->v[i][1]], a), vec3_sub(p[t->v[i][2]], a));
}

/* the triangles, largest first by binary exponent of the area (a counting
 * sort: a seed within a factor 2 of the largest has as good a plane) */
static int *by_area(const Tris *t, const vec3 *p)
{
    enum { NB = 2200, BIAS = 1100 };
    int *count = calloc(NB + 1, sizeof *count), *key = malloc(sizeof *key * (t->n + 1));
    /* order zeroed only for gcc -fanalyzer, which does not see the sort write it all */
    int *order = calloc((size_t)t->n + 1, sizeof *order), i, b;
    if (!count || !key || !order) {
        free(count);
        free(key);
        free(order);
        return NULL;
    }
    for (i = 0; i < t->n; i++) {
        double a2 = vec3_len2(tri_cross(t, p, i));
        key[i] = a2 > 0 && isfinite(a2) ? NB - 1 - (ilogb(a2) + BIAS) : NB - 1;
        count[key[i] + 1]++;
    }
    for (b = 0; b < NB; b++) count[b + 1] += count[b];
    for (i = 0; i < t->n; i++) order[count[key[i]]++] = i;
    free(count);
    free(key);
    return order;
}

/* is point w on the plane of group g, at g's level? */
static int on_plane(const Tris *t, const vec3 *p, const Group *g, int w, double tolabs)
{
    const int *s = t->v[g->seed];
    if (g->level == EXACT_LEVEL) return vrOrient(p[s[0]], p[s[1]], p[s[2]], p[w]) == 0;
    return fabs(vec3_dot(g->n, vec3_sub(p[w], g->a))) <= tolabs * level_scale[g->level];
}

static int new_group(Tris *t, const vec3 *p, int seed)
{
    Group *g;
    if (vrGrow((void **)&t->g, &t->capgroup, t->ngroup + 1, sizeof *t->g) != 0) return -1;
    g = &t->g[t->ngroup];
    g->n = vec3_normalize(tri_cross(t, p, seed));
    g->a = p[t->v[seed][0]];
    g->seed = seed;
    g->level = t->level[seed];
    return t->ngroup++;
}

static int grow_group(Tris *t, const vec3 *p, int seed, double tolabs, int *queue)
{
    int head = 0, tail = 0, g = new_group(t, p, seed), i;
    if (g < 0) return -1;
    t->group[seed] = g;
    queue[tail++] = seed;
    while (head < tail) {
        int s = queue[head++];
        for (i = 0; i < 3; i++) {
            int u = t->nb[s][i], j;
            if (t->group[u] >= 0 || t->level[u] > t->g[g].level) continue;
            for (j = 0; t->nb[u][j] != s; j++) continue;
            if (on_plane(t, p, &t->g[g], t->v[u][(j + 2) % 3], tolabs)) { /* the corner off the shared edge */
                t->group[u] = g;
                queue[tail++] = u;
            }
        }
    }
    return 0;
}

static int group_triangles(Tris *t, const vec3 *p, const int *order, double tolabs, int *queue)
{
    int k;
    for (k = 0; k < t->n; k++) {
        vrProgress_Tick();          /* a fine superquadric's 700,000 triangles: a worker's heartbeat */
        if (t->group[order[k]] < 0 && grow_group(t, p, order[k], tolabs, queue) != 0) return -1;
    }
    return 0;
}

static int loops_add(vrLoops *l, int v)
{
    if (vrGrow((void **)&l->vert, &l->cap, l->len + 1, sizeof *l->vert) != 0) return -1;
    l->vert[l->len++] = v;
    return 0;
}

static int close_loop(vrLoops *l, int g)
{
    if (l->n + 2 > l->capn) {
        int cap = 2 * l->capn + 64;
        int *s = realloc(l->start, sizeof *s * cap), *gr = s ? realloc(l->group, sizeof *gr * cap) : NULL;
        if (s) l->start = s;
        if (!s || !gr) return -1;
        l->group = gr;
        l->capn = cap;
    }
    l->start[l->n + 1] = l->len;
    l->group[l->n++] = g;
    return 0;
}

/* from boundary half-edge (tri, i) of a group, the next one round it: turn
 * about the head vertex through the group's triangles */
static int next_boundary(const Tris *t, int tri, int i)
{
    int g = t->group[tri], e = (i + 1) % 3, guard = 0;
    while (t->group[t->nb[tri][e]] == g && guard++ < t->n) {
        int u = t->nb[tri][e], j;
        for (j = 0; t->nb[u][j] != tri; j++) continue;
        tri = u;
        e = (j + 1) % 3;
    }
    return 3 * tri + e;
}

/* Traces group g's boundary from half-edge first into l: 0 when it is one
 * simple cycle of all its nb boundary half-edges, 1 when not (a hole or a
 * pinch; nothing is added), -1 out of memory.  mark: per vertex, the last
 * group that passed it. */
static int trace_loop(const Tris *t, vrLoops *l, int first, int nb, int *mark, int g)
{
    int he = first, count = 0, len0 = l->len;
    do {
        int v = t->v[he / 3][he % 3];
        if (mark[v] == g || count == nb) {
            l->len = len0;
            return 1;
        }
        if (loops_add(l, v) != 0) return -1;
        mark[v] = g;
        count++;
        he = next_boundary(t, he / 3, he % 3);
    } while (he != first);
    if (count == nb) return close_loop(l, g);
    l->len = len0;
    return 1;
}

typedef struct Merge {
    Tris *t;
    const vec3 *p;
    int npts;
    double tolabs;
    vrLoops l;
    int *count;      /* per point: the live loops through it */
    char *dirty;     /* per point: its count changed since loops were checked */
    int *mark;       /* per point: trace_loop's */
    int *loop_of;    /* per group: its loop, -1: none */
    char *bad;       /* per group: to be grown again, tighter */
} Merge;

static void merge_free(Merge *m)
{
    free(m->count);
    free(m->dirty);
    free(m->mark);
    free(m->loop_of);
    free(m->bad);
}

static int merge_alloc(Merge *m)
{
    int i;
    m->count = calloc(m->npts, sizeof *m->count);
    m->dirty = calloc(m->npts, 1);
    m->mark = malloc(sizeof *m->mark * m->npts);
    if (!m->count || !m->dirty || !m->mark) return -1;
    for (i = 0; i < m->npts; i++) m->mark[i] = -1;
    return 0;
}

/* the loops of groups first_new.. (grown this round); a group whose
 * boundary is not one cycle is bad */
static int trace_new(Merge *m, int first_new, int *nbad)
{
    const Tris *t = m->t;
    int n = t->ngroup - first_new, i, g, rc = 0;
    int *first = calloc(n + 1, sizeof *first), *nb = calloc(n + 1, sizeof *nb);
    int *lo = realloc(m->loop_of, sizeof *lo * (t->ngroup + 1));
    char *bad = realloc(m->bad, t->ngroup + 1);
    if (lo) m->loop_of = lo;
    if (bad) m->bad = bad;
    if (!first || !nb || !lo || !bad) rc = -1;
    for (i = 0; rc == 0 && i < 3 * t->n; i++) {
        int gi = t->group[i / 3] - first_new;
        if (gi >= 0 && t->group[t->nb[i / 3][i % 3]] != gi + first_new && nb[gi]++ == 0) first[gi] = i;
    }
    for (g = first_new; rc == 0 && g < t->ngroup; g++) {
        vrProgress_Tick();
        m->loop_of[g] = -1;
        m->bad[g] = 0;
        /* no boundary at all would be a group covering the whole (flat) hull */
        rc = nb[g - first_new] > 0 ? trace_loop(t, &m->l, first[g - first_new], nb[g - first_new], m->mark, g) : 1;
        if (rc == 0) m->loop_of[g] = m->l.n - 1;
        if (rc == 1) {
            m->bad[g] = 1;
            ++*nbad;
            rc = 0;
        }
    }
    free(first);
    free(nb);
    return rc;
}

static int next_kept(const int *vl, int k, const int *count, int i)
{
    do i = i + 1 < k ? i + 1 : 0;
    while (count[vl[i]] < 3);
    return i;
}

/* Does loop vl[0..k) stay a convex polygon within tl when its corners on
 * fewer than three polygons go? */
static int loop_holds(const vec3 *p, const int *vl, int k, const int *count, vec3 n, double tl)
{
    int i, first = -1, kept = 0;
    for (i = 0; i < k; i++)
        if (count[vl[i]] >= 3) {
            if (first < 0) first = i;
            kept++;
        }
    if (kept < 3) return 0;
    i = first;
    do {
        int j = next_kept(vl, k, count, i), c = next_kept(vl, k, count, j), m;
        vec3 a = p[vl[i]], b = p[vl[j]];
        for (m = i + 1 < k ? i + 1 : 0; m != j; m = m + 1 < k ? m + 1 : 0)
            if (vrGeom_DistToLine(a, b, p[vl[m]]) > tl) return 0;
        if (vec3_dot(vec3_cross(vec3_sub(b, a), vec3_sub(p[vl[c]], b)), n) < -tl * vec3_dist(a, b)) return 0;
        i = j;
    } while (i != first);
    return 1;
}

/* checks the new loops and those through a vertex whose count changed */
static void check_loops(Merge *m, int first_new, int *nbad)
{
    const vrLoops *l = &m->l;
    int f, i;
    for (f = 0; f < l->n; f++) {
        const Group *g = l->group[f] >= 0 ? &m->t->g[l->group[f]] : NULL;
        int s = l->start[f], k = l->start[f + 1] - s, touched = l->group[f] >= first_new;
        vrProgress_Tick();
        if (!g || g->level == EXACT_LEVEL) continue;
        for (i = 0; i < k && !touched; i++) touched = m->dirty[l->vert[s + i]];
        if (touched && !loop_holds(m->p, l->vert + s, k, m->count, g->n, m->tolabs * level_scale[g->level])) {
            m->bad[l->group[f]] = 1;
            ++*nbad;
        }
    }
}

/* drops the bad groups' loops and frees their triangles for the next level */
static int regrow_bad(Merge *m)
{
    Tris *t = m->t;
    int i, g;
    memset(m->dirty, 0, m->npts);
    for (g = 0; g < t->ngroup; g++) {
        int f = m->loop_of[g];
        if (!m->bad[g] || f < 0) continue;
        for (i = m->l.start[f]; i < m->l.start[f + 1]; i++) {
            m->count[m->l.vert[i]]--;
            m->dirty[m->l.vert[i]] = 1;
        }
        m->l.group[f] = -1;
        m->loop_of[g] = -1;
    }
    for (i = 0; i < t->n; i++) {
        const Group *gr = &t->g[t->group[i]];
        if (!m->bad[t->group[i]]) continue;
        if (gr->level == EXACT_LEVEL) return -2; /* cannot happen with exact signs */
        t->level[i] = gr->level + 1;
        t->group[i] = -1;
    }
    return 0;
}

/* One round: the groups grown since first_new get their loops, the loops
 * they may affect are checked, the bad groups go back to be grown again.
 * *nbad = 0 when the loops are final. */
static int merge_round(Merge *m, int first_new, int *nbad)
{
    int f0 = m->l.n, f, i, rc;
    *nbad = 0;
    rc = trace_new(m, first_new, nbad);
    for (f = f0; rc == 0 && f < m->l.n; f++)
        for (i = m->l.start[f]; i < m->l.start[f + 1]; i++) {
            m->count[m->l.vert[i]]++;
            m->dirty[m->l.vert[i]] = 1;
        }
    if (rc == 0) check_loops(m, first_new, nbad);
    if (rc == 0 && *nbad > 0) rc = regrow_bad(m);
    return rc;
}

/* keeps the live loops only */
static void compact_loops(vrLoops *l)
{
    int f, i, n = 0, len = 0;
    for (f = 0; f < l->n; f++) {
        int s = l->start[f], e = l->start[f + 1];
        if (l->group[f] < 0) continue;
        l->start[n] = len;
        for (i = s; i < e; i++) l->vert[len++] = l->vert[i];
        l->group[n++] = l->group[f];
    }
    l->n = n;
    l->len = len;
    l->start[n] = len;
}

/* the polygon faces of the triangulated hull, as loops (vertices: point
 * indices, corners that lie on fewer than three polygons still in) */
static int merge_triangles(Merge *m, char *err, size_t errlen)
{
    Tris *t = m->t;
    int *order = by_area(t, m->p), *queue = malloc(sizeof *queue * (t->n + 1)), nbad = 1, rc = 0;
    m->l.capn = 64;
    m->l.start = malloc(sizeof *m->l.start * m->l.capn);
    m->l.group = malloc(sizeof *m->l.group * m->l.capn);
    if (!order || !queue || !m->l.start || !m->l.group || merge_alloc(m) != 0) rc = -1;
    if (rc == 0) m->l.start[0] = 0;
    while (rc == 0 && nbad > 0) {
        int first_new = t->ngroup;
        rc = group_triangles(t, m->p, order, m->tolabs, queue);
        if (rc == 0) rc = merge_round(m, first_new, &nbad);
    }
    if (rc == 0) compact_loops(&m->l);
    free(order);
    free(queue);
    if (rc == -2) {
        vrGeom_Fail(err, errlen, "exactly coplanar faces do not form one polygon");
        return VR_HULL_RETRY;
    }
    return rc == 0 ? 0 : vrGeom_Fail(err, errlen, "out of memory");
}

void vrLoops_Free(vrLoops *l)
{
    free(l->start);
    free(l->vert);
    free(l->group);
    memset(l, 0, sizeof *l);
}

int vrCoplanar_Merge(const vrHullMesh *mesh, const vec3 *pts, int npts, double tolabs, vrLoops *out, char *err,
                     size_t errlen)
{
    Tris t = {0};
    Merge m = {0};
    int rc;
    m.t = &t;
    m.p = pts;
    m.npts = npts;
    m.tolabs = tolabs;
    rc = tris_init(&t, mesh) != 0 ? vrGeom_Fail(err, errlen, "out of memory") : merge_triangles(&m, err, errlen);
    tris_free(&t);
    merge_free(&m);
    *out = m.l;
    return rc;
}
