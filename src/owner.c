/* owner.c — a pair owner's bookkeeping (thesis 3.4.2, 3.5: the GP): its
 * life cycle, the bodies and pairs it holds, where a pair waits for its
 * next look (the heap, the active list of pairs inside the envelope, or
 * flagged for the next span start), the start-up overlap check, and the
 * owner's answer to its event (effect.c).  The look-ahead that finds
 * events is lookahead.c; owner_state.h lists the other files. */
#include <stdlib.h>
#include <string.h>
#include "owner_state.h"
#include "grow.h"

/* gcc 12's -fanalyzer loses the block vrGrow hands back through its void **
 * and calls it leaked: a false positive (make lint) */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wanalyzer-malloc-leak"
#endif
int vrIntList_Push(vrIntList *l, int v)
{
    if (vrGrow((void **)&l->v, &l->cap, l->n + 1, sizeof *l->v) != 0) return -1;
    l->v[l->n++] = v;
    return 0;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

int vrEvents_Push(vrEvent **arr, int *n, int *cap, const vrEvent *ev)
{
    if (vrGrow((void **)arr, cap, *n + 1, sizeof **arr) != 0) return -1;
    (*arr)[(*n)++] = *ev;
    return 0;
}

vrOwner *vrOwner_Create(void)
{
    vrOwner *o = calloc(1, sizeof *o);
    if (!o) return NULL;
    vrHeap_Init(&o->heap);
    o->responder = vrResponder_Create();
    o->pending_t = -INFINITY;
    o->gather_t = NAN;       /* no island step yet: no pair is an island's */
    o->closed_t = o->closed_end = NAN;
    o->gather_h = INFINITY;
    vrBroad_Init(&o->bp);
    o->p.use_heap = 1;
    if (!o->responder) {
        vrOwner_Free(o);
        return NULL;
    }
    return o;
}

void vrOwner_Free(vrOwner *o)
{
    int i;
    if (!o) return;
    for (i = 0; i < o->bodycap; i++) {
        free(o->body_pairs[i].v);
        free(o->body_partners[i].v);
        free(o->body_awake[i].v);
    }
    free(o->body_pairs);
    free(o->body_partners);
    free(o->body_awake);
    free(o->was_frozen);
    free(o->fresh);
    free(o->free_pairs.v);
    free(o->hot);
    vrBroad_Free(&o->bp);
    free(o->body);
    free(o->pair);
    vrHeap_Free(&o->heap);
    free(o->active.v);
    free(o->flagged.v);
    free(o->due.v);
    free(o->due_inside.v);
    free(o->later);
    free(o->undo);
    free(o->pending);
    free(o->found);
    free(o->kept);
    free(o->redo.v);
    free(o->again.v);
    free(o->marked.v);
    free(o->mark);
    free(o->reach.v);
    free(o->reached);
    vrResponder_Free(o->responder);
    free(o);
}

void vrPair_Flag(vrOwner *o, int pi)
{
    if (!o->pair[pi].flagged) {
        o->pair[pi].flagged = 1;
        vrIntList_Push(&o->flagged, pi);
    }
}

/* a pair that is not dormant is in both its bodies' awake lists */
void vrPair_ListAwake(vrOwner *o, int pi)
{
    unsigned char *h = &o->hot[pi];
    if (!(*h & HOT_LISTED_A) && vrIntList_Push(&o->body_awake[o->pair[pi].a], pi) == 0) *h |= HOT_LISTED_A;
    if (!(*h & HOT_LISTED_B) && vrIntList_Push(&o->body_awake[o->pair[pi].b], pi) == 0) *h |= HOT_LISTED_B;
    if (!(*h & HOT_LISTED_A) || !(*h & HOT_LISTED_B)) o->awake_lost = 1;
}

static void deactivate(vrOwner *o, int pi)
{
    vrPair *p = &o->pair[pi];
    int last;
    if (p->active < 0) return;
    last = o->active.v[--o->active.n];
    o->active.v[p->active] = last;
    o->pair[last].active = p->active;
    p->active = -1;
}

/* With the heap, a pair waits in the heap until its key, or — inside the
 * envelope, due at every grid point — in the active list, which costs no
 * heap operation per step.  Without the heap, every scheduled pair is due
 * always and neither is used. */
void vrPair_Place(vrOwner *o, int pi)
{
    vrPair *p = &o->pair[pi];
    deactivate(o, pi);
    /* a pair in the heap already moves to its new key in one sift */
    if (o->p.use_heap && p->scheduled && !p->inside && p->key < INFINITY
        && vrHeap_Set(&o->heap, pi, p->key, p->order) == 0)
        return;
    vrHeap_Remove(&o->heap, pi);
    if (o->p.use_heap && p->scheduled && p->inside) {
        p->active = o->active.n;
        vrIntList_Push(&o->active, pi);
    }
}

/* pairs of two frozen bodies cannot change until one of them wakes: they are
 * not scheduled (SPEC 3.3: a resting body and its supports) */
void vrPair_UpdateSchedule(vrOwner *o, int pi)
{
    vrPair *p = &o->pair[pi];
    p->scheduled = !(vrBody_Frozen(o->body[p->a]) && vrBody_Frozen(o->body[p->b]));
    if (!p->scheduled) vrPair_Place(o, pi);
}

void vrOwner_SetParams(vrOwner *o, const vrParams *p)
{
    int i;
    o->p = *p;
    o->gc = vrParams_Gap(p);
    o->region = vrParams_RegionLevel(p);
    o->v_rest = vrParams_RestSpeed(p);
    vrBroad_SetEnvelope(&o->bp, p->d);    /* the boxes are padded by d: made anew */
    vrBroad_SetKind(&o->bp, p->use_tree ? VR_BROAD_TREE : VR_BROAD_SWEEP);
    for (i = 0; i < o->npair; i++) {
        if (vrPair_Free(&o->pair[i])) continue;
        vrPair_Place(o, i);
        vrPair_Flag(o, i);
    }
    /* lazy: the pairs the new envelope brings close are made at the next
     * look at the poses, flagged as these are */
    for (i = 0; o->lazy && i < o->bodycap; i++)
        if (o->body[i]) o->fresh[i] = 1, o->any_fresh = 1;
}

int vrOwner_HoldBody(vrOwner *o, int id, vrBody *b)
{
    if (id >= o->bodycap) {
        int old = o->bodycap, cap = old, i;
        if (vrGrow((void **)&o->body, &cap, id + 1, sizeof *o->body) != 0) return -1; /* NOLINT(bugprone-sizeof-expression): an array of pointers */
        cap = old;
        if (vrGrow((void **)&o->body_pairs, &cap, id + 1, sizeof *o->body_pairs) != 0) return -1;
        cap = old;
        if (vrGrow((void **)&o->body_partners, &cap, id + 1, sizeof *o->body_partners) != 0) return -1;
        cap = old;
        if (vrGrow((void **)&o->body_awake, &cap, id + 1, sizeof *o->body_awake) != 0) return -1;
        if (vrBroad_Reserve(&o->bp, cap) != 0) return -1;
        cap = old;
        if (vrGrow((void **)&o->was_frozen, &cap, id + 1, sizeof *o->was_frozen) != 0) return -1;
        cap = old;
        if (vrGrow((void **)&o->fresh, &cap, id + 1, sizeof *o->fresh) != 0) return -1;
        for (i = old; i < cap; i++) {
            o->fresh[i] = 0;
            o->was_frozen[i] = 2;
            o->body[i] = NULL;
            o->body_pairs[i].n = o->body_pairs[i].cap = 0;
            o->body_pairs[i].v = NULL;
            o->body_partners[i].n = o->body_partners[i].cap = 0;
            o->body_partners[i].v = NULL;
            o->body_awake[i].n = o->body_awake[i].cap = 0;
            o->body_awake[i].v = NULL;
        }
        o->bodycap = cap;
    }
    if (!o->body[id]) o->nheld++;
    o->body[id] = b;
    vrBroad_BodyChanged(&o->bp, id);
    return 0;
}

int vrOwner_BodyCount(const vrOwner *o) { return o->nheld; }

/* the pair's key after a look that found it dist apart along n; only the
 * heap reads keys, so heap = 0 (the thesis's ablation) does not pay for
 * them (a change of settings re-evaluates every pair) */
double vrPair_Key(const vrOwner *o, const vrPair *p, double t, double dist, vec3 n)
{
    if (!o->p.use_heap) return t;
    return vrSchedule_Key(o->body[p->a], o->body[p->b], t, dist, n, o->p.d, &o->p.flight);
}

/* A pair's state at a frame boundary is a pure function of the poses: every
 * pair is evaluated at the last grid point of a frame (or, with the heap,
 * provably outside there), so inside = distance <= d at that time.  A
 * flagged pair is instead evaluated afresh at the next span start. */
/* a slot for a new pair: a dropped pair's (pair_life.c), or a new one */
static int new_slot(vrOwner *o)
{
    if (o->free_pairs.n > 0) return o->free_pairs.v[--o->free_pairs.n];
    if (vrGrow((void **)&o->pair, &o->paircap, o->npair + 1, sizeof *o->pair) != 0
        || vrGrow((void **)&o->hot, &o->hotcap, o->npair + 1, sizeof *o->hot) != 0) return -1;
    return o->npair++;
}

/* the map by order, at most half full */
static int map_pair(vrOwner *o, int pi)
{
    if (2 * (o->bp.map.n + 1) + 2 > o->bp.map.cap) {
        int i;
        if (vrPairMap_Reset(&o->bp.map, 2 * (o->bp.map.n + 1)) != 0) return -1;
        for (i = 0; i < o->npair; i++)
            if (i != pi && !vrPair_Free(&o->pair[i])) vrPairMap_Put(&o->bp.map, o->pair[i].order, i);
    }
    vrPairMap_Put(&o->bp.map, o->pair[pi].order, pi);
    return 0;
}

static void settle_at(vrOwner *o, int pi, double t)
{
    vrPair *p = &o->pair[pi];
    vrPose pa, pb;
    vrContact c;
    int inside;
    vrPair_Query(o, p, t, 0, &pa, &pb, &c);
    inside = c.dist <= o->p.d;
    p->t_check = t;
    p->near = vrPair_Near(o, c.dist);
    p->overlap = c.dist < -VR_PENETRATION_TOL;
    vrPair_Settle(o, pi, inside, inside ? t : vrPair_Key(o, p, t, c.dist, c.n));
}

/* A pair's state at a frame boundary is a pure function of the poses: every
 * pair is evaluated at the last grid point of a frame (or, with the heap,
 * provably outside there), so inside = distance <= d at that time.  A
 * flagged pair is instead evaluated afresh at the next span start. */
int vrOwner_AddPairAt(vrOwner *o, int a, int b, double t, int flagged)
{
    vrPair *p;
    int pi = new_slot(o);
    if (pi < 0) return -1;
    p = &o->pair[pi];
    memset(p, 0, sizeof *p);
    p->a = a;
    p->b = b;
    p->order = vrPair_Order(a, b);
    p->t_check = p->looked = -INFINITY;
    p->key = -INFINITY;
    p->quiet_until = -INFINITY;
    p->touch_t = -INFINITY;
    p->active = -1;
    o->hot[pi] = 0;
    if (map_pair(o, pi) != 0) return -1;
    if (vrIntList_Push(&o->body_pairs[a], pi) != 0 || vrIntList_Push(&o->body_pairs[b], pi) != 0
        || vrIntList_Push(&o->body_partners[a], b) != 0 || vrIntList_Push(&o->body_partners[b], a) != 0) return -1;
    vrPair_ListAwake(o, pi);
    vrPair_UpdateSchedule(o, pi);
    if (flagged) vrPair_Flag(o, pi);
    else if (p->scheduled) settle_at(o, pi, t);
    return 0;
}

int vrOwner_AddPair(vrOwner *o, int a, int b) { return vrOwner_AddPairAt(o, a, b, 0, 1); }

long vrOwner_PairCount(const vrOwner *o) { return o->npair - o->free_pairs.n; }

/* rebuilds pair indices after pairs were removed */
static void reindex(vrOwner *o)
{
    int i;
    vrHeap_Free(&o->heap);
    vrHeap_Init(&o->heap);
    o->active.n = 0;
    o->flagged.n = 0;
    vrPairMap_Reset(&o->bp.map, o->npair);   /* no memory: no map, see new_frame */
    for (i = 0; i < o->bodycap; i++) o->body_pairs[i].n = o->body_partners[i].n = o->body_awake[i].n = 0;
    o->awake_lost = 0;
    for (i = 0; i < o->npair; i++) {
        vrPair *p = &o->pair[i];
        vrIntList_Push(&o->body_pairs[p->a], i);
        vrIntList_Push(&o->body_pairs[p->b], i);
        vrIntList_Push(&o->body_partners[p->a], p->b);
        vrIntList_Push(&o->body_partners[p->b], p->a);
        o->hot[i] = p->inside ? HOT_INSIDE : 0;
        vrPair_ListAwake(o, i);
        if (o->bp.map.cap) vrPairMap_Put(&o->bp.map, p->order, i);
        p->flagged = 0;
        p->active = -1;
        vrPair_Flag(o, i);
        vrPair_UpdateSchedule(o, i);
        vrPair_Place(o, i);
    }
    /* every pair was scheduled from its bodies' state now: a body that
     * froze or thawed since the owner last heard must not look unchanged
     * when it does (a ball put to rest, then a table deleted or made
     * dynamic: its pairs with static bodies were left unscheduled, and it
     * fell through the floor when it woke) */
    for (i = 0; i < o->bodycap; i++)
        if (o->body[i]) o->was_frozen[i] = (unsigned char)vrBody_Frozen(o->body[i]);
}

void vrOwner_DropBody(vrOwner *o, int id)
{
    int i, k = 0;
    if (id >= o->bodycap || !o->body[id]) return;
    for (i = 0; i < o->npair; i++)
        if (!vrPair_Free(&o->pair[i]) && o->pair[i].a != id && o->pair[i].b != id) o->pair[k++] = o->pair[i];
    o->npair = k;
    o->free_pairs.n = 0;
    if (o->fresh) o->fresh[id] = 0;
    o->body[id] = NULL;
    o->nheld--;
    vrBroad_BodyChanged(&o->bp, id);
    o->npending = 0;
    o->nundo = o->nkept = o->redo.n = 0;
    reindex(o);
}

/* a pair's status and key after an evaluation, and where it waits */
void vrPair_Settle(vrOwner *o, int pi, int inside, double key)
{
    o->hot[pi] = (unsigned char)((o->hot[pi] & (HOT_LISTED_A | HOT_LISTED_B)) | (inside ? HOT_INSIDE : 0));
    vrPair_ListAwake(o, pi);
    o->pair[pi].inside = inside;
    o->pair[pi].key = key;
    vrPair_Place(o, pi);
}

static int cmp_order(const void *x, const void *y, const vrOwner *o)
{
    long long a = o->pair[*(const int *)x].order, b = o->pair[*(const int *)y].order;
    return a < b ? -1 : a > b;
}

static const vrOwner *sort_owner; /* qsort has no context argument in C99 */
static int cmp_pairs(const void *x, const void *y) { return cmp_order(x, y, sort_owner); }

static void sort_pairs(vrOwner *o, vrIntList *l)
{
    int i;
    for (i = 1; i < l->n && o->pair[l->v[i - 1]].order < o->pair[l->v[i]].order; i++)
        ;
    if (i >= l->n) return;    /* in order already, as pairs made in order are */
    sort_owner = o;
    qsort(l->v, (size_t)l->n, sizeof *l->v, cmp_pairs);
}

int vrOwner_Overlapping(vrOwner *o, double t, double tol, const int *ids, int nids, int (*out)[2], int max)
{
    unsigned char *mine = calloc((size_t)o->bodycap + 1, 1);
    int i, n = 0;
    if (!mine || vrOwner_MakeFresh(o, t) != 0) return free(mine), -1;
    for (i = 0; i < nids; i++)
        if (ids[i] >= 0 && ids[i] < o->bodycap) mine[ids[i]] = 1;
    sort_pairs(o, &o->flagged);
    for (i = 0; i < o->flagged.n; i++) {
        vrPair *p = &o->pair[o->flagged.v[i]];
        vrPose pa, pb;
        vrContact c;
        vec3 dir;
        if (!(mine[p->a] || mine[p->b])) continue;
        if (!p->scheduled || vrPair_SphereGap(o, p, t, &dir) > tol) continue;   /* bounding spheres apart: no overlap */
        vrPair_Query(o, p, t, 0, &pa, &pb, &c);
        if (c.dist < -tol) {
            if (n < max) { out[n][0] = p->a; out[n][1] = p->b; }
            n++;
        }
    }
    free(mine);
    return n;
}

void vrOwner_SetProgress(vrOwner *o, void (*fn)(void *ctx), void *ctx)
{
    o->progress = fn;
    o->progress_ctx = ctx;
}

int vrOwner_Respond(vrOwner *o, const vrEvent *ev, vrUpdate *up)
{
    return vrEffect_Compute(o->body, o->responder, &o->p.flight, o->v_rest, ev, up);
}

void vrOwner_Stats(const vrOwner *o, vrOwnerStats *s)
{
    s->checks = o->checks;
    s->heap_pops = o->heap_pops;
    s->response = vrResponder_Stats(o->responder);
}

/* An island step would find nothing here: no pair in the envelope (those
 * are the only ones that can touch), none flagged for a look, no body
 * whose pairs are still to be made — vrOwner_Touching looks at no pair. */
int vrOwner_Quiet(const vrOwner *o)
{
    int i;
    if (o->any_fresh || o->flagged.n > 0) return 0;
    if (o->p.use_heap) return o->active.n == 0;
    for (i = 0; i < o->npair; i++)
        if (!vrPair_Free(&o->pair[i]) && o->pair[i].inside && o->pair[i].scheduled) return 0;
    return 1;
}
