/* pair_events.c — which event a pair has at a time it was looked at
 * (SPEC 3.1): an impact or a touch at a bisected moment, and inside the
 * envelope a push-out, a contact impulse, or support beginning or ending;
 * at a frame end, the contacts that could carry a body together (rest.c).
 *   approach           the region points' normal velocities
 *   *_event            an event filled in
 *   supports           SPEC 3.1's support test
 *   vrPair_InsideEvents, vrPair_LostSupport, vrPair_Impact, vrPair_Touch
 *   candidate, vrOwner_SupportCandidates */
#include <string.h>
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
    if (vrBody_Frozen(x) || !(vrBody_Frozen(y) || y->nsupport > 0) || c->npoints == 0) return 0;
    if (gl == 0 || vec3_dot(g, n_yx) > -1e-6 * gl) return 0;
    if (ap->umin < -VR_V_EPS || ap->umax > VR_V_EPS) return 0;
    if (joint) return 1;    /* the regions together are checked at frame ends (rest.c) */
    q = vec3_madd(px->p, vec3_dot(vec3_sub(c->point[0], px->p), n_yx), n_yx);
    return vrRegion_Contains(c->point, c->npoints, n_yx, q, VR_CONTAIN_TOL);
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
        if (vrBody_Frozen(o->body[x])) continue;
        was = vrBody_SupportKind(o->body[x], y);
        now = supports(o, o->body[x], o->body[y], n_yx, side ? pb : pa, c, ap, was == 2);
        if (was && !now) return support_event(ev, VR_EV_SUPPORT_END, t, p, c, x, y, n_yx, ap->region_centre);
        if (!was && now && o->body[x]->nsupport < VR_MAX_SUPPORTS)
            return support_event(ev, VR_EV_SUPPORT_BEGIN, t, p, c, x, y, n_yx, ap->region_centre);
    }
    return 0;
}

int vrPair_LostSupport(vrOwner *o, vrEvent *ev, double t, const vrPair *p, const vrContact *c)
{
    if (vrBody_SupportKind(o->body[p->a], p->b))
        return support_event(ev, VR_EV_SUPPORT_END, t, p, c, p->a, p->b, vec3_neg(c->n), c->pa);
    if (vrBody_SupportKind(o->body[p->b], p->a))
        return support_event(ev, VR_EV_SUPPORT_END, t, p, c, p->b, p->a, c->n, c->pb);
    return 0;
}

/* events of a pair inside the envelope at t, by priority */
int vrPair_InsideEvents(vrOwner *o, vrEvent *ev, double t, const vrPair *p, const vrPose *pa,
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
    vrPair_EventQuery(o, p, tau, &pa, &pb, &c);
    if (c.npoints == 0 || c.dist < -deeper) return 0;
    approach(o, p, tau, &pa, &pb, &c, &ap);
    if (!(ap.umin < -faster)) return 0;
    impulse_event(o, ev, kind, tau, p, &c, &ap);
    return 1;
}

/* an impact at tau if the contact points approach there */
int vrPair_Impact(vrOwner *o, vrEvent *ev, vrPair *p, double tau)
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
int vrPair_Touch(vrOwner *o, vrEvent *ev, vrPair *p, double tau)
{
    return impulse_at(o, ev, p, tau, VR_EV_CONTACT, VR_V_EPS, VR_PENETRATION_TOL);
}

static int candidate(vrOwner *o, const vrPair *p, int side, double t, vrCandidates *out)
{
    int x = side ? p->b : p->a, y = side ? p->a : p->b;
    vrBody *Y = o->body[y];
    vec3 g = o->p.flight.accel, n_yx;
    vrPose pa, pb, py;
    vrContact c;
    vrApproach ap;
    vrCandidate *k;
    if (!(vrBody_Frozen(Y) || Y->nsupport > 0) || vec3_len2(g) == 0) return 0;
    vrPair_EventQuery(o, (vrPair *)p, t, &pa, &pb, &c);
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
        if (!p->near || !p->scheduled) continue;
        for (side = 0; side < 2; side++) {
            int x = side ? p->b : p->a;
            if (x < nwant && want[x] && candidate(o, p, side, t, out) != 0) return -1;
        }
    }
    return 0;
}
