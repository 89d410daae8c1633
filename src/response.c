/* response.c — the 15x15 collision response of thesis 3.2.2 (Hahn 1988;
 * Moore & Wilhelms 1988), frictionless, with Newton's restitution (SPEC 3.4).
 *
 * Unknowns x = (v1', v2', w1', w2', R), R the impulse on body 1:
 *   rows  0-2   m1 v1' - R         = m1 v1
 *   rows  3-5   m2 v2' + R         = m2 v2
 *   rows  6-8   I1 w1' - p1 x R    = I1 w1
 *   rows  9-11  I2 w2' + p2 x R    = I2 w2
 *   rows 12-13  t1.R = 0, t2.R = 0 (no friction: R along n)
 *   row  14     n.u' = -e n.u,  u = (v2 + w2 x p2) - (v1 + w1 x p1)
 * A static body's rows become v' = v, w' = w.  A dynamic body's rows are
 * taken divided by its mass and multiplied by its inverse inertia:
 *   v1' - R / m1 = v1,   w1' - I1^-1 (p1 x R) = w1   (and body 2's alike),
 * the same equations, so the same solution, with every body's block a
 * unit diagonal whatever its units: a 0.2 kg apple's inertia rows (1e-4)
 * no longer sit beside a table's identity rows, klu_rcond's ratio of
 * pivots measures the contact, not the units, and polish() is rarely
 * needed.  The pattern is the same for
 * every contact (explicit zeros where a value vanishes), so KLU analyses it
 * once.  Pivots: klu_refactor reuses the pivot order of the factorisation
 * it was given, so results would depend on which contacts were factored
 * before — and differ between processes.  Instead each solve refactors a
 * canonical factorisation chosen by the matrix's zero pattern (a static
 * body's identity rows and axis-aligned normals put exact zeros where a
 * general contact has pivots), made once from a fixed fill of that pattern;
 * when that refactor is singular or poor, the contact is factored afresh in
 * a scratch object.  Each solve depends on its own matrix only.
 */
#include <stdlib.h>
#include <klu.h>
#include "response.h"

#define N 15
#define NNZ_MAX 90   /* entries of the pattern with the sticking rows; 66 without */
#define RCOND_MIN 1e-12
#define RESIDUAL_MAX 1e-10    /* relative residual accepted */
#define RESIDUAL_FINE 1e-15   /* rounding: with RCOND_FINE, no refinement needed */
#define RCOND_FINE 1e-3

/* zero patterns with a canonical factorisation kept: exact zeros of lever
 * arms and normals vary (a wall's normal is an axis; a cube's or sphere's
 * world inertia is scalar, motion.c), so a 100-object room under gravity
 * meets about 60 in 200 frames and 75 in 600 (808 and 1,600 when rotated
 * inertias carried rounding); a table, open addressing, emptied when 3/4
 * full (a few MB of factors at most) */
#define PATTERNS 4096

typedef struct vrPattern {
    unsigned long long bits[2];   /* bit k: Ax[k] != 0 */
    klu_numeric *numeric;
} vrPattern;

/* One CSC pattern with its analysis and canonical factorisations.  Two
 * are kept: without friction rows 12 and 13 only touch R (R.t = 0, the
 * thesis's system, as small as it can be); with friction they may hold
 * the sticking condition u'.t = 0 too, so they also touch the velocities. */
typedef struct vrSystem {
    klu_symbolic *symbolic;
    vrPattern pattern[PATTERNS];
    int npattern;
    int nnz;
    int Ap[N + 1], Ai[NNZ_MAX];
    double Ax[NNZ_MAX];
    int at[N][N];            /* at[row][col]: index into Ax, -1 outside the pattern */
} vrSystem;

struct vrResponder {
    klu_common common;
    vrSystem plain, friction;
    vrSystem *s;             /* the one being assembled and solved */
    vrResponseStats stats;
};

