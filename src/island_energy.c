/* island_energy.c — an island solve's energy check (SPEC 7: with e < 1 or
 * friction, energy never rises; island.c's tries ask for it).
 *   vrIslandEnergy_Kinetic, step_energy   its measures (vrIsland_Pushed, island.c: whose)
 *   vrIslandEnergy_StepGain, _PayBack     what a step's solve gains; impulses scaled back until
 *                                         it gains nothing
 *   vrIslandEnergy_NoBounces, _Poisson    the bounces dropped; Poisson's bounce given back
 */
#include <math.h>
#include <string.h>
#include "island_energy.h"

/* the bodies' kinetic energy; inertia[i] is the inverse of body i's
 * inv_inertia, found once a solve (the energy checks measure it four
 * times, and the inverse was a tenth of their cost) */
double vrIslandEnergy_Kinetic(const vrIslandBody *b, const mat33 *inertia, int n)
{
    double e = 0;
    int i;
    for (i = 0; i < n; i++) {
        if (!b[i].dynamic) continue;
        e += 0.5 / b[i].inv_mass * vec3_len2(b[i].v) + 0.5 * vec3_dot(b[i].w, mat33_mulv(&inertia[i], b[i].w));
    }
    return e;
}

/* a moving body's kinetic energy less the work the force paid in does
 * over the step's flight at its velocities as they are: its step's energy
 * but for the potential energy at the start, which no impulse changes */
static double step_energy(const vrIslandBody *b, const mat33 *inertia)
{
    return vrIslandEnergy_Kinetic(b, inertia, 1) - vec3_dot(b->paid, b->v) / b->inv_mass;
}

/* the step's energy after the solve less before the force was paid in,
 * when that is above SPEC 7's allowance (else 0); *C the step's loss with
 * no impulse at all, sum m |paid|^2 / 2.  Of the bodies an impulse acts on
 * only: the others fly free under the force (island_step.c), which loses
 * nothing, and counted with the rest their C let the rest gain it (a pile
 * of fifty rose 1.9e-4 J in a step, a body of its island lifted). */
double vrIslandEnergy_StepGain(const vrIslandBody *body, const vrIslandBody *before, const mat33 *inertia, int nbody,
                        const vrIslandContact *c, int ncontact, unsigned char *pushed, double *C)
{
    double e0 = 0, R = 0;   /* the kinetic energy before the force, the step's energy after */
    int i;
    *C = 0;
    vrIsland_Pushed(c, ncontact, pushed, nbody);
    for (i = 0; i < nbody; i++)
        if (body[i].dynamic && pushed[i]) {
            *C += 0.5 * vec3_len2(body[i].paid) / body[i].inv_mass;
            e0 += step_energy(&before[i], &inertia[i]), R += step_energy(&body[i], &inertia[i]);
        }
    if (!(*C > 0)) return 0;
    e0 += *C, R -= e0;
    return R > 1e-9 * fmin(1.0, e0 + *C) ? R : 0;
}

/* The step's energy after the solve against before the force was paid in
 * (island.h).  When it rose by R, the impulses are scaled by s in [0, 1]:
 * with none the step loses C = sum m |paid|^2 / 2, and the step's energy
 * is convex in s, so s = C / (C + R) gains nothing (s is 1 - R / C to
 * first order: 4e-5 for the pile's worst, a resting body sinking 4e-9 m in
 * the step).  A gain within SPEC 7's 1e-9 J (and 1e-9 of the island's own
 * energy, when that is less than 1 J) is left alone: most solves of a
 * settling pile gain 1e-12 J or less, rounding, and scaled every one
 * pulled the pile's settling along another path.  Without a force there
 * is nothing to scale back to; the kinetic check's tries hold there. */
void vrIslandEnergy_PayBack(vrIslandBody *body, const vrIslandBody *before, int nbody, vrIslandContact *c, int ncontact,
                     double R, double C)
{
    double s;
    int i, k;
    if (!(R > 0)) return;
    s = C / (C + R);
    for (i = 0; i < nbody; i++) {
        body[i].v = vec3_add(before[i].v, vec3_scale(vec3_sub(body[i].v, before[i].v), s));
        body[i].w = vec3_add(before[i].w, vec3_scale(vec3_sub(body[i].w, before[i].w), s));
    }
    for (i = 0; i < ncontact; i++) {
        for (k = 0; k < c[i].npoints; k++) c[i].lambda[k] *= s;
        c[i].friction = vec3_scale(c[i].friction, s), c[i].twist *= s;
    }
}

/* the floors cut to <= 0: the bounces go; bounced[i] = 1 for a contact
 * that had one.  With hold, every point of such a contact is held (floor
 * 0, none closing its gap): Poisson's bounce then gives back exactly what
 * the compression took, which a point let close (floor < 0) and pushed
 * would keep */
