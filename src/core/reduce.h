/* reduce: every global reduction of the solver goes through here (docs/architecture.md), in a fixed
 * order, so that results do not depend on the number of threads (and MPI_Allreduce can drop
 * in later). */
#ifndef VCSPH_REDUCE_H
#define VCSPH_REDUCE_H

#include <stddef.h>

/* The size of reduce_sum's blocks. The MPI build's sum (parallel/mpi_reduce.h) forms the same
 * blocks of the global order across processes. */
#define REDUCE_BLOCK 4096

/* Sum of a[0..n): blocks of REDUCE_BLOCK summed in parallel, each from 0 in index order, then
 * the block sums from 0 in order (a single block: its sum). The grouping depends on n only,
 * never on the thread count. */
double reduce_sum(const double *a, size_t n);
/* Part `part` of `parts` of n items in their order, [first, end): the parts in order are the
 * whole, their sizes differ by at most one. What each process of an MPI run keeps of the
 * initial liquid. */
static inline void reduce_share(size_t n, int part, int parts, size_t *first, size_t *end)
{
    *first = n * (size_t)part / (size_t)parts;
    *end = n * (size_t)(part + 1) / (size_t)parts;
}

/* Largest of a[0..n) (-inf when n = 0); exact in any order. */
double reduce_max(const double *a, size_t n);
double reduce_min(const double *a, size_t n);
/* A count of the liquid (free-surface particles, EdBC corrections), counted over this
 * process's particles, totalled over the processes: one process holds them all, so today the
 * count itself; the MPI build sums it (exact in any order). Counts that only steer this
 * process's own work (bounced particles, the longest neighbour row) stay local. */
long reduce_total(long local);

/* The reductions over a liquid split among processes (the MPI build's parallel/mpi_domain.h):
 * each function gets this process's part and returns the global result, the sum equal to
 * reduce_sum of the whole liquid in its global order. NULL is the whole liquid on one
 * process: the functions above. */
typedef struct reducer {
    double (*sum)(const struct reducer *r, const double *a, size_t n);
    double (*max)(const struct reducer *r, const double *a, size_t n);
    double (*min)(const struct reducer *r, const double *a, size_t n);
    long (*total)(const struct reducer *r, long local);
    void *context;
} reducer;

static inline double reducer_sum(const reducer *r, const double *a, size_t n)
{
    return r ? r->sum(r, a, n) : reduce_sum(a, n);
}
static inline double reducer_max(const reducer *r, const double *a, size_t n)
{
    return r ? r->max(r, a, n) : reduce_max(a, n);
}
static inline double reducer_min(const reducer *r, const double *a, size_t n)
{
    return r ? r->min(r, a, n) : reduce_min(a, n);
}
static inline long reducer_total(const reducer *r, long local)
{
    return r ? r->total(r, local) : reduce_total(local);
}

#endif
