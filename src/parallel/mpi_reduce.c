/* mpi_reduce: reduce_sum's blocks formed across processes. */
#include "parallel/mpi_reduce.h"
#include "core/reduce.h"

#include <stdint.h>
#include <stdlib.h>

/* A few bytes per process or per block: without them there is nothing sensible to do, and
 * MPI's default handler likewise aborts the run on a failed message, so nothing here returns
 * an error. */
static void *allocate(size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (!p) MPI_Abort(MPI_COMM_WORLD, 3);
    return p;
}

/* Where the global order lies: process q holds indices offset[q] .. offset[q] + count[q]. */
typedef struct {
    int n_ranks, rank;
    uint64_t *count, *offset, total;
} layout;

static void layout_gather(size_t n, MPI_Comm comm, layout *l)
{
    MPI_Comm_size(comm, &l->n_ranks);
    MPI_Comm_rank(comm, &l->rank);
    l->count = allocate((size_t)l->n_ranks * sizeof *l->count);
    l->offset = allocate((size_t)l->n_ranks * sizeof *l->offset);
    uint64_t mine = n;
    MPI_Allgather(&mine, 1, MPI_UINT64_T, l->count, 1, MPI_UINT64_T, comm);
    l->total = 0;
    for (int q = 0; q < l->n_ranks; q++) {
        l->offset[q] = l->total;
        l->total += l->count[q];
    }
}

static void layout_free(layout *l)
{
    free(l->count);
    free(l->offset);
}

static uint64_t block_start(uint64_t b) { return b * REDUCE_BLOCK; }
static uint64_t block_end(const layout *l, uint64_t b)
{
    uint64_t end = (b + 1) * REDUCE_BLOCK;
    return end < l->total ? end : l->total;
}

/* The process that holds global index i (the first one with a non-empty range there). */
static int holder(const layout *l, uint64_t i)
{
    for (int q = 0; q < l->n_ranks; q++)
        if (i >= l->offset[q] && i < l->offset[q] + l->count[q]) return q;
    return l->n_ranks - 1; /* not reached for i < total */
}

/* Process q's head: its indices that belong to a block begun on an earlier process. They go
 * to that process. Returns how many (0 when q's range starts a block or is empty). */
static uint64_t head_length(const layout *l, int q)
{
    if (l->count[q] == 0 || l->offset[q] % REDUCE_BLOCK == 0) return 0;
    uint64_t b = l->offset[q] / REDUCE_BLOCK, end = block_end(l, b);
    uint64_t range_end = l->offset[q] + l->count[q];
    return (end < range_end ? end : range_end) - l->offset[q];
}

static int head_owner(const layout *l, int q)
{
    return holder(l, block_start(l->offset[q] / REDUCE_BLOCK));
}

/* The blocks process q sums: those whose first index it holds, consecutive. */
static void owned_blocks(const layout *l, int q, uint64_t *first, uint64_t *n_owned)
{
    uint64_t lo = l->offset[q], hi = l->offset[q] + l->count[q];
    uint64_t b = (lo + REDUCE_BLOCK - 1) / REDUCE_BLOCK; /* first block starting at or after lo */
    uint64_t b_end = (hi + REDUCE_BLOCK - 1) / REDUCE_BLOCK;
    *first = b;
    *n_owned = l->count[q] == 0 || b_end <= b ? 0 : b_end - b;
}

/* The sums of this process's blocks, each from 0 in global order: its own values, then those
 * that later processes sent (they arrive in rank order, which is index order). */
static void block_sums(const layout *l, const double *a, const double *received, double *sums)
{
    uint64_t first, n_owned, lo = l->offset[l->rank];
    owned_blocks(l, l->rank, &first, &n_owned);
    size_t k = 0; /* next received value */
    for (uint64_t b = 0; b < n_owned; b++) {
        double s = 0.0;
        for (uint64_t i = block_start(first + b); i < block_end(l, first + b); i++)
            s += i < lo + l->count[l->rank] ? a[i - lo] : received[k++];
        sums[b] = s;
    }
}

