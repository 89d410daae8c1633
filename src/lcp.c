/* lcp.c — a small LCP solved exactly by Murty's least-index principal
 * pivoting (Murty 1974; Cottle, Pang and Stone, "The Linear
 * Complementarity Problem", 4.2): guess which x are positive (the basis:
 * the caller's guess first),
 * solve for them with the others 0, and move the first index that breaks
 * x >= 0 or w >= 0 across; for a positive definite A it ends.  With at
 * most eight unknowns a Cholesky factorisation per guess is cheap, and
 * the answer is exact where projected Gauss-Seidel over a face's points
 * (rotations coupling them) took hundreds of sweeps.
 *   cholesky_solve   the basis's system
 *   vrLcp_Solve
 */
#include <math.h>
#include "lcp.h"

#define REGULARISE 1e-12
#define PIVOTS_MAX 256
/* w_i below zero by no more than this times the size of its terms is
 * rounding (per row: a point no contact holds, q_i ~ 1e30, must not set
 * the tolerance of the others) */
#define ROUNDING 1e-13

/* solves M y = b in place (M m x m, positive definite); -1 when not */
static int cholesky_solve(double M[VR_LCP_MAX][VR_LCP_MAX], double *b, int m)
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
    for (i = 0; i < m; i++) {
        for (k = 0; k < i; k++) b[i] -= M[i][k] * b[k];
        b[i] /= M[i][i];
    }
    for (i = m - 1; i >= 0; i--) {
        for (k = i + 1; k < m; k++) b[i] -= M[k][i] * b[k];
        b[i] /= M[i][i];
    }
    return 0;
}

int vrLcp_Solve(const double *A, const double *q, int n, double *x)
{
    int in[VR_LCP_MAX], idx[VR_LCP_MAX], pivot, i, j;
    double scale = 0;
    for (i = 0; i < n; i++) scale = fmax(scale, A[i * n + i]), in[i] = x[i] > 0;
    for (pivot = 0; pivot < PIVOTS_MAX; pivot++) {
        double M[VR_LCP_MAX][VR_LCP_MAX], y[VR_LCP_MAX];
        int m = 0, bad = -1;
        for (i = 0; i < n; i++)
            if (in[i]) idx[m++] = i;
        for (i = 0; i < m; i++) {
            for (j = 0; j < m; j++) M[i][j] = A[idx[i] * n + idx[j]];
            M[i][i] += REGULARISE * scale;
            y[i] = -q[idx[i]];
        }
        if (m && cholesky_solve(M, y, m) != 0) return -1;
        for (i = 0; i < n; i++) x[i] = 0;
        for (i = 0; i < m; i++) x[idx[i]] = y[i];
        for (i = 0; i < n && bad < 0; i++) {
            double w = q[i], size = fabs(q[i]);
            for (j = 0; j < n; j++) w += A[i * n + j] * x[j], size += fabs(A[i * n + j] * x[j]);
            if ((in[i] && x[i] < 0) || (!in[i] && w < -ROUNDING * size)) bad = i;
        }
        if (bad < 0) return 0;
        in[bad] = !in[bad];
    }
    for (i = 0; i < n; i++) x[i] = x[i] > 0 ? x[i] : 0;
    return -1;
}
