/* effect.c — what an event does to its bodies (SPEC 3.1, 3.4): an impact
 * or a contact impulse (the 15x15 solve of response.c, then the spin clamp),
 * a push-out of overlapping bodies, support beginning (the region's normal
 * velocities settled) or ending.  The result is an update: the new states of
 * the bodies it changed, which every holder of those bodies applies alike
 * (event.c).  The owner that found the event answers it (owner.c). */
#include "effect.h"

/* what a response reads: the bodies by id, the solver, the flight settings */
typedef struct vrResponding {
    vrBody **body;
    vrResponder *responder;
    const vrFlight *flight;
} vrResponding;

static void impact_body(vrBody *b, double t, vec3 c, vrImpactBody *ib)
{
    vrPose pose;
    vrBody_Pose(b, t, &pose);
    ib->is_static = b->is_static;
    ib->mass = b->mass;
    ib->inertia = vrBody_InertiaWorld(b, &pose);
    ib->inv_inertia = vrBody_InvInertiaWorld(b, &pose);
    ib->p = vec3_sub(c, pose.p);
    vrBody_Velocity(b, t, &ib->v);
    ib->w = vrBody_Omega(b, &pose);
}

/* The new state of a body after an impulse: woken, hit, new velocities
 * (ib: the body as the solve saw it, its world inertia and lever arm).
 * max_angular clamps the spin at every event (SPEC 3.2); where the clamp
 * bites, the body's velocity along the normal makes up for the change of
 * its contact point's normal velocity, so that one impulse still settles
 * the contact (the clamp gives up momentum either way). */
static int kick(const vrResponding *o, vrUpdate *up, vrBody *b, const vrEvent *ev, const vrImpactBody *ib, vec3 v,
                vec3 w)
{
    vrBodyState *st;
    double spin = vec3_len(w), cap = o->flight->max_angular;
    if (b->is_static) return 0;
    st = vrUpdate_Body(up, b, ev->t);
    if (!st) return -1;
    if (spin > cap) {
        vec3 clamped = vec3_scale(w, cap / spin);
        v = vec3_madd(v, -vec3_dot(ev->n, vec3_cross(vec3_sub(clamped, w), ib->p)), ev->n);
        w = clamped;
    }
    st->v = v;
    st->L = b->rot == VR_ROT_NONE && vec3_len2(w) == 0 ? vec3_zero() : mat33_mulv(&ib->inertia, w);
    st->resting = 0;
    st->hit = 1;
    return 0;
}

static int respond_impulse(const vrResponding *o, const vrEvent *ev, vrUpdate *up)
{
    vrBody *A = o->body[ev->a], *B = o->body[ev->b];
    vrImpactBody ia, ib;
    vec3 v1, w1, v2, w2;
    impact_body(A, ev->t, ev->c, &ia);
    impact_body(B, ev->t, ev->c, &ib);
    if (vrResponder_Solve(o->responder, &ia, &ib, ev->n, ev->e, 0, &v1, &w1, &v2, &w2, NULL) != 0) return -1;
    if (kick(o, up, A, ev, &ia, v1, w1) != 0 || kick(o, up, B, ev, &ib, v2, w2) != 0) return -1;
    return 0;
}

/* x lies on a static body that the push along dir would drive it into */
static int held_against(const vrBody *x, vec3 dir)
{
    int i;
    for (i = 0; i < x->nsupport; i++)
        if (x->support[i].fixed && vec3_dot(dir, x->support[i].n) < 0) return 1;
    return 0;
}

/* What the speed into the contact could not pay comes out of the spin
 * (all of it scaled, the axis kept): a body turning on a flat side about
 * the vertical brings a vertex down with no speed into the floor at all (a
 * pinched superquadric, supported, lifted 1 um a step gained 0.7 mJ a
 * frame).  A true sphere's spin moves no point of it toward anything. */
static void pay_from_spin(const vrBody *b, vrBodyState *st, double owed)
{
    vrPose pose;
    mat33 inv;
    double spin_energy;
    if (!(owed > 0) || b->shape.kind == VR_SHAPE_SPHERE) return;
    pose = vrPose_make(st->x, st->q);
    inv = vrBody_InvInertiaWorld(b, &pose);
    spin_energy = 0.5 * vec3_dot(st->L, mat33_mulv(&inv, st->L));
    if (!(spin_energy > 0)) return;
    st->L = vec3_scale(st->L, owed < spin_energy ? sqrt(1 - owed / spin_energy) : 0);
}

