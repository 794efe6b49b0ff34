/* mpi_team: the run's team on MPI (mpi_team.h). Dimension-free: the split goes to the 2D or 3D
 * solver's mpi_domain_split. */
#include "parallel/mpi_team.h"
#include "parallel/mpi_reduce.h"

#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* parallel/mpi_domain.h's split, compiled once per dimension */
void *mpi_domain_split_2d(void *s, MPI_Comm comm);
void *mpi_domain_split_3d(void *s, MPI_Comm comm);
void mpi_domain_unsplit_2d(void *d);
void mpi_domain_unsplit_3d(void *d);

static MPI_Comm team_comm(const run_team *t) { return *(const MPI_Comm *)t->context; }

static int agree(const run_team *t, int local)
{
    int all;
    MPI_Allreduce(&local, &all, 1, MPI_INT, MPI_MAX, team_comm(t));
    return all;
}

static int first_message(const run_team *t, int has, char *text, size_t len)
{
    int mine = has ? t->rank : INT_MAX, first;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, team_comm(t));
    if (first == INT_MAX) return 0;
    MPI_Bcast(text, (int)len, MPI_CHAR, first, team_comm(t));
    return 1;
}

/* A gather that rank 0 has no room for cannot be left halfway by one process: the others
 * wait in it. The whole run stops, with the last checkpoint kept. */
static void out_of_memory(MPI_Comm comm)
{
    fprintf(stderr, "vcsph: out of memory gathering the particles on rank 0\n");
    MPI_Abort(comm, 1);
}

/* Counts and offsets in bytes fit an int (MPI's) up to 2 GiB per gather: beyond that a
 * derived datatype of whole elements would be needed. */
static void *gather(const run_team *t, const void *mine, size_t n, size_t size, size_t *n_total)
{
    MPI_Comm comm = team_comm(t);
    int bytes = (int)(n * size);
    int *counts = t->rank == 0 ? malloc(2 * (size_t)t->size * sizeof *counts) : NULL;
    if (t->rank == 0 && !counts) out_of_memory(comm);
    MPI_Gather(&bytes, 1, MPI_INT, counts, 1, MPI_INT, 0, comm);
    long long total = 0;
    if (t->rank == 0)
        for (int q = 0; q < t->size; q++) {
            counts[t->size + q] = (int)total;
            total += counts[q];
        }
    MPI_Bcast(&total, 1, MPI_LONG_LONG, 0, comm);
    *n_total = (size_t)total / size;
    char *all = t->rank == 0 ? malloc(total ? (size_t)total : 1) : NULL;
    if (t->rank == 0 && !all) out_of_memory(comm);
    MPI_Gatherv(mine, bytes, MPI_BYTE, all, counts, counts ? counts + t->size : NULL, MPI_BYTE, 0,
                comm);
    free(counts);
    return all;
}

static size_t first_index(const run_team *t, size_t n)
{
    return (size_t)mpi_first_index(n, team_comm(t));
}

static void *split(const run_team *t, int dim, void *solver)
{
    return (dim == 3 ? mpi_domain_split_3d : mpi_domain_split_2d)(solver, team_comm(t));
}

static void unsplit(int dim, void *d)
{
    (dim == 3 ? mpi_domain_unsplit_3d : mpi_domain_unsplit_2d)(d);
}

void mpi_team_init(run_team *t, MPI_Comm *comm)
{
    memset(t, 0, sizeof *t);
    MPI_Comm_rank(*comm, &t->rank);
    MPI_Comm_size(*comm, &t->size);
    t->agree = agree;
    t->first_message = first_message;
    t->gather = gather;
    t->first_index = first_index;
    t->io_comm = comm;
    t->split = split;
    t->unsplit = unsplit;
    t->context = comm;
}
