/* island_contact.c — one contact of an island's solve (island_contact.h;
 * SPEC 7).
 *   make_row, row_velocity, push_row   an impulse direction: made, read, applied
 *   prepare_points, prepare_patch      a contact's rows for the solve
 *   normal_step, normal_block, block_normal_step   the points' normal impulses
 *   cone, friction_step    the patch's friction, on Coulomb's round cone
 *   vrSolve_ContactStep, vrSolve_Hold, vrSolve_ApplyImpulses
 */
#include "island_contact.h"

/* m: no contact is a point (a ball on a table presses a patch of about
 * this); without it a ball that lands spinning about the vertical spins
 * for ever and keeps its whole island awake */
#define VR_PATCH_RADIUS_MIN 1e-3

static void make_row(const vrIslandBody *A, const vrIslandBody *B, const vrSolvePatch *pa, vec3 d, vec3 p,
                     vrSolveRow *r)
{
    r->d = d;
    r->ja = vec3_cross(vec3_sub(p, A->x), d);
    r->jb = vec3_cross(vec3_sub(p, B->x), d);
    r->wa = pa->fa ? mat33_mulv(&A->inv_inertia, r->ja) : vec3_zero();
    r->wb = pa->fb ? mat33_mulv(&B->inv_inertia, r->jb) : vec3_zero();
}

/* b's velocity minus a's along the row (a held body still moves) */
static double row_velocity(const vrIslandBody *A, const vrIslandBody *B, const vrSolveRow *r)
{
    return vec3_dot(r->d, vec3_sub(B->v, A->v)) + vec3_dot(r->jb, B->w) - vec3_dot(r->ja, A->w);
}

/* the change of velocity along row x per unit impulse along row y */
static double row_k(const vrSolvePatch *pa, const vrSolveRow *x, const vrSolveRow *y)
{
    return (pa->ma + pa->mb) * vec3_dot(x->d, y->d) + vec3_dot(x->ja, y->wa) + vec3_dot(x->jb, y->wb);
}

/* impulse p along the row on b, -p on a; a held body takes nothing */
static void push_row(vrIslandBody *A, vrIslandBody *B, const vrSolvePatch *pa, const vrSolveRow *r, double p)
{
    if (pa->fb) B->v = vec3_madd(B->v, pa->mb * p, r->d), B->w = vec3_madd(B->w, p, r->wb);
    if (pa->fa) A->v = vec3_madd(A->v, -pa->ma * p, r->d), A->w = vec3_madd(A->w, -p, r->wa);
}

static void prepare_points(const vrIslandBody *A, const vrIslandBody *B, const vrIslandContact *c,
                           const vrSolvePatch *pa, vrSolvePoint *pt)
{
    int i;
    for (i = 0; i < c->npoints; i++) {
        make_row(A, B, pa, c->n, c->p[i], &pt[i].n);
        pt[i].kn = row_k(pa, &pt[i].n, &pt[i].n);
    }
}

static void prepare_patch(const vrIslandBody *A, const vrIslandBody *B, const vrIslandContact *c, vrSolvePatch *pa)
{
    vec3 centre = vec3_zero();
    double det, r = 0, a, b, d;
    int i, k;
    for (i = 0; i < c->npoints; i++) centre = vec3_add(centre, c->p[i]);
    centre = vec3_scale(centre, 1.0 / c->npoints);
    for (i = 0; i < c->npoints; i++) r += vec3_dist(c->p[i], centre);
    pa->radius = vr_max(r / c->npoints, VR_PATCH_RADIUS_MIN);
    make_row(A, B, pa, vec3_orthogonal(c->n), centre, &pa->t[0]);
    make_row(A, B, pa, vec3_cross(c->n, pa->t[0].d), centre, &pa->t[1]);
    for (k = 0; k < 2; k++) pa->f[k] = vec3_dot(pa->t[k].d, c->friction);
    a = row_k(pa, &pa->t[0], &pa->t[0]), b = row_k(pa, &pa->t[0], &pa->t[1]), d = row_k(pa, &pa->t[1], &pa->t[1]);
    det = a * d - b * b;
    if (det > 1e-300 && a > 0) pa->kt[0][0] = d / det, pa->kt[0][1] = pa->kt[1][0] = -b / det, pa->kt[1][1] = a / det;
    else pa->kt[0][0] = pa->kt[0][1] = pa->kt[1][0] = pa->kt[1][1] = 0;
    pa->twa = pa->fa ? mat33_mulv(&A->inv_inertia, c->n) : vec3_zero();
    pa->twb = pa->fb ? mat33_mulv(&B->inv_inertia, c->n) : vec3_zero();
    det = vec3_dot(c->n, vec3_add(pa->twa, pa->twb));
    pa->ktw = det > 0 && pa->radius > 0 ? 1.0 / det : 0;
}