void vrIslandEnergy_NoBounces(vrIslandContact *c, int ncontact, int *bounced, int hold)
{
    int i, k;
    for (i = 0; i < ncontact; i++) {
        bounced[i] = 0;
        for (k = 0; k < c[i].npoints; k++) bounced[i] |= c[i].floor[k] > 0;
        for (k = 0; k < c[i].npoints; k++) c[i].floor[k] = hold && bounced[i] ? 0 : vr_min(0, c[i].floor[k]);
    }
}

/* an impulse p along n at point at: on b, and minus on a */
static void push_pair(vrIslandBody *a, vrIslandBody *b, vec3 n, vec3 at, double p)
{
    vec3 j = vec3_scale(n, p);
    if (b->dynamic) {
        b->v = vec3_madd(b->v, b->inv_mass, j);
        b->w = vec3_add(b->w, mat33_mulv(&b->inv_inertia, vec3_cross(vec3_sub(at, b->x), j)));
    }
    if (a->dynamic) {
        a->v = vec3_madd(a->v, -a->inv_mass, j);
        a->w = vec3_sub(a->w, mat33_mulv(&a->inv_inertia, vec3_cross(vec3_sub(at, a->x), j)));
    }
}

/* how far past 1 (a rounding's worth) s must come to be taken past it */
#define POISSON_SHORT 1e-9

/* Newton's bounces at several points at once may gain energy (a turning
 * box landing on two corners: the impulse that meets one point's floor
 * also lifts the other), and a solve that gains goes without bounces: an
 * impact that came within an island step lost all it bounced with (physics
 * fuzzer seed 915, e = 1 and no force: a box knocked onto the floor on
 * three corners, 0.49 J of its 0.96 J).  Poisson's bounce instead: each
 * contact that bounced gets its compression impulses (the bounceless
 * solve's) again, e times, scaled by the s that gives back e^2 of what
 * the bounceless solve took, e the largest of theirs (with e = 1 the
 * island keeps its energy).  The velocities are linear in s, so the energy
 * is quadratic in it: K(s) = K + a s + b s^2 / 2.  The contacts' impulses
 * stay compression's (the next step's warm start).
 * s is at most 1 unless compression's impulses give back less than it
 * took (POISSON_SHORT): a solve whose ground-up pass held the bodies
 * below a level (island.c shock_pass) moved the bodies above without the
 * reactions below, so its impulses do not account for the energy it
 * took, and s = 1 left an island short (the physics fuzzer's seed 11123:
 * e = 1, no force, a light box rattling between the floor and a heavy box
 * at one instant lost 3.6e-3 J of 0.54 J in one answer).  s then gives
 * back e^2 of the loss, as Stronge's energetic restitution defines it;
 * the energy is the target, never above e0. */
void vrIslandEnergy_Poisson(vrIslandBody *body, int nbody, const vrIslandContact *c, int ncontact, const int *bounced,
                            const mat33 *inertia, double e0, vrIslandBody *save)
{
    double e = 0, k = vrIslandEnergy_Kinetic(body, inertia, nbody), a = 0, b = 0, target, s;
    int i, j;
    for (i = 0; i < ncontact; i++)
        if (bounced[i]) e = vr_max(e, c[i].e);
    if (!(e > 0) || !(k < e0)) return;
    memcpy(save, body, (size_t)nbody * sizeof *save);
    for (i = 0; i < ncontact; i++)
        for (j = 0; bounced[i] && j < c[i].npoints; j++)
            push_pair(&body[c[i].a], &body[c[i].b], c[i].n, c[i].p[j], c[i].e * c[i].lambda[j]);
    for (i = 0; i < nbody; i++) {
        vec3 dv = vec3_sub(body[i].v, save[i].v), dw = vec3_sub(body[i].w, save[i].w);
        if (!body[i].dynamic) continue;
        a += vec3_dot(save[i].v, dv) / body[i].inv_mass + vec3_dot(save[i].w, mat33_mulv(&inertia[i], dw));
        b += vec3_len2(dv) / body[i].inv_mass + vec3_dot(dw, mat33_mulv(&inertia[i], dw));
    }
    target = k + e * e * (e0 - k);
    s = b > 0 ? (-a + sqrt(a * a + 2 * b * (target - k))) / b : 0;
    if (!(s > 1 + POISSON_SHORT)) s = vr_min(1, s);
    for (i = 0; i < nbody; i++) {
        body[i].v = vec3_madd(save[i].v, s, vec3_sub(body[i].v, save[i].v));
        body[i].w = vec3_madd(save[i].w, s, vec3_sub(body[i].w, save[i].w));
    }
    if (!(s > 0) || !(vrIslandEnergy_Kinetic(body, inertia, nbody) <= e0 * (1 + 1e-12) + 1e-300))
        memcpy(body, save, (size_t)nbody * sizeof *body);
}

