/* mpi_team: the run's team (core/run_team.h) on the processes of an MPI communicator. */
#ifndef VCSPH_MPI_TEAM_H
#define VCSPH_MPI_TEAM_H

#include "core/run_team.h"

#include <mpi.h>

/* The team of every process of comm, which must outlive it. */
void mpi_team_init(run_team *t, MPI_Comm *comm);

#endif
