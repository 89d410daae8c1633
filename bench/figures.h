/* figures.h — what the benchmarks that run vroc many times share: the
 * median of their runs' figures, and the benchmarks named on the command
 * line (bench_contact.c, bench_scenes.c, bench_broadphase.c). */
#ifndef VROC_BENCH_FIGURES_H
#define VROC_BENCH_FIGURES_H

#include <stdlib.h>
#include <string.h>

static inline int bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the median of v[0..n) (sorted in place), 0 when n <= 0 */
static inline double bench_median(double *v, int n)
{
    if (n <= 0) return 0;
    qsort(v, (size_t)n, sizeof *v, bench_cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* name is among argv[1..], or none is named (all are run) */
static inline int bench_wanted(int argc, char **argv, const char *name)
{
    int k;
    for (k = 1; k < argc; k++)
        if (!strcmp(argv[k], name)) return 1;
    return argc < 2;
}

#endif
