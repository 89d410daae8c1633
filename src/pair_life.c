/* pair_life.c — lazy pairs (SPEC 10: "memory grows with the objects and the
 * pairs that are close").  A lazy owner holds the pair of every two of its
 * bodies, not both static, but keeps a record (vrPair, its lists, its map
 * entry) only while the bodies' boxes meet:
 *   made     when boxes meet: a new owner's pairs from the poses (settled as
 *            vrOwner_AddPairAt settles them), a new body's at the next look
 *            at the poses, and, within a run, the broadphase's meetings at a
 *            frame start or after an event (flagged, as a dormant pair woken)
 *   dropped  at a frame start, when the boxes are apart and the pair has
 *            nothing in hand: outside the envelope, not touching, not
 *            flagged, not an island's, no look to undo.
 * A pair without a record is one the eager owner would hold dormant or keyed
 * in its heap: apart all frame, it is more than d apart at every grid point,
 * where a look could only find it outside with nothing to do; the first look
 * that matters (within d) comes after its boxes met, so it finds a record
 * made then.  A record carries nothing a result depends on across its
 * absence: the walk cache and the keys only say where and when to look (the
 * runs of heap = 0 and of any worker count agree with these).
 * A worker's lazy owner holds only its share of the pairs (the deal,
 * parallel/distribution.c): `mine` says which, and every path that makes a
 * record asks it (owns), so a worker makes records of its own pairs only;
 * the serial owner's filter is none, every pair.
 *   vrOwner_SetLazy, vrOwner_SetFilter, owns
 *   vrOwner_AddBody, vrOwner_MakePairsAt, vrOwner_MakeFresh
 *   vrPair_Meet, vrOwner_MeetAll      a record made on meeting
 *   vrOwner_DropApart, drop            records that go */
#include <stdlib.h>
#include "owner_state.h"

void vrOwner_SetLazy(vrOwner *o, int lazy) { o->lazy = lazy; }

void vrOwner_SetFilter(vrOwner *o, int (*mine)(const void *ctx, int a, int b), const void *ctx)
{
    o->mine = mine;
    o->mine_ctx = ctx;
}

static int both_static(const vrOwner *o, int x, int y) { return o->body[x]->is_static && o->body[y]->is_static; }

/* the pair of x and y is one this owner holds: not both static, and its own */
static int owns(const vrOwner *o, int x, int y)
{
    if (both_static(o, x, y)) return 0;
    return !o->mine || o->mine(o->mine_ctx, x < y ? x : y, x < y ? y : x);
}

int vrOwner_AddBody(vrOwner *o, int id, vrBody *b)
{
    if (vrOwner_HoldBody(o, id, b) != 0) return -1;
    o->fresh[id] = 1;
    o->any_fresh = 1;
    return 0;
}

typedef struct vrMaker { vrOwner *o; double t; const unsigned char *pending; int all_flagged, failed; } vrMaker;

static void make_one(void *ctx, int x, int y)
{
    vrMaker *m = ctx;
    int flagged = m->all_flagged || (m->pending && (m->pending[x] || m->pending[y]));
    if (m->failed || !owns(m->o, x, y) || vrPairMap_Find(&m->o->bp.map, vrPair_Order(x, y)) >= 0) return;
    if (vrOwner_AddPairAt(m->o, x, y, m->t, flagged) != 0) m->failed = 1;
}

static int make_at(vrOwner *o, vrMaker *m, const unsigned char *want)
{
    int i;
    if (vrBroad_MeetAt(&o->bp, o->body, o->bodycap, m->t, want, make_one, m) != 0 || m->failed) return -1;
    for (i = 0; i < o->bodycap; i++) o->fresh[i] = 0;
    o->any_fresh = 0;
    return 0;
}

int vrOwner_MakePairsAt(vrOwner *o, double t, const unsigned char *pending)
{
    vrMaker m = {0};
    m.o = o, m.t = t, m.pending = pending;
    return make_at(o, &m, NULL);
}

/* the fresh bodies' pairs that could be within d now, flagged as
 * vrOwner_AddPair flags them; the others meet at the frame start's sweep */
int vrOwner_MakeFresh(vrOwner *o, double t)
{
    vrMaker m = {0};
    if (!o->any_fresh) return 0;
    m.o = o, m.t = t, m.all_flagged = 1;
    return make_at(o, &m, o->fresh);
}

int vrPair_Meet(vrOwner *o, int x, int y)
{
    long long order = vrPair_Order(x, y);
    int pi = vrPairMap_Find(&o->bp.map, order);
    if (pi >= 0 || !o->lazy || !owns(o, x, y)) return pi;
    if (vrOwner_AddPairAt(o, x < y ? x : y, x < y ? y : x, 0, 1) != 0) {
        o->awake_lost = 1;     /* no memory: the next events look at every record */
        return -1;
    }
    return vrPairMap_Find(&o->bp.map, order);
}

int vrOwner_MeetAll(vrOwner *o, int id)
{
    int y;
    for (y = 0; o->lazy && y < o->bodycap; y++)
        if (y != id && o->body[y] && owns(o, id, y) && vrPair_Meet(o, id, y) < 0) return -1;
    return 0;
}

/* pi out of a body's list (body_pairs and body_partners go together) */
static void unlist(vrIntList *l, vrIntList *partner, int pi)
{
    int j;
    for (j = 0; j < l->n; j++)
        if (l->v[j] == pi) {
            l->v[j] = l->v[--l->n];
            if (partner) partner->v[j] = partner->v[--partner->n];
            return;
        }
}

static void drop(vrOwner *o, int pi)
{
    vrPair *p = &o->pair[pi];
    if (vrIntList_Push(&o->free_pairs, pi) != 0) return;   /* no memory: the record stays */
    unlist(&o->body_pairs[p->a], &o->body_partners[p->a], pi);
    unlist(&o->body_pairs[p->b], &o->body_partners[p->b], pi);
    if (o->hot[pi] & HOT_LISTED_A) unlist(&o->body_awake[p->a], NULL, pi);
    if (o->hot[pi] & HOT_LISTED_B) unlist(&o->body_awake[p->b], NULL, pi);
    vrHeap_Remove(&o->heap, pi);
    vrPairMap_Remove(&o->bp.map, p->order);
    o->hot[pi] = 0;
    p->a = p->b = -1;
    p->scheduled = p->inside = p->flagged = 0;
}

/* A pair with something in hand keeps its record: in the envelope or
 * touching, flagged, an island's (its approach stopped until the next
 * island step), or with a look Advance may undo */
static int droppable(vrOwner *o, int pi)
{
    const vrPair *p = &o->pair[pi];
    if (vrPair_Free(p) || p->inside || p->near || p->overlap || p->flagged || p->active >= 0) return 0;
    if (vrPair_InIsland(o, p)) return 0;
    return vrBroad_Apart(vrBroad_Box(&o->bp, o->body, p->a), vrBroad_Box(&o->bp, o->body, p->b));
}

void vrOwner_DropApart(vrOwner *o)
{
    int i;
    if (!o->lazy || o->nundo > 0 || o->npending > 0) return;
    for (i = 0; i < o->npair; i++)
        if (droppable(o, i)) drop(o, i);
}
