/* broadphase.c — boxes for the rest of a frame, sorted and swept (see
 * broadphase.h), and the pair map. */
#include <stdlib.h>
#include <string.h>
#include "broadphase.h"
#include "broad_tree.h"
#include "grow.h"

void vrBroad_Init(vrBroadphase *bp)
{
    memset(bp, 0, sizeof *bp);
    bp->t0 = bp->T = NAN;     /* no frame yet: no boxes */
    bp->stale = 1;
    bp->near_frame = -1;
    vrTree_Init(&bp->moving);
    vrTree_Init(&bp->fixed);
}

void vrBroad_SetKind(vrBroadphase *bp, vrBroadKind kind)
{
    int i;
    if (kind == bp->kind) return;
    vrBroadTree_Free(bp);
    for (i = 0; i < bp->cap; i++) bp->box[i].frame = -1;   /* a resting body's box is kept by the trees only */
    bp->kind = kind;
    bp->stale = 1;
    bp->near_frame = -1;
}

void vrBroad_Free(vrBroadphase *bp)
{
    free(bp->box);
    free(bp->sweep);
    free(bp->near);
    free(bp->pos);
    free(bp->odd);
    vrPairMap_Free(&bp->map);
    vrBroadTree_Free(bp);
    vrBroad_Init(bp);
}

int vrBroad_Reserve(vrBroadphase *bp, int n)
{
    int i, old = bp->cap;
    if (vrGrow((void **)&bp->box, &bp->cap, n, sizeof *bp->box) != 0) return -1;
    for (i = old; i < bp->cap; i++) {
        bp->box[i].valid = 0;
        bp->box[i].frame = -1;
    }
    return 0;
}

void vrBroad_BodyChanged(vrBroadphase *bp, int id)
{
    if (id < bp->cap) bp->box[id].frame = -1;
    bp->stale = 1;
    bp->near_frame = -1;
}

void vrBroad_SetEnvelope(vrBroadphase *bp, double d)
{
    int i;
    bp->d = d;
    bp->T = NAN;
    bp->near_frame = -1;
    for (i = 0; i < bp->cap; i++) bp->box[i].frame = -1;
}

/* the exact bounding box of a static body's surface: its support points
 * along the six axis directions */
static void static_extent(vrBody *b, vec3 *lo, vec3 *hi)
{
    const vrShape *s = &b->shape;
    vrPose p;
    vrBody_Pose(b, b->m.t0, &p);
    lo->x = vrShape_Support(s, &p, vec3_make(-1, 0, 0)).x;
    lo->y = vrShape_Support(s, &p, vec3_make(0, -1, 0)).y;
    lo->z = vrShape_Support(s, &p, vec3_make(0, 0, -1)).z;
    hi->x = vrShape_Support(s, &p, vec3_make(1, 0, 0)).x;
    hi->y = vrShape_Support(s, &p, vec3_make(0, 1, 0)).y;
    hi->z = vrShape_Support(s, &p, vec3_make(0, 0, 1)).z;
}

/* a moving body's box over [its anchor or the span start, the frame's end];
 * a static body's wherever it is */
static void make_box(vrBroadphase *bp, vrBody *const *body, int id)
{
    vrBody *b = body[id];
    vrBox *x = &bp->box[id];
    double t1, size, pad;
    x->valid = 0;
    x->frame = bp->frame;
    if (!b || !(bp->t0 <= bp->T)) return;
    if (b->is_static) {
        static_extent(b, &x->lo, &x->hi);
        x->frame = VR_BOX_FOR_GOOD;
        pad = 0.0;
    } else {
        t1 = fmax(b->m.t0, bp->t0);
        if (!(t1 <= bp->T)) return;
        vrBody_PathBox(b, t1, bp->T, &x->lo, &x->hi);
        pad = b->r_out;
        /* the trees keep a resting body's box, as a static one's, until an
         * update wakes it (vrBroad_Rebox): 10,000 cubes at rest on a floor
         * are not boxed, refitted and met again every frame */
        if (b->resting && bp->kind == VR_BROAD_TREE) x->frame = VR_BOX_FOR_GOOD;
    }
    size = fmax(vec3_maxabs(x->lo), vec3_maxabs(x->hi));
    pad += 0.5 * bp->d + 1e-9 + 1e-12 * size;   /* far above the rounding of a position */
    x->lo = vec3_sub(x->lo, vec3_make(pad, pad, pad));
    x->hi = vec3_add(x->hi, vec3_make(pad, pad, pad));
    x->valid = 1;
}

