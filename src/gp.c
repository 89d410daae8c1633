/* gp.c — a pair owner (thesis 3.4.2 "Graphic Processor control loop").
 *
 * For a span [t0, T] on the coordinator's grid, the owner visits grid
 * points in order; at each it checks the pairs that are due (all of them
 * with heap = 0; with the heap, those whose expected earliest event time
 * has come, thesis 3.3.1.2), finds the events there (SPEC 3.1), and stops at
 * the first grid point that has any.  An impact found at a grid point is
 * moved back to its moment by bisection of the step.  Pairs are evaluated
 * with the same operations whatever the heap mode or the owner, so the
 * outcome is the same; the heap only skips checks that cannot matter.
 * The owner answers the event it found with respond.c.
 */
#include <stdlib.h>
#include <string.h>
#include "gp.h"
#include "distbound.h"
#include "broadphase.h"
#include "grow.h"
#include "heap.h"

#define BISECTIONS 48
#define TIE_SPEED 1e-9        /* m/s: points this close to the most approaching one share the impulse */
#define CONTAIN_TOL 1e-9      /* m: support containment in the contact plane */

typedef struct vrPair {
    int a, b;                 /* object ids, a < b */
    long long order;
    int inside;               /* distance <= d at t_check */
    int scheduled;            /* 0 when both bodies are frozen (static or resting) */
    int flagged;              /* to be evaluated at the next span start */
    double t_check;
    double key;               /* expected earliest event (in the heap when scheduled and finite) */
    double quiet_until;       /* inside, but nothing can happen until then (quiet_slide) */
    int active;               /* index in the active list, or -1 */
    vrWalkCache cache;
} vrPair;

/* per pair, in a byte array an event can sweep without touching the pairs
 * themselves (a thousand bodies make half a million pairs) */
enum { HOT_DORMANT = 1, HOT_INSIDE = 2, HOT_LISTED_A = 4, HOT_LISTED_B = 8 };

/* what an evaluation changed, so Advance can take it back */
typedef struct vrUndo {
    int pair;
    double at;                /* the evaluation time */
    int inside;
    double t_check;
    double key, quiet_until;
} vrUndo;

typedef struct vrIntList { int n, cap; int *v; } vrIntList;

/* A pair's last contacts with their regions (see query) */
#define REGION_MEMO 64
typedef struct vrRegionMemo {
    long long order;          /* the pair; 0 with nothing kept (a pair's order is never 0: a < b) */
    unsigned long shape_a, shape_b;   /* the shapes' serials */
    double d;
    vec3 pa, pb;              /* the poses it was made at */
    quat qa, qb;
    vrContact c;
} vrRegionMemo;

struct vrOwner {
    vrParams p;
    double v_rest;            /* sqrt(2 |a| d), SPEC 3.1 */
    vrBody **body;            /* by id, NULL when not held */
    vrIntList *body_pairs;    /* by id: indices of its pairs */
    vrIntList *body_partners; /* by id: the other body of each of those pairs */
    vrIntList *body_awake;    /* by id: its pairs that may not be dormant (each listed once,
                                 HOT_LISTED_A or _B; a dormant one may linger) */
    unsigned char *was_frozen; /* by id: frozen when its pairs were last scheduled (2: not yet) */
    unsigned char *hot;       /* by pair: HOT_* */
    vrBroadphase bp;          /* which pairs could meet in the rest of the frame; its t0 and T
                                 are the span being looked through and the frame's end */
    int hotcap;
    int bodycap, nheld;
    vrPair *pair;
    int npair, paircap;
    vrHeap heap;
    vrIntList active;         /* inside pairs: due at every grid point, kept out of the heap */
    vrIntList flagged, due, due_inside;  /* due at a grid point: outside the envelope, inside */
    /* keys of pairs found outside at the grid point being looked at (by the
     * walk or a full look), made once it is known whether an impact before
     * it rolls them back */
    int defer_keys, nlater, latercap;
    struct vrLaterKey { int pair; double dist; vec3 n; } *later;
    vrUndo *undo;
    int nundo, undocap;
    vrEvent *pending;         /* events found at pending_t not yet taken */
    int npending, pendcap;
    double pending_t;
    vrEvent *found;           /* scratch: the events of one grid point */
    int nfound, foundcap;
    vrResponder *responder;
    vrRegionMemo memo[REGION_MEMO];
    long long checks, heap_pops;
    int awake_lost;           /* no memory to list a pair awake: events look at every pair */
    void (*progress)(void *ctx);
    void *progress_ctx;
};

/* ---- small containers ------------------------------------------------------ */

static int list_push(vrIntList *l, int v)
{
    if (vrGrow((void **)&l->v, &l->cap, l->n + 1, sizeof *l->v) != 0) return -1;
    l->v[l->n++] = v;
    return 0;
}

static int push_event(vrEvent **arr, int *n, int *cap, const vrEvent *ev)
{
    if (vrGrow((void **)arr, cap, *n + 1, sizeof **arr) != 0) return -1;
    (*arr)[(*n)++] = *ev;
    return 0;
}

/* ---- life cycle ---------------------------------------------------------------- */

vrOwner *vrOwner_Create(void)
{
    vrOwner *o = calloc(1, sizeof *o);
    if (!o) return NULL;
    vrHeap_Init(&o->heap);
    o->responder = vrResponder_Create();
    o->pending_t = -INFINITY;
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
    vrResponder_Free(o->responder);
    free(o);
}

static int frozen(const vrBody *b) { return b->is_static || b->resting; }

static void flag(vrOwner *o, int pi)
{
    if (!o->pair[pi].flagged) {
        o->pair[pi].flagged = 1;
        list_push(&o->flagged, pi);
    }
}

/* a pair that is not dormant is in both its bodies' awake lists */
static void list_awake(vrOwner *o, int pi)
{
    unsigned char *h = &o->hot[pi];
    if (!(*h & HOT_LISTED_A) && list_push(&o->body_awake[o->pair[pi].a], pi) == 0) *h |= HOT_LISTED_A;
    if (!(*h & HOT_LISTED_B) && list_push(&o->body_awake[o->pair[pi].b], pi) == 0) *h |= HOT_LISTED_B;
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
static void place(vrOwner *o, int pi)
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
        list_push(&o->active, pi);
    }
}

/* pairs of two frozen bodies cannot change until one of them wakes: they are
 * not scheduled (SPEC 3.3: a resting body and its supports) */
static void update_schedule(vrOwner *o, int pi)
{
    vrPair *p = &o->pair[pi];
    p->scheduled = !(frozen(o->body[p->a]) && frozen(o->body[p->b]));
    if (!p->scheduled) place(o, pi);
}

void vrOwner_SetParams(vrOwner *o, const vrParams *p)
{
    int i;
    o->p = *p;
    o->v_rest = sqrt(2.0 * vec3_len(p->flight.accel) * p->d);
    vrBroad_SetEnvelope(&o->bp, p->d);    /* the boxes are padded by d: made anew */
    for (i = 0; i < o->npair; i++) {
        place(o, i);
        flag(o, i);
    }
}

