/* effect.c — what an event of a pair does to its bodies (SPEC 3.1, 3.4, 7):
 * an impact or a contact impulse (the 15x15 solve of response.c, with
 * friction, then the spin clamp), or a push-out of overlapping bodies.  The
 * result is an update: the new states of the bodies it changed, which every
 * holder of those bodies applies alike (event.c).  The owner that found the
 * event answers it (owner.c); an island's contacts are answered together by
 * the coordinator (island_step.c). */
#include "effect.h"

/* what a response reads: the bodies by id, the solver, the flight settings */
typedef struct vrResponding {
    vrBody **body;
    vrResponder *responder;
    const vrFlight *flight;
    double v_rest;       /* a smaller change of speed is a tap, not a hit (vrBody_Jolted) */
} vrResponding;

static void impact_body(vrBody *b, double t, vec3 c, vrImpactBody *ib)
{
    vrPose pose;
    vrBody_Pose(b, t, &pose);
    ib->is_static = vrBody_Immovable(b);   /* a held body: infinite mass, its velocity kept */
    ib->mass = b->mass;
    ib->inertia = vrBody_InertiaWorld(b, &pose);
    ib->inv_inertia = vrBody_InvInertiaWorld(b, &pose);
    ib->p = vec3_sub(c, pose.p);
    vrBody_Velocity(b, t, &ib->v);
    ib->w = vrBody_Omega(b, &pose);
}

/* The normal speed that keeps the contact point's normal velocity when the
 * spin w is clamped to `clamped`, as far as the spin's lost energy pays for
 * it: a clamp only takes energy out (SPEC 7).  Paid in full, a body knocked
 * away from the contact and spun past the cap got more normal speed than
 * the spin gave up (a ball at 8 m/s on a rod's end: 7.9 J more, the pile's
 * 2.3 J); then the speed is what the energy buys, and a contact still
 * approaching is answered again at the same instant. */
static double clamp_lift(const vrImpactBody *ib, vec3 n, vec3 v, vec3 w, vec3 clamped)
{
    double full = -vec3_dot(n, vec3_cross(vec3_sub(clamped, w), ib->p)), vn = vec3_dot(v, n);
    double lost = 0.5 * (vec3_dot(w, mat33_mulv(&ib->inertia, w)) - vec3_dot(clamped, mat33_mulv(&ib->inertia, clamped)));
    double bought = sqrt(vn * vn + 2 * fmax(lost, 0) / ib->mass);
    if (ib->mass * (vn * full + 0.5 * full * full) <= lost) return full;
    return full > 0 ? bought - vn : -bought - vn;
}

/* The new state of a body after an impulse: woken, hit, new velocities
 * (ib: the body as the solve saw it, its world inertia and lever arm).
 * max_angular clamps the spin at every event (SPEC 3.2); where the clamp
 * bites, the body's velocity along the normal makes up for the change of
 * its contact point's normal velocity, so that one impulse still settles
 * the contact, as far as the spin's energy pays (clamp_lift; the clamp
 * gives up momentum either way). */
static int kick(const vrResponding *o, vrUpdate *up, vrBody *b, const vrEvent *ev, const vrImpactBody *ib, vec3 v,
                vec3 w)
{
    vrBodyState *st;
    double spin = vec3_len(w), cap = o->flight->max_angular;
    if (vrBody_Immovable(b)) return 0;
    st = vrUpdate_Body(up, b, ev->t);
    if (!st) return -1;
    if (vrFlight_OverCap(spin, cap)) {
        vec3 clamped = vec3_scale(w, cap / spin);
        v = vec3_madd(v, clamp_lift(ib, ev->n, v, w, clamped), ev->n);
        w = clamped;
        st->clamped = 1;   /* counted where the state is applied (stats clamps) */
    }
    st->v = v;
    st->L = b->rot == VR_ROT_NONE && vec3_len2(w) == 0 ? vec3_zero() : mat33_mulv(&ib->inertia, w);
    st->resting = 0;
    if (vrBody_Jolted(vec3_sub(v, ib->v), vec3_sub(w, ib->w), b->r_out, o->v_rest)) vrBodyState_Jolt(st, o->flight->accel);
    return 0;
}

