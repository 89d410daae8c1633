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
#define NNZ 66
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

struct vrResponder {
    klu_common common;
    klu_symbolic *symbolic;
    vrPattern pattern[PATTERNS];
    int npattern;
    int Ap[N + 1], Ai[NNZ];
    double Ax[NNZ];
    int at[N][N];            /* at[row][col]: index into Ax, -1 outside the pattern */
    vrResponseStats stats;
};

/* the pattern, column by column (CSC) */
static void build_pattern(vrResponder *r)
{
    int col, row, k = 0, i;
    for (row = 0; row < N; row++)
        for (col = 0; col < N; col++) r->at[row][col] = -1;
    for (col = 0; col < N; col++) {
        int mark[N] = {0};
        if (col < 6) { mark[col] = 1; mark[14] = 1; }                 /* v1', v2' */
        else if (col < 12) {                                          /* w1', w2' */
            int base = col < 9 ? 6 : 9;
            for (i = 0; i < 3; i++) mark[base + i] = 1;
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
}

static void set(vrResponder *r, int row, int col, double v) { r->Ax[r->at[row][col]] = v; }

static void set_block(vrResponder *r, int row, int col, const mat33 *m)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) set(r, row + i, col + j, m->m[i][j]);
}

/* fills Ax and the right-hand side for one contact */
static void assemble(vrResponder *r, const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e, double *rhs)
{
    const vrImpactBody *b[2] = {b1, b2};
    vec3 t1 = vec3_orthogonal(n), t2 = vec3_cross(n, t1);
    vec3 u = vec3_sub(vec3_add(b2->v, vec3_cross(b2->w, b2->p)), vec3_add(b1->v, vec3_cross(b1->w, b1->p)));
    int s, i;
    for (i = 0; i < NNZ; i++) r->Ax[i] = 0.0;
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
        /* restitution row: +n.v2' + (p2 x n).w2' - n.v1' - (p1 x n).w1' */
        for (i = 0; i < 3; i++) {
            set(r, 14, vr + i, sign * vec3_get(n, i));
            set(r, 14, wr + i, sign * vec3_get(pn, i));
        }
        rhs[vr] = x->v.x, rhs[vr + 1] = x->v.y, rhs[vr + 2] = x->v.z;
        rhs[wr] = x->w.x, rhs[wr + 1] = x->w.y, rhs[wr + 2] = x->w.z;
    }
    for (i = 0; i < 3; i++) {
        set(r, 12, 12 + i, vec3_get(t1, i));
        set(r, 13, 12 + i, vec3_get(t2, i));
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
        for (k = r->Ap[col]; k < r->Ap[col + 1]; k++) res[r->Ai[k]] -= r->Ax[k] * x[col];
}

static double larger(double a, double b) { return a > b ? a : b; }   /* fmax is a call */

/* max-norm residual res = b - A x relative to the sizes involved
 * (infinite when x is not finite) */
static double residual_size(const vrResponder *r, const double *x, const double *b, double *res)
{
    double amax = 0, xmax = 0, bmax = 0, rmax = 0;
    int k, i;
    residual(r, x, b, res);
    for (k = 0; k < NNZ; k++) amax = larger(amax, fabs(r->Ax[k]));
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
    if (klu_solve(r->symbolic, num, N, 1, d, &r->common)) {
        for (i = 0; i < N; i++) x[i] += d[i];
        size = residual_size(r, x, b, d);
    }
    return size <= RESIDUAL_MAX ? 0 : -1;
}

static void pattern_of(const vrResponder *r, unsigned long long bits[2])
{
    int k;
    bits[0] = bits[1] = 0;
    for (k = 0; k < NNZ; k++)
        if (r->Ax[k] != 0) bits[k / 64] |= 1ULL << (k % 64);
}

/* the canonical factorisation of a zero pattern: the pattern filled with
 * fixed values of the sizes a contact has (masses and inertias ~1, lever
 * arms and normal components below), slightly varied to avoid pivot ties */
static klu_numeric *canonical_for(vrResponder *r, const unsigned long long bits[2])
{
    double fill[NNZ];
    int k, col;
    for (col = 0; col < N; col++)
        for (k = r->Ap[col]; k < r->Ap[col + 1]; k++) {
            int row = r->Ai[k], on = (bits[k / 64] >> (k % 64)) & 1;
            double size = row == col || (row < 12 && col < 12) ? 1.0 : 0.5;
            fill[k] = on ? size * (1.0 + 0.01 * ((row * 31 + col * 17) % 13)) : 0.0;
        }
    r->stats.factors++;
    return klu_factor(r->Ap, r->Ai, fill, r->symbolic, &r->common);
}

static void forget_patterns(vrResponder *r)
{
    int i;
    for (i = 0; i < PATTERNS; i++)
        if (r->pattern[i].numeric) klu_free_numeric(&r->pattern[i].numeric, &r->common);
    r->npattern = 0;
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
    for (i = (int)((h >> 32) % PATTERNS); r->pattern[i].numeric; i = (i + 1) % PATTERNS)
        if (r->pattern[i].bits[0] == bits[0] && r->pattern[i].bits[1] == bits[1]) return r->pattern[i].numeric;
    if (4 * (r->npattern + 1) > 3 * PATTERNS) {
        forget_patterns(r);
        return numeric_for(r);
    }
    slot = &r->pattern[i];
    slot->bits[0] = bits[0];
    slot->bits[1] = bits[1];
    slot->numeric = canonical_for(r, bits);
    if (slot->numeric) r->npattern++;
    return slot->numeric;
}

static int refactor_solve(vrResponder *r, double *x, const double *b)
{
    klu_numeric *num = numeric_for(r);
    if (!num) return -1;
    r->stats.refactors++;
    if (!klu_refactor(r->Ap, r->Ai, r->Ax, r->symbolic, num, &r->common)) return -1;
    if (!klu_rcond(r->symbolic, num, &r->common) || r->common.rcond < RCOND_MIN) return -1;
    if (!klu_solve(r->symbolic, num, N, 1, x, &r->common)) return -1;
    return polish(r, num, r->common.rcond, x, b);
}

static int fresh_solve(vrResponder *r, double *x, const double *b)
{
    klu_numeric *num;
    int ok;
    r->stats.factors++;
    num = klu_factor(r->Ap, r->Ai, r->Ax, r->symbolic, &r->common);
    if (!num) return -1;
    ok = klu_solve(r->symbolic, num, N, 1, x, &r->common) && polish(r, num, 0, x, b) == 0;
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
    build_pattern(r);
    r->symbolic = klu_analyze(N, r->Ap, r->Ai, &r->common);
    if (!r->symbolic) {
        vrResponder_Free(r);
        return NULL;
    }
    return r;
}

void vrResponder_Free(vrResponder *r)
{
    if (!r) return;
    forget_patterns(r);
    if (r->symbolic) klu_free_symbolic(&r->symbolic, &r->common);
    free(r);
}

int vrResponder_Solve(vrResponder *r, const vrImpactBody *b1, const vrImpactBody *b2, vec3 n, double e,
                      vec3 *v1, vec3 *w1, vec3 *v2, vec3 *w2, vec3 *impulse)
{
    double rhs[N], x[N];
    int i;
    assemble(r, b1, b2, n, e, rhs);
    for (i = 0; i < N; i++) x[i] = rhs[i];
    r->stats.solves++;
    if (refactor_solve(r, x, rhs) != 0) {
        for (i = 0; i < N; i++) x[i] = rhs[i];
        if (fresh_solve(r, x, rhs) != 0) return -1;
    }
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