static double near_key(const vrBroadphase *bp, int i) { return bp->box[bp->near[i]].lo.x; }

static void near_put(vrBroadphase *bp, int i, int id)
{
    bp->near[i] = id;
    bp->pos[id] = i;
}

/* a moving body's box changed within the frame: it moves to its place in
 * near (a short way: an event changes a path a little), or, boxless now,
 * to odd */
static void near_moved(vrBroadphase *bp, int id)
{
    const vrBox *x = &bp->box[id];
    int i = bp->pos[id];
    if (!x->valid) {
        for (; i + 1 < bp->nnear; i++) near_put(bp, i, bp->near[i + 1]);
        bp->nnear--;
        bp->pos[id] = -1;
        if (vrGrow((void **)&bp->odd, &bp->oddcap, bp->nodd + 1, sizeof *bp->odd) != 0) bp->near_frame = -1;
        else bp->odd[bp->nodd++] = id;
        return;
    }
    bp->widest = fmax(bp->widest, x->hi.x - x->lo.x);
    for (; i > 0 && near_key(bp, i - 1) > x->lo.x; i--) near_put(bp, i, bp->near[i - 1]);
    for (; i + 1 < bp->nnear && near_key(bp, i + 1) < x->lo.x; i++) near_put(bp, i, bp->near[i + 1]);
    near_put(bp, i, id);
}

void vrBroad_Rebox(vrBroadphase *bp, vrBody *const *body, int id)
{
    make_box(bp, body, id);
    if (bp->near_frame != bp->frame) return;
    if (bp->kind == VR_BROAD_TREE) vrBroadTree_Moved(bp, id);
    else if (id < bp->poscap && bp->pos[id] >= 0) near_moved(bp, id);
}

/* the sweep's order: lower x of the box, then id (invalid boxes first) */
static int sweep_before(const vrBroadphase *bp, int a, int b)
{
    double ka = bp->box[a].valid ? bp->box[a].lo.x : -INFINITY, kb = bp->box[b].valid ? bp->box[b].lo.x : -INFINITY;
    return ka < kb || (ka == kb && a < b);
}

/* insertion sort: from one frame to the next the order hardly changes */
static void sort_sweep(vrBroadphase *bp)
{
    int i, j;
    for (i = 1; i < bp->nsweep; i++) {
        int id = bp->sweep[i];
        for (j = i; j > 0 && sweep_before(bp, id, bp->sweep[j - 1]); j--) bp->sweep[j] = bp->sweep[j - 1];
        bp->sweep[j] = id;
    }
}

static const vrBroadphase *sorting;   /* qsort has no context argument in C99 */
static int cmp_sweep(const void *x, const void *y)
{
    int a = *(const int *)x, b = *(const int *)y;
    return sweep_before(sorting, a, b) ? -1 : sweep_before(sorting, b, a) ? 1 : 0;
}

/* the list made anew (bodies came or went) is sorted at once: by
 * insertion, 10,000 bodies in id order would take 25 M moves; the order
 * is the same (sweep_before is a total order) */
static int remake_sweep(vrBroadphase *bp, vrBody *const *body, int nbody)
{
    int i;
    if (vrGrow((void **)&bp->sweep, &bp->sweepcap, nbody, sizeof *bp->sweep) != 0) return -1;
    bp->nsweep = 0;
    for (i = 0; i < nbody; i++)
        if (body[i]) bp->sweep[bp->nsweep++] = i;
    bp->stale = 0;
    for (i = 0; i < bp->nsweep; i++) vrBroad_Box(bp, body, bp->sweep[i]);
    sorting = bp;
    if (bp->nsweep > 1) qsort(bp->sweep, (size_t)bp->nsweep, sizeof *bp->sweep, cmp_sweep);   /* none: sweep may be NULL */
    return 0;
}

/* near and odd from the sorted sweep list; without memory, no list */
static void make_near(vrBroadphase *bp)
{
    int i;
    bp->near_frame = -1;
    if (vrGrow((void **)&bp->near, &bp->nearcap, bp->nsweep, sizeof *bp->near) != 0
        || vrGrow((void **)&bp->odd, &bp->oddcap, bp->nsweep, sizeof *bp->odd) != 0
        || vrGrow((void **)&bp->pos, &bp->poscap, bp->cap, sizeof *bp->pos) != 0)
        return;
    for (i = 0; i < bp->poscap; i++) bp->pos[i] = -1;
    bp->nnear = bp->nodd = 0;
    bp->widest = 0;
    for (i = 0; i < bp->nsweep; i++) {
        int id = bp->sweep[i];
        const vrBox *x = &bp->box[id];
        if (!x->valid || x->frame == VR_BOX_FOR_GOOD) {
            bp->odd[bp->nodd++] = id;
            continue;
        }
        near_put(bp, bp->nnear++, id);
        bp->widest = fmax(bp->widest, x->hi.x - x->lo.x);
    }
    bp->near_frame = bp->frame;
}