/* A push-out that lifts a body against the force adds m a.dx to its
 * energy: taken back from its velocity into the contact (along dir, the
 * way it was pushed), as far as that holds, and the rest from its spin.  A
 * tip or an edge that is not supported sinks g h^2/2 a step h and gains
 * g h of speed; lifted back and that speed kept, the impulses that follow
 * take only what the contact's effective mass carries, and a spinning
 * superquadric gained 0.15 J a second (physics fuzzer seed 2413).  Speed
 * away from the contact is left alone: a push-out never adds speed. */
static void pay_for_lift(const vrResponding *o, const vrBody *b, vrBodyState *st, vec3 dir, double moved)
{
    double lift = -b->mass * vec3_dot(o->flight->accel, dir) * moved, into = vec3_dot(st->v, dir), left;
    if (!(lift > 0)) return;
    if (into < 0) {
        left = into * into - 2 * lift / b->mass;
        st->v = vec3_madd(st->v, (left > 0 ? -sqrt(left) : 0) - into, dir);
        lift = left > 0 ? 0 : lift - 0.5 * b->mass * into * into;
    }
    pay_from_spin(b, st, lift);
}

/* Interpenetrating bodies are pushed apart along the normal out of the
 * overlap, to VR_PUSHOUT_GAP apart, shared by inverse mass.  No further: a
 * 10 kg body pushed to half a 1 cm envelope gained 0.49 J; what the lift
 * still adds is paid from its speed (pay_for_lift), and the contact that
 * follows at the same instant takes what approach is left.  A body lying
 * on a static one that its share would push into it stays, and the other
 * takes all: a box on a light board on the floor, shared, pushed the board
 * into the floor, whose push-out pushed it back into the box, 64 times an
 * instant, and the overlap grew to 36 mm. */
static int respond_pushout(const vrResponding *o, const vrEvent *ev, vrUpdate *up)
{
    vrBody *b[2] = {o->body[ev->a], o->body[ev->b]};
    double w0 = b[0]->inv_mass, w1 = b[1]->inv_mass, total = ev->depth + VR_PUSHOUT_GAP;
    double share[2], sign[2] = {-1, 1};
    int s;
    if (w1 > 0 && held_against(b[0], vec3_neg(ev->n)) && !held_against(b[1], ev->n)) w0 = 0;
    else if (w0 > 0 && held_against(b[1], ev->n) && !held_against(b[0], vec3_neg(ev->n))) w1 = 0;
    share[0] = w0 / (w0 + w1);
    share[1] = w1 / (w0 + w1);
    for (s = 0; s < 2; s++) {
        vrBodyState *st;
        if (b[s]->is_static) continue;
        st = vrUpdate_Body(up, b[s], ev->t);
        if (!st) return -1;
        st->x = vec3_madd(st->x, sign[s] * share[s] * total, ev->n);
        pay_for_lift(o, b[s], st, vec3_scale(ev->n, sign[s]), share[s] * total);
        st->resting = 0;
    }
    return 0;
}

/* Gaussian elimination with partial pivoting of a k x k system (k <= 3)
 * given as rows [a b]; the solution replaces b (column 3) */
static int solve_small(double A[3][4], int k)
{
    int i, j, c, piv;
    for (c = 0; c < k; c++) {
        for (piv = c, i = c + 1; i < k; i++)
            if (fabs(A[i][c]) > fabs(A[piv][c])) piv = i;
        if (!(fabs(A[piv][c]) > 0)) return -1;
        for (j = 0; j < 4; j++) {
            double t = A[c][j];
            A[c][j] = A[piv][j];
            A[piv][j] = t;
        }
        for (i = 0; i < k; i++) {
            double f;
            if (i == c) continue;
            f = A[i][c] / A[c][c];
            for (j = c; j < 4; j++) A[i][j] -= f * A[c][j];
        }
    }
    for (i = 0; i < k; i++) A[i][3] /= A[i][i];
    return 0;
}

/* Support begins (SPEC 3.1: what is left of the normal relative velocity
 * goes): an e = 0 contact over the whole region.  Normal impulses at the
 * corners that span it make every region point's normal velocity zero, so
 * a box that comes down flat keeps no rocking spin below v_eps that would
 * tip it onto an edge later (and a sphere, one point below its centre,
 * loses only its normal velocity).  A static or resting partner takes no
 * impulse; a moving one (supported, sliding) takes the opposite ones, or
 * the settle would make momentum from nothing (a ball settling on a board
 * that slides under it). */
