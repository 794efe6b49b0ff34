/* mpi_reduce: the global reductions of an MPI run (docs/mpi.md), equal to the bit to those of
 * core/reduce.h over the whole array on one process. The particles of the processes, in rank
 * order, are the global order (parallel/decomposition.h): process r holds a contiguous range
 * of it, after those of ranks 0 .. r - 1. Collective: every process of comm calls each
 * function with its own part, and all get the same result. */
#ifndef VCSPH_MPI_REDUCE_H
#define VCSPH_MPI_REDUCE_H

#include <mpi.h>
#include <stddef.h>
#include <stdint.h>

/* reduce_sum of the concatenation of every process's a[0 .. n): the blocks of REDUCE_BLOCK
 * global indices are summed each on the process that holds its first index, the parts of it
 * that other processes hold sent there first, and the block sums added in order on rank 0,
 * which shares the result. */
double mpi_reduce_sum(const double *a, size_t n, MPI_Comm comm);
/* Largest and smallest of every process's a[0 .. n) (-inf, +inf where all are empty): exact in
 * any order. */
double mpi_reduce_max(const double *a, size_t n, MPI_Comm comm);
double mpi_reduce_min(const double *a, size_t n, MPI_Comm comm);
/* The global index of this process's first element: the counts n of the processes before it. */
uint64_t mpi_first_index(size_t n, MPI_Comm comm);
/* The total of every process's count (exact in any order). */
long mpi_reduce_total(long local, MPI_Comm comm);

#endif