double vrSolve_NormalVelocity(const vrIslandSolve *s, int ci, int i)
{
    const vrIslandContact *c = &s->c[ci];
    return row_velocity(&s->body[c->a], &s->body[c->b], &vrSolve_Point(s, ci, i)->n);
}

/* the normal impulse that brings the point's normal velocity to its floor,
 * kept >= 0 in total; returns the change of normal velocity it made */
static double normal_step(vrIslandSolve *s, int ci, int i)
{
    vrIslandContact *c = &s->c[ci];
    const vrSolvePoint *pt = vrSolve_Point(s, ci, i);
    double was, now;
    if (!(pt->kn > 0)) return 0;
    was = c->lambda[i];
    now = was + (c->floor[i] - vrSolve_NormalVelocity(s, ci, i)) / pt->kn;
    if (now < 0) now = 0;
    if (now == was) return 0;
    c->lambda[i] = now;
    push_row(&s->body[c->a], &s->body[c->b], &s->patch[ci], &pt->n, now - was);
    return fabs(now - was) * pt->kn;
}

/* the normal block of the contact's points: M[i][j], the normal velocity
 * at point i per unit normal impulse at point j (the bodies not held) */
static void normal_block(const vrIslandContact *c, const vrSolvePatch *pa, const vrSolvePoint *pts, double *M)
{
    int n = c->npoints, i, j;
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) M[i * n + j] = row_k(pa, &pts[j].n, &pts[i].n);
}

/* the points' impulse changes d applied at once: their normals are one
 * direction, so the bodies' velocities change by their sum */
