/* quantile: order statistics of a sample, the same for any order in which it arrives (the
 * sample is sorted first). Dimension-free. */
#ifndef VCSPH_QUANTILE_H
#define VCSPH_QUANTILE_H

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

static inline int quantile_compare(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static inline void quantile_sort(double *v, size_t n)
{
    if (n > 1) qsort(v, n, sizeof *v, quantile_compare);
}

/* The q-quantile (0 <= q <= 1) of sorted[0..n): linear between the order statistics around
 * position q (n - 1) (Hyndman and Fan's type 7, numpy.percentile's default); NaN for n = 0. */
static inline double quantile_sorted(const double *sorted, size_t n, double q)
{
    if (n == 0) return NAN;
    double position = q * (double)(n - 1);
    size_t below = (size_t)position;
    if (below + 1 >= n) return sorted[n - 1];
    return sorted[below] + (position - (double)below) * (sorted[below + 1] - sorted[below]);
}

#endif