int vrOwner_HoldBody(vrOwner *o, int id, vrBody *b)
{
    if (id >= o->bodycap) {
        int old = o->bodycap, cap = old, i;
        if (vrGrow((void **)&o->body, &cap, id + 1, sizeof *o->body) != 0) return -1;
        cap = old;
        if (vrGrow((void **)&o->body_pairs, &cap, id + 1, sizeof *o->body_pairs) != 0) return -1;
        cap = old;
        if (vrGrow((void **)&o->body_partners, &cap, id + 1, sizeof *o->body_partners) != 0) return -1;
        cap = old;
        if (vrGrow((void **)&o->body_awake, &cap, id + 1, sizeof *o->body_awake) != 0) return -1;
        if (vrBroad_Reserve(&o->bp, cap) != 0) return -1;
        cap = old;
        if (vrGrow((void **)&o->was_frozen, &cap, id + 1, sizeof *o->was_frozen) != 0) return -1;
        for (i = old; i < cap; i++) {
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

static void query(vrOwner *o, vrPair *p, double t, int region, vrPose *pa, vrPose *pb, vrContact *c);
static void settle(vrOwner *o, int pi, int inside, double key);

/* the pair's key after a look that found it dist apart along n; only the
 * heap reads keys, so heap = 0 (the thesis's ablation) does not pay for
 * them (a change of settings re-evaluates every pair) */
static double pair_key(const vrOwner *o, const vrPair *p, double t, double dist, vec3 n)
{
    if (!o->p.use_heap) return t;
    return vrSchedule_Key(o->body[p->a], o->body[p->b], t, dist, n, o->p.d, &o->p.flight);
}

/* A pair's state at a frame boundary is a pure function of the poses: every
 * pair is evaluated at the last grid point of a frame (or, with the heap,
 * provably outside there), so inside = distance <= d at that time.  A
 * flagged pair is instead evaluated afresh at the next span start. */
int vrOwner_AddPairAt(vrOwner *o, int a, int b, double t, int flagged)
{
    vrPair *p;
    if (vrGrow((void **)&o->pair, &o->paircap, o->npair + 1, sizeof *o->pair) != 0) return -1;
    p = &o->pair[o->npair];
    memset(p, 0, sizeof *p);
    p->a = a;
    p->b = b;
    p->order = vrPair_Order(a, b);
    p->t_check = -INFINITY;
    p->key = -INFINITY;
    p->quiet_until = -INFINITY;
    p->active = -1;
    if (vrGrow((void **)&o->hot, &o->hotcap, o->npair + 1, sizeof *o->hot) != 0) return -1;
    o->hot[o->npair] = 0;
    if (2 * (o->bp.map.n + 1) + 2 > o->bp.map.cap) {
        int i;
        if (vrPairMap_Reset(&o->bp.map, 2 * (o->npair + 1)) != 0) return -1;
        for (i = 0; i < o->npair; i++) vrPairMap_Put(&o->bp.map, o->pair[i].order, i);
    }
    vrPairMap_Put(&o->bp.map, p->order, o->npair);
    if (list_push(&o->body_pairs[a], o->npair) != 0 || list_push(&o->body_pairs[b], o->npair) != 0
        || list_push(&o->body_partners[a], b) != 0 || list_push(&o->body_partners[b], a) != 0) return -1;
    o->npair++;
    list_awake(o, o->npair - 1);
    update_schedule(o, o->npair - 1);
    if (flagged) {
        flag(o, o->npair - 1);
    } else if (p->scheduled) {
        vrPose pa, pb;
        vrContact c;
        int inside;
        query(o, p, t, 0, &pa, &pb, &c);
        inside = c.dist <= o->p.d;
        p->t_check = t;
        settle(o, o->npair - 1, inside, inside ? t : pair_key(o, &o->pair[o->npair - 1], t, c.dist, c.n));
    }
    return 0;
}

int vrOwner_AddPair(vrOwner *o, int a, int b) { return vrOwner_AddPairAt(o, a, b, 0, 1); }

long vrOwner_PairCount(const vrOwner *o) { return o->npair; }

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
        list_push(&o->body_pairs[p->a], i);
        list_push(&o->body_pairs[p->b], i);
        list_push(&o->body_partners[p->a], p->b);
        list_push(&o->body_partners[p->b], p->a);
        o->hot[i] = p->inside ? HOT_INSIDE : 0;
        list_awake(o, i);
        if (o->bp.map.cap) vrPairMap_Put(&o->bp.map, p->order, i);
        p->flagged = 0;
        p->active = -1;
        flag(o, i);
        update_schedule(o, i);
        place(o, i);
    }
    /* every pair was scheduled from its bodies' state now: a body that
     * froze or thawed since the owner last heard must not look unchanged
     * when it does (a ball put to rest, then a table deleted or made
     * dynamic: its pairs with static bodies were left unscheduled, and it
     * fell through the floor when it woke) */
    for (i = 0; i < o->bodycap; i++)
        if (o->body[i]) o->was_frozen[i] = (unsigned char)frozen(o->body[i]);
}

void vrOwner_DropBody(vrOwner *o, int id)
{
    int i, k = 0;
    if (id >= o->bodycap || !o->body[id]) return;
    for (i = 0; i < o->npair; i++)
        if (o->pair[i].a != id && o->pair[i].b != id) o->pair[k++] = o->pair[i];
    o->npair = k;
    o->body[id] = NULL;
    o->nheld--;
    vrBroad_BodyChanged(&o->bp, id);
    o->npending = 0;
    o->nundo = 0;
    reindex(o);
}

static int event_involves(const vrEvent *ev, const int *ids, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (ev->a == ids[i] || ev->b == ids[i]) return 1;
    return 0;
}

static int has_support(const vrBody *x, int partner);

/* either body of the pair rests on (or slides over) the other */
static int supported_pair(const vrOwner *o, int a, int b)
{
    return has_support(o->body[a], b) || has_support(o->body[b], a);
}

/* pair pi of bodies x and y cannot come within d before the frame ends:
 * it can be dormant (with heap = 1; never while inside or supporting) */
static int apart_from(vrOwner *o, int pi, const vrBox *box_x, int x, int y)
{
    if (!o->p.use_heap || (o->hot[pi] & HOT_INSIDE)) return 0;
    return vrBroad_Apart(box_x, vrBroad_Box(&o->bp, o->body, y)) && !supported_pair(o, x, y);
}

static int apart(vrOwner *o, int pi, int x, int y) { return apart_from(o, pi, vrBroad_Box(&o->bp, o->body, x), x, y); }

static int pair_apart(vrOwner *o, int pi) { return apart(o, pi, o->pair[pi].a, o->pair[pi].b); }

/* out of the heap too: a dormant pair's key is for nothing (the heap stays
 * the size of the pairs that could meet) */
static void make_dormant(vrOwner *o, int pi)
{
    if (o->hot[pi] & HOT_DORMANT) return;     /* out already: no look at the heap */
    o->hot[pi] |= HOT_DORMANT;
    vrHeap_Remove(&o->heap, pi);
}

static void wake(vrOwner *o, int pi)
{
    if (!(o->hot[pi] & HOT_DORMANT)) return;
    o->hot[pi] &= (unsigned char)~HOT_DORMANT;
    list_awake(o, pi);
    flag(o, pi);
}

static void wake_pairs_of(vrOwner *o, int id)
{
    int i;
    for (i = 0; i < o->body_pairs[id].n; i++) wake(o, o->body_pairs[id].v[i]);
}

static void wake_met(void *ctx, int x, int y)
{
    vrOwner *o = ctx;
    int pi = vrPairMap_Find(&o->bp.map, vrPair_Order(x, y));
    if (pi >= 0) wake(o, pi);
}

static void wake_boxless(void *ctx, int id) { wake_pairs_of(ctx, id); }

/* A new frame: new boxes, and the dormant pairs whose boxes now overlap are
 * woken, to be evaluated at its start (the broadphase sweeps the boxes, so
 * the pairs that stay apart, nearly all of them among a thousand bodies,
 * are not looked at).  Without the map or memory, every pair wakes.
 * `hit` is per frame (rest.c): a worker's copies must forget it as the
 * shell's bodies do, or an update that is no impulse (a push-out, a
 * support change) carries an old hit back to the shell. */
static void new_frame(vrOwner *o, const vrGrid *g)
{
    int i;
    for (i = 0; i < o->bodycap; i++)
        if (o->body[i]) o->body[i]->hit = 0;
    if (!o->bp.map.cap || vrBroad_NewFrame(&o->bp, o->body, o->bodycap, g->t0, g->T, wake_met, wake_boxless, o) != 0)
        for (i = 0; i < o->npair; i++) wake(o, i);
}

/* body id changed: each key of its pairs was for the old motion, so a
 * pair is evaluated anew, or dormant (apart from the other's box) */
static void changed_pair(vrOwner *o, int pi, const vrBox *box, int id, int other)
{
    if (apart_from(o, pi, box, id, other)) {
        make_dormant(o, pi);
    } else {
        o->hot[pi] &= (unsigned char)~HOT_DORMANT;
        list_awake(o, pi);
        flag(o, pi);
    }
}

/* every pair of id, one by one */
static void changed_all(vrOwner *o, int id, const vrBox *box)
{
    const vrIntList *l = &o->body_pairs[id], *partner = &o->body_partners[id];
    int j;
    for (j = 0; j < l->n; j++) changed_pair(o, l->v[j], box, id, partner->v[j]);
}

typedef struct vrChanged { vrOwner *o; int id; const vrBox *box; } vrChanged;

/* a body whose box may meet the changed one's: their pair, if dormant and
 * no longer apart, wakes (an awake one was seen in the awake list) */
static void changed_meets(void *ctx, int y)
{
    vrChanged *c = ctx;
    vrOwner *o = c->o;
    int x = c->id, pi = vrPairMap_Find(&o->bp.map, vrPair_Order(x, y));
    if (pi >= 0 && (o->hot[pi] & HOT_DORMANT)) changed_pair(o, pi, c->box, x, y);
}

/* The same for a thousand bodies: a dormant pair stays dormant while the
 * boxes are apart, so only the pairs awake and those of the bodies whose
 * boxes meet the new one (a search in the broadphase's sorted list) are
 * looked at.  A dormant pair lingering in the awake list leaves it. */
static void changed_near(vrOwner *o, int id, const vrBox *box)
{
    vrIntList *l = &o->body_awake[id];
    vrChanged c;
    int j = 0;
    while (j < l->n) {
        int pi = l->v[j], other = o->pair[pi].a == id ? o->pair[pi].b : o->pair[pi].a;
        if (!(o->hot[pi] & HOT_DORMANT)) changed_pair(o, pi, box, id, other);
        if (o->hot[pi] & HOT_DORMANT) {
            o->hot[pi] &= (unsigned char)~(o->pair[pi].a == id ? HOT_LISTED_A : HOT_LISTED_B);
            l->v[j] = l->v[--l->n];
        } else {
            j++;
        }
    }
    c.o = o, c.id = id, c.box = box;
    vrBroad_Meeting(&o->bp, id, changed_meets, &c);
}

void vrOwner_BodiesChanged(vrOwner *o, const int *ids, int n)
{
    int i, j, k = 0, near;
    for (i = 0; i < n; i++)
        if (ids[i] < o->bodycap && o->body[ids[i]]) vrBroad_Rebox(&o->bp, o->body, ids[i]);
    near = o->bp.map.cap && !o->awake_lost && vrBroad_CanMeet(&o->bp);
    for (i = 0; i < n; i++) {
        int id = ids[i], now_frozen;
        const vrBox *box;
        if (id >= o->bodycap || !o->body[id]) continue;
        /* a pair's scheduling only changes when a body freezes or thaws */
        now_frozen = frozen(o->body[id]);
        if (o->was_frozen[id] != now_frozen)
            for (j = 0; j < o->body_pairs[id].n; j++) update_schedule(o, o->body_pairs[id].v[j]);
        o->was_frozen[id] = (unsigned char)now_frozen;
        box = vrBroad_Box(&o->bp, o->body, id);
        if (near) changed_near(o, id, box);
        else changed_all(o, id, box);
    }
    for (i = 0; i < o->npending; i++)
        if (!event_involves(&o->pending[i], ids, n)) o->pending[k++] = o->pending[i];
    o->npending = k;
}

/* ---- keys and the undo log ---------------------------------------------------- */

/* a pair's status and key after an evaluation, and where it waits */
static void settle(vrOwner *o, int pi, int inside, double key)
{
    o->hot[pi] = (unsigned char)((o->hot[pi] & (HOT_LISTED_A | HOT_LISTED_B)) | (inside ? HOT_INSIDE : 0));
    list_awake(o, pi);
    o->pair[pi].inside = inside;
    o->pair[pi].key = key;
    place(o, pi);
}

static void remember(vrOwner *o, int pi, double at)
{
    vrUndo *u;
    if (vrGrow((void **)&o->undo, &o->undocap, o->nundo + 1, sizeof *o->undo) != 0) return;
    u = &o->undo[o->nundo++];
    u->pair = pi;
    u->at = at;
    u->inside = o->pair[pi].inside;
    u->t_check = o->pair[pi].t_check;
    u->key = o->pair[pi].key;
    u->quiet_until = o->pair[pi].quiet_until;
}

void vrOwner_Advance(vrOwner *o, double t)
{
    int i;
    for (i = o->nundo - 1; i >= 0; i--) {
        const vrUndo *u = &o->undo[i];
        vrPair *p = &o->pair[u->pair];
        if (u->at <= t) continue;
        p->t_check = u->t_check;
        p->quiet_until = u->quiet_until;
        settle(o, u->pair, u->inside, u->key);
    }
    o->nundo = 0;
    if (o->pending_t != t) o->npending = 0;
}

/* ---- evaluation -------------------------------------------------------------- */

static int is_sphere(const vrBody *b) { return b->shape.kind == VR_SHAPE_SPHERE; }

/* what needs a sphere's spin (approach speeds, responses): its real pose,
 * where distances took vrBody_ShapePose's */
static void real_poses(vrOwner *o, const vrPair *p, double t, vrPose *pa, vrPose *pb)
{
    if (is_sphere(o->body[p->a])) vrBody_Pose(o->body[p->a], t, pa);
    if (is_sphere(o->body[p->b])) vrBody_Pose(o->body[p->b], t, pb);
}

static int same_bits(const void *x, const void *y, size_t n) { return memcmp(x, y, n) == 0; }

/* a contact and its region's points, not the unused room after them */
static void copy_contact(vrContact *to, const vrContact *from)
{
    int i;
    to->dist = from->dist, to->n = from->n, to->pa = from->pa, to->pb = from->pb;
    to->npoints = from->npoints, to->walk_steps = from->walk_steps;
    for (i = 0; i < from->npoints; i++) to->point[i] = from->point[i];
}

/* A contact is a function of the two shapes, their poses and d alone
 * (SPEC 3.2's determinism rule), and a pair is asked again at the same
 * poses: after an event at a grid point the pairs of its bodies are
 * evaluated anew there, the responding one among them (a body's pose at
 * its own event is the same bits from its new anchor).  The last region of
 * each of a few pairs is kept, with the serials of the shapes it was made
 * for (an edit remakes a shape in place, a body put anew has a new one). */
static vrRegionMemo *memo_slot(vrOwner *o, const vrPair *p)
{
    return &o->memo[(unsigned long long)p->order % REGION_MEMO];
}

static int memo_holds(const vrOwner *o, const vrRegionMemo *m, const vrPair *p, const vrPose *pa, const vrPose *pb)
{
    return m->order == p->order && m->shape_a == o->body[p->a]->shape.serial
        && m->shape_b == o->body[p->b]->shape.serial && m->d == o->p.d && same_bits(&m->pa, &pa->p, sizeof m->pa)
        && same_bits(&m->qa, &pa->q, sizeof m->qa) && same_bits(&m->pb, &pb->p, sizeof m->pb)
        && same_bits(&m->qb, &pb->q, sizeof m->qb);
}

static void query(vrOwner *o, vrPair *p, double t, int region, vrPose *pa, vrPose *pb, vrContact *c)
{
    vrBody *A = o->body[p->a], *B = o->body[p->b];
    vrRegionMemo *m;
    vrBody_ShapePose(A, t, pa);
    vrBody_ShapePose(B, t, pb);
    if (!region) {
        o->checks++;
        vrContact_Distance(&A->shape, pa, &B->shape, pb, &p->cache, c);
        return;
    }
    m = memo_slot(o, p);
    if (memo_holds(o, m, p, pa, pb)) {
        copy_contact(c, &m->c);
        return;
    }
    o->checks++;
    if (vrContact_Region(&A->shape, pa, &B->shape, pb, o->p.d, &p->cache, c) != 0) return;
    m->order = p->order, m->d = o->p.d, m->pa = pa->p, m->qa = pa->q, m->pb = pb->p, m->qb = pb->q;
    m->shape_a = A->shape.serial, m->shape_b = B->shape.serial;
    copy_contact(&m->c, c);
}

/* Flush surfaces (a table top made of two boxes side by side): a body
 * sliding on one meets the next one's edge at a slant inside the envelope,
 * and the slanted normal would kick it back (Box2D's ghost collisions,
 * Bullet's internal edges).  When x is supported by another body with
 * normal m and frozen y reaches no higher along m than x's lowest point,
 * y cannot stop x sliding along its support: the pair's normal for events
 * and responses is m, as if y were part of the support.  Distances, and so
 * the schedule, are untouched.  A step up higher than x's gap over its
 * support is a real obstacle and keeps its normal. */
static void flush_normal(const vrOwner *o, const vrPair *p, const vrPose *pa, const vrPose *pb, vrContact *c)
{
    int side, i;
    if (c->dist <= 0) return;
    for (side = 0; side < 2; side++) {
        const vrBody *x = o->body[side ? p->b : p->a], *y = o->body[side ? p->a : p->b];
        const vrPose *px = side ? pb : pa, *py = side ? pa : pb;
        vec3 n_yx = side ? c->n : vec3_neg(c->n);
        if (frozen(x) || !frozen(y)) continue;
        for (i = 0; i < x->nsupport; i++) {
            vec3 m = x->support[i].n;
            if (x->support[i].partner == (side ? p->a : p->b) || vec3_dot(n_yx, m) >= 1 - 1e-12) continue;
            double y_top = vec3_dot(m, vrShape_Support(&y->shape, py, m));
            double x_bottom = vec3_dot(m, vrShape_Support(&x->shape, px, vec3_neg(m)));
            if (y_top > x_bottom + CONTAIN_TOL) continue;
            c->n = side ? m : vec3_neg(m);
            return;
        }
    }
}

/* what events are decided from, besides a query with the region: the
 * spheres' real poses (their spin) and the flush-surface normal */
static void for_events(vrOwner *o, const vrPair *p, double t, vrPose *pa, vrPose *pb, vrContact *c)
{
    real_poses(o, p, t, pa, pb);
    flush_normal(o, p, pa, pb, c);
}

/* the query that events are decided from */
static void event_query(vrOwner *o, vrPair *p, double t, vrPose *pa, vrPose *pb, vrContact *c)
{
    query(o, p, t, 1, pa, pb, c);
    for_events(o, p, t, pa, pb, c);
}

/* how far from d the distance bounds must be to decide a halving: a
 * hundred times what they and the measured distance differ by in the
 * tests (below 1e-14 m for bodies 9 m from the origin a minute into a run,
 * below 1e-15 m near it).  1e-13 m would save three measurements an impact
 * (3 % of peer-random-100's instructions) and changed no bit in any scene,
 * but leaves only ten times the rounding seen, and a minute into a run a
 * time rounds a 16 m/s body's position by 1e-13 m: not taken. */
#define BOUND_TOL 1e-12

/* the bisection's test: is the pair's distance at t at most level (d: an
 * impact; 0: touching)?  When what was measured can bound the distance
 * nearby (a gap and closest points), *near (if not NULL) gets those bounds
 * for times in [lo, hi]. */
static int within(vrOwner *o, vrPair *p, double t, double level, double lo, double hi, vrDistBound *near)
{
    vrBody *A = o->body[p->a], *B = o->body[p->b];
    vrPose pa, pb;
    vrContact seen;
    int in;
    vrBody_ShapePose(A, t, &pa);
    vrBody_ShapePose(B, t, &pb);
    o->checks++;
    in = vrContact_Within(&A->shape, &pa, &B->shape, &pb, &p->cache, level, &seen);
    if (!near) return in;
    near->valid = 0;
    /* bounds from a measurement within a few tolerances of the level cannot
     * decide anything beside it: not worth making */
    if (seen.dist > 0 && fabs(seen.dist - level) > 4 * BOUND_TOL)
        vrDistBound_Make(near, A, &pa, B, &pb, t, seen.pa, seen.pb, 1, lo, hi);
    return in;
}

/* the time of the first event found so far at this grid point */
static double earliest_found(const vrOwner *o)
{
    double t = INFINITY;
    int i;
    for (i = 0; i < o->nfound; i++) t = vr_min(t, o->found[i].t);
    return t;
}

/* what the bounds from the bracket's two ends say about the distance at t */
static int decided(vrDistBound *const near[2], double t, double level)
{
    int k, say;
    for (k = 0; k < 2; k++)
        if ((say = vrDistBound_Decide(near[k], t, level, BOUND_TOL)) >= 0) return say;
    return -1;
}

/* the first time in (lo, hi] with distance <= level: exactly BISECTIONS halvings,
 * the event at the upper end of the final bracket (SPEC 3.2).  at_hi is the
 * query at hi.  A halving whose answer the bounds from a measurement at
 * either end of the bracket prove (distbound.h) is not asked of the
 * geometry: the same answers, so the same bracket, from a few walks.
 * NAN once the bracket is past `wanted` (an event found at this grid point
 * comes first): the event would be dropped, and this grid point's looks
 * rolled back, after the first is answered; the halvings left, where most
 * of the geometry is asked, would be for nothing (in a heap of 1,000
 * bodies, more than half of all bisections). */
static double bisect(vrOwner *o, vrPair *p, double lo, double hi, const vrContact *at_hi, double level,
                     double wanted)
{
    const double lo0 = lo, hi0 = hi;
    /* the bounds from the measurements at lo and at hi, and a slot for the
     * next: a measurement takes the place of the end it moves by a swap of
     * pointers (a bound is some 700 bytes; copying it was 1.6 % of the
     * peers' time) */
    vrDistBound slot[3], *near[2], *spare = &slot[2];
    vrPose pa, pb;
    int i, lo_tested = 0;
    near[0] = &slot[0], near[1] = &slot[1];
    near[0]->valid = near[1]->valid = 0;
    if (at_hi->dist > 0) {
        vrBody_ShapePose(o->body[p->a], hi, &pa);
        vrBody_ShapePose(o->body[p->b], hi, &pb);
        /* the query's closest points are canonical, not always points of
         * the bodies: its direction bounds from below only */
        vrDistBound_Make(near[1], o->body[p->a], &pa, o->body[p->b], &pb, hi, at_hi->pa, at_hi->pb, 0, lo0, hi0);
    }
    for (i = 0; i < BISECTIONS; i++) {
        double mid = lo + 0.5 * (hi - lo);
        int in;
        /* Once lo and hi are adjacent doubles the midpoint rounds to one of
         * them and the halvings left change nothing (late in a run, with
         * times of tens of seconds, a dozen of the 48): hi tests true, a lo
         * that was tested false does again, so neither is tested twice. */
        if (mid == hi || (mid == lo && lo_tested)) break;
        if ((in = decided(near, mid, level)) < 0) {
            vrDistBound *was;
            in = within(o, p, mid, level, lo0, hi0, spare);
            was = near[in], near[in] = spare, spare = was;
        }
        if (in) {
            hi = mid;
        } else {
            lo = mid, lo_tested = 1;
            /* lo tested apart: the event comes after it.  (An untested lo
             * may itself be the event, at the instant of one found here:
             * a tie, that pair order decides.) */
            if (lo >= wanted) return NAN;
        }
    }
    return hi;
}

/* relative normal velocities of the region points, b's minus a's */
typedef struct vrApproach {
    double u[VR_REGION_MAX];
    double umin, umax;
    vec3 centroid;            /* of the points within TIE_SPEED of umin */
    vec3 region_centre;
} vrApproach;

static void approach(vrOwner *o, const vrPair *p, double t, const vrPose *pa, const vrPose *pb,
                     const vrContact *c, vrApproach *ap)
{
    vrBody *A = o->body[p->a], *B = o->body[p->b];
    vec3 sum = vec3_zero(), all = vec3_zero(), va, vb;
    vec3 wa = vrBody_Omega(A, pa), wb = vrBody_Omega(B, pb);   /* once, not per point */
    int i, ties = 0;
    vrBody_Velocity(A, t, &va);
    vrBody_Velocity(B, t, &vb);
    ap->umin = INFINITY;
    ap->umax = -INFINITY;
    for (i = 0; i < c->npoints; i++) {
        vec3 u = vec3_sub(vrRigid_PointVelocity(vb, wb, pb->p, c->point[i]),
                          vrRigid_PointVelocity(va, wa, pa->p, c->point[i]));
        ap->u[i] = vec3_dot(c->n, u);
        if (ap->u[i] < ap->umin) ap->umin = ap->u[i];
        if (ap->u[i] > ap->umax) ap->umax = ap->u[i];
        all = vec3_add(all, c->point[i]);
    }
    for (i = 0; i < c->npoints; i++)
        if (ap->u[i] <= ap->umin + TIE_SPEED) {
            sum = vec3_add(sum, c->point[i]);
            ties++;
        }
    ap->centroid = ties ? vec3_scale(sum, 1.0 / ties) : c->pa;
    ap->region_centre = c->npoints ? vec3_scale(all, 1.0 / c->npoints) : c->pa;
}

static void fill_event(vrEvent *ev, int kind, double t, const vrPair *p, const vrContact *c)
{
    memset(ev, 0, sizeof *ev);
    ev->kind = kind;
    ev->t = t;
    ev->order = p->order;
    ev->a = p->a;
    ev->b = p->b;
    ev->n = c->n;
    ev->body = ev->partner = -1;
}

static double restitution(const vrOwner *o, const vrPair *p, double speed)
{
    const vrBody *A = o->body[p->a], *B = o->body[p->b];
    if (speed < o->v_rest) return 0.0;   /* SPEC 3.1: slow impacts do not bounce */
    return fmin(A->elasticity, B->elasticity);
}

static void impulse_event(vrOwner *o, vrEvent *ev, int kind, double t, const vrPair *p,
                          const vrContact *c, const vrApproach *ap)
{
    fill_event(ev, kind, t, p, c);
    ev->c = ap->centroid;
    ev->approach = ap->umin;
    ev->e = restitution(o, p, -ap->umin);
}

/* 0: partner does not support x; 1: alone; 2: together with others */
static int has_support(const vrBody *x, int partner)
{
    int i;
    for (i = 0; i < x->nsupport; i++)
        if (x->support[i].partner == partner) return x->support[i].joint ? 2 : 1;
    return 0;
}

/* SPEC 3.1: x is supported through this contact when its partner is static,
 * resting or supported, the force presses x onto it, nothing approaches or
 * separates faster than v_eps, and the reaction can balance the force: the
 * line through x's centre of mass along the contact normal meets the contact
 * region (on a level support this is the projection along the force; on a
 * slope it is where a frictionless reaction can act) */
static int supports(const vrOwner *o, const vrBody *x, const vrBody *y, vec3 n_yx, const vrPose *px,
                    const vrContact *c, const vrApproach *ap, int joint)
{
    vec3 g = o->p.flight.accel, q;
    double gl = vec3_len(g);
    if (frozen(x) || !(frozen(y) || y->nsupport > 0) || c->npoints == 0) return 0;
    if (gl == 0 || vec3_dot(g, n_yx) > -1e-6 * gl) return 0;
    if (ap->umin < -VR_V_EPS || ap->umax > VR_V_EPS) return 0;
    if (joint) return 1;    /* the regions together are checked at frame ends (rest.c) */
    q = vec3_madd(px->p, vec3_dot(vec3_sub(c->point[0], px->p), n_yx), n_yx);
    return vrRegion_Contains(c->point, c->npoints, n_yx, q, CONTAIN_TOL);
}

/* Up to three corners of a contact region that span it: the first point,
 * the one farthest from it, and the one farthest from the line of those
 * two (a segment or a single point when the region is one). */
#define SPAN_TOL 1e-7   /* m: thinner than this, a region is a segment (or a point) */
static int region_corners(const vrContact *c, vec3 corner[3])
{
    int i, k = 1;
    double best = SPAN_TOL;
    vec3 e;
    corner[0] = c->point[0];
    for (i = 1; i < c->npoints; i++) {
        double l = vec3_dist(c->point[i], corner[0]);
        if (l > best) best = l, corner[1] = c->point[i], k = 2;
    }
    if (k < 2) return k;
    e = vec3_normalize(vec3_sub(corner[1], corner[0]));
    best = SPAN_TOL;
    for (i = 1; i < c->npoints; i++) {
        vec3 r = vec3_sub(c->point[i], corner[0]);
        double h = vec3_len(vec3_madd(r, -vec3_dot(r, e), e));
        if (h > best) best = h, corner[2] = c->point[i], k = 3;
    }
    return k;
}

static int support_event(vrEvent *ev, int kind, double t, const vrPair *p, const vrContact *c,
                         int body, int partner, vec3 n_yx, vec3 centre)
{
    fill_event(ev, kind, t, p, c);
    ev->body = body;
    ev->partner = partner;
    ev->n = n_yx;
    ev->c = centre;
    if (kind == VR_EV_SUPPORT_BEGIN) ev->ncorner = region_corners(c, ev->corner);   /* for settle_on_support */
    return 1;
}

/* support begins or ends for either body of an inside pair */
static int support_change(vrOwner *o, vrEvent *ev, double t, const vrPair *p, const vrPose *pa,
                          const vrPose *pb, const vrContact *c, const vrApproach *ap)
{
    int side;
    for (side = 0; side < 2; side++) {
        int x = side ? p->b : p->a, y = side ? p->a : p->b;
        vec3 n_yx = side ? c->n : vec3_neg(c->n);
        int now, was;
        if (frozen(o->body[x])) continue;
        was = has_support(o->body[x], y);
        now = supports(o, o->body[x], o->body[y], n_yx, side ? pb : pa, c, ap, was == 2);
        if (was && !now) return support_event(ev, VR_EV_SUPPORT_END, t, p, c, x, y, n_yx, ap->region_centre);
        if (!was && now && o->body[x]->nsupport < VR_MAX_SUPPORTS)
            return support_event(ev, VR_EV_SUPPORT_BEGIN, t, p, c, x, y, n_yx, ap->region_centre);
    }
    return 0;
}

static int lost_support(vrOwner *o, vrEvent *ev, double t, const vrPair *p, const vrContact *c)
{
    if (has_support(o->body[p->a], p->b))
        return support_event(ev, VR_EV_SUPPORT_END, t, p, c, p->a, p->b, vec3_neg(c->n), c->pa);
    if (has_support(o->body[p->b], p->a))
        return support_event(ev, VR_EV_SUPPORT_END, t, p, c, p->b, p->a, c->n, c->pb);
    return 0;
}

/* events of a pair inside the envelope at t, by priority */
static int inside_events(vrOwner *o, vrEvent *ev, double t, const vrPair *p, const vrPose *pa,
                         const vrPose *pb, const vrContact *c)
{
    vrApproach ap;
    if (c->dist < -VR_PENETRATION_TOL) {
        fill_event(ev, VR_EV_PUSHOUT, t, p, c);
        ev->depth = -c->dist;
        ev->c = c->pa;
        return 1;
    }
    approach(o, p, t, pa, pb, c, &ap);
    if (ap.umin < -VR_V_EPS) {
        impulse_event(o, ev, VR_EV_CONTACT, t, p, c, &ap);
        return 1;
    }
    return support_change(o, ev, t, p, pa, pb, c, &ap);
}

/* An impulse event of kind at tau if the contact points approach there
 * faster than `faster` and the pair is not more than `deeper` inside:
 * an impact (any approach) and a touch share it. */
static int impulse_at(vrOwner *o, vrEvent *ev, vrPair *p, double tau, int kind, double faster, double deeper)
{
    vrPose pa, pb;
    vrContact c;
    vrApproach ap;
    event_query(o, p, tau, &pa, &pb, &c);
    if (c.npoints == 0 || c.dist < -deeper) return 0;
    approach(o, p, tau, &pa, &pb, &c, &ap);
    if (!(ap.umin < -faster)) return 0;
    impulse_event(o, ev, kind, tau, p, &c, &ap);
    return 1;
}

/* an impact at tau if the contact points approach there */
static int impact(vrOwner *o, vrEvent *ev, vrPair *p, double tau)
{
    return impulse_at(o, ev, p, tau, VR_EV_IMPACT, 0, INFINITY);
}

/* A pair inside the envelope at the last grid point found overlapping at
 * this one: free flight carried a contact point through the surface
 * between them (a body on a tip or an edge and not supported sinks
 * g h^2 / 2 in a step h under the force).  The moment the distance came
 * to 0 is found by bisection, as an impact's, and the contact answered
 * there if its points approach faster than v_eps (a push-out at t lifts
 * the body against the force: that much energy more).  A contact answered
 * at the step's start still touches there: its touch is found at once and
 * slow, and the push-out follows (an impulse would only start a run of
 * ever smaller ones). */
static int touch(vrOwner *o, vrEvent *ev, vrPair *p, double tau)
{
    return impulse_at(o, ev, p, tau, VR_EV_CONTACT, VR_V_EPS, VR_PENETRATION_TOL);
}

/* heap = 0 is the thesis's ablation: every pair looked at fully, every
 * step; an inside or support pair always is (its events need the contact) */
static int cheap_look_allowed(const vrOwner *o, const vrPair *p)
{
    return o->p.use_heap && !p->inside && !supported_pair(o, p->a, p->b);
}

/* a pair found outside at the grid point being looked at: its key (from
 * dist along n) is made by later_keys; 0 when keys are made at once */
static int put_off_key(vrOwner *o, int pi, double dist, vec3 n)
{
    struct vrLaterKey *k;
    if (!o->defer_keys || vrGrow((void **)&o->later, &o->latercap, o->nlater + 1, sizeof *o->later) != 0) return 0;
    k = &o->later[o->nlater++];
    k->pair = pi, k->dist = dist, k->n = n;
    return 1;
}

/* the walk's distance when it is clear of the envelope: outside, no event,
 * and a key from that distance (VR_QUICK_CLEAR below it: the canonical
 * distance a full look measures may be that much less; heap = 0 makes the
 * full look, and the two must agree) */
static int clear_by_walk(vrOwner *o, int pi, double t)
{
    vrPair *p = &o->pair[pi];
    vrBody *A = o->body[p->a], *B = o->body[p->b];
    vrPose pa, pb;
    double dist;
    vec3 n;
    if (!cheap_look_allowed(o, p) || is_sphere(A) || is_sphere(B)) return 0;
    vrBody_Pose(A, t, &pa);
    vrBody_Pose(B, t, &pb);
    if (vrContact_Quick(&A->shape, &pa, &B->shape, &pb, &p->cache, &dist, &n) != 0) return 0;
    o->checks++;
    if (dist <= o->p.d + VR_QUICK_CLEAR) return 0;
    p->t_check = t;
    if (!put_off_key(o, pi, dist - VR_QUICK_CLEAR, n))
        settle(o, pi, 0, pair_key(o, p, t, dist - VR_QUICK_CLEAR, n));
    return 1;
}

/* an event found so far comes before t */
static int impact_before(const vrOwner *o, double t) { return earliest_found(o) < t; }

/* the keys put off at grid point t: made, unless an impact
 * before t means they would be rolled back unused (in a heap of 1,000
 * bodies, most looks at a grid point with an impact come before it) */
static void later_keys(vrOwner *o, double t)
{
    int i, drop = impact_before(o, t);
    for (i = 0; i < o->nlater && !drop; i++) {
        const struct vrLaterKey *k = &o->later[i];
        settle(o, k->pair, 0, pair_key(o, &o->pair[k->pair], t, k->dist, k->n));
    }
    o->nlater = 0;
}

/* the gap between the bodies' bounding spheres about their centres at t (a
 * lower bound on their distance) and the unit direction from a's centre to
 * b's (zero when the centres meet) */
static double sphere_gap(const vrOwner *o, const vrPair *p, double t, vec3 *dir)
{
    const vrBody *A = o->body[p->a], *B = o->body[p->b];
    vec3 xa, xb, gap;
    double len;
    vrBody_Position(A, t, &xa);
    vrBody_Position(B, t, &xb);
    gap = vec3_sub(xb, xa);
    len = vec3_len(gap);
    *dir = len > 0 ? vec3_scale(gap, 1.0 / len) : vec3_zero();
    return len - A->r_out - B->r_out;
}

/* A cheap look first: the bounding spheres about the centres are a lower
 * bound on the distance.  When they are clear of the envelope, the full
 * query could only find the pair outside with nothing to do, and the
 * spheres' key (they do not change as the bodies turn) is as valid as the
 * full one, if earlier: the pair is looked at again then, unless a change
 * of either body comes first (in a room of a hundred, a body is hit every
 * fifth of a second).  Taking it only when it passed the frame's end cost
 * peer-random-100 4 % more instructions.  A support pair always gets the
 * full look (its support may have to end). */
static int clear_by_spheres(vrOwner *o, int pi, double t)
{
    vrPair *p = &o->pair[pi];
    vec3 dir;
    double gap, key;
    if (!cheap_look_allowed(o, p)) return 0;
    gap = sphere_gap(o, p, t, &dir);
    if (gap <= o->p.d || vec3_len2(dir) == 0) return 0;
    key = vrSchedule_SphereKey(o->body[p->a], o->body[p->b], t, gap, dir, o->p.d, &o->p.flight);
    if (!(key > t)) return 0;
    p->t_check = t;
    settle(o, pi, 0, key);
    return 1;
}

/* The axis (0..2) the unit normal n lies exactly along, when B is a
 * static unrotated box, so that n can be the normal of one of its faces;
 * -1 otherwise */
static int box_face_axis(const vrBody *B, vec3 n)
{
    int k;
    if (!B->is_static || B->shape.kind != VR_SHAPE_BOX) return -1;
    if (B->m.q0.w != 1 || B->m.q0.x != 0 || B->m.q0.y != 0 || B->m.q0.z != 0) return -1;
    for (k = 0; k < 3 && fabs(vec3_get(n, k)) != 1; k++)
        ;
    if (k == 3 || vec3_get(n, (k + 1) % 3) != 0 || vec3_get(n, (k + 2) % 3) != 0) return -1;
    return k;
}

/* x's footprint (a ball's centre) stays over the face of static box Y
 * whose normal is axis k, inside it by margin, until `until`.  px is x's
 * pose at t (a ball's is not needed). */
static int over_face(const vrBody *X, const vrPose *px, const vrBody *Y, int k, double t, double until,
                     double margin)
{
    vec3 lo, hi;
    double turn = 0;
    int j;
    vrBody_PathBox(X, t, until, &lo, &hi);
    if (!is_sphere(X)) {   /* its vertices now, carried along the path, and how far turning can carry them */
        vec3 vlo = px->p, vhi = px->p;
        for (j = 0; j < X->shape.poly->nv; j++) {
            vec3 w = vrPose_apply(px, X->shape.poly->vert[j]);
            vlo = vec3_min(vlo, w);
            vhi = vec3_max(vhi, w);
        }
        lo = vec3_add(vlo, vec3_sub(lo, px->p));
        hi = vec3_add(vhi, vec3_sub(hi, px->p));
        turn = X->m.spin * X->r_out * (until - t);
    }
    for (j = 0; j < 3; j++) {
        double at = vec3_get(Y->m.x0, j), half = vec3_get(Y->shape.half, j) - turn - margin;
        if (j != k && !(vec3_get(lo, j) - at > -half && vec3_get(hi, j) - at < half)) return 0;
    }
    return 1;
}

/* A ball sliding on a level table, or grazing a wall: a sphere in the
 * envelope of a static box with no rotation (its only support, if it has
 * one), the contact normal an axis, no velocity or acceleration along it,
 * and its centre over the face's inside (by 1e-9 m) until `until`.
 * Its distance then stays the same bits, its contact point lies exactly
 * beside its centre, and that point's normal velocity is exactly 0 however
 * it spins: every evaluation until then would find what this one found,
 * and none is made (with the heap; heap = 0 looks at every pair at every
 * step).  Anything that changes either body flags the pair, and its
 * evaluation starts afresh. */
static int quiet_slide(vrOwner *o, const vrPair *p, double t, double until, const vrContact *c)
{
    const vrBody *S = o->body[p->b], *B = o->body[p->a];
    int k;
    if (!is_sphere(S)) S = o->body[p->a], B = o->body[p->b];
    if (!is_sphere(S) || !vrBody_IsFree(S) || S->nsupport > 1 || (S->nsupport == 1 && S->support[0].partner != B->id))
        return 0;
    if ((k = box_face_axis(B, c->n)) < 0) return 0;
    if (vec3_get(S->m.v0, k) != 0 || vec3_get(S->m.a, k) != 0) return 0;
    return over_face(S, NULL, B, k, t, until, 1e-9);
}

/* A box, superquadric or ball sliding on a level static box (the table,
 * the floor), supported by it alone: every evaluation until `until` would
 * find it inside, supported, with no event, unless something changes
 * either body (which flags the pair) or its own motion brings a change.
 * This proves, from the query at t, that its motion cannot, and then no
 * evaluation is made until then (heap = 1 only; heap = 0 looks at every
 * pair at every step and finds nothing, so the runs keep the same bits).
 * Over [t, until] (length span), with the normal n along one of the box's
 * axes and x's footprint staying over the box's face:
 *  - x's spin changes at most |omega x L| / I_min a second, growing at
 *    most by e^(spin span) (torque-free: d omega/dt = -R I^-1 R^T (omega
 *    x L)); 4x for the integrator of asymmetric bodies;
 *  - so every point of x moves along n at most U = |n.v| + |n.a| span +
 *    w_perp R a second (w_perp: the spin's part off n; turning about n
 *    moves nothing along it), and at most H = U span in all: the contact
 *    points never approach or separate by v_eps / 2, the distance stays
 *    inside (0, d], and no vertex crosses the region's slab edge;
 *  - the region is x's near vertices turned about n and carried along,
 *    tilted at most w_perp span: the centre of mass stays inside it. */
#define QUIET_FACE_MARGIN 1e-6   /* m: x's footprint inside the box's face */

static int quiet_support(vrOwner *o, const vrPair *p, double t, double until, const vrPose *pa, const vrPose *pb,
                         const vrContact *c)
{
    int x_is_a = !frozen(o->body[p->a]);
    const vrBody *X = o->body[x_is_a ? p->a : p->b], *Y = o->body[x_is_a ? p->b : p->a];
    const vrPose *px = x_is_a ? pa : pb;
    vec3 n = x_is_a ? vec3_neg(c->n) : c->n, v, w, q;  /* n: from Y toward X */
    double span = until - t, top, w_perp, drift, U, H;
    int k, j;
    if (frozen(X) || X->nsupport != 1 || X->support[0].partner != Y->id || X->support[0].joint
        || c->npoints >= VR_REGION_MAX || (k = box_face_axis(Y, n)) < 0)
        return 0;
    if (2 * vec3_get(Y->shape.half, k) <= o->p.d + QUIET_FACE_MARGIN) return 0;  /* its far face stays out of the slab */
    vrBody_Velocity(X, t, &v);
    w = vrBody_Omega(X, px);
    drift = X->i_min > 0 ? vec3_len(vec3_cross(w, X->m.L)) / X->i_min * span * exp(X->m.spin * span) : 0;
    w_perp = vec3_len(vec3_madd(w, -vec3_dot(w, n), n)) + 4 * drift + 1e-12;
    U = fabs(vec3_dot(n, v)) + fabs(vec3_dot(n, X->m.a)) * span + w_perp * X->r_out;
    H = U * span + 1e-12;
    if (!(U <= 0.5 * VR_V_EPS) || !(c->dist - H > VR_PENETRATION_TOL) || !(c->dist + H < o->p.d - 1e-9)) return 0;
    if (!over_face(X, px, Y, k, t, until, QUIET_FACE_MARGIN)) return 0;
    if (is_sphere(X)) return 1;   /* its region is the point below its centre */
    top = vec3_dot(n, Y->m.x0) + vec3_get(Y->shape.half, k);
    for (j = 0; j < X->shape.poly->nv; j++) {
        double gap = vec3_dot(n, vrPose_apply(px, X->shape.poly->vert[j])) - top;
        if (fabs(gap - o->p.d) <= H + 1e-8) return 0;   /* it might enter or leave the region's slab */
    }
    q = vec3_madd(px->p, vec3_dot(vec3_sub(c->point[0], px->p), n), n);
    return vrRegion_Margin(c->point, c->npoints, n, q) > 2 * X->r_out * w_perp * span + 1e-8;
}

/* How far ahead of t an inside pair with no event at t is proved quiet:
 * to the frame's end, and then QUIET_AHEAD seconds past it when the proof
 * holds that far (a box or a ball sliding across a table would otherwise
 * be looked at again at the start of every frame: in Office, a tenth of
 * heap on's instructions; longer or shorter horizons, or tries at a part
 * of the frame when the whole fails, cost more than they saved there).
 * -INFINITY when not quiet.  Nothing at a frame's end needs the pair
 * looked at: rest and support are decided from the bodies' states, and
 * whatever changes either body flags the pair. */
#define QUIET_AHEAD 0.1   /* s */

static int quiet_to(vrOwner *o, const vrPair *p, double t, double until, const vrPose *pa, const vrPose *pb,
                    const vrContact *c)
{
    return quiet_slide(o, p, t, until, c) || quiet_support(o, p, t, until, pa, pb, c);
}

static double quiet_horizon(vrOwner *o, const vrPair *p, double t, const vrPose *pa, const vrPose *pb,
                            const vrContact *c)
{
    double T = o->bp.T;
    if (!quiet_to(o, p, t, T, pa, pb, c)) return -INFINITY;
    return quiet_to(o, p, t, T + QUIET_AHEAD, pa, pb, c) ? T + QUIET_AHEAD : T;
}

/* Evaluates pair pi at t.  t_prev is the previous grid point (t_prev == t at
 * a span start, where no step can be bisected).  Returns 1 with *ev when the
 * pair has an event. */
static int evaluate(vrOwner *o, int pi, double t, double t_prev, vrEvent *ev)
{
    vrPair *p = &o->pair[pi];
    vrPose pa, pb;
    vrContact c;
    int was_inside;
    double wanted = earliest_found(o);   /* events found here so far: later ones are dropped */
    remember(o, pi, t);
    p->quiet_until = -INFINITY;
    if (clear_by_spheres(o, pi, t) || clear_by_walk(o, pi, t)) return 0;
    query(o, p, t, 1, &pa, &pb, &c);   /* the region is only made inside the envelope */
    p->t_check = t;
    if (c.dist > o->p.d) {
        was_inside = p->inside;
        if (was_inside || t == t_prev || !put_off_key(o, pi, c.dist, c.n))
            settle(o, pi, 0, pair_key(o, p, t, c.dist, c.n));
        return was_inside || t == t_prev ? lost_support(o, ev, t, p, &c) : 0;
    }
    if (!p->inside && t > t_prev) {
        double at = bisect(o, p, t_prev, t, &c, o->p.d, wanted);
        if (isnan(at) || impact(o, ev, p, at)) {
            settle(o, pi, p->inside, t);  /* due again at once: it is rolled back or re-evaluated */
            return !isnan(at);
        }
    }
    was_inside = p->inside;
    settle(o, pi, 1, t);
    for_events(o, p, t, &pa, &pb, &c);   /* the query above had the region: event_query's */
    if (was_inside && t > t_prev && c.dist < -VR_PENETRATION_TOL) {
        double at = bisect(o, p, t_prev, t, &c, 0, wanted);
        if (isnan(at)) return 0;         /* after an event found here: rolled back */
        if (touch(o, ev, p, at)) return 1; /* due again at once, as after an impact */
    }
    if (inside_events(o, ev, t, p, &pa, &pb, &c)) return 1;
    if (o->p.use_heap) p->quiet_until = quiet_horizon(o, p, t, &pa, &pb, &c);
    return 0;
}

/* ---- the look-ahead ------------------------------------------------------------ */

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

static int cmp_events(const void *x, const void *y)
{
    const vrEvent *a = x, *b = y;
    return vrEvent_Before(a, b) ? -1 : vrEvent_Before(b, a) ? 1 : 0;
}

/* keeps the events found at one instant; returns the first */
static int take_first(vrOwner *o, double at, vrEvent *ev)
{
    int i;
    qsort(o->found, (size_t)o->nfound, sizeof *o->found, cmp_events);
    *ev = o->found[0];
    o->npending = 0;
    for (i = 0; i < o->nfound; i++)
        if (o->found[i].t == at) push_event(&o->pending, &o->npending, &o->pendcap, &o->found[i]);
    o->pending_t = at;
    return 1;
}

void vrOwner_SetProgress(vrOwner *o, void (*fn)(void *ctx), void *ctx)
{
    o->progress = fn;
    o->progress_ctx = ctx;
}

static void evaluate_into_found(vrOwner *o, int pi, double t, double t_prev, int keep)
{
    vrEvent ev;
    if (!o->pair[pi].scheduled) return;
    if (o->progress && (o->checks & 255) == 0) o->progress(o->progress_ctx);
    if (evaluate(o, pi, t, t_prev, &ev) && keep) push_event(&o->found, &o->nfound, &o->foundcap, &ev);
}

/* k = 0: pairs whose bodies changed are evaluated at the span start; events
 * still pending there (found at this instant, bodies unchanged) stand */
static void span_start(vrOwner *o, double ts, int allow)
{
    int i;
    for (i = 0; i < o->flagged.n; i++) {
        int pi = o->flagged.v[i];
        o->pair[pi].flagged = 0;
        evaluate_into_found(o, pi, ts, ts, allow);
    }
    o->flagged.n = 0;
    if (allow && o->pending_t == ts)
        for (i = 0; i < o->npending; i++) push_event(&o->found, &o->nfound, &o->foundcap, &o->pending[i]);
    o->npending = 0;
}

static void collect_due(vrOwner *o, double t)
{
    double key;
    int id;
    o->due.n = o->due_inside.n = 0;
    if (!o->p.use_heap) {
        for (id = 0; id < o->npair; id++)
            if (o->pair[id].scheduled) list_push(o->pair[id].inside ? &o->due_inside : &o->due, id);
        return;
    }
    /* the order pairs are evaluated in at one grid point does not matter:
     * they do not touch each other, and events are sorted afterwards */
    for (id = 0; id < o->active.n; id++)
        if (!(o->pair[o->active.v[id]].quiet_until >= t)) list_push(&o->due_inside, o->active.v[id]);
    while ((id = vrHeap_Top(&o->heap, &key)) >= 0 && key <= t) {
        vrHeap_Pop(&o->heap);
        o->heap_pops++;
        if (!(o->hot[id] & HOT_DORMANT) && pair_apart(o, id)) make_dormant(o, id);
        if (!(o->hot[id] & HOT_DORMANT)) list_push(&o->due, id);
    }
}

/* may inside pair pi overlap at t (so that it may touch before t)?  The
 * walk decides: the canonical distance may lie up to 1e-6 m below it
 * (contact.h), so a walk within VR_QUICK_CLEAR of touching says maybe. */
static int overlaps(vrOwner *o, int pi, double t)
{
    return within(o, &o->pair[pi], t, VR_QUICK_CLEAR, t, t, NULL);
}

int vrOwner_FirstEvent(vrOwner *o, const vrGrid *g, int allow_instant, vrEvent *ev)
{
    long k = 1;
    int i;
    o->nfound = 0;
    if (!(g->T == o->bp.T)) new_frame(o, g);
    o->bp.t0 = g->t0;
    span_start(o, g->t0, allow_instant);
    if (o->nfound) return take_first(o, g->t0, ev);
    while (k <= g->n) {
        double t = vrGrid_Point(g, k), key;
        collect_due(o, t);
        o->defer_keys = 1;
        for (i = 0; i < o->due.n; i++) evaluate_into_found(o, o->due.v[i], t, vrGrid_Point(g, k - 1), 1);
        o->defer_keys = 0;
        /* A pair inside the envelope has its events at grid points only,
         * unless it overlaps there (touch): after an event bisected to
         * before t the others could only be rolled back (in a heap of
         * bodies, most of the look-ahead's work), so only overlapping ones
         * are looked at, as a worker without that event would */
        for (i = 0; i < o->due_inside.n; i++)
            if (!impact_before(o, t) || overlaps(o, o->due_inside.v[i], t))
                evaluate_into_found(o, o->due_inside.v[i], t, vrGrid_Point(g, k - 1), 1);
        later_keys(o, t);
        if (o->nfound) return take_first(o, t, ev);
        if (!o->p.use_heap || o->active.n > 0) { k++; continue; }
        if (vrHeap_Top(&o->heap, &key) < 0) break;
        k = k + 1 > vrSchedule_FirstPointAtOrAfter(g, key) ? k + 1 : vrSchedule_FirstPointAtOrAfter(g, key);
    }
    return 0;
}

/* ---- several supports at once ---------------------------------------------------- */

static int candidate(vrOwner *o, const vrPair *p, int side, double t, vrCandidates *out)
{
    int x = side ? p->b : p->a, y = side ? p->a : p->b;
    vrBody *Y = o->body[y];
    vec3 g = o->p.flight.accel, n_yx;
    vrPose pa, pb, py;
    vrContact c;
    vrApproach ap;
    vrCandidate *k;
    if (!(frozen(Y) || Y->nsupport > 0) || vec3_len2(g) == 0) return 0;
    event_query(o, (vrPair *)p, t, &pa, &pb, &c);
    n_yx = side ? c.n : vec3_neg(c.n);
    if (c.npoints == 0 || vec3_dot(g, n_yx) > -1e-6 * vec3_len(g)) return 0;
    approach(o, p, t, &pa, &pb, &c, &ap);
    if (ap.umin < -o->v_rest || ap.umax > o->v_rest) return 0;
    k = vrCandidates_Add(out);
    if (!k) return -1;
    k->body = x;
    k->partner = y;
    k->n = n_yx;
    py = side ? pa : pb;
    k->partner_velocity = vrBody_PointVelocity(Y, t, &py, ap.region_centre);
    k->npoints = c.npoints;
    memcpy(k->point, c.point, (size_t)c.npoints * sizeof c.point[0]);
    return 0;
}

/* (the order they are found in does not matter: rest.c sorts them by body
 * and partner; with the heap the pairs inside are the active list) */
int vrOwner_SupportCandidates(vrOwner *o, double t, const unsigned char *want, int nwant, vrCandidates *out)
{
    int i, side, n = o->p.use_heap ? o->active.n : o->npair;
    for (i = 0; i < n; i++) {
        const vrPair *p = &o->pair[o->p.use_heap ? o->active.v[i] : i];
        if (!p->inside || !p->scheduled) continue;
        for (side = 0; side < 2; side++) {
            int x = side ? p->b : p->a;
            if (x < nwant && want[x] && candidate(o, p, side, t, out) != 0) return -1;
        }
    }
    return 0;
}

/* ---- start-up overlap check ---------------------------------------------------- */

int vrOwner_Overlapping(vrOwner *o, double t, double tol, const int *ids, int nids, int (*out)[2], int max)
{
    unsigned char *mine = calloc((size_t)o->bodycap + 1, 1);
    int i, n = 0;
    if (!mine) return -1;
    for (i = 0; i < nids; i++)
        if (ids[i] >= 0 && ids[i] < o->bodycap) mine[ids[i]] = 1;
    sort_pairs(o, &o->flagged);
    for (i = 0; i < o->flagged.n; i++) {
        vrPair *p = &o->pair[o->flagged.v[i]];
        vrPose pa, pb;
        vrContact c;
        vec3 dir;
        if (!(mine[p->a] || mine[p->b])) continue;
        if (!p->scheduled || sphere_gap(o, p, t, &dir) > tol) continue;   /* bounding spheres apart: no overlap */
        query(o, p, t, 0, &pa, &pb, &c);
        if (c.dist < -tol) {
            if (n < max) { out[n][0] = p->a; out[n][1] = p->b; }
            n++;
        }
    }
    free(mine);
    return n;
}

int vrOwner_Respond(vrOwner *o, const vrEvent *ev, vrUpdate *up)
{
    return vrRespond(o->body, o->responder, &o->p.flight, ev, up);
}

void vrOwner_Stats(const vrOwner *o, vrOwnerStats *s)
{
    s->checks = o->checks;
    s->heap_pops = o->heap_pops;
    s->response = vrResponder_Stats(o->responder);
}