static void push_points(vrIslandSolve *s, int ci, const double *d)
{
    const vrIslandContact *c = &s->c[ci];
    const vrSolvePatch *pa = &s->patch[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    vec3 wa = vec3_zero(), wb = vec3_zero();
    double sum = 0;
    int i;
    for (i = 0; i < c->npoints; i++) {
        const vrSolveRow *r = &vrSolve_Point(s, ci, i)->n;
        sum += d[i], wa = vec3_madd(wa, d[i], r->wa), wb = vec3_madd(wb, d[i], r->wb);
    }
    if (pa->fb) B->v = vec3_madd(B->v, pa->mb * sum, c->n), B->w = vec3_add(B->w, wb);
    if (pa->fa) A->v = vec3_madd(A->v, -pa->ma * sum, c->n), A->w = vec3_sub(A->w, wa);
}

/* The contact's points' normal impulses at once, exactly: the small LCP
 * of their normal velocities (lcp.c); Gauss-Seidel point by point, the
 * face's rotation coupling its points, took hundreds of sweeps on a box
 * rocking about a diagonal.  Returns the largest change of normal
 * velocity made. */
static double block_normal_step(vrIslandSolve *s, int ci)
{
    vrIslandContact *c = &s->c[ci];
    const vrSolvePatch *pa = &s->patch[ci];
    const double *M = &s->m[ci * VR_LCP_MAX * VR_LCP_MAX];
    double q[VR_LCP_MAX] = {0}, x[VR_LCP_MAX] = {0}, d[VR_LCP_MAX], most = 0;
    int n = c->npoints, i, j;
    if (n == 1 || (!pa->fa && !pa->fb)) {
        for (i = 0; i < n; i++) most = vr_max(most, normal_step(s, ci, i));
        return most;
    }
    for (i = 0; i < n; i++) {
        double k = 0;
        for (j = 0; j < n; j++) k += M[i * n + j] * c->lambda[j];
        q[i] = vrSolve_NormalVelocity(s, ci, i) - c->floor[i] - k;
        x[i] = c->lambda[i];
    }
    vrLcp_SolveWith(M, q, n, x, &s->lcp[ci]);
    for (i = 0; i < n; i++) {
        d[i] = x[i] - c->lambda[i];
        most = vr_max(most, fabs(d[i]) * M[i * n + i]);
        c->lambda[i] = x[i];
    }
    if (most > 0) push_points(s, ci, d);
    return most;
}

static double normal_total(const vrIslandContact *c)
{
    double s = 0;
    int i;
    for (i = 0; i < c->npoints; i++) s += c->lambda[i];
    return s;
}

/* the tangential impulse (in the patch's t1, t2) that stops the
 * centroid's slip u, cut back to the round cone |f| <= limit.  (Cut back
 * along its own direction, not turned against the slip left: K is nearly
 * isotropic in the tangent plane, and the turned impulse, a fixed point
 * that need not converge, made Gauss-Seidel gain energy.) */
static void cone(const vrSolvePatch *pa, double u1, double u2, double limit, double *g1, double *g2)
{
    double s1 = pa->f[0] - (pa->kt[0][0] * u1 + pa->kt[0][1] * u2), s2 = pa->f[1] - (pa->kt[1][0] * u1 + pa->kt[1][1] * u2);
    double len = sqrt(s1 * s1 + s2 * s2), k = len > limit ? limit / len : 1;
    *g1 = k * s1, *g2 = k * s2;
}

/* the twist: a pure angular impulse about n, within the patch's limit */
static void twist_step(vrIslandContact *c, const vrSolvePatch *pa, vrIslandBody *A, vrIslandBody *B, double limit)
{
    double spin = vec3_dot(c->n, vec3_sub(B->w, A->w)), tw = c->twist - spin * pa->ktw, most = limit * pa->radius;
    if (tw > most) tw = most;
    if (tw < -most) tw = -most;
    if (pa->fb) B->w = vec3_madd(B->w, tw - c->twist, pa->twb);
    if (pa->fa) A->w = vec3_madd(A->w, -(tw - c->twist), pa->twa);
    c->twist = tw;
}

static void friction_step(vrIslandSolve *s, int ci)
{
    vrIslandContact *c = &s->c[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    vrSolvePatch *pa = &s->patch[ci];
    double limit = c->mu * normal_total(c), f[2];
    int k;
    if (c->mu <= 0 || s->frictionless) return;
    /* with no normal impulse and no friction yet, the cone allows none and
     * the step would change nothing: a fifth of a landing pile's friction
     * steps */
    if (limit == 0 && pa->f[0] == 0 && pa->f[1] == 0 && c->twist == 0) return;
    if (pa->kt[0][0] != 0) {
        cone(pa, row_velocity(A, B, &pa->t[0]), row_velocity(A, B, &pa->t[1]), limit, &f[0], &f[1]);
        for (k = 0; k < 2; k++) push_row(A, B, pa, &pa->t[k], f[k] - pa->f[k]), pa->f[k] = f[k];
        c->friction = vec3_add(vec3_scale(pa->t[0].d, f[0]), vec3_scale(pa->t[1].d, f[1]));
    }
    if (pa->ktw > 0) twist_step(c, pa, A, B, limit);
}

/* one contact: its points' normal impulses, then its friction (the
 * largest change of normal velocity made) */
double vrSolve_ContactStep(vrIslandSolve *s, int ci)
{
    double most = block_normal_step(s, ci);
    friction_step(s, ci);
    return most;
}

/* the contact's rows and normal block made again with its lower body held */
void vrSolve_Hold(vrIslandSolve *s, int ci, int hold_a, int hold_b)
{
    vrIslandContact *c = &s->c[ci];
    const vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    vrSolvePatch *pa = &s->patch[ci];
    pa->fa = A->dynamic && !hold_a, pa->fb = B->dynamic && !hold_b;
    pa->ma = pa->fa ? A->inv_mass : 0, pa->mb = pa->fb ? B->inv_mass : 0;
    prepare_points(A, B, c, pa, vrSolve_Point(s, ci, 0));
    prepare_patch(A, B, c, pa);
    normal_block(c, pa, vrSolve_Point(s, ci, 0), &s->m[ci * VR_LCP_MAX * VR_LCP_MAX]);
    s->lcp[ci].valid = 0;
}

/* a contact's impulses so far applied to its bodies (a warm start; the
 * friction kept is its part in this step's tangent plane) */
void vrSolve_ApplyImpulses(vrIslandSolve *s, int ci)
{
    vrIslandContact *c = &s->c[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    const vrSolvePatch *pa = &s->patch[ci];
    int k;
    push_points(s, ci, c->lambda);
    for (k = 0; k < 2; k++) push_row(A, B, pa, &pa->t[k], pa->f[k]);
    c->friction = vec3_add(vec3_scale(pa->t[0].d, pa->f[0]), vec3_scale(pa->t[1].d, pa->f[1]));
    if (pa->fb) B->w = vec3_madd(B->w, c->twist, pa->twb);
    if (pa->fa) A->w = vec3_madd(A->w, -c->twist, pa->twa);
}
