/* aabb_tree.c — the dynamic box tree (aabb_tree.h).
 *   node_alloc, node_free          the node pool and its free list
 *   unite, area, fix               an inner node's box and height
 *   rotate, balance, fix_upward    AVL-style rotations after a change
 *   pick_sibling                   where a new leaf costs least (area)
 *   vrTree_Insert/Remove/Refit/RefitAll/Rebuild   the changes
 *   query, cross, self             the searches
 *   check                          the invariants, for the tests */
#include <stdlib.h>
#include <string.h>
#include "aabb_tree.h"
#include "grow.h"

void vrTree_Init(vrTree *t)
{
    memset(t, 0, sizeof *t);
    t->root = t->free_list = -1;
}

void vrTree_Free(vrTree *t)
{
    free(t->node);
    vrTree_Init(t);
}

/* ---- the pool -------------------------------------------------------------------- */

static int node_alloc(vrTree *t)
{
    int i, old = t->cap;
    if (t->free_list < 0) {
        if (vrGrow((void **)&t->node, &t->cap, t->cap + 1, sizeof *t->node) != 0) return -1;
        for (i = t->cap - 1; i >= old; i--) {   /* the new nodes free, lowest first */
            t->node[i].height = -1;
            t->node[i].parent = t->free_list;
            t->free_list = i;
        }
    }
    i = t->free_list;
    t->free_list = t->node[i].parent;
    t->node[i].parent = t->node[i].child1 = t->node[i].child2 = -1;
    t->node[i].height = 0;
    t->node[i].id = -1;
    return i;
}

static void node_free(vrTree *t, int i)
{
    t->node[i].height = -1;
    t->node[i].parent = t->free_list;
    t->free_list = i;
}

/* ---- boxes and heights ----------------------------------------------------------------- */

static vrAabb unite(const vrAabb *a, const vrAabb *b)
{
    vrAabb r;
    r.lo = vec3_make(vr_min(a->lo.x, b->lo.x), vr_min(a->lo.y, b->lo.y), vr_min(a->lo.z, b->lo.z));
    r.hi = vec3_make(vr_max(a->hi.x, b->hi.x), vr_max(a->hi.y, b->hi.y), vr_max(a->hi.z, b->hi.z));
    return r;
}

