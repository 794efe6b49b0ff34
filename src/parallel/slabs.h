/* slabs: the particles of an MPI run split by slabs of whole strips of cells along x
 * (docs/mpi.md). Each process holds its own fluid particles in [0, n_fluid), in the global
 * order restricted to them, and copies of its neighbours' boundary particles (the halo) at the
 * head of the tail, as ghosts of kind GHOST_HALO. Every function is collective over comm. */
#ifndef VCSPH_SLABS_H
#define VCSPH_SLABS_H

#include "core/cells.h"
#include "core/particles.h"

#include <mpi.h>

typedef struct {
    int n_ranks, rank;
    size_t n_strips;
    /* n_ranks + 1: rank r owns strips first_strip[r] .. first_strip[r + 1] - 1 */
    size_t *first_strip;
    /* what this process has sent since the count was last cleared (migration to another
       process and halo copies; records it keeps are not counted): the traffic figures of
       docs/scaling.md */
    unsigned long long sent_records, sent_bytes;
} slabs;

/* The halo of a step: which own particles go to each neighbouring process, and how many of
 * theirs this store holds (from n_fluid on: the left neighbour's, then the right's). Side 0
 * is the process on the left (rank - 1), side 1 the right. */
typedef struct {
    size_t n_send[2], capacity[2];
    size_t *send[2]; /* indices of own particles, ascending */
    size_t n_recv[2];
} halo_plan;

#define slabs_balance        DIM_NAME(slabs_balance)
#define slabs_owner          DIM_NAME(slabs_owner)
#define slabs_migrate        DIM_NAME(slabs_migrate)
#define slabs_free           DIM_NAME(slabs_free)
#define halo_build           DIM_NAME(halo_build)
#define halo_refresh         DIM_NAME(halo_refresh)
#define halo_free            DIM_NAME(halo_free)
#define halo_exchange_values DIM_NAME(halo_exchange_values)

/* The split of grid g's strips that balances the fluid particles of every process (counted
 * where they are now; an exact sum over the processes, so every process finds the same split,
 * decomposition_balance). Returns 0, or -1 when the grid has fewer strips than processes or
 * out of memory. */
int slabs_balance(slabs *s, const cell_grid *g, const particles *p, MPI_Comm comm);
/* The process that owns position x (its column's strip). */
int slabs_owner(const slabs *s, const cell_grid *g, double x);
void slabs_free(slabs *s);

/* Sends every fluid particle's state (the registry's FIELD_STATE fields) to the process that
 * owns its position. The particles arrive from processes 0, 1, ... in turn, each in its order,
 * so the store holds them in the global order they had: sorting by cell with a stable sort
 * (cells_bin) then gives the order one process would have. Drops the tail (n_total =
 * n_fluid). Returns 0, or -1 when out of memory. */
int slabs_migrate(slabs *s, const cell_grid *g, particles *p, MPI_Comm comm);

/* After the fluid is sorted by cell: the own particles in the first and last column of cells
 * of the slab go to the process on that side, and theirs are appended to the tail (left's
 * first, then right's), as ghosts of kind GHOST_HALO with the identity map 0, their state
 * copied. A cell is at least the search radius, so every neighbour of an own particle is own
 * or in the halo. Returns 0, or -1 when out of memory. */
int halo_build(halo_plan *h, slabs *s, const cell_grid *g, particles *p, MPI_Comm comm);
/* Copies the fields of `fields` (a set of FIELD_MASK) of the plan's own particles into the
 * other processes' halos again, after they have changed (a pass, an RK stage). */
int halo_refresh(const halo_plan *h, slabs *s, particles *p, uint64_t fields, MPI_Comm comm);
/* For each halo particle k (0 .. n_halo - 1), halo[k] = its own process's own[i]: a value per
 * particle of `size` bytes (MPI type `type`) that is not a registry field (a label, a global
 * index, a work array of a pass). */
void halo_exchange_values(const halo_plan *h, slabs *s, const void *own, void *halo, size_t size,
                          MPI_Datatype type, MPI_Comm comm);
void halo_free(halo_plan *h);

#endif
