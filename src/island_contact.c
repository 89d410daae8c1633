/* island_contact.c — one contact of an island's solve (island_contact.h;
 * SPEC 7).
 *   point_k, prepare_*     what an impulse at a point or the patch does
 *   push                   an impulse applied to the two bodies
 *   normal_step, normal_block, block_normal_step   the points' normal impulses
 *   cone, friction_step    the patch's friction, on Coulomb's round cone
 *   vrSolve_ContactStep, vrSolve_Hold, vrSolve_ApplyImpulses
 */
#include "island_contact.h"
#include "lcp.h"

/* K = sum over the moving bodies of (1/m) I - [r] I^-1 [r]: the change of
 * the point's relative velocity per unit impulse */
static mat33 point_k(const vrIslandBody *x, vec3 r)
{
    mat33 id = mat33_identity(), k = mat33_scale(&id, x->inv_mass), rc = mat33_cross(r), t;
    t = mat33_mul(&x->inv_inertia, &rc);
    t = mat33_mul(&rc, &t);
    t = mat33_scale(&t, -1.0);
    return mat33_add(&k, &t);
}

static double quad(const mat33 *k, vec3 a, vec3 b) { return vec3_dot(a, mat33_mulv(k, b)); }

static mat33 contact_k(const vrIslandBody *A, const vrIslandBody *B, vec3 ra, vec3 rb, int hold_a, int hold_b)
{
    mat33 k = mat33_zero();
    if (A->dynamic && !hold_a) { mat33 ka = point_k(A, ra); k = mat33_add(&k, &ka); }
    if (B->dynamic && !hold_b) { mat33 kb = point_k(B, rb); k = mat33_add(&k, &kb); }
    return k;
}

static void prepare_point(const vrIslandBody *A, const vrIslandBody *B, vec3 n, vec3 p, int hold_a, int hold_b,
                          vrSolvePoint *pt)
{
    mat33 k;
    pt->ra = vec3_sub(p, A->x);
    pt->rb = vec3_sub(p, B->x);
    k = contact_k(A, B, pt->ra, pt->rb, hold_a, hold_b);
    pt->kn = quad(&k, n, n);
}

static void prepare_patch(const vrIslandBody *A, const vrIslandBody *B, const vrIslandContact *c, int hold_a,
                          int hold_b, vrSolvePatch *pa)
{
    vec3 centre = vec3_zero();
    mat33 k, iw = mat33_zero();
    double det, r = 0;
    int i;
    for (i = 0; i < c->npoints; i++) centre = vec3_add(centre, c->p[i]);
    centre = vec3_scale(centre, 1.0 / c->npoints);
    for (i = 0; i < c->npoints; i++) r += vec3_dist(c->p[i], centre);
    pa->radius = r / c->npoints;
    prepare_point(A, B, c->n, centre, hold_a, hold_b, &pa->at);
    k = contact_k(A, B, pa->at.ra, pa->at.rb, hold_a, hold_b);
    pa->t1 = vec3_orthogonal(c->n);
    pa->t2 = vec3_cross(c->n, pa->t1);
    {
        double a = quad(&k, pa->t1, pa->t1), b = quad(&k, pa->t1, pa->t2), d = quad(&k, pa->t2, pa->t2);
        det = a * d - b * b;
        if (det > 1e-300 && a > 0) pa->kt[0][0] = d / det, pa->kt[0][1] = pa->kt[1][0] = -b / det, pa->kt[1][1] = a / det;
        else pa->kt[0][0] = pa->kt[0][1] = pa->kt[1][0] = pa->kt[1][1] = 0;
    }
    if (A->dynamic && !hold_a) iw = mat33_add(&iw, &A->inv_inertia);
    if (B->dynamic && !hold_b) iw = mat33_add(&iw, &B->inv_inertia);
    det = quad(&iw, c->n, c->n);
    pa->ktw = det > 0 && pa->radius > 0 ? 1.0 / det : 0;
}

static vec3 point_velocity(const vrIslandBody *x, vec3 r) { return vec3_add(x->v, vec3_cross(x->w, r)); }

vec3 vrSolve_RelativeVelocity(const vrIslandBody *A, const vrIslandBody *B, const vrSolvePoint *pt)
{
    return vec3_sub(point_velocity(B, pt->rb), point_velocity(A, pt->ra));
}

