/* run_team: the processes that share one run (`mpirun -n P vcsph-mpi run`, docs/mpi.md), as the
 * time loop and the outputs see them. The solver's own split (its particles, halos and global
 * sums) is its domain (scheme/solver.h); what is left to the run is to agree on when to stop
 * and to bring the particles together for the files. Rank 0 writes every file and every
 * line on the terminal; the others compute with it. A run on one process has no team (NULL),
 * and every function below is then the identity. Dimension-free. */
#ifndef VCSPH_RUN_TEAM_H
#define VCSPH_RUN_TEAM_H

#include <stddef.h>

typedef struct run_team {
    int rank, size;
    /* The largest of every process's value (a status, a signal, a due checkpoint).
       Collective. */
    int (*agree)(const struct run_team *t, int local);
    /* Whether any process has a message (has != 0), and the message of the lowest rank that
       has one, into text on every process (a breakdown's diagnosis). Collective. */
    int (*first_message)(const struct run_team *t, int has, char *text, size_t len);
    /* The global index of this process's first of n elements, the counts of the ranks before
       it. Collective. */
    size_t (*first_index)(const struct run_team *t, size_t n);
    /* The communicator of a file that every process writes its part of at once (an MPI_Comm,
       for io/snapshot.h's snapshot_write_part). */
    const void *io_comm;
    /* Every process's n elements of `size` bytes, on rank 0 one after the other in rank order
       (malloc'd; the caller frees it), NULL on the others; *n_total the count of them all.
       Collective. */
    void *(*gather)(const struct run_team *t, const void *mine, size_t n, size_t size,
                    size_t *n_total);
    /* Splits a solver of `dim` (a solver_2d or solver_3d) among the processes, each keeping
       its share: the one it set up alone (solver_init_part) or its part of the whole liquid
       (parallel/mpi_domain.h). Returns the split for `unsplit`, NULL when out of memory. */
    void *(*split)(const struct run_team *t, int dim, void *solver);
    void (*unsplit)(int dim, void *split);
    void *context;
} run_team;

/* Whether this process writes the files: rank 0, or the only process. */
static inline int team_writes(const run_team *t) { return !t || t->rank == 0; }

static inline int team_agree(const run_team *t, int local)
{
    return t ? t->agree(t, local) : local;
}

static inline int team_first_message(const run_team *t, int has, char *text, size_t len)
{
    return t ? t->first_message(t, has, text, len) : has;
}

#endif