/* half the surface area: the chance, roughly, that a random box meets it */
static double area(const vrAabb *b)
{
    vec3 e = vec3_sub(b->hi, b->lo);
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

static int imax(int a, int b) { return a > b ? a : b; }

/* inner node i from its children */
static void fix(vrTree *t, int i)
{
    vrTreeNode *n = &t->node[i];
    n->box = unite(&t->node[n->child1].box, &t->node[n->child2].box);
    n->height = 1 + imax(t->node[n->child1].height, t->node[n->child2].height);
}

/* in old's parent (or at the root), now: put */
static void replace_child(vrTree *t, int old, int put)
{
    int p = t->node[old].parent;
    t->node[put].parent = p;
    if (p < 0) t->root = put;
    else if (t->node[p].child1 == old) t->node[p].child1 = put;
    else t->node[p].child2 = put;
}

/* a's child c (the taller, by two) takes a's place: c keeps its taller
 * child and gives a its shorter one; returns c */
static int rotate(vrTree *t, int a, int c)
{
    int f = t->node[c].child1, g = t->node[c].child2;
    int keep = t->node[f].height >= t->node[g].height ? f : g, give = keep == f ? g : f;
    replace_child(t, a, c);
    if (t->node[a].child1 == c) t->node[a].child1 = give;
    else t->node[a].child2 = give;
    t->node[give].parent = a;
    t->node[c].child1 = keep;
    t->node[c].child2 = a;
    t->node[a].parent = c;
    fix(t, a);
    fix(t, c);
    return c;
}

/* i balanced: its children's heights within one (returns the subtree's root) */
static int balance(vrTree *t, int i)
{
    int b = t->node[i].child1, c = t->node[i].child2, d;
    if (b < 0) return i;
    d = t->node[c].height - t->node[b].height;
    if (d > 1) return rotate(t, i, c);
    if (d < -1) return rotate(t, i, b);
    return i;
}

/* boxes, heights and balance from inner node i up to the root */
static void fix_upward(vrTree *t, int i)
{
    while (i >= 0) {
        fix(t, i);
        i = balance(t, i);
        i = t->node[i].parent;
    }
}

/* ---- changes ---------------------------------------------------------------------- */

/* Box2D's descent: at each inner node, making the new parent here costs
 * twice the united area; going down costs the growth of this node's box
 * (inherited by every ancestor) plus the cost at the cheaper child */
static int pick_sibling(const vrTree *t, const vrAabb *b)
{
    int i = t->root;
    while (t->node[i].child1 >= 0) {
        const vrTreeNode *n = &t->node[i];
        vrAabb u = unite(&n->box, b), u1 = unite(&t->node[n->child1].box, b), u2 = unite(&t->node[n->child2].box, b);
        double here = 2.0 * area(&u), inherit = 2.0 * (area(&u) - area(&n->box));
        double c1 = area(&u1) + inherit, c2 = area(&u2) + inherit;
        if (t->node[n->child1].child1 >= 0) c1 -= area(&t->node[n->child1].box);
        if (t->node[n->child2].child1 >= 0) c2 -= area(&t->node[n->child2].box);
        if (here < c1 && here < c2) break;
        i = c1 <= c2 ? n->child1 : n->child2;
    }
    return i;
}

/* leaf under a new parent beside sibling s (both nodes made already) */
static void join(vrTree *t, int leaf, int s, int parent)
{
    replace_child(t, s, parent);
    t->node[parent].child1 = s;
    t->node[parent].child2 = leaf;
    t->node[s].parent = t->node[leaf].parent = parent;
    fix_upward(t, parent);
}

int vrTree_Insert(vrTree *t, const vrAabb *b, int id)
{
    int leaf = node_alloc(t), parent;
    if (leaf < 0) return -1;
    t->node[leaf].box = *b;
    t->node[leaf].id = id;
    if (t->root < 0) {
        t->root = leaf;
    } else {
        if ((parent = node_alloc(t)) < 0) return node_free(t, leaf), -1;
        join(t, leaf, pick_sibling(t, b), parent);
    }
    t->nleaf++;
    return leaf;
}

void vrTree_Remove(vrTree *t, int leaf)
{
    int p = t->node[leaf].parent, s, g;
    node_free(t, leaf);
    t->nleaf--;
    if (p < 0) {
        t->root = -1;
        return;
    }
    s = t->node[p].child1 == leaf ? t->node[p].child2 : t->node[p].child1;
    g = t->node[p].parent;
    replace_child(t, p, s);
    node_free(t, p);
    fix_upward(t, g);
}

static int same_box(const vrAabb *a, const vrAabb *b)
{
    return a->lo.x == b->lo.x && a->lo.y == b->lo.y && a->lo.z == b->lo.z && a->hi.x == b->hi.x
        && a->hi.y == b->hi.y && a->hi.z == b->hi.z;
}

void vrTree_Refit(vrTree *t, int leaf, const vrAabb *b)
{
    int i = t->node[leaf].parent;
    t->node[leaf].box = *b;
    for (; i >= 0; i = t->node[i].parent) {
        vrAabb old = t->node[i].box;
        fix(t, i);
        if (same_box(&old, &t->node[i].box)) return;   /* the ancestors hold it already */
    }
}

static void refit_below(vrTree *t, int i)
{
    if (t->node[i].child1 < 0) return;
    refit_below(t, t->node[i].child1);
    refit_below(t, t->node[i].child2);
    fix(t, i);
}

void vrTree_RefitAll(vrTree *t)
{
    if (t->root >= 0) refit_below(t, t->root);
}

static double centre(const vrTree *t, int leaf, int axis)
{
    const vrAabb *b = &t->node[leaf].box;
    return vec3_get(b->lo, axis) + vec3_get(b->hi, axis);
}

/* leaves v[0..n) reordered so that v[k] has the k-th centre along axis
 * (Hoare's selection; ties make no difference to the tree's correctness) */
static void select_kth(const vrTree *t, int *v, int n, int k, int axis)
{
    int lo = 0, hi = n - 1;
    while (lo < hi) {
        double pivot = centre(t, v[lo + (hi - lo) / 2], axis);
        int i = lo, j = hi;
        while (i <= j) {
            while (centre(t, v[i], axis) < pivot) i++;
            while (centre(t, v[j], axis) > pivot) j--;
            if (i <= j) {
                int x = v[i];
                v[i++] = v[j];
                v[j--] = x;
            }
        }
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else return;
    }
}

static int longest_axis(const vrTree *t, const int *v, int n)
{
    vec3 lo = vec3_make(INFINITY, INFINITY, INFINITY), hi = vec3_neg(lo), e;
    int i;
    for (i = 0; i < n; i++) {
        const vrAabb *b = &t->node[v[i]].box;
        vec3 c = vec3_add(b->lo, b->hi);
        lo = vec3_make(vr_min(lo.x, c.x), vr_min(lo.y, c.y), vr_min(lo.z, c.z));
        hi = vec3_make(vr_max(hi.x, c.x), vr_max(hi.y, c.y), vr_max(hi.z, c.z));
    }
    e = vec3_sub(hi, lo);
    return e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
}

/* the subtree of leaves v[0..n), n >= 1; its inner nodes come from the
 * pool, which holds the n - 1 the old tree freed */
static int build(vrTree *t, int *v, int n)
{
    int i, a, b, m = n / 2;
    if (n == 1) return v[0];
    select_kth(t, v, n, m, longest_axis(t, v, n));
    a = build(t, v, m);
    b = build(t, v + m, n - m);
    i = node_alloc(t);
    t->node[i].child1 = a;
    t->node[i].child2 = b;
    t->node[a].parent = t->node[b].parent = i;
    fix(t, i);
    return i;
}

int vrTree_Rebuild(vrTree *t)
{
    int *v, i, n = 0;
    if (t->nleaf < 3) return 0;
    if (!(v = malloc((size_t)t->nleaf * sizeof *v))) return -1;
    for (i = 0; i < t->cap; i++) {
        if (t->node[i].height < 0) continue;
        if (t->node[i].child1 < 0) v[n++] = i;
        else node_free(t, i);
    }
    t->root = build(t, v, n);
    t->node[t->root].parent = -1;
    free(v);
    return 0;
}

double vrTree_Cost(const vrTree *t)
{
    double c = 0;
    int i;
    for (i = 0; i < t->cap; i++)
        if (t->node[i].height > 0) c += area(&t->node[i].box);
    return c;
}

/* ---- searches ----------------------------------------------------------------------- */

static void query(const vrTree *t, int i, const vrAabb *b, void (*hit)(void *ctx, int id), void *ctx)
{
    const vrTreeNode *n = &t->node[i];
    if (vrAabb_Disjoint(&n->box, b)) return;
    if (n->child1 < 0) {
        hit(ctx, n->id);
        return;
    }
    query(t, n->child1, b, hit, ctx);
    query(t, n->child2, b, hit, ctx);
}

void vrTree_Query(const vrTree *t, const vrAabb *b, void (*hit)(void *ctx, int id), void *ctx)
{
    if (t->root >= 0) query(t, t->root, b, hit, ctx);
}

typedef struct vrPairSink { void (*pair)(void *ctx, int a, int b); void *ctx; } vrPairSink;

/* the overlapping leaves of node i of t against node j of u: the larger
 * box is opened first, so that the smaller is tested against its parts */
static void cross(const vrTree *t, int i, const vrTree *u, int j, const vrPairSink *s)
{
    const vrTreeNode *a = &t->node[i], *b = &u->node[j];
    if (vrAabb_Disjoint(&a->box, &b->box)) return;
    if (a->child1 < 0 && b->child1 < 0) {
        s->pair(s->ctx, a->id, b->id);
    } else if (b->child1 < 0 || (a->child1 >= 0 && area(&a->box) >= area(&b->box))) {
        cross(t, a->child1, u, j, s);
        cross(t, a->child2, u, j, s);
    } else {
        cross(t, i, u, b->child1, s);
        cross(t, i, u, b->child2, s);
    }
}

static void self(const vrTree *t, int i, const vrPairSink *s)
{
    const vrTreeNode *n = &t->node[i];
    if (n->child1 < 0) return;
    self(t, n->child1, s);
    self(t, n->child2, s);
    cross(t, n->child1, t, n->child2, s);
}

void vrTree_SelfPairs(const vrTree *t, void (*pair)(void *ctx, int a, int b), void *ctx)
{
    vrPairSink s;
    s.pair = pair, s.ctx = ctx;
    if (t->root >= 0) self(t, t->root, &s);
}

void vrTree_CrossPairs(const vrTree *t, const vrTree *u, void (*pair)(void *ctx, int a, int b), void *ctx)
{
    vrPairSink s;
    s.pair = pair, s.ctx = ctx;
    if (t->root >= 0 && u->root >= 0) cross(t, t->root, u, u->root, &s);
}

/* ---- invariants ---------------------------------------------------------------------- */

/* the subtree of i: its leaf count, or -1 when broken */
static int check(const vrTree *t, int i, int parent, int slack)
{
    const vrTreeNode *n = &t->node[i];
    int a, b;
    vrAabb u;
    if (n->parent != parent || n->height < 0) return -1;
    if (n->child1 < 0) return n->child2 < 0 && n->height == 0 ? 1 : -1;
    a = check(t, n->child1, i, slack);
    b = check(t, n->child2, i, slack);
    if (a < 0 || b < 0) return -1;
    u = unite(&t->node[n->child1].box, &t->node[n->child2].box);
    if (!same_box(&u, &n->box) || n->height != 1 + imax(t->node[n->child1].height, t->node[n->child2].height)) return -1;
    if (abs(t->node[n->child1].height - t->node[n->child2].height) > slack) return -1;
    return a + b;
}

int vrTree_Check(const vrTree *t, int slack)
{
    if (t->root < 0) return t->nleaf == 0 ? 0 : -1;
    return check(t, t->root, -1, slack) == t->nleaf ? 0 : -1;
}
