/* lcp.c — a small LCP solved exactly by Murty's least-index principal
 * pivoting (Murty 1974; Cottle, Pang and Stone, "The Linear
 * Complementarity Problem", 4.2): guess which x are positive (the basis:
 * the caller's guess first),
 * solve for them with the others 0, and move the first index that breaks
 * x >= 0 or w >= 0 across; for a positive definite A it ends.  With at
 * most eight unknowns a Cholesky factorisation per guess is cheap, and
 * the answer is exact where projected Gauss-Seidel over a face's points
 * (rotations coupling them) took hundreds of sweeps.
 *   cholesky, substitute, factor   the basis's system (its factor kept)
 *   vrLcp_SolveWith, vrLcp_Solve
 */
#include <math.h>
#include "lcp.h"

#define REGULARISE 1e-12
#define PIVOTS_MAX 256
/* w_i below zero by no more than this times the size of its terms is
 * rounding (per row: a point no contact holds, q_i ~ 1e30, must not set
 * the tolerance of the others) */
#define ROUNDING 1e-13

/* M = L L^T in place (the lower triangle; M m x m, positive definite);
 * -1 when not */
static int cholesky(double M[VR_LCP_MAX][VR_LCP_MAX], int m)
{
    int i, j, k;
    for (j = 0; j < m; j++) {
        double d = M[j][j];
        for (k = 0; k < j; k++) d -= M[j][k] * M[j][k];
        if (!(d > 0)) return -1;
        M[j][j] = sqrt(d);
        for (i = j + 1; i < m; i++) {
            double s = M[i][j];
            for (k = 0; k < j; k++) s -= M[i][k] * M[j][k];
            M[i][j] = s / M[j][j];
        }
    }
    return 0;
}

/* L L^T y = b, b into y in place */
static void substitute(double L[VR_LCP_MAX][VR_LCP_MAX], double *b, int m)
{
    int i, k;
    for (i = 0; i < m; i++) {
        for (k = 0; k < i; k++) b[i] -= L[i][k] * b[k];
        b[i] /= L[i][i];
    }
    for (i = m - 1; i >= 0; i--) {
        for (k = i + 1; k < m; k++) b[i] -= L[k][i] * b[k];
        b[i] /= L[i][i];
    }
}

/* the basis's factor: the one kept when it is that basis's (A unchanged
 * since: the caller's promise), else made and kept, regularised by A's
 * largest diagonal (found only then: nearly every call keeps its factor) */
static int factor(const double *A, int n, const int *idx, int m, unsigned basis, vrLcpFactor *f)
{
    double scale = 0;
    int i, j;
    if (f->valid && f->basis == basis) return 0;
    for (i = 0; i < n; i++) scale = fmax(scale, A[i * n + i]);
    for (i = 0; i < m; i++) {
        for (j = 0; j < m; j++) f->L[i][j] = A[idx[i] * n + idx[j]];
        f->L[i][i] += REGULARISE * scale;
    }
    f->valid = cholesky(f->L, m) == 0, f->basis = basis;
    return f->valid ? 0 : -1;
}

int vrLcp_SolveWith(const double *A, const double *q, int n, double *x, vrLcpFactor *f)
{
    int in[VR_LCP_MAX], idx[VR_LCP_MAX], pivot, i, j;
    for (i = 0; i < n; i++) in[i] = x[i] > 0;
    for (pivot = 0; pivot < PIVOTS_MAX; pivot++) {
        double y[VR_LCP_MAX];
        unsigned basis = 0;
        int m = 0, bad = -1;
        for (i = 0; i < n; i++)
            if (in[i]) idx[m++] = i, basis |= 1u << i;
        for (i = 0; i < m; i++) y[i] = -q[idx[i]];
        if (m && factor(A, n, idx, m, basis, f) != 0) return -1;
        if (m) substitute(f->L, y, m);
        for (i = 0; i < n; i++) x[i] = 0;
        for (i = 0; i < m; i++) x[idx[i]] = y[i];
        for (i = 0; i < n && bad < 0; i++) {
            double w = q[i], size = fabs(q[i]);
            if (in[i]) {               /* w_i = 0 there: only x_i's sign is asked */
                if (x[i] < 0) bad = i;
                continue;
            }
            /* the x outside the basis are 0 and add nothing, not even a bit */
            for (j = 0; j < m; j++) w += A[i * n + idx[j]] * y[j], size += fabs(A[i * n + idx[j]] * y[j]);
            if (w < -ROUNDING * size) bad = i;
        }
        if (bad < 0) return 0;
        in[bad] = !in[bad];
    }
    for (i = 0; i < n; i++) x[i] = x[i] > 0 ? x[i] : 0;
    return -1;
}

int vrLcp_Solve(const double *A, const double *q, int n, double *x)
{
    vrLcpFactor f;
    f.valid = 0, f.basis = 0;
    return vrLcp_SolveWith(A, q, n, x, &f);
}
