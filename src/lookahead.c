/* lookahead.c — a pair owner's answer to the coordinator's question
 * (thesis 3.4.2; ARCHITECTURE "the loop, once"): for a span [t0, T] on
 * the coordinator's grid it visits the grid points in order; at each it
 * evaluates the pairs that are due (all of them with heap = 0; with the
 * heap, those whose expected earliest event time has come, thesis
 * 3.3.1.2), and stops at the first grid point that has events.  An impact
 * found at a grid point is moved back to its moment by bisection of the
 * step (bisect.c).  Pairs are evaluated with the same operations whatever
 * the heap mode or the owner, so the outcome is the same; the heap only
 * skips checks that cannot matter.
 * Look-ahead is speculative: what it learnt past the first event of all
 * is taken back (look_log.c), or with keep_looks kept for the pairs the
 * answer does not change.
 *   kept_events_at, kept_look   what a walk before this one found and looked at
 *   vrOwner_PutOffKey, later_keys   keys made once no earlier impact drops them
 *   evaluate                    one pair at one grid point: cheap looks,
 *                               query, bisection, events, quiet proofs
 *   take_first, span_start, collect_due, vrOwner_FirstEvent   the grid walk */
#include <stdlib.h>
#include "owner_state.h"
#include "grow.h"

/* The events kept for points after t stay; with take, those kept for
 * point t join the events found there.  At a span start t (take = 0) those
 * kept for t or before go: an event at the start itself is a pending one
 * (span_start), and the walk visits its points in order. */
static void kept_events_at(vrOwner *o, double t, int take)
{
    int i, k = 0;
    for (i = 0; i < o->nkept; i++) {
        if (o->kept[i].point > t) o->kept[k++] = o->kept[i];
        else if (take && o->kept[i].point == t) vrEvents_Push(&o->found, &o->nfound, &o->foundcap, &o->kept[i].ev);
    }
    o->nkept = k;
}

/* the time of the first event found so far at this grid point */
static double earliest_found(const vrOwner *o)
{
    double t = INFINITY;
    int i;
    for (i = 0; i < o->nfound; i++) t = vr_min(t, o->found[i].t);
    return t;
}

/* a pair found outside at the grid point being looked at: its key (from
 * dist along n) is made by later_keys; 0 when keys are made at once */
int vrOwner_PutOffKey(vrOwner *o, int pi, double dist, vec3 n)
{
    struct vrLaterKey *k;
    if (!o->defer_keys || vrGrow((void **)&o->later, &o->latercap, o->nlater + 1, sizeof *o->later) != 0) return 0;
    k = &o->later[o->nlater++];
    k->pair = pi, k->dist = dist, k->n = n;
    return 1;
}

/* an event found so far comes before t */
static int impact_before(const vrOwner *o, double t) { return earliest_found(o) < t; }

/* the keys put off at grid point t: made, unless an impact
 * before t means they would be rolled back unused (among many bodies,
 * most looks at a grid point with an impact come before it) */
static void later_keys(vrOwner *o, double t)
{
    int i, drop = impact_before(o, t) && !o->p.keep_looks;   /* kept looks keep their keys */
    for (i = 0; i < o->nlater && !drop; i++) {
        const struct vrLaterKey *k = &o->later[i];
        vrPair_Settle(o, k->pair, 0, vrPair_Key(o, &o->pair[k->pair], t, k->dist, k->n));
    }
    o->nlater = 0;
}

/* Evaluates pair pi at t.  t_prev is the anchored grid point before t, or
 * t itself at a span start, where no step can be bisected.  The bracket
 * starts there, or where either body's motion starts if later (an event
 * changed it within the step): so it is the pair's own, not the span's,
 * and the same whatever other events started the span.  Returns 1 with
 * *ev when the pair has an event. */