/* the pattern, column by column (CSC) */
static void build_pattern(vrSystem *r, int sticking)
{
    int col, row, k = 0, i;
    for (row = 0; row < N; row++)
        for (col = 0; col < N; col++) r->at[row][col] = -1;
    for (col = 0; col < N; col++) {
        int mark[N] = {0};
        if (col < 6) { mark[col] = 1; mark[12] = mark[13] = sticking; mark[14] = 1; }   /* v1', v2' */
        else if (col < 12) {                                          /* w1', w2' */
            int base = col < 9 ? 6 : 9;
            for (i = 0; i < 3; i++) mark[base + i] = 1;
            mark[12] = mark[13] = sticking;
            mark[14] = 1;
        } else {                                                      /* R */
            int j = col - 12;
            mark[j] = mark[3 + j] = 1;
            for (i = 0; i < 3; i++) mark[6 + i] = mark[9 + i] = 1;
            mark[12] = mark[13] = 1;
        }
        r->Ap[col] = k;
        for (row = 0; row < N; row++)
            if (mark[row]) { r->Ai[k] = row; r->at[row][col] = k++; }
    }
    r->Ap[N] = k;
    r->nnz = k;
}

static void set(vrResponder *r, int row, int col, double v) { r->s->Ax[r->s->at[row][col]] = v; }

static void set_block(vrResponder *r, int row, int col, const mat33 *m)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) set(r, row + i, col + j, m->m[i][j]);
}

/* how rows 12 and 13 hold the impulse's tangential part (t1, t2) */
typedef enum { FRICTIONLESS, STICK, SLIDE } Tangent;

/* fills Ax and the right-hand side for one contact: rows 12, 13 are
 * R.t = 0 (FRICTIONLESS), u'.t = 0 (STICK: the contact points leave
 * together), or R.t + mu (R.n)(s.t) = 0 (SLIDE: mu times the normal
 * impulse along s) */
static void assemble(vrResponder *r, const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e, Tangent how,
                     double mu, vec3 s_dir, double *rhs)
{
    const vrImpactBody *b[2] = {b1, b2};
    vec3 t1 = vec3_orthogonal(n), t2 = vec3_cross(n, t1), tk[2];
    vec3 u = vec3_sub(vec3_add(b2->v, vec3_cross(b2->w, b2->p)), vec3_add(b1->v, vec3_cross(b1->w, b1->p)));
    int s, i;
    for (i = 0; i < r->s->nnz; i++) r->s->Ax[i] = 0.0;
    for (s = 0; s < 2; s++) {
        const vrImpactBody *x = b[s];
        double sign = s == 0 ? -1.0 : 1.0;          /* -R on body 1's rows, +R on body 2's */
        int vr = 3 * s, wr = 6 + 3 * s;
        mat33 id = mat33_identity(), pc = mat33_cross(x->p), lever;
        vec3 pn = vec3_cross(x->p, n);
        set_block(r, wr, wr, &id);
        for (i = 0; i < 3; i++) {
            set(r, vr + i, vr + i, 1.0);
            set(r, vr + i, 12 + i, x->is_static ? 0.0 : sign / x->mass);
        }
        if (!x->is_static) {
            pc = mat33_scale(&pc, sign);
            lever = mat33_mul(&x->inv_inertia, &pc);
            set_block(r, wr, 12, &lever);
        }
        /* restitution row: +n.v2' + (p2 x n).w2' - n.v1' - (p1 x n).w1';
         * sticking rows alike along t1, t2 */
        for (i = 0; i < 3; i++) {
            set(r, 14, vr + i, sign * vec3_get(n, i));
            set(r, 14, wr + i, sign * vec3_get(pn, i));
        }
        if (how == STICK) {
            int k;
            tk[0] = t1, tk[1] = t2;
            for (k = 0; k < 2; k++) {
                vec3 pt = vec3_cross(x->p, tk[k]);
                for (i = 0; i < 3; i++) {
                    set(r, 12 + k, vr + i, sign * vec3_get(tk[k], i));
                    set(r, 12 + k, wr + i, sign * vec3_get(pt, i));
                }
            }
        }
        rhs[vr] = x->v.x, rhs[vr + 1] = x->v.y, rhs[vr + 2] = x->v.z;
        rhs[wr] = x->w.x, rhs[wr + 1] = x->w.y, rhs[wr + 2] = x->w.z;
    }
    if (how != STICK) {
        double m1 = how == SLIDE ? mu * vec3_dot(s_dir, t1) : 0, m2 = how == SLIDE ? mu * vec3_dot(s_dir, t2) : 0;
        for (i = 0; i < 3; i++) {
            set(r, 12, 12 + i, vec3_get(t1, i) + m1 * vec3_get(n, i));
            set(r, 13, 12 + i, vec3_get(t2, i) + m2 * vec3_get(n, i));
        }
    }
    rhs[12] = rhs[13] = 0.0;
    rhs[14] = -e * vec3_dot(n, u);
}

