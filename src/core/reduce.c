/* reduce: fixed-order global sums. */
#include "core/reduce.h"

#include <math.h>
#include <stdlib.h>

double reduce_sum(const double *a, size_t n)
{
    size_t n_blocks = (n + REDUCE_BLOCK - 1) / REDUCE_BLOCK;
    if (n_blocks <= 1) {
        double s = 0.0;
        for (size_t i = 0; i < n; i++) s += a[i];
        return s;
    }
    double *partial = malloc(n_blocks * sizeof *partial);
    if (!partial) abort(); /* a few KiB; nothing sensible to do without them */
#pragma omp parallel for schedule(static)
    for (size_t b = 0; b < n_blocks; b++) {
        size_t end = (b + 1) * REDUCE_BLOCK < n ? (b + 1) * REDUCE_BLOCK : n;
        double s = 0.0;
        for (size_t i = b * REDUCE_BLOCK; i < end; i++) s += a[i];
        partial[b] = s;
    }
    double s = 0.0;
    for (size_t b = 0; b < n_blocks; b++) s += partial[b];
    free(partial);
    return s;
}

double reduce_max(const double *a, size_t n)
{
    double m = -INFINITY;
#pragma omp parallel for schedule(static) reduction(max : m)
    for (size_t i = 0; i < n; i++)
        if (a[i] > m) m = a[i];
    return m;
}

double reduce_min(const double *a, size_t n)
{
    double m = INFINITY;
#pragma omp parallel for schedule(static) reduction(min : m)
    for (size_t i = 0; i < n; i++)
        if (a[i] < m) m = a[i];
    return m;
}

long reduce_total(long local) { return local; }
