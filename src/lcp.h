/* lcp.h — a small linear complementarity problem solved exactly (lcp.c):
 * find x >= 0 with w = A x + q >= 0 and x.w = 0, for a symmetric positive
 * semi-definite A of at most VR_LCP_MAX rows (the normal impulses of one
 * contact's points, island.c). */
#ifndef VR_LCP_H
#define VR_LCP_H

#define VR_LCP_MAX 8

/* A is n x n, row major; x holds a guess (its positive entries are the
 * first basis: the last sweep's answer usually is the answer's) and gets
 * the answer.  A is regularised by a
 * relative 1e-12 on its diagonal (the points of a face are redundant: A
 * is singular).  0, or -1 when the pivoting did not end (then x is the
 * last basis's, clamped to >= 0). */
int vrLcp_Solve(const double *A, const double *q, int n, double *x);

/* A basis's Cholesky factor, kept between solves with the same A: the
 * sweeps of island.c solve each contact's LCP once a sweep with the same
 * A and nearly always the same basis, and the factor was most of the
 * cost.  The answer is the same bits as without it. */
typedef struct vrLcpFactor {
    int valid;                /* 0: none kept (set it so whenever A changes) */
    unsigned basis;           /* bit i: x_i in the basis */
    double L[VR_LCP_MAX][VR_LCP_MAX];
} vrLcpFactor;

/* vrLcp_Solve with the factor f kept from the last call with this A */
int vrLcp_SolveWith(const double *A, const double *q, int n, double *x, vrLcpFactor *f);

#endif
