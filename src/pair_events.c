/* pair_events.c — which event a pair has at a time it was looked at
 * (SPEC 3.1, 7): an impact or a touch at a bisected moment, and within the
 * contact gap a push-out or a contact impulse; at an island step, the
 * pairs that touch (island_step.c solves them together).
 *   approach           the region points' normal velocities
 *   *_event            an event filled in
 *   too_fast           a contact impulse's test: faster than v_eps, or for a
 *                      pair of an island faster than its step allows
 *   vrPair_InsideEvents, vrPair_Impact, vrPair_Touch
 *   keep_points, touch_of, may_touch, vrOwner_Touching   the island step's contacts
 *   reach_body, vrOwner_TouchingFrom   an instant's: those of its islands */
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "owner_state.h"

/* relative normal velocities of the region points, b's minus a's */
typedef struct vrApproach {
    double u[VR_REGION_MAX];
    double umin, umax;
    vec3 centroid;            /* of the points within VR_TIE_SPEED of umin */
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
        if (ap->u[i] <= ap->umin + VR_TIE_SPEED) {
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
    ev->mu = sqrt(o->body[p->a]->friction * o->body[p->b]->friction);
}

/* A pair of an island (touching at the last island step) may close each
 * point's gap to g_c within the step (island.h's floors): a contact
 * impulse answers only what approaches faster than that, and none at the
 * step's end, where the next island step answers it.  Any other pair:
 * faster than v_eps. */
static int too_fast(const vrOwner *o, const vrPair *p, double t, const vrContact *c, const vrApproach *ap)
{
    int i;
    if (!vrPair_InIsland(o, p)) return ap->umin < -VR_V_EPS;
    if (t == o->span_end) return 0;     /* the next island step, at this instant, takes it */
    for (i = 0; i < c->npoints; i++)
        if (ap->u[i] < -(VR_V_EPS + vr_max(0, c->gap[i] - o->gc) / o->gather_h)) return 1;
    return 0;
}

/* events of a pair inside the envelope at t, by priority */
int vrPair_InsideEvents(vrOwner *o, vrEvent *ev, double t, const vrPair *p, const vrPose *pa,
                         const vrPose *pb, const vrContact *c)
{
    vrApproach ap;
    if (c->dist < -VR_OVERLAP_SLOP) {
        fill_event(ev, VR_EV_PUSHOUT, t, p, c);
        ev->depth = -c->dist;
        ev->c = c->pa;
        return 1;
    }
    approach(o, p, t, pa, pb, c, &ap);
    if (!too_fast(o, p, t, c, &ap)) return 0;
    impulse_event(o, ev, VR_EV_CONTACT, t, p, c, &ap);
    return 1;
}

/* An impulse event of kind at tau if the contact points approach there
 * faster than `faster` and the pair is not more than `deeper` inside:
 * an impact (any approach) and a touch share it. */
static int impulse_at(vrOwner *o, vrEvent *ev, vrPair *p, double tau, int kind, double faster, double deeper)
{
    vrPose pa, pb;
    vrContact c;
    vrApproach ap;
    if (tau == o->closed_t || (tau > o->closed_t && tau < o->closed_end)) return 0;   /* a closed instant */
    vrPair_EventQuery(o, p, tau, &pa, &pb, &c);
    if (c.npoints == 0 || c.dist < -deeper) return 0;
    approach(o, p, tau, &pa, &pb, &c, &ap);
    if (!(ap.umin < -faster)) return 0;
    impulse_event(o, ev, kind, tau, p, &c, &ap);
    return 1;
}

/* an impact at tau if the contact points approach there (a pair of an
 * island, faster than v_eps: one at rest there crosses g_c by rounding) */
int vrPair_Impact(vrOwner *o, vrEvent *ev, vrPair *p, double tau)
{
    return impulse_at(o, ev, p, tau, VR_EV_IMPACT, vrPair_InIsland(o, p) ? VR_V_EPS : 0, INFINITY);
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
int vrPair_Touch(vrOwner *o, vrEvent *ev, vrPair *p, double tau)
{
    return impulse_at(o, ev, p, tau, VR_EV_CONTACT, VR_V_EPS, VR_PENETRATION_TOL);
}

/* At most VR_TOUCH_POINTS of a region's points, in its order: those
 * extreme along as many directions spread evenly in the contact plane
 * (the corners that carry it), and the least gap among the rest kept in
 * the nearest one kept (the solve then never lets a point it drops close
 * in further than the one that stands for it). */
static void keep_points(const vrContact *c, vrTouch *k)
{
    int keep[VR_REGION_MAX] = {0}, i, d, m = 0;
    vec3 t1 = vec3_orthogonal(c->n), t2 = vec3_cross(c->n, t1);
    if (c->npoints <= VR_TOUCH_POINTS) {
        for (i = 0; i < c->npoints; i++) k->point[i] = c->point[i], k->gap[i] = c->gap[i];
        k->npoints = c->npoints;
        return;
    }
    for (d = 0; d < VR_TOUCH_POINTS; d++) {
        vec3 dir = vec3_add(vec3_scale(t1, cos(2 * VR_PI * d / VR_TOUCH_POINTS)), vec3_scale(t2, sin(2 * VR_PI * d / VR_TOUCH_POINTS)));
        int best = 0;
        for (i = 1; i < c->npoints; i++)
            if (vec3_dot(dir, c->point[i]) > vec3_dot(dir, c->point[best])) best = i;
        keep[best] = 1;
    }
    for (i = 0; i < c->npoints; i++)
        if (keep[i]) k->point[m] = c->point[i], k->gap[m++] = c->gap[i];
    k->npoints = m;
    for (i = 0; i < c->npoints; i++) {
        int j, near = 0;
        if (keep[i]) continue;
        for (j = 1; j < m; j++)
            if (vec3_dist(c->point[i], k->point[j]) < vec3_dist(c->point[i], k->point[near])) near = j;
        k->gap[near] = vr_min(k->gap[near], c->gap[i]);
    }
}

/* what the island step's paid gravity (vrBody_StepGravity) adds to a
 * point's normal velocity n.(v_b - v_a) */
static double paid_lift(const vrOwner *o, const vrPair *p, vec3 n, double h)
{
    vec3 ga = vrBody_StepGravity(o->body[p->a], o->p.flight.accel, h);
    vec3 gb = vrBody_StepGravity(o->body[p->b], o->p.flight.accel, h);
    return vec3_dot(n, vec3_sub(gb, ga));
}

/* Pair p's contact at t when it touches (within the region's level),
 * marked leaving when every point separates faster than v_eps (it flies
 * on, unless the island's solve turns it back: island_step.c), and none
 * when every point comes in faster than an impact that does not bounce
 * (v_rest, SPEC 3.1; v_eps with no force) and would close its gap past
 * g_c within the step (with the step's gravity paid in, as the island
 * step would fly it): that is an impact, found at g_c and answered with
 * its restitution, exactly, as in free flight.  A pair that rests on some
 * points while others come in fast (a box tipping onto a face) is the
 * island's, which bounces those points (island_step.c). */
static int touch_of(vrOwner *o, vrPair *p, double t, double h, vrTouches *out)
{
    vrPose pa, pb;
    vrContact c;
    vrApproach ap;
    vrTouch *k;
    double lift;
    int i;
    vrPair_EventQuery(o, p, t, &pa, &pb, &c);
    if (c.npoints == 0 || c.dist > o->region) return 0;
    approach(o, p, t, &pa, &pb, &c, &ap);
    lift = h > 0 ? paid_lift(o, p, c.n, h) : 0;
    for (i = 0; h > 0 && ap.umin <= VR_V_EPS && i < c.npoints && ap.u[i] < -(o->v_rest + VR_V_EPS)
                && ap.u[i] + lift < -vr_max(0, c.gap[i] - o->gc) / h; i++)
        ;
    if (h > 0 && i == c.npoints) return 0;
    if (h > 0 && ap.umin <= VR_V_EPS) p->touch_t = t;
    if (!(k = vrTouches_Add(out))) return -1;
    k->a = p->a, k->b = p->b, k->n = c.n, k->dist = c.dist;
    k->leaving = ap.umin > VR_V_EPS;
    keep_points(&c, k);
    return 0;
}

/* a pair vrOwner_Touching looks at: scheduled, and inside the envelope
 * (with the heap, the active list) or flagged since its last look; one
 * flagged outside it only when the bounding spheres come within the
 * region */
static int may_touch(vrOwner *o, vrPair *p, double t)
{
    vec3 dir;
    if (!(p->inside || p->flagged) || !p->scheduled) return 0;
    return p->inside || vrPair_SphereGap(o, p, t, &dir) <= o->region;
}

/* (the order they are found in does not matter: the coordinator sorts
 * them by pair; with the heap the pairs in the envelope are the active
 * list, a pair outside it cannot touch, and one flagged since its last
 * look, in the flagged list, is looked at here too: a pair inside the
 * envelope but not yet listed, as a resting body's with its support is
 * when the island step wakes it, among them) */
int vrOwner_Touching(vrOwner *o, double t, double h, vrTouches *out)
{
    int i, n;
    if (vrOwner_MakeFresh(o, t) != 0) return -1;
    n = o->p.use_heap ? o->active.n + o->flagged.n : o->npair;
    if (h > 0) o->gather_t = t, o->gather_h = h;
    for (i = 0; i < n; i++) {
        int pi = !o->p.use_heap ? i : i < o->active.n ? o->active.v[i] : o->flagged.v[i - o->active.n];
        vrPair *p = &o->pair[pi];
        if (o->p.use_heap && i >= o->active.n && p->active >= 0) continue;   /* listed as active already */
        if (may_touch(o, p, t) && touch_of(o, p, t, h, out) != 0) return -1;
    }
    return 0;
}

/* body id queued once, if this owner holds it and it can move */
static int reach_body(vrOwner *o, int id)
{
    if (id < 0 || id >= o->bodycap || !o->body[id] || vrBody_Immovable(o->body[id]) || o->reached[id]) return 0;
    o->reached[id] = 1;
    return vrIntList_Push(&o->reach, id);
}

/* An instant's islands, from a and b out: each body's pairs looked at
 * once (a pair of two reached bodies from the first of them), a touch
 * reaching its other body.  A leaving touch reaches it too: the solve may
 * turn that pair back (island_step.c), which joins the other body's
 * island to it.  In a landing pile of 300 an instant's islands hold a
 * quarter of the touches, and an answer looked at them all, 40 % of the
 * landing's time. */
int vrOwner_TouchingFrom(vrOwner *o, double t, int a, int b, vrTouches *out)
{
    int q, k, r = 0;
    if (vrOwner_MakeFresh(o, t) != 0 || vrGrow((void **)&o->reached, &o->reachedcap, o->bodycap, 1) != 0) return -1;
    memset(o->reached, 0, (size_t)o->bodycap);
    o->reach.n = 0;
    if (reach_body(o, a) != 0 || reach_body(o, b) != 0) r = -1;
    if (r == 0 && o->reach.n == 0) return vrOwner_Touching(o, t, 0, out);   /* neither can move: the pair's own touch */
    for (q = 0; r == 0 && q < o->reach.n; q++) {
        int x = o->reach.v[q];
        const vrIntList *l = &o->body_pairs[x], *partner = &o->body_partners[x];
        for (k = 0; r == 0 && k < l->n; k++) {
            vrPair *p = &o->pair[l->v[k]];
            int y = partner->v[k], before = out->n;
            if (o->reached[y] == 2 || !may_touch(o, p, t)) continue;
            if ((r = touch_of(o, p, t, 0, out)) == 0 && out->n > before) r = reach_body(o, y);
        }
        o->reached[x] = 2;
    }
    return r;
}
