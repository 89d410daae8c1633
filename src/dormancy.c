/* dormancy.c — pairs that cannot meet before the frame ends sleep: the
 * broadphase's boxes (broadphase.c) tell which; a dormant pair is out of
 * the heap and looked at again only when a box of its bodies meets the
 * other's (a new frame, or an event that changes one of them).  Among a
 * thousand bodies nearly every pair is dormant.
 *   apart_from, apart, pair_apart   the test
 *   make_dormant, wake, wake_*      the two moves
 *   vrOwner_NewFrame                new boxes for a frame, the pairs they wake
 *   changed_*, vrOwner_BodiesChanged an event's bodies: their pairs anew */
#include "owner_state.h"

static int event_involves(const vrEvent *ev, const int *ids, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (ev->a == ids[i] || ev->b == ids[i]) return 1;
    return 0;
}

/* pair pi of bodies x and y cannot come within d before the frame ends:
 * it can be dormant (with heap = 1; never while in the envelope) */
static int apart_from(vrOwner *o, int pi, const vrBox *box_x, int x, int y)
{
    (void)x;
    if (!o->p.use_heap || (o->hot[pi] & HOT_INSIDE)) return 0;
    return vrBroad_Apart(box_x, vrBroad_Box(&o->bp, o->body, y));
}

static int apart(vrOwner *o, int pi, int x, int y) { return apart_from(o, pi, vrBroad_Box(&o->bp, o->body, x), x, y); }

int vrPair_Apart(vrOwner *o, int pi) { return apart(o, pi, o->pair[pi].a, o->pair[pi].b); }

/* out of the heap too: a dormant pair's key is for nothing (the heap stays
 * the size of the pairs that could meet) */
void vrPair_MakeDormant(vrOwner *o, int pi)
{
    if (o->hot[pi] & HOT_DORMANT) return;     /* out already: no look at the heap */
    o->hot[pi] |= HOT_DORMANT;
    vrHeap_Remove(&o->heap, pi);
}

static void wake(vrOwner *o, int pi)
{
    if (!(o->hot[pi] & HOT_DORMANT)) return;
    o->hot[pi] &= (unsigned char)~HOT_DORMANT;
    vrPair_ListAwake(o, pi);
    vrPair_Flag(o, pi);
}

static void wake_pairs_of(vrOwner *o, int id)
{
    int i;
    for (i = 0; i < o->body_pairs[id].n; i++) wake(o, o->body_pairs[id].v[i]);
}

/* (a lazy owner makes the record of a pair met for the first time, flagged
 * as a woken one: pair_life.c) */
static void wake_met(void *ctx, int x, int y)
{
    int pi = vrPair_Meet(ctx, x, y);
    if (pi >= 0) wake(ctx, pi);
}

static void wake_boxless(void *ctx, int id)
{
    vrOwner_MeetAll(ctx, id);
    wake_pairs_of(ctx, id);
}

/* A new frame: new boxes, and the dormant pairs whose boxes now overlap are
 * woken, to be evaluated at its start (the broadphase sweeps the boxes, so
 * the pairs that stay apart, nearly all of them among a thousand bodies,
 * are not looked at).  Without the map or memory, every pair wakes.
 * `hit` is per frame (rest.c): a worker's copies must forget it as the
 * shell's bodies do, or an update that is no impulse (a push-out, a
 * support change) carries an old hit back to the shell. */
int vrOwner_NewFrame(vrOwner *o, const vrGrid *g)
{
    int i;
    for (i = 0; i < o->bodycap; i++)
        if (o->body[i]) o->body[i]->hit = 0;
    if (o->lazy && !o->bp.map.cap && vrPairMap_Reset(&o->bp.map, 16) != 0) return -1;
    if (!o->bp.map.cap || vrBroad_NewFrame(&o->bp, o->body, o->bodycap, g->t0, g->frame_T, wake_met, wake_boxless, o) != 0) {
        if (o->lazy) return -1;             /* no records for the pairs that meet */
        for (i = 0; i < o->npair; i++) wake(o, i);
        return 0;
    }
    vrOwner_DropApart(o);
    return 0;
}

/* body id changed: each key of its pairs was for the old motion, so a
 * pair is evaluated anew, or dormant (apart from the other's box) */
static void changed_pair(vrOwner *o, int pi, const vrBox *box, int id, int other)
{
    if (apart_from(o, pi, box, id, other)) {
        vrPair_MakeDormant(o, pi);
    } else {
        o->hot[pi] &= (unsigned char)~HOT_DORMANT;
        vrPair_ListAwake(o, pi);
        vrPair_Flag(o, pi);
    }
}

/* every pair of id, one by one; a lazy owner makes those without a record
 * that could be within d now at its next look at the poses (the frame
 * start that follows, where bodies come and go, meets the others) */
static void changed_all(vrOwner *o, int id, const vrBox *box)
{
    const vrIntList *l = &o->body_pairs[id], *partner = &o->body_partners[id];
    int j;
    for (j = 0; j < l->n; j++) changed_pair(o, l->v[j], box, id, partner->v[j]);
    if (o->lazy) o->fresh[id] = 1, o->any_fresh = 1;
}

typedef struct vrChanged { vrOwner *o; int id; const vrBox *box; } vrChanged;

/* a body whose box may meet the changed one's: their pair, if dormant and
 * no longer apart, wakes (an awake one was seen in the awake list) */
static void changed_meets(void *ctx, int y)
{
    vrChanged *c = ctx;
    vrOwner *o = c->o;
    int x = c->id, pi = vrPairMap_Find(&o->bp.map, vrPair_Order(x, y));
    if (pi < 0 && o->lazy && !vrBroad_Apart(c->box, vrBroad_Box(&o->bp, o->body, y))) pi = vrPair_Meet(o, x, y);
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
    vrOwner_TakeBackChanged(o, ids, n);    /* their looks past the event first */
    for (i = 0; i < n; i++)
        if (ids[i] < o->bodycap && o->body[ids[i]]) vrBroad_Rebox(&o->bp, o->body, ids[i]);
    near = o->bp.map.cap && !o->awake_lost && vrBroad_CanMeet(&o->bp);
    for (i = 0; i < n; i++) {
        int id = ids[i], now_frozen;
        const vrBox *box;
        if (id >= o->bodycap || !o->body[id]) continue;
        /* a pair's scheduling only changes when a body freezes or thaws */
        now_frozen = vrBody_Frozen(o->body[id]);
        if (o->was_frozen[id] != now_frozen)
            for (j = 0; j < o->body_pairs[id].n; j++) vrPair_UpdateSchedule(o, o->body_pairs[id].v[j]);
        o->was_frozen[id] = (unsigned char)now_frozen;
        box = vrBroad_Box(&o->bp, o->body, id);
        if (near) changed_near(o, id, box);
        else changed_all(o, id, box);
    }
    for (i = 0; i < o->npending; i++)
        if (!event_involves(&o->pending[i], ids, n)) o->pending[k++] = o->pending[i];
    o->npending = k;
}