/* Every process's head to its owner; returns the values this process receives. */
static double *exchange_heads(const layout *l, const double *a, MPI_Comm comm)
{
    int *counts = calloc(4 * (size_t)l->n_ranks, sizeof *counts);
    if (!counts) MPI_Abort(MPI_COMM_WORLD, 3);
    int *send = counts, *send_at = counts + l->n_ranks, *recv = counts + 2 * l->n_ranks,
        *recv_at = counts + 3 * l->n_ranks;
    uint64_t mine = head_length(l, l->rank);
    if (mine) send[head_owner(l, l->rank)] = (int)mine; /* from a[0], send_at 0 */
    int n_recv = 0;
    for (int q = 0; q < l->n_ranks; q++) {
        if (q != l->rank && head_length(l, q) && head_owner(l, q) == l->rank)
            recv[q] = (int)head_length(l, q);
        recv_at[q] = n_recv;
        n_recv += recv[q];
    }
    double *received = allocate((size_t)n_recv * sizeof *received);
    MPI_Alltoallv(a, send, send_at, MPI_DOUBLE, received, recv, recv_at, MPI_DOUBLE, comm);
    free(counts);
    return received;
}

/* The block sums gathered on rank 0 in block order and added there as reduce_sum adds them. */
static double total_on_root(const layout *l, const double *sums, MPI_Comm comm)
{
    uint64_t n_blocks = (l->total + REDUCE_BLOCK - 1) / REDUCE_BLOCK, first, n_owned;
    int *counts = allocate(2 * (size_t)l->n_ranks * sizeof *counts), *at = counts + l->n_ranks;
    double *all = allocate((size_t)n_blocks * sizeof *all), s = 0.0;
    for (int q = 0; q < l->n_ranks; q++) {
        owned_blocks(l, q, &first, &n_owned);
        counts[q] = (int)n_owned;
        at[q] = (int)first;
    }
    owned_blocks(l, l->rank, &first, &n_owned);
    MPI_Gatherv(sums, (int)n_owned, MPI_DOUBLE, all, counts, at, MPI_DOUBLE, 0, comm);
    if (l->rank == 0) {
        if (n_blocks == 1)
            s = all[0];
        else
            for (uint64_t b = 0; b < n_blocks; b++) s += all[b];
    }
    free(counts);
    free(all);
    return s;
}

double mpi_reduce_sum(const double *a, size_t n, MPI_Comm comm)
{
    layout l = {0};
    layout_gather(n, comm, &l);
    double total = 0.0;
    if (l.total > 0) {
        uint64_t first, n_owned;
        owned_blocks(&l, l.rank, &first, &n_owned);
        double *received = exchange_heads(&l, a, comm);
        double *sums = allocate((size_t)n_owned * sizeof *sums);
        block_sums(&l, a, received, sums);
        total = total_on_root(&l, sums, comm);
        MPI_Bcast(&total, 1, MPI_DOUBLE, 0, comm);
        free(received);
        free(sums);
    }
    layout_free(&l);
    return total;
}

double mpi_reduce_max(const double *a, size_t n, MPI_Comm comm)
{
    double local = reduce_max(a, n), global = local;
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, comm);
    return global;
}

double mpi_reduce_min(const double *a, size_t n, MPI_Comm comm)
{
    double local = reduce_min(a, n), global = local;
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MIN, comm);
    return global;
}

long mpi_reduce_total(long local, MPI_Comm comm)
{
    long global = local;
    MPI_Allreduce(&local, &global, 1, MPI_LONG, MPI_SUM, comm);
    return global;
}

uint64_t mpi_first_index(size_t n, MPI_Comm comm)
{
    int rank;
    MPI_Comm_rank(comm, &rank);
    uint64_t mine = n, before = 0;
    MPI_Exscan(&mine, &before, 1, MPI_UINT64_T, MPI_SUM, comm);
    return rank == 0 ? 0 : before; /* Exscan leaves rank 0's undefined */
}