/* res = b - A x */
static void residual(const vrResponder *r, const double *x, const double *b, double *res)
{
    int col, k, i;
    for (i = 0; i < N; i++) res[i] = b[i];
    for (col = 0; col < N; col++)
        for (k = r->s->Ap[col]; k < r->s->Ap[col + 1]; k++) res[r->s->Ai[k]] -= r->s->Ax[k] * x[col];
}

static double larger(double a, double b) { return a > b ? a : b; }   /* fmax is a call */

/* max-norm residual res = b - A x relative to the sizes involved
 * (infinite when x is not finite) */
static double residual_size(const vrResponder *r, const double *x, const double *b, double *res)
{
    double amax = 0, xmax = 0, bmax = 0, rmax = 0;
    int k, i;
    residual(r, x, b, res);
    for (k = 0; k < r->s->nnz; k++) amax = larger(amax, fabs(r->s->Ax[k]));
    for (i = 0; i < N; i++) {
        if (!isfinite(x[i])) return INFINITY;
        rmax = larger(rmax, fabs(res[i]));
        xmax = larger(xmax, fabs(x[i]));
        bmax = larger(bmax, fabs(b[i]));
    }
    return rmax / (bmax + amax * xmax);
}

/* One step of iterative refinement: the 15x15 system is badly scaled
 * when masses differ by orders of magnitude (and a refactor keeps the
 * pivots of a canonical fill), and a step recovers most of it.  Skipped
 * when the residual is at rounding and the factors well conditioned
 * (rcond: klu_rcond's, or 0 when not known), so that the error is too.
 * 0 when x is then good to RESIDUAL_MAX. */
static int polish(vrResponder *r, klu_numeric *num, double rcond, double *x, const double *b)
{
    double d[N], size = residual_size(r, x, b, d);
    int i;
    if (size <= RESIDUAL_FINE && rcond >= RCOND_FINE) return 0;
    r->stats.refined++;
    if (klu_solve(r->s->symbolic, num, N, 1, d, &r->common)) {
        for (i = 0; i < N; i++) x[i] += d[i];
        size = residual_size(r, x, b, d);
    }
    return size <= RESIDUAL_MAX ? 0 : -1;
}

static void pattern_of(const vrResponder *r, unsigned long long bits[2])
{
    int k;
    bits[0] = bits[1] = 0;
    for (k = 0; k < r->s->nnz; k++)
        if (r->s->Ax[k] != 0) bits[k / 64] |= 1ULL << (k % 64);
}

/* the canonical factorisation of a zero pattern: the pattern filled with
 * fixed values of the sizes a contact has (masses and inertias ~1, lever
 * arms and normal components below), slightly varied to avoid pivot ties */
static klu_numeric *canonical_for(vrResponder *r, const unsigned long long bits[2])
{
    double fill[NNZ_MAX];
    int k, col;
    for (col = 0; col < N; col++)
        for (k = r->s->Ap[col]; k < r->s->Ap[col + 1]; k++) {
            int row = r->s->Ai[k], on = (bits[k / 64] >> (k % 64)) & 1;
            double size = row == col || (row < 12 && col < 12) ? 1.0 : 0.5;
            fill[k] = on ? size * (1.0 + 0.01 * ((row * 31 + col * 17) % 13)) : 0.0;
        }
    r->stats.factors++;
    return klu_factor(r->s->Ap, r->s->Ai, fill, r->s->symbolic, &r->common);
}

static void forget_patterns(vrResponder *r)
{
    int i;
    for (i = 0; i < PATTERNS; i++)
        if (r->s->pattern[i].numeric) klu_free_numeric(&r->s->pattern[i].numeric, &r->common);
    r->s->npattern = 0;
}