/* SPEC 8: a static object stops a held one, which slides along it: its
 * velocity into the static is removed at the contact, and its turning
 * (which could bring another point in), until the next cut re-aims it at
 * the hand (grab.c).  sign: +1 when the held body is the event's a (the
 * normal points from it into the static), -1 when it is b. */
static int slide_held(vrUpdate *up, vrBody *held, const vrEvent *ev, double sign)
{
    vrBodyState *st = vrUpdate_Body(up, held, ev->t);
    vec3 n = vec3_scale(ev->n, sign);
    double into;
    if (!st) return -1;
    into = vec3_dot(st->v, n);
    if (into > 0) st->v = vec3_madd(st->v, -into, n);
    st->L = vec3_zero();
    st->hit = 1;
    return 0;
}

static int respond_impulse(const vrResponding *o, const vrEvent *ev, vrUpdate *up)
{
    vrBody *A = o->body[ev->a], *B = o->body[ev->b];
    vrImpactBody ia, ib;
    vec3 v1, w1, v2, w2;
    if (A->kinematic && B->is_static) return slide_held(up, A, ev, 1);
    if (B->kinematic && A->is_static) return slide_held(up, B, ev, -1);
    impact_body(A, ev->t, ev->c, &ia);
    impact_body(B, ev->t, ev->c, &ib);
    if (vrResponder_Solve(o->responder, &ia, &ib, ev->n, ev->e, ev->mu, &v1, &w1, &v2, &w2, NULL) != 0) return -1;
    if (kick(o, up, A, ev, &ia, v1, w1) != 0 || kick(o, up, B, ev, &ib, v2, w2) != 0) return -1;
    return 0;
}

/* What the speed into the contact could not pay comes out of the spin
 * (all of it scaled, the axis kept): a body turning on a flat side about
 * the vertical brings a vertex down with no speed into the floor at all (a
 * pinched superquadric, supported, lifted 1 um a step gained 0.7 mJ a
 * frame).  A true sphere's spin brought nothing down, but its energy pays
 * the lift as well as any; returns what is still owed. */
static double pay_from_spin(const vrBody *b, vrBodyState *st, double owed)
{
    vrPose pose;
    mat33 inv;
    double spin_energy;
    if (!(owed > 0)) return 0;
    pose = vrPose_make(st->x, st->q);
    inv = vrBody_InvInertiaWorld(b, &pose);
    spin_energy = 0.5 * vec3_dot(st->L, mat33_mulv(&inv, st->L));
    if (!(spin_energy > 0)) return owed;
    st->L = vec3_scale(st->L, owed < spin_energy ? sqrt(1 - owed / spin_energy) : 0);
    return owed < spin_energy ? 0 : owed - spin_energy;
}

/* ...and what the spin could not pay, from the speed left (a ball's spin,
 * once skipped here, left a pile's ball lifted 0.1 mm with 5.8e-4 J more) */
static void pay_from_speed(const vrBody *b, vrBodyState *st, double owed)
{
    double speed_energy = 0.5 * b->mass * vec3_len2(st->v);
    if (!(owed > 0) || !(speed_energy > 0)) return;
    st->v = vec3_scale(st->v, owed < speed_energy ? sqrt(1 - owed / speed_energy) : 0);
}

/* A push-out that lifts a body against the force adds m a.dx to its
 * energy: taken back from its velocity into the contact (along dir, the
 * way it was pushed), as far as that holds, the rest from its spin, then
 * from its speed left (a body lifted from rest keeps the lift: there is
 * nothing to pay it from).  A
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
    pay_from_speed(b, st, pay_from_spin(b, st, lift));
}

/* A push-out moves positions, not velocities, so m x × v changes by
 * sum m dx × v = mu D n × (v_b - v_a) where the two bodies share it (their
 * momenta and centre of mass stay): a ball stuck to a tumbling box lost
 * 1e-4 of its 5.73 of angular momentum to 18 push-outs (physics fuzzer
 * seed 602).  The two spins take that much back, as one common change of
 * turn rate dw = -(I_a + I_b)^-1 dL, the split that costs the least energy:
 * a push-out keeps angular momentum as it keeps linear momentum. */
