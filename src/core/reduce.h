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
/* Largest of a[0..n) (-inf when n = 0); exact in any order. */
double reduce_max(const double *a, size_t n);
double reduce_min(const double *a, size_t n);
/* A count of the liquid (free-surface particles, EdBC corrections), counted over this
 * process's particles, totalled over the processes: one process holds them all, so today the
 * count itself; the MPI build sums it (exact in any order). Counts that only steer this
 * process's own work (bounced particles, the longest neighbour row) stay local. */
long reduce_total(long local);

#endif