/* The canonical factorisation of this matrix's pattern.  The table only
 * saves work: a pattern's factorisation is the same whenever it is made, so
 * emptying it changes no result (what a solve gives must not depend on
 * which contacts this process saw before). */
static klu_numeric *numeric_for(vrResponder *r)
{
    unsigned long long bits[2], h;
    vrPattern *slot;
    int i;
    pattern_of(r, bits);
    h = (bits[0] ^ (bits[1] * 0x9E3779B97F4A7C15ull)) * 0xBF58476D1CE4E5B9ull;
    for (i = (int)((h >> 32) % PATTERNS); r->s->pattern[i].numeric; i = (i + 1) % PATTERNS)
        if (r->s->pattern[i].bits[0] == bits[0] && r->s->pattern[i].bits[1] == bits[1]) return r->s->pattern[i].numeric;
    if (4 * (r->s->npattern + 1) > 3 * PATTERNS) {
        forget_patterns(r);
        return numeric_for(r);
    }
    slot = &r->s->pattern[i];
    slot->bits[0] = bits[0];
    slot->bits[1] = bits[1];
    slot->numeric = canonical_for(r, bits);
    if (slot->numeric) r->s->npattern++;
    return slot->numeric;
}

static int refactor_solve(vrResponder *r, double *x, const double *b)
{
    klu_numeric *num = numeric_for(r);
    if (!num) return -1;
    r->stats.refactors++;
    if (!klu_refactor(r->s->Ap, r->s->Ai, r->s->Ax, r->s->symbolic, num, &r->common)) return -1;
    if (!klu_rcond(r->s->symbolic, num, &r->common) || r->common.rcond < RCOND_MIN) return -1;
    if (!klu_solve(r->s->symbolic, num, N, 1, x, &r->common)) return -1;
    return polish(r, num, r->common.rcond, x, b);
}

static int fresh_solve(vrResponder *r, double *x, const double *b)
{
    klu_numeric *num;
    int ok;
    r->stats.factors++;
    num = klu_factor(r->s->Ap, r->s->Ai, r->s->Ax, r->s->symbolic, &r->common);
    if (!num) return -1;
    ok = klu_solve(r->s->symbolic, num, N, 1, x, &r->common) && polish(r, num, 0, x, b) == 0;
    klu_free_numeric(&num, &r->common);
    return ok ? 0 : -1;
}

vrResponder *vrResponder_Create(void)
{
    vrResponder *r = calloc(1, sizeof *r);
    if (!r) return NULL;
    klu_defaults(&r->common);
    /* no row scaling by KLU: the rows come in unit-free (assemble), a
     * refactor keeps its pivots, and an LU without pivoting of D A is D
     * times that of A, so scaling would only add rounding; the pattern is
     * ours, so KLU's input checks are not needed either (a large part of
     * klu_refactor's work), and every answer is still checked. */
    r->common.scale = -1;
    build_pattern(&r->plain, 0);
    build_pattern(&r->friction, 1);
    r->plain.symbolic = klu_analyze(N, r->plain.Ap, r->plain.Ai, &r->common);
    r->friction.symbolic = klu_analyze(N, r->friction.Ap, r->friction.Ai, &r->common);
    r->s = &r->plain;
    if (!r->plain.symbolic || !r->friction.symbolic) {
        vrResponder_Free(r);
        return NULL;
    }
    return r;
}

void vrResponder_Free(vrResponder *r)
{
    vrSystem *sys[2];
    int i;
    if (!r) return;
    sys[0] = &r->plain, sys[1] = &r->friction;
    for (i = 0; i < 2; i++) {
        r->s = sys[i];
        forget_patterns(r);
        if (r->s->symbolic) klu_free_symbolic(&r->s->symbolic, &r->common);
    }
    free(r);
}

/* one solve of the system assembled as `how` says, into x */
static int solve_as(vrResponder *r, const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e, Tangent how,
                    double mu, vec3 s_dir, double *x)
{
    double rhs[N];
    int i;
    r->s = how == FRICTIONLESS ? &r->plain : &r->friction;
    assemble(r, b1, b2, n, e, how, mu, s_dir, rhs);
    for (i = 0; i < N; i++) x[i] = rhs[i];
    r->stats.solves++;
    if (refactor_solve(r, x, rhs) == 0) return 0;
    for (i = 0; i < N; i++) x[i] = rhs[i];
    return fresh_solve(r, x, rhs);
}

