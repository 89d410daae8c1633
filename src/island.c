/* island.c — an island's impulses, found together (island.h; SPEC 7).
 *   Point, Patch, prepare_*   what an impulse at a point or the patch does
 *   push                   an impulse applied to the two bodies
 *   normal_step            one Gauss-Seidel step at a point
 *   cone, friction_step    the patch's friction, on Coulomb's round cone
 *   contact_step, sweep    a contact, every contact once, in order
 *   levels, shock_pass     the ground-up pass with lower bodies held still
 *   vrIsland_Solve
 */
#include <stdlib.h>
#include <string.h>
#include "island.h"
#include "lcp.h"

/* what one point of a contact needs through the sweeps: its lever arms
 * and the inverse effective mass along the normal (both bodies free, or
 * the lower one held still in the shock pass) */
typedef struct Point {
    vec3 ra, rb;
    double kn;                /* n.K n: normal velocity per unit normal impulse */
} Point;

/* Friction acts on the contact as a whole (a patch, as PhysX does): a
 * tangential impulse at the points' centroid within mu times the points'
 * normal impulses together, and a twist about the normal within that times
 * the patch's mean radius.  Per point, the points' coupling through the
 * body's turning sets their impulses against each other and wastes the
 * cone: a box on a slope below atan mu crept down it. */
typedef struct Patch {
    Point at;                 /* the centroid */
    vec3 t1, t2;
    double kt[2][2];          /* K in the tangent plane, inverted (0 when singular) */
    double ktw;               /* twist about n per unit angular impulse, inverted (0: none) */
    double radius;            /* mean distance of the points from the centroid */
} Patch;

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
                          Point *pt)
{
    mat33 k;
    pt->ra = vec3_sub(p, A->x);
    pt->rb = vec3_sub(p, B->x);
    k = contact_k(A, B, pt->ra, pt->rb, hold_a, hold_b);
    pt->kn = quad(&k, n, n);
}

static void prepare_patch(const vrIslandBody *A, const vrIslandBody *B, const vrIslandContact *c, int hold_a,
                          int hold_b, Patch *pa)
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

static vec3 relative_velocity(const vrIslandBody *A, const vrIslandBody *B, const Point *pt)
{
    return vec3_sub(point_velocity(B, pt->rb), point_velocity(A, pt->ra));
}

/* impulse P on B at the point, -P on A; a held body takes nothing */
static void push(vrIslandBody *A, vrIslandBody *B, const Point *pt, vec3 P, int hold_a, int hold_b)
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

typedef struct Solve {
    vrIslandBody *body;
    vrIslandContact *c;
    Point *pt;                /* VR_ISLAND_POINTS per contact */
    Patch *patch;             /* one per contact */
    double *m;                /* per contact: its points' normal block, VR_LCP_MAX^2 (block_normal_step) */
    int ncontact;
    int frictionless;         /* the energy check's second try */
} Solve;

static Point *point_of(const Solve *s, int ci, int i) { return &s->pt[ci * VR_ISLAND_POINTS + i]; }

/* the normal impulse that brings the point's normal velocity to its floor,
 * kept >= 0 in total; returns the change of normal velocity it made */