int vrBroad_Meeting(const vrBroadphase *bp, int id, void (*meet)(void *ctx, int y), void *ctx)
{
    const vrBox *x = &bp->box[id];
    int lo = 0, hi = bp->nnear, i;
    if (bp->near_frame != bp->frame) return -1;
    for (i = 0; i < bp->nodd; i++)
        if (bp->odd[i] != id && !vrBroad_Apart(x, &bp->box[bp->odd[i]])) meet(ctx, bp->odd[i]);
    if (bp->kind == VR_BROAD_TREE) {
        vrBroadTree_Meeting(bp, id, meet, ctx);
        return 0;
    }
    if (!x->valid) {         /* meets everything */
        for (i = 0; i < bp->nnear; i++)
            if (bp->near[i] != id) meet(ctx, bp->near[i]);
        return 0;
    }
    /* the first box that could reach x: its lower x at most widest below x's */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (near_key(bp, mid) < x->lo.x - bp->widest) lo = mid + 1;
        else hi = mid;
    }
    for (i = lo; i < bp->nnear && near_key(bp, i) <= x->hi.x; i++)
        if (bp->near[i] != id && !vrBox_Disjoint(x, &bp->box[bp->near[i]])) meet(ctx, bp->near[i]);
    return 0;
}

int vrBroad_NewFrame(vrBroadphase *bp, vrBody *const *body, int nbody, double t0, double T,
                     void (*meet)(void *ctx, int x, int y), void (*boxless)(void *ctx, int id), void *ctx)
{
    int i, j, passed;   /* passed: the moving bodies the sweep has passed, which lead near */
    bp->frame++;
    bp->t0 = t0;
    bp->T = T;
    if (bp->kind == VR_BROAD_TREE) {
        if (vrBroadTree_NewFrame(bp, body, nbody, meet, boxless, ctx) != 0) return -1;
        bp->near_frame = bp->frame;
        return 0;
    }
    if (bp->stale && remake_sweep(bp, body, nbody) != 0) return -1;
    for (i = 0; i < bp->nsweep; i++)
        if (!vrBroad_Box(bp, body, bp->sweep[i])->valid) boxless(ctx, bp->sweep[i]);
    sort_sweep(bp);
    make_near(bp);
    for (i = 0, passed = 0; i < bp->nsweep; i++) {
        int x = bp->sweep[i];
        const vrBox *a = &bp->box[x];
        if (!a->valid) continue;
        if (a->frame != VR_BOX_FOR_GOOD || bp->near_frame != bp->frame) {
            for (j = i + 1; j < bp->nsweep && bp->box[bp->sweep[j]].lo.x <= a->hi.x; j++) {
                int y = bp->sweep[j];
                /* two static bodies make no pair: furniture overlapping at
                 * its joints is not met again every frame */
                if (a->frame == VR_BOX_FOR_GOOD && bp->box[y].frame == VR_BOX_FOR_GOOD) continue;
                if (!vrBox_Disjoint(a, &bp->box[y])) meet(ctx, x < y ? x : y, x < y ? y : x);
            }
            if (a->frame != VR_BOX_FOR_GOOD) passed++;
            continue;
        }
        /* a static body: only the moving ones after it in the sweep (near
         * holds them in the same order), the same meetings in the same
         * order without a look at the many other statics a room has */
        for (j = passed; j < bp->nnear && near_key(bp, j) <= a->hi.x; j++) {
            int y = bp->near[j];
            if (!vrBox_Disjoint(a, &bp->box[y])) meet(ctx, x < y ? x : y, x < y ? y : x);
        }
    }
    return 0;
}

/* ---- boxes at one instant (vrBroad_MeetAt) ----------------------------------- */

typedef struct vrAtBox { vrBox box; int id; } vrAtBox;

static int at_before(const void *x, const void *y)
{
    const vrAtBox *a = x, *b = y;
    return a->box.lo.x < b->box.lo.x ? -1 : a->box.lo.x > b->box.lo.x ? 1 : a->id - b->id;
}