static double kinetic(const vrImpactBody *b, vec3 v, vec3 w)
{
    return b->is_static ? 0 : 0.5 * b->mass * vec3_dot(v, v) + 0.5 * vec3_dot(w, mat33_mulv(&b->inertia, w));
}

static double kinetic_of(const vrImpactBody *b1, const vrImpactBody *b2, const double *x)
{
    return kinetic(b1, vec3_make(x[0], x[1], x[2]), vec3_make(x[6], x[7], x[8]))
         + kinetic(b2, vec3_make(x[3], x[4], x[5]), vec3_make(x[9], x[10], x[11]));
}

/* Coulomb at an impact (SPEC 7): the contact points leave together
 * (sticking) when the tangential impulse that takes lies within mu times
 * the normal one; else it slides, the tangential impulse mu times the
 * normal one along that sticking impulse's direction.  Newton's
 * restitution with friction can gain energy where the two couple (Kane's
 * paradox): a response that would gain it is the frictionless one, which
 * never does with e <= 1. */
static int solve_with_friction(vrResponder *r, const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e,
                               double mu, double *x)
{
    vec3 R, Rt;
    double Rn, before;
    if (solve_as(r, b1, b2, n, e, STICK, 0, vec3_zero(), x) != 0) return -1;
    R = vec3_make(x[12], x[13], x[14]);
    Rn = -vec3_dot(R, n);
    Rt = vec3_madd(R, Rn, n);
    if (vec3_len(Rt) > mu * Rn) {
        vec3 s = vec3_len(Rt) > 0 ? vec3_scale(Rt, 1.0 / vec3_len(Rt)) : vec3_zero();
        if (solve_as(r, b1, b2, n, e, SLIDE, mu, s, x) != 0) return -1;
    }
    before = kinetic(b1, b1->v, b1->w) + kinetic(b2, b2->v, b2->w);
    if (kinetic_of(b1, b2, x) > before * (1 + 1e-12)) return solve_as(r, b1, b2, n, e, FRICTIONLESS, 0, vec3_zero(), x);
    return 0;
}

int vrResponder_Solve(vrResponder *r, const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e, double mu,
                      vec3 *v1, vec3 *w1, vec3 *v2, vec3 *w2, vec3 *impulse)
{
    double x[N];
    if (mu > 0 ? solve_with_friction(r, b1, b2, n, e, mu, x) != 0
               : solve_as(r, b1, b2, n, e, FRICTIONLESS, 0, vec3_zero(), x) != 0)
        return -1;
    *v1 = vec3_make(x[0], x[1], x[2]);
    *v2 = vec3_make(x[3], x[4], x[5]);
    *w1 = vec3_make(x[6], x[7], x[8]);
    *w2 = vec3_make(x[9], x[10], x[11]);
    if (impulse) *impulse = vec3_make(x[12], x[13], x[14]);
    return 0;
}

vrResponseStats vrResponder_Stats(const vrResponder *r) { return r->stats; }

/* SPEC 3.4: j = -(1+e) n.u / (1/m1 + 1/m2 + n.((I1^-1 (p1 x n)) x p1) + n.((I2^-1 (p2 x n)) x p2)) */
double vrResponse_ClosedForm(const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e)
{
    const vrImpactBody *b[2] = {b1, b2};
    vec3 u = vec3_sub(vec3_add(b2->v, vec3_cross(b2->w, b2->p)), vec3_add(b1->v, vec3_cross(b1->w, b1->p)));
    double k = 0;
    int s;
    for (s = 0; s < 2; s++) {
        vec3 a;
        if (b[s]->is_static) continue;
        a = mat33_mulv(&b[s]->inv_inertia, vec3_cross(b[s]->p, n));
        k += 1.0 / b[s]->mass + vec3_dot(n, vec3_cross(a, b[s]->p));
    }
    return -(1.0 + e) * vec3_dot(n, u) / k;
}
