/* mpi_bodies: bodies of liquid across the processes of an MPI run split by slabs
 * (scheme/bodies.h, docs/mpi.md): joined by labels, summed in global order along the
 * processes, and the halo's values of the work arrays a pass reads at the neighbours. */
#ifndef VCSPH_MPI_BODIES_H
#define VCSPH_MPI_BODIES_H

#include "parallel/mpi_domain.h"

#define mpi_bodies_domain DIM_NAME(mpi_bodies_domain)

/* The hooks of d's bodies (its slabs, halo and communicator). */
bodies_domain mpi_bodies_domain(mpi_domain *d);

#endif