/* impulse P on B at the point, -P on A; a held body takes nothing */
static void push(vrIslandBody *A, vrIslandBody *B, const vrSolvePoint *pt, vec3 P, int hold_a, int hold_b)
{
    if (B->dynamic && !hold_b) {
        B->v = vec3_madd(B->v, B->inv_mass, P);
        B->w = vec3_add(B->w, mat33_mulv(&B->inv_inertia, vec3_cross(pt->rb, P)));
    }
    if (A->dynamic && !hold_a) {
        A->v = vec3_madd(A->v, -A->inv_mass, P);
        A->w = vec3_sub(A->w, mat33_mulv(&A->inv_inertia, vec3_cross(pt->ra, P)));
    }
}

/* the normal impulse that brings the point's normal velocity to its floor,
 * kept >= 0 in total; returns the change of normal velocity it made */
static double normal_step(vrIslandSolve *s, int ci, int i, int hold_a, int hold_b)
{
    vrIslandContact *c = &s->c[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    const vrSolvePoint *pt = vrSolve_Point(s, ci, i);
    double un, was, now;
    if (!(pt->kn > 0)) return 0;
    un = vec3_dot(c->n, vrSolve_RelativeVelocity(A, B, pt));
    was = c->lambda[i];
    now = was + (c->floor[i] - un) / pt->kn;
    if (now < 0) now = 0;
    if (now == was) return 0;
    c->lambda[i] = now;
    push(A, B, pt, vec3_scale(c->n, now - was), hold_a, hold_b);
    return fabs(now - was) * pt->kn;
}

/* the normal block of the contact's points: M[i][j], the normal velocity
 * at point i per unit normal impulse at point j (the bodies not held) */
static void normal_block(const vrIslandBody *A, const vrIslandBody *B, const vrIslandContact *c, const vrSolvePoint *pts,
                         int hold_a, int hold_b, double *M)
{
    vec3 ja[VR_LCP_MAX], jb[VR_LCP_MAX];
    int n = c->npoints, i, j, fa = A->dynamic && !hold_a, fb = B->dynamic && !hold_b;
    for (i = 0; i < n; i++) ja[i] = vec3_cross(pts[i].ra, c->n), jb[i] = vec3_cross(pts[i].rb, c->n);
    for (i = 0; i < n; i++) {
        vec3 ia = fa ? mat33_mulv(&A->inv_inertia, ja[i]) : vec3_zero(), ib = fb ? mat33_mulv(&B->inv_inertia, jb[i]) : vec3_zero();
        for (j = 0; j < n; j++)
            M[i * n + j] = (fa ? A->inv_mass : 0) + (fb ? B->inv_mass : 0) + vec3_dot(ia, ja[j]) + vec3_dot(ib, jb[j]);
    }
}

/* The contact's points' normal impulses at once, exactly: the small LCP
 * of their normal velocities (lcp.c); Gauss-Seidel point by point, the
 * face's rotation coupling its points, took hundreds of sweeps on a box
 * rocking about a diagonal.  Returns the largest change of normal
 * velocity made. */
static double block_normal_step(vrIslandSolve *s, int ci, int hold_a, int hold_b)
{
    vrIslandContact *c = &s->c[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    const double *M = &s->m[ci * VR_LCP_MAX * VR_LCP_MAX];
    double q[VR_LCP_MAX] = {0}, x[VR_LCP_MAX] = {0}, most = 0;
    int n = c->npoints, i, j, fa = A->dynamic && !hold_a, fb = B->dynamic && !hold_b;
    if (n == 1 || (!fa && !fb)) {
        for (i = 0; i < n; i++) most = vr_max(most, normal_step(s, ci, i, hold_a, hold_b));
        return most;
    }
    for (i = 0; i < n; i++) {
        double k = 0;
        for (j = 0; j < n; j++) k += M[i * n + j] * c->lambda[j];
        q[i] = vec3_dot(c->n, vrSolve_RelativeVelocity(A, B, vrSolve_Point(s, ci, i))) - c->floor[i] - k;
        x[i] = c->lambda[i];
    }
    vrLcp_Solve(M, q, n, x);
    for (i = 0; i < n; i++) {
        double d = x[i] - c->lambda[i];
        if (d == 0) continue;
        push(A, B, vrSolve_Point(s, ci, i), vec3_scale(c->n, d), hold_a, hold_b);
        most = vr_max(most, fabs(d) * M[i * n + i]);
        c->lambda[i] = x[i];
    }
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
static void cone(const vrSolvePatch *pa, double u1, double u2, double f1, double f2, double limit, double *g1, double *g2)
{
    double s1 = f1 - (pa->kt[0][0] * u1 + pa->kt[0][1] * u2), s2 = f2 - (pa->kt[1][0] * u1 + pa->kt[1][1] * u2);
    double len = sqrt(s1 * s1 + s2 * s2), k = len > limit ? limit / len : 1;
    *g1 = k * s1, *g2 = k * s2;
}

static void friction_step(vrIslandSolve *s, int ci, int hold_a, int hold_b)
{
    vrIslandContact *c = &s->c[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    const vrSolvePatch *pa = &s->patch[ci];
    double limit = c->mu * normal_total(c), f1, f2, u1, u2, was1, was2;
    vec3 u, f;
    if (c->mu <= 0 || s->frictionless) return;
    if (pa->kt[0][0] != 0) {
        u = vrSolve_RelativeVelocity(A, B, &pa->at);
        u1 = vec3_dot(pa->t1, u), u2 = vec3_dot(pa->t2, u);
        was1 = vec3_dot(pa->t1, c->friction), was2 = vec3_dot(pa->t2, c->friction);
        cone(pa, u1, u2, was1, was2, limit, &f1, &f2);
        f = vec3_add(vec3_scale(pa->t1, f1), vec3_scale(pa->t2, f2));
        push(A, B, &pa->at, vec3_sub(f, c->friction), hold_a, hold_b);
        c->friction = f;
    }
    if (pa->ktw > 0) {       /* the twist: a pure angular impulse about n */
        double spin = vec3_dot(c->n, vec3_sub(B->w, A->w)), tw = c->twist - spin * pa->ktw;
        double most = limit * pa->radius;
        vec3 dw;
        if (tw > most) tw = most;
        if (tw < -most) tw = -most;
        dw = vec3_scale(c->n, tw - c->twist);
        if (B->dynamic && !hold_b) B->w = vec3_add(B->w, mat33_mulv(&B->inv_inertia, dw));
        if (A->dynamic && !hold_a) A->w = vec3_sub(A->w, mat33_mulv(&A->inv_inertia, dw));
        c->twist = tw;
    }
}

/* one contact: its points' normal impulses, then its friction (the
 * largest change of normal velocity made) */
double vrSolve_ContactStep(vrIslandSolve *s, int ci, int hold_a, int hold_b)
{
    double most = block_normal_step(s, ci, hold_a, hold_b);
    friction_step(s, ci, hold_a, hold_b);
    return most;
}

/* the contact's points and patch made again with its lower body held */
void vrSolve_Hold(vrIslandSolve *s, int ci, int hold_a, int hold_b)
{
    vrIslandContact *c = &s->c[ci];
    const vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    int i;
    for (i = 0; i < c->npoints; i++) prepare_point(A, B, c->n, c->p[i], hold_a, hold_b, vrSolve_Point(s, ci, i));
    prepare_patch(A, B, c, hold_a, hold_b, &s->patch[ci]);
    normal_block(A, B, c, vrSolve_Point(s, ci, 0), hold_a, hold_b, &s->m[ci * VR_LCP_MAX * VR_LCP_MAX]);
}

/* a contact's impulses so far applied to its bodies (a warm start) */
void vrSolve_ApplyImpulses(vrIslandSolve *s, int ci)
{
    vrIslandContact *c = &s->c[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    vec3 dw = vec3_scale(c->n, c->twist);
    int i;
    for (i = 0; i < c->npoints; i++) push(A, B, vrSolve_Point(s, ci, i), vec3_scale(c->n, c->lambda[i]), 0, 0);
    push(A, B, &s->patch[ci].at, c->friction, 0, 0);
    if (B->dynamic) B->w = vec3_add(B->w, mat33_mulv(&B->inv_inertia, dw));
    if (A->dynamic) A->w = vec3_sub(A->w, mat33_mulv(&A->inv_inertia, dw));
}