static double normal_step(Solve *s, int ci, int i, int hold_a, int hold_b)
{
    vrIslandContact *c = &s->c[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    const Point *pt = point_of(s, ci, i);
    double un, was, now;
    if (!(pt->kn > 0)) return 0;
    un = vec3_dot(c->n, relative_velocity(A, B, pt));
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
static void normal_block(const vrIslandBody *A, const vrIslandBody *B, const vrIslandContact *c, const Point *pts,
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
static double block_normal_step(Solve *s, int ci, int hold_a, int hold_b)
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
        q[i] = vec3_dot(c->n, relative_velocity(A, B, point_of(s, ci, i))) - c->floor[i] - k;
        x[i] = c->lambda[i];
    }
    vrLcp_Solve(M, q, n, x);
    for (i = 0; i < n; i++) {
        double d = x[i] - c->lambda[i];
        if (d == 0) continue;
        push(A, B, point_of(s, ci, i), vec3_scale(c->n, d), hold_a, hold_b);
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
static void cone(const Patch *pa, double u1, double u2, double f1, double f2, double limit, double *g1, double *g2)
{
    double s1 = f1 - (pa->kt[0][0] * u1 + pa->kt[0][1] * u2), s2 = f2 - (pa->kt[1][0] * u1 + pa->kt[1][1] * u2);
    double len = sqrt(s1 * s1 + s2 * s2), k = len > limit ? limit / len : 1;
    *g1 = k * s1, *g2 = k * s2;
}

static void friction_step(Solve *s, int ci, int hold_a, int hold_b)
{
    vrIslandContact *c = &s->c[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    const Patch *pa = &s->patch[ci];
    double limit = c->mu * normal_total(c), f1, f2, u1, u2, was1, was2;
    vec3 u, f;
    if (c->mu <= 0 || s->frictionless) return;
    if (pa->kt[0][0] != 0) {
        u = relative_velocity(A, B, &pa->at);
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

/* one contact: its points' normal impulses, then its friction; the
 * largest change of normal velocity made */
static double contact_step(Solve *s, int ci, int hold_a, int hold_b)
{
    double most = block_normal_step(s, ci, hold_a, hold_b);
    friction_step(s, ci, hold_a, hold_b);
    return most;
}

static double sweep(Solve *s)
{
    double most = 0;
    int ci;
    for (ci = 0; ci < s->ncontact; ci++) most = vr_max(most, contact_step(s, ci, 0, 0));
    return most;
}

/* what the sweeps leave: the normal velocities below their floors */
static double residual(Solve *s)
{
    double worst = 0;
    int ci, i;
    for (ci = 0; ci < s->ncontact; ci++) {
        const vrIslandContact *c = &s->c[ci];
        for (i = 0; i < c->npoints; i++) {
            const Point *pt = point_of(s, ci, i);
            double un = vec3_dot(c->n, relative_velocity(&s->body[c->a], &s->body[c->b], pt));
            if (pt->kn > 0) worst = vr_max(worst, c->floor[i] - un);
        }
    }
    return worst;
}

/* breadth first from the static bodies: a body's level is the fewest
 * contacts between it and one (-1: it touches none, even through others);
 * returns 1 when some body is static */
static int levels(vrIslandBody *b, int nb, const vrIslandContact *c, int nc)
{
    int i, k, changed = 1, any = 0;
    for (i = 0; i < nb; i++) {
        b[i].level = b[i].dynamic ? -1 : 0;
        any |= !b[i].dynamic;
    }
    for (k = 0; changed && any; k++) {
        changed = 0;
        for (i = 0; i < nc; i++) {
            vrIslandBody *A = &b[c[i].a], *B = &b[c[i].b];
            if (A->level == k && B->level < 0) B->level = k + 1, changed = 1;
            if (B->level == k && A->level < 0) A->level = k + 1, changed = 1;
        }
    }
    return any;
}

/* the level a contact's pass belongs to: its higher body's (the one it
 * settles), -1 when a body of it touches no static body */
static int pass_level(const vrIslandBody *b, const vrIslandContact *c)
{
    int la = b[c->a].level, lb = b[c->b].level;
    return la < 0 || lb < 0 ? -1 : la > lb ? la : lb;
}

/* the contact's points and patch made again with its lower body held */
static void hold(Solve *s, int ci, int hold_a, int hold_b)
{
    vrIslandContact *c = &s->c[ci];
    const vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    int i;
    for (i = 0; i < c->npoints; i++) prepare_point(A, B, c->n, c->p[i], hold_a, hold_b, point_of(s, ci, i));
    prepare_patch(A, B, c, hold_a, hold_b, &s->patch[ci]);
    normal_block(A, B, c, point_of(s, ci, 0), hold_a, hold_b, &s->m[ci * VR_LCP_MAX * VR_LCP_MAX]);
}

/* a contact's impulses so far applied to its bodies (a warm start) */
static void apply_impulses(Solve *s, int ci)
{
    vrIslandContact *c = &s->c[ci];
    vrIslandBody *A = &s->body[c->a], *B = &s->body[c->b];
    vec3 dw = vec3_scale(c->n, c->twist);
    int i;
    for (i = 0; i < c->npoints; i++) push(A, B, point_of(s, ci, i), vec3_scale(c->n, c->lambda[i]), 0, 0);
    push(A, B, &s->patch[ci].at, c->friction, 0, 0);
    if (B->dynamic) B->w = vec3_add(B->w, mat33_mulv(&B->inv_inertia, dw));
    if (A->dynamic) A->w = vec3_sub(A->w, mat33_mulv(&A->inv_inertia, dw));
}

/* From the ground up: level by level, the contacts that settle the bodies
 * of that level (against the bodies under them, held still, and among
 * themselves), swept until they settle, so that a body is settled against
 * what lies under it before anything above is settled against it, and is
 * not moved again by what lies above. */
static void shock_pass(Solve *s, int sweeps, double tol)
{
    int ci, level, top = -1, k;
    for (ci = 0; ci < s->ncontact; ci++) top = top > pass_level(s->body, &s->c[ci]) ? top : pass_level(s->body, &s->c[ci]);
    for (level = 1; level <= top; level++) {
        for (ci = 0; ci < s->ncontact; ci++) {
            const vrIslandContact *c = &s->c[ci];
            if (pass_level(s->body, c) == level)
                hold(s, ci, s->body[c->a].level < level, s->body[c->b].level < level);
        }
        for (k = 0; k < sweeps; k++) {
            double most = 0;
            for (ci = 0; ci < s->ncontact; ci++) {
                const vrIslandContact *c = &s->c[ci];
                if (pass_level(s->body, c) != level) continue;
                most = vr_max(most, contact_step(s, ci, s->body[c->a].level < level, s->body[c->b].level < level));
            }
            if (most <= tol) break;
        }
    }
    for (ci = 0; ci < s->ncontact; ci++) hold(s, ci, 0, 0);
}

static int valid(const vrIslandBody *body, int nbody, const vrIslandContact *c, int ncontact)
{
    int i, k;
    for (i = 0; i < ncontact; i++) {
        if (c[i].a < 0 || c[i].a >= nbody || c[i].b < 0 || c[i].b >= nbody || c[i].a == c[i].b) return 0;
        if (c[i].npoints < 1 || c[i].npoints > VR_ISLAND_POINTS || !(c[i].mu >= 0)) return 0;
        for (k = 0; k < c[i].npoints; k++)
            if (!isfinite(c[i].floor[k])) return 0;
    }
    for (i = 0; i < nbody; i++)
        if (body[i].dynamic && !(body[i].inv_mass > 0)) return 0;
    return 1;
}

static int solve(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                 int frictionless, vrIslandStats *st)
{
    Solve s;
    int ci, i, k;
    st->sweeps = st->shock = st->frictionless = st->bounceless = 0;
    st->residual = 0;
    if (!valid(body, nbody, c, ncontact)) return -1;
    if (ncontact == 0) return 0;
    s.pt = malloc((size_t)ncontact * VR_ISLAND_POINTS * sizeof *s.pt);
    s.patch = malloc((size_t)ncontact * sizeof *s.patch);
    s.m = malloc((size_t)ncontact * VR_LCP_MAX * VR_LCP_MAX * sizeof *s.m);
    if (!s.pt || !s.patch || !s.m) {
        free(s.pt);
        free(s.patch);
        free(s.m);
        return -1;
    }
    s.body = body, s.c = c, s.ncontact = ncontact, s.frictionless = frictionless;
    for (ci = 0; ci < ncontact; ci++) {
        hold(&s, ci, 0, 0);
        if (c[ci].warm && !frictionless) {
            apply_impulses(&s, ci);
            continue;
        }
        for (i = 0; i < c[ci].npoints; i++) c[ci].lambda[i] = 0;
        c[ci].friction = vec3_zero();
        c[ci].twist = 0;
    }
    for (k = 0; k < sweeps; k++) {
        st->sweeps++;
        if (sweep(&s) <= tol) break;
    }
    if (residual(&s) > tol && levels(body, nbody, c, ncontact)) {
        shock_pass(&s, sweeps, tol);
        st->shock = 1;
    }
    st->residual = residual(&s);
    free(s.pt);
    free(s.patch);
    free(s.m);
    return 0;
}

/* the bodies' kinetic energy (inertia from the inverse given) */
static double kinetic(const vrIslandBody *b, int n)
{
    double e = 0;
    int i;
    for (i = 0; i < n; i++) {
        mat33 inertia;
        if (!b[i].dynamic) continue;
        inertia = mat33_inverse(&b[i].inv_inertia);
        e += 0.5 / b[i].inv_mass * vec3_len2(b[i].v) + 0.5 * vec3_dot(b[i].w, mat33_mulv(&inertia, b[i].w));
    }
    return e;
}

/* the floors cut to <= 0: the bounces go */
static void no_bounces(vrIslandContact *c, int ncontact)
{
    int i, k;
    for (i = 0; i < ncontact; i++)
        for (k = 0; k < c[i].npoints; k++) c[i].floor[k] = vr_min(0, c[i].floor[k]);
}

int vrIsland_Solve(vrIslandBody *body, int nbody, vrIslandContact *c, int ncontact, int sweeps, double tol,
                   vrIslandStats *st)
{
    vrIslandBody *before;
    double e0;
    int i, r, try;
    vrIslandStats dummy;
    if (!st) st = &dummy;
    if (nbody <= 0 || ncontact <= 0) return solve(body, nbody, c, ncontact, sweeps, tol, 0, st);
    before = malloc((size_t)nbody * sizeof *before);
    if (!before) return -1;
    memcpy(before, body, (size_t)nbody * sizeof *before);
    e0 = kinetic(body, nbody);
    /* The exact solution with floors <= 0 never gains energy (the
     * impulses' work at the velocities after is lambda floor + f.u <= 0);
     * a solve left short of it with friction may, and bounces may, and
     * such a solve is done again without friction, then without bounces
     * too, which never gains (each step then lowers the energy or keeps it). */
    for (try = 0; try < 3; try++) {
        if (try == 2) no_bounces(c, ncontact);
        r = solve(body, nbody, c, ncontact, sweeps, tol, try > 0, st);
        st->frictionless = try > 0, st->bounceless = try > 1;
        if (r != 0 || try == 2 || kinetic(body, nbody) <= e0 * (1 + 1e-12) + 1e-300) break;
        memcpy(body, before, (size_t)nbody * sizeof *before);
    }
    if (st->frictionless)
        for (i = 0; i < ncontact; i++) c[i].friction = vec3_zero(), c[i].twist = 0;
    free(before);
    return r;
}