static void keep_angular_momentum(vrBody *const b[2], vrBodyState *const st[2], const vec3 moved[2])
{
    mat33 inertia[2], sum;
    vec3 lost = vec3_zero(), dw;
    int s;
    for (s = 0; s < 2; s++) {
        vrPose pose = vrPose_make(st[s]->x, st[s]->q);
        inertia[s] = vrBody_InertiaWorld(b[s], &pose);
        lost = vec3_add(lost, vec3_scale(vec3_cross(moved[s], st[s]->v), b[s]->mass));
    }
    if (vec3_len2(lost) == 0) return;   /* at rest, or pushed along the relative velocity */
    sum = mat33_add(&inertia[0], &inertia[1]);
    sum = mat33_inverse(&sum);
    dw = mat33_mulv(&sum, vec3_scale(lost, -1));
    for (s = 0; s < 2; s++) st[s]->L = vec3_add(st[s]->L, mat33_mulv(&inertia[s], dw));
}

/* Interpenetrating bodies are pushed apart along the normal out of the
 * overlap, to VR_PUSHOUT_GAP apart, shared by inverse mass.  No further: a
 * 10 kg body pushed to half a 1 cm envelope gained 0.49 J; what the lift
 * still adds is paid from its speed (pay_for_lift), and the contact that
 * follows at the same instant takes what approach is left.  A body in an
 * island's contact step (lying on something) against one that is not
 * stays, and the other takes all: a box on a light board on the floor,
 * shared, pushed the board into the floor, whose push-out pushed it back
 * into the box.  Islands prevent overlap (SPEC 7): a push-out is what is
 * left for deep overlaps, not the way contact is kept. */
static int respond_pushout(const vrResponding *o, const vrEvent *ev, vrUpdate *up)
{
    vrBody *b[2] = {o->body[ev->a], o->body[ev->b]};
    double w0 = b[0]->kinematic ? 0 : b[0]->inv_mass, w1 = b[1]->kinematic ? 0 : b[1]->inv_mass;
    double total = ev->depth + VR_PUSHOUT_GAP, share[2], sign[2] = {-1, 1};
    vrBodyState *st[2] = {NULL, NULL};
    vec3 moved[2];
    int s;
    if (w0 + w1 == 0) w0 = b[0]->kinematic, w1 = b[1]->kinematic;   /* held against a static: it moves */
    if (w1 > 0 && b[0]->contact && !b[1]->contact) w0 = 0;
    else if (w0 > 0 && b[1]->contact && !b[0]->contact) w1 = 0;
    share[0] = w0 / (w0 + w1);
    share[1] = w1 / (w0 + w1);
    for (s = 0; s < 2; s++) {
        if (b[s]->is_static || (b[s]->kinematic && share[s] == 0)) continue;
        if (!(st[s] = vrUpdate_Body(up, b[s], ev->t))) return -1;
        moved[s] = vec3_scale(ev->n, sign[s] * share[s] * total);
        st[s]->x = vec3_add(st[s]->x, moved[s]);
        pay_for_lift(o, b[s], st[s], vec3_scale(ev->n, sign[s]), share[s] * total);
        st[s]->resting = 0;
    }
    /* shared between two free bodies: nothing outside the pair acts */
    if (share[0] > 0 && share[1] > 0 && !b[0]->kinematic && !b[1]->kinematic && st[0] && st[1])
        keep_angular_momentum(b, st, moved);
    return 0;
}

static int respond(const vrResponding *o, const vrEvent *ev, vrUpdate *up)
{
    switch (ev->kind) {
    case VR_EV_IMPACT:
    case VR_EV_CONTACT:
        return respond_impulse(o, ev, up);
    case VR_EV_PUSHOUT:
        return respond_pushout(o, ev, up);
    default:
        return 0;
    }
}

int vrEffect_Compute(vrBody **body, vrResponder *responder, const vrFlight *flight, double v_rest, const vrEvent *ev,
                     vrUpdate *up)
{
    vrResponding o;
    o.body = body;
    o.responder = responder;
    o.flight = flight;
    o.v_rest = v_rest;
    return respond(&o, ev, up);
}
