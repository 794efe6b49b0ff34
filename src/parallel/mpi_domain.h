/* mpi_domain: the solver's domain hooks (scheme/solver.h) for a run split among the
 * processes of an MPI communicator by slabs (parallel/slabs.h, docs/mpi.md). */
#ifndef VCSPH_MPI_DOMAIN_H
#define VCSPH_MPI_DOMAIN_H

#include "parallel/slabs.h"
#include "scheme/solver.h"

#include <mpi.h>

typedef struct {
    solver_domain hooks;
    MPI_Comm comm;
    slabs slabs;
    halo_plan halo;
} mpi_domain;

#define mpi_domain_attach DIM_NAME(mpi_domain_attach)
#define mpi_domain_free   DIM_NAME(mpi_domain_free)

/* Splits the liquid of s among the processes of comm: each keeps its share of the particles in
 * their order (reduce_share), which it set up alone (solver_init_part) or cuts out of the
 * whole liquid (solver_init, a checkpoint loaded); the next step hands them to the owners of
 * their positions, and the solver reduces and refreshes through d from then on. */
void mpi_domain_attach(mpi_domain *d, solver *s, MPI_Comm comm);
void mpi_domain_free(mpi_domain *d);

#define mpi_domain_split   DIM_NAME(mpi_domain_split)
#define mpi_domain_unsplit DIM_NAME(mpi_domain_unsplit)

/* The run's team (parallel/mpi_team.h) through dimension-free pointers: a domain allocated and
 * attached to `s`, a solver of this DIM (NULL when out of memory), and its release. */
void *mpi_domain_split(void *s, MPI_Comm comm);
void mpi_domain_unsplit(void *d);

#endif
