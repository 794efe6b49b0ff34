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

/* Splits the liquid of s, which every process has set up whole (solver_init), among the
 * processes of comm: each keeps its share of the particles in their order, the next step
 * hands them to the owners of their positions, and the solver reduces and refreshes through
 * d from then on. Collective. */
void mpi_domain_attach(mpi_domain *d, solver *s, MPI_Comm comm);
void mpi_domain_free(mpi_domain *d);

#endif