static int evaluate(vrOwner *o, int pi, double t, double t_prev, vrEvent *ev)
{
    vrPair *p = &o->pair[pi];
    vrPose pa, pb;
    vrContact c;
    int was_inside, was_near, was_overlap;
    double wanted = earliest_found(o);   /* events found here so far: later ones are dropped */
    t_prev = vr_max(t_prev, vr_max(o->body[p->a]->m.t0, o->body[p->b]->m.t0));
    vrLook_Remember(o, pi, t);
    p->looked = t;
    p->quiet_until = -INFINITY;
    if (vrPair_ClearBySpheres(o, pi, t) || vrPair_ClearByWalk(o, pi, t)) return 0;
    vrPair_Query(o, p, t, 1, &pa, &pb, &c);   /* the region is only made inside the envelope */
    p->t_check = t;
    if (c.dist > o->p.d) {
        was_inside = p->inside;
        p->near = p->overlap = 0;
        if (was_inside || t == t_prev || !vrOwner_PutOffKey(o, pi, c.dist, c.n))
            vrPair_Settle(o, pi, 0, vrPair_Key(o, p, t, c.dist, c.n));
        return 0;
    }
    /* an impact where the distance came down to the contact gap g_c (SPEC
     * 7), from outside the envelope or from inside it (a pair of an island
     * comes to g_c as its step allows, and the impact there answers a point
     * that still comes in, pair_events.c) */
    if (!p->near && c.dist <= o->gc && t > t_prev) {
        double at = vrPair_Bisect(o, p, t_prev, t, &c, o->gc, wanted);
        if (isnan(at)) vrLook_Redo(o, pi);
        if (isnan(at) || vrPair_Impact(o, ev, p, at)) {
            vrPair_Settle(o, pi, p->inside, t);  /* due again at once: it is rolled back or re-evaluated */
            return !isnan(at);
        }
    }
    was_near = p->near;
    was_overlap = p->overlap;
    p->near = vrPair_Near(o, c.dist);
    p->overlap = c.dist < -VR_PENETRATION_TOL;
    vrPair_Settle(o, pi, 1, t);
    if (!p->near) {                      /* in the envelope, not touching */
        if (o->p.use_heap) p->quiet_until = vrPair_ApproachHorizon(o, p, t, &pa, &pb, &c);
        return 0;
    }
    vrPair_ForEvents(o, p, t, &pa, &pb, &c);   /* the query above had the region: vrPair_EventQuery's */
    if (was_near && !was_overlap && t > t_prev && p->overlap) {
        double at = vrPair_Bisect(o, p, t_prev, t, &c, 0, wanted);
        if (isnan(at)) return vrLook_Redo(o, pi), 0;   /* after an event found here: rolled back */
        if (vrPair_Touch(o, ev, p, at)) return 1; /* due again at once, as after an impact */
    }
    if (vrPair_InsideEvents(o, ev, t, p, &pa, &pb, &c)) return 1;
    if (o->p.use_heap) p->quiet_until = vrPair_QuietHorizon(o, p, t, &c);
    return 0;
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
        if (o->found[i].t == at) vrEvents_Push(&o->pending, &o->npending, &o->pendcap, &o->found[i]);
    o->pending_t = at;
    /* they are kept with their looks: the first too, which is not the
     * answer when another owner's comes first (the answered one goes at
     * vrOwner_AdvanceTo), and those at the grid point itself, pending only
     * while the answer is at that instant */
    for (i = 0; o->p.keep_looks && i < o->nfound; i++) {
        if (vrGrow((void **)&o->kept, &o->keptcap, o->nkept + 1, sizeof *o->kept) != 0) {
            o->keep_lost = 1;                   /* no memory: nothing is kept past the answer */
            break;
        }
        o->kept[o->nkept].ev = o->found[i];
        o->kept[o->nkept++].point = at;
    }
    return 1;
}

/* pair pi was looked at at grid point t, or a later one, by a walk before
 * this one: that look stands (keep_looks; a worker's walk goes past the
 * answer to its own first event, so its pairs may hold looks at several
 * points, and one looked at again at an earlier point would start from the
 * later look's state), and one the heap gave goes back into it after this
 * point, due at the next, as after a look made now */
static int kept_look(vrOwner *o, int pi, double t, int from_heap)
{
    if (!(o->p.keep_looks && o->pair[pi].looked >= t)) return 0;
    if (from_heap && vrIntList_Push(&o->again, pi) != 0) {
        o->keep_lost = 1;      /* no memory: looked at again (the next answer takes every look back) */
        return 0;
    }
    return 1;
}

static void evaluate_into_found(vrOwner *o, int pi, double t, double t_prev, int keep)
{
    vrEvent ev;
    if (!o->pair[pi].scheduled) return;
    if (o->progress && (o->checks & 255) == 0) o->progress(o->progress_ctx);
    if (evaluate(o, pi, t, t_prev, &ev) && keep) vrEvents_Push(&o->found, &o->nfound, &o->foundcap, &ev);
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
        for (i = 0; i < o->npending; i++) vrEvents_Push(&o->found, &o->nfound, &o->foundcap, &o->pending[i]);
    o->npending = 0;
}