static void settle_on_support(const vrResponding *o, const vrEvent *ev, vrBodyState *st, vrBodyState *sy)
{
    vrBody *x = o->body[ev->body], *y = o->body[ev->partner];
    int k = ev->ncorner, i, j;
    vrPose px, py;
    vec3 r[3], q[3], w, wy = vec3_zero();
    mat33 Iinv, Iinv_y = mat33_zero();
    double A[3][4];
    vrBody_Pose(x, ev->t, &px);
    vrBody_Pose(y, ev->t, &py);
    Iinv = vrBody_InvInertiaWorld(x, &px);
    w = mat33_mulv(&Iinv, st->L);
    if (sy) {
        Iinv_y = vrBody_InvInertiaWorld(y, &py);
        wy = mat33_mulv(&Iinv_y, sy->L);
    }
    for (i = 0; i < k; i++) {
        vec3 u = vec3_add(st->v, vec3_cross(w, r[i] = vec3_sub(ev->corner[i], px.p)));
        vec3 uy = sy ? vec3_add(sy->v, vec3_cross(wy, q[i] = vec3_sub(ev->corner[i], py.p)))
                     : vrBody_PointVelocity(y, ev->t, &py, ev->corner[i]);
        A[i][3] = -vec3_dot(ev->n, vec3_sub(u, uy));
    }
    for (i = 0; i < k; i++)
        for (j = 0; j < k; j++) {
            A[i][j] = x->inv_mass + vec3_dot(ev->n, vec3_cross(mat33_mulv(&Iinv, vec3_cross(r[j], ev->n)), r[i]));
            if (sy)
                A[i][j] += y->inv_mass + vec3_dot(ev->n, vec3_cross(mat33_mulv(&Iinv_y, vec3_cross(q[j], ev->n)), q[i]));
        }
    if (solve_small(A, k) != 0) return;
    for (i = 0; i < k; i++) {
        vec3 J = vec3_scale(ev->n, A[i][3]);
        st->v = vec3_madd(st->v, x->inv_mass, J);
        st->L = vec3_add(st->L, vec3_cross(r[i], J));
        if (sy) {
            sy->v = vec3_madd(sy->v, -y->inv_mass, J);
            sy->L = vec3_sub(sy->L, vec3_cross(q[i], J));
        }
    }
}

static int respond_support(const vrResponding *o, const vrEvent *ev, vrUpdate *up)
{
    vrBody *x = o->body[ev->body], *y = o->body[ev->partner];
    int moving = ev->kind == VR_EV_SUPPORT_BEGIN && vrBody_IsFree(y), i, k = 0;
    vrBodyState *st, *sy;
    if (vrUpdate_Bodies(up, x, moving ? y : NULL, ev->t, &st, &sy) != 0) return -1;
    if (ev->kind == VR_EV_SUPPORT_BEGIN) {
        settle_on_support(o, ev, st, sy);
        st->support[st->nsupport].partner = ev->partner;
        st->support[st->nsupport].n = ev->n;
        st->support[st->nsupport].joint = 0;
        st->support[st->nsupport].fixed = y->is_static;
        st->nsupport++;
        return 0;
    }
    for (i = 0; i < st->nsupport; i++)
        if (st->support[i].partner != ev->partner) st->support[k++] = st->support[i];
    st->nsupport = k;
    return 0;
}

/* Supported bodies slide at constant distance (SPEC 3.1).  What an event
 * leaves of a body's velocity along the normal of a static support, when
 * slower than v_eps, no contact impulse would ever answer: it goes, as it
 * does when support begins (a ball nudged at a slant by a box, or a ball
 * that begins to lean on another, would otherwise sink into the table, or
 * rise off it, at a fraction of a mm/s for ever). */
static void hold_to_supports(vrUpdate *up)
{
    int i, k;
    for (i = 0; i < up->n; i++) {
        vrBodyState *st = &up->body[i];
        if (st->raw) continue;   /* a setup's anchor, restored as it was */
        for (k = 0; k < st->nsupport; k++) {
            double along = vec3_dot(st->support[k].n, st->v);
            if (st->support[k].fixed && fabs(along) <= VR_V_EPS) st->v = vec3_madd(st->v, -along, st->support[k].n);
        }
    }
}

static int respond(const vrResponding *o, const vrEvent *ev, vrUpdate *up)
{
    switch (ev->kind) {
    case VR_EV_IMPACT:
    case VR_EV_CONTACT:
        return respond_impulse(o, ev, up);
    case VR_EV_PUSHOUT:
        return respond_pushout(o, ev, up);
    case VR_EV_SUPPORT_BEGIN:
    case VR_EV_SUPPORT_END:
        return respond_support(o, ev, up);
    default:
        return 0;
    }
}

int vrEffect_Compute(vrBody **body, vrResponder *responder, const vrFlight *flight, const vrEvent *ev, vrUpdate *up)
{
    vrResponding o;
    o.body = body;
    o.responder = responder;
    o.flight = flight;
    if (respond(&o, ev, up) != 0) return -1;
    hold_to_supports(up);
    return 0;
}