/* where body b is at t, padded as make_box pads (statics are valid for good) */
static void box_at(const vrBroadphase *bp, vrBody *b, double t, vrBox *x)
{
    double size, pad = 0.0;
    if (b->is_static) {
        static_extent(b, &x->lo, &x->hi);
    } else {
        vrBody_Position(b, t, &x->lo);
        x->hi = x->lo;
        pad = b->r_out;
    }
    size = fmax(vec3_maxabs(x->lo), vec3_maxabs(x->hi));
    pad += 0.5 * bp->d + 1e-9 + 1e-12 * size;
    x->lo = vec3_sub(x->lo, vec3_make(pad, pad, pad));
    x->hi = vec3_add(x->hi, vec3_make(pad, pad, pad));
    x->valid = 1;
    x->frame = b->is_static ? VR_BOX_FOR_GOOD : -1;
}

static void sweep_at(const vrAtBox *e, int n, const unsigned char *want, void (*meet)(void *ctx, int x, int y),
                     void *ctx)
{
    int i, j;
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n && e[j].box.lo.x <= e[i].box.hi.x; j++) {
            int x = e[i].id, y = e[j].id;
            if (e[i].box.frame == VR_BOX_FOR_GOOD && e[j].box.frame == VR_BOX_FOR_GOOD) continue;
            if (want && !want[x] && !want[y]) continue;
            if (!vrBox_Disjoint(&e[i].box, &e[j].box)) meet(ctx, x < y ? x : y, x < y ? y : x);
        }
}

int vrBroad_MeetAt(const vrBroadphase *bp, vrBody *const *body, int nbody, double t, const unsigned char *want,
                   void (*meet)(void *ctx, int x, int y), void *ctx)
{
    vrAtBox *e = malloc((size_t)(nbody > 0 ? nbody : 1) * sizeof *e);
    int i, n = 0;
    if (!e) return -1;
    for (i = 0; i < nbody; i++)
        if (body[i]) {
            box_at(bp, body[i], t, &e[n].box);
            e[n++].id = i;
        }
    qsort(e, (size_t)n, sizeof *e, at_before);
    sweep_at(e, n, want, meet, ctx);
    free(e);
    return 0;
}

/* ---- the pair map ------------------------------------------------------------ */

static unsigned map_slot(const vrPairMap *m, long long key)
{
    unsigned long long h = (unsigned long long)key * 0x9E3779B97F4A7C15ull;
    return (unsigned)(h >> 32) & (unsigned)(m->cap - 1);
}

int vrPairMap_Find(const vrPairMap *m, long long key)
{
    unsigned i;
    if (!m->cap) return -1;
    for (i = map_slot(m, key); m->key[i] != -1; i = (i + 1) & (unsigned)(m->cap - 1))
        if (m->key[i] == key) return m->val[i];
    return -1;
}

void vrPairMap_Put(vrPairMap *m, long long key, int val)
{
    unsigned i = map_slot(m, key);
    while (m->key[i] != -1 && m->key[i] != key) i = (i + 1) & (unsigned)(m->cap - 1);
    if (m->key[i] == -1) m->n++;
    m->key[i] = key;
    m->val[i] = val;
}

/* linear probing's deletion: the entries after the hole that hash at or
 * before it move back into it, so that no search stops short */
void vrPairMap_Remove(vrPairMap *m, long long key)
{
    unsigned mask = (unsigned)(m->cap - 1), i, j;
    if (!m->cap) return;
    for (i = map_slot(m, key); m->key[i] != key; i = (i + 1) & mask)
        if (m->key[i] == -1) return;
    for (j = (i + 1) & mask; m->key[j] != -1; j = (j + 1) & mask) {
        unsigned home = map_slot(m, m->key[j]);
        /* j's entry may fill the hole at i unless its home lies in (i, j] */
        if (i <= j ? (i < home && home <= j) : (i < home || home <= j)) continue;
        m->key[i] = m->key[j];
        m->val[i] = m->val[j];
        i = j;
    }
    m->key[i] = -1;
    m->n--;
}

void vrPairMap_Free(vrPairMap *m)
{
    free(m->key);
    free(m->val);
    memset(m, 0, sizeof *m);
}

/* kept at most half full */
int vrPairMap_Reset(vrPairMap *m, int n)
{
    int cap = 16, i;
    while (cap < 2 * n + 2) cap *= 2;
    if (cap != m->cap) {
        long long *k = malloc((size_t)cap * sizeof *k);
        int *v = malloc((size_t)cap * sizeof *v);
        vrPairMap_Free(m);
        if (!k || !v) {
            free(k);
            free(v);
            return -1;
        }
        m->key = k, m->val = v, m->cap = cap;
    }
    for (i = 0; i < cap; i++) m->key[i] = -1;
    m->n = 0;
    return 0;
}