static void collect_due(vrOwner *o, double t)
{
    double key;
    int id;
    o->due.n = o->due_inside.n = 0;
    if (!o->p.use_heap) {
        for (id = 0; id < o->npair; id++)
            if (o->pair[id].scheduled) vrIntList_Push(o->pair[id].inside ? &o->due_inside : &o->due, id);
        return;
    }
    /* the order pairs are evaluated in at one grid point does not matter:
     * they do not touch each other, and events are sorted afterwards */
    for (id = 0; id < o->active.n; id++)
        if (!(o->pair[o->active.v[id]].quiet_until >= t)) vrIntList_Push(&o->due_inside, o->active.v[id]);
    while ((id = vrHeap_Top(&o->heap, &key)) >= 0 && key <= t) {
        vrHeap_Pop(&o->heap);
        o->heap_pops++;
        if (!(o->hot[id] & HOT_DORMANT) && vrPair_Apart(o, id)) vrPair_MakeDormant(o, id);
        if (!(o->hot[id] & HOT_DORMANT)) vrIntList_Push(&o->due, id);
    }
}

/* may inside pair pi have an event before t: a touching one that may
 * overlap at t (so that it may touch before t), one in the envelope that
 * may be within g_c at t (an impact before t)?  The walk decides: the
 * canonical distance may lie a little below it (its slack, contact.h), so
 * a walk within VR_QUICK_CLEAR of the level says maybe. */
static int may_cross(vrOwner *o, int pi, double t)
{
    double level = o->pair[pi].near ? 0 : o->gc;
    return vrPair_Within(o, &o->pair[pi], t, level + VR_QUICK_CLEAR, t, t, NULL);
}

int vrOwner_FirstEvent(vrOwner *o, const vrGrid *g, int allow_instant, vrEvent *ev)
{
    long k = 1;
    int i;
    o->nfound = 0;
    if (vrOwner_MakeFresh(o, g->t0) != 0) return -1;
    if (!(g->frame_T == o->bp.T) && vrOwner_NewFrame(o, g) != 0) return -1;
    o->bp.t0 = g->t0;
    o->span_end = g->T;
    o->step_h = g->h;
    /* closed: at t0 (0), or to the next grid point (-1: events creeping
     * a rounding of t at a time, owner.h vrInstant_Span) */
    o->closed_t = allow_instant > 0 ? NAN : g->t0;
    o->closed_end = allow_instant >= 0 ? g->t0 : g->n >= 1 ? vrGrid_Point(g, 1) : g->T;
    allow_instant = allow_instant > 0;
    /* kept looks stand on the grid they were made on, and not where an
     * instant is closed (an event there is dropped, pair_events.c) */
    if (o->p.keep_looks && (!allow_instant || !(g->a == o->kept_a && g->h == o->kept_h))) vrOwner_Advance(o, g->t0);
    o->kept_a = g->a;
    o->kept_h = g->h;
    kept_events_at(o, g->t0, 0);
    span_start(o, g->t0, allow_instant);
    if (o->nfound) return take_first(o, g->t0, ev);
    while (k <= g->n) {
        double t = vrGrid_Point(g, k), key;
        collect_due(o, t);
        kept_events_at(o, t, 1);
        o->defer_keys = 1;
        for (i = 0; i < o->due.n; i++)
            if (!kept_look(o, o->due.v[i], t, o->p.use_heap)) evaluate_into_found(o, o->due.v[i], t, vrGrid_Before(g, k), 1);
        o->defer_keys = 0;
        /* A touching pair has its events at grid points only, unless it
         * overlaps there (touch), and one in the envelope only where it
         * comes within g_c: after an event bisected to before t the others
         * could only be rolled back (in a heap of bodies, most of the
         * look-ahead's work), so only those that may cross are looked at,
         * as a worker without that event would */
        for (i = 0; i < o->due_inside.n; i++)
            if (!kept_look(o, o->due_inside.v[i], t, 0) && (!impact_before(o, t) || may_cross(o, o->due_inside.v[i], t)))
                evaluate_into_found(o, o->due_inside.v[i], t, vrGrid_Before(g, k), 1);
        later_keys(o, t);
        for (i = 0; i < o->again.n; i++) vrPair_Place(o, o->again.v[i]);
        o->again.n = 0;
        if (o->nfound) return take_first(o, t, ev);
        if (!o->p.use_heap || o->active.n > 0 || o->nkept > 0) { k++; continue; }
        if (vrHeap_Top(&o->heap, &key) < 0) break;
        k = k + 1 > vrSchedule_FirstPointAtOrAfter(g, key) ? k + 1 : vrSchedule_FirstPointAtOrAfter(g, key);
    }
    return 0;
}
