/* look_log.c — what the look-ahead learnt past the present, and how it is
 * taken back (thesis 3.4.2: look-ahead is speculative).  Every look at a
 * pair is logged with the pair's state before it; an answered event takes
 * back the looks past it.
 *
 * Kept looks (keep_looks = 1).  The grid is the contact step's (schedule.h)
 * and a look's bracket is its pair's own (lookahead.c's evaluate), so a
 * look at a pair whose bodies an event did not change is the look a walk
 * after the event would make: it is kept, with its event, and the walk
 * after the event starts where the looks stopped (among a thousand bodies,
 * half of all looks were made again after each impact).  Taken back: the
 * answered pair's, those that stopped short (vrLook_Redo), and those of
 * the bodies the answer changes (vrOwner_TakeBackChanged, from
 * vrOwner_BodiesChanged).  Whatever is kept, the outcome is the one with
 * every look past the event taken back: the tests run keep_looks on and
 * off.  A pair's walk cache is logged too: where a walk starts decides the
 * last bits of a distance in a tie (parallel faces), so a look made again
 * must start where the first one did.
 *   vrLook_Remember, restore, vrOwner_Advance   the log; everything back
 *   mark_pair, marks_ready, take_back_marked    some pairs' looks back
 *   vrOwner_AdvanceTo, vrOwner_TakeBackChanged, vrLook_Redo */
#include <string.h>
#include "owner_state.h"
#include "grow.h"

void vrLook_Remember(vrOwner *o, int pi, double at)
{
    vrUndo *u;
    if (vrGrow((void **)&o->undo, &o->undocap, o->nundo + 1, sizeof *o->undo) != 0) return;
    u = &o->undo[o->nundo++];
    u->pair = pi;
    u->at = at;
    u->inside = o->pair[pi].inside;
    u->near = o->pair[pi].near;
    u->overlap = o->pair[pi].overlap;
    u->t_check = o->pair[pi].t_check;
    u->looked = o->pair[pi].looked;
    u->key = o->pair[pi].key;
    u->quiet_until = o->pair[pi].quiet_until;
    u->cache = o->pair[pi].cache;
}

static void restore(vrOwner *o, const vrUndo *u)
{
    vrPair *p = &o->pair[u->pair];
    p->t_check = u->t_check;
    p->looked = u->looked;
    p->quiet_until = u->quiet_until;
    p->near = u->near;
    p->overlap = u->overlap;
    p->cache = u->cache;
    vrPair_Settle(o, u->pair, u->inside, u->key);
}

void vrOwner_Advance(vrOwner *o, double t)
{
    int i;
    for (i = o->nundo - 1; i >= 0; i--)
        if (o->undo[i].at > t) restore(o, &o->undo[i]);
    o->nundo = o->nkept = o->redo.n = 0;
    if (o->pending_t != t) o->npending = 0;
}

/* a pair whose looks are to be taken back */
static void mark_pair(vrOwner *o, int pi)
{
    if (o->mark[pi]) return;
    o->mark[pi] = 1;
    if (vrIntList_Push(&o->marked, pi) != 0) o->mark[pi] = 2;   /* no memory: every look goes */
}

static int marks_ready(vrOwner *o)
{
    int old = o->markcap;
    if (vrGrow((void **)&o->mark, &o->markcap, o->npair, 1) != 0) return 0;
    if (o->markcap > old) memset(o->mark + old, 0, (size_t)(o->markcap - old));
    return 1;
}

/* the looks after t of the marked pairs taken back, the others' kept,
 * those up to t forgotten */
static void take_back_marked(vrOwner *o, double t)
{
    int i, k = 0, all = 0;
    for (i = 0; i < o->marked.n; i++) all |= o->mark[o->marked.v[i]] == 2;
    if (all) o->nkept = 0;
    for (i = o->nundo - 1; i >= 0; i--)
        if (o->undo[i].at > t && (all || o->mark[o->undo[i].pair])) restore(o, &o->undo[i]);
    for (i = 0; i < o->nundo && !all; i++)
        if (o->undo[i].at > t && !o->mark[o->undo[i].pair]) o->undo[k++] = o->undo[i];
    o->nundo = k;
    for (i = 0; i < o->marked.n; i++) o->mark[o->marked.v[i]] = 0;
    o->marked.n = 0;
}

void vrOwner_AdvanceTo(vrOwner *o, const vrEvent *ev)
{
    int i, k = 0;
    if (!o->p.keep_looks || o->keep_lost || !marks_ready(o)) {
        vrOwner_Advance(o, ev->t);
        o->keep_lost = 0;
        return;
    }
    for (i = 0; i < o->redo.n; i++) mark_pair(o, o->redo.v[i]);
    for (i = 0; i < o->nundo; i++)
        if (o->pair[o->undo[i].pair].order == ev->order) mark_pair(o, o->undo[i].pair);
    take_back_marked(o, ev->t);
    for (i = 0; i < o->nkept; i++)
        if (o->kept[i].ev.order != ev->order) o->kept[k++] = o->kept[i];
    o->nkept = k;
    o->redo.n = 0;
    if (o->pending_t != ev->t) o->npending = 0;
}

static int involves(int a, int b, const int *ids, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (a == ids[i] || b == ids[i]) return 1;
    return 0;
}

void vrOwner_TakeBackChanged(vrOwner *o, const int *ids, int n)
{
    int i, k = 0;
    if (o->nundo == 0 && o->nkept == 0) return;
    if (!marks_ready(o)) {
        vrOwner_Advance(o, -INFINITY);
        return;
    }
    for (i = 0; i < o->nundo; i++) {
        const vrPair *p = &o->pair[o->undo[i].pair];
        if (involves(p->a, p->b, ids, n)) mark_pair(o, o->undo[i].pair);
    }
    take_back_marked(o, -INFINITY);
    for (i = 0; i < o->nkept; i++)
        if (!involves(o->kept[i].ev.a, o->kept[i].ev.b, ids, n)) o->kept[k++] = o->kept[i];
    o->nkept = k;
}

void vrLook_Redo(vrOwner *o, int pi)
{
    if (vrIntList_Push(&o->redo, pi) != 0) o->keep_lost = 1;
}
