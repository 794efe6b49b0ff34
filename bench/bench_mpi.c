/* bench_mpi: the cost of a step split among MPI processes (parallel/mpi_domain.h), for the
 * scaling figures of docs/scaling.md: bench_mpi CASE STEPS [section.key=value ...]. Runs
 * STEPS steps of the case (after 3 of warm-up) on every process of MPI_COMM_WORLD, each with
 * its OpenMP threads, and prints on rank 0 the wall time per step, the particle-steps per
 * second, and per process the fluid particles it owns, its halo (count and fraction of the
 * own) and what it sent per step (records and bytes: migration and halo copies). A
 * benchmark: it never fails on timing. Built with -DVCSPH_MPI=ON only. */
#include "parallel/mpi_domain.h"
#include "parallel/mpi_reduce.h"

#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

enum { WARM_UP = 3 };

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, ranks;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (argc < 3) {
        if (rank == 0) fprintf(stderr, "usage: bench_mpi CASE STEPS [section.key=value ...]\n");
        MPI_Finalize();
        return 2;
    }
    int steps = atoi(argv[2]);
    config cfg;
    char err[1024];
    solver s;
    if (config_load(&cfg, argv[1], (const char *const *)argv + 3, argc - 3, err, sizeof err) ||
        cfg.dim != DIM || solver_init(&s, &cfg, err, sizeof err)) {
        if (rank == 0)
            fprintf(stderr, "bench_mpi: %s\n", cfg.dim != DIM ? "not this dimension" : err);
        MPI_Abort(MPI_COMM_WORLD, 2);
    }
    mpi_domain d;
    mpi_domain_attach(&d, &s, MPI_COMM_WORLD);
    for (int k = 0; k < WARM_UP; k++)
        if (solver_step(&s, cfg.t_end)) MPI_Abort(MPI_COMM_WORLD, 3);
    d.slabs.sent_records = d.slabs.sent_bytes = 0;
    double halo = 0.0, own = 0.0;
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    for (int k = 0; k < steps; k++) {
        if (solver_step(&s, cfg.t_end)) MPI_Abort(MPI_COMM_WORLD, 3);
        halo += (double)s.p.n_halo;
        own += (double)s.p.n_fluid;
    }
    double wall = MPI_Wtime() - t0, slowest;
    MPI_Reduce(&wall, &slowest, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    double mine[4] = {own / steps, halo / steps, (double)d.slabs.sent_records / steps,
                      (double)d.slabs.sent_bytes / steps};
    double *all = rank == 0 ? malloc(4 * (size_t)ranks * sizeof *all) : NULL;
    MPI_Gather(mine, 4, MPI_DOUBLE, all, 4, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    long n = mpi_reduce_total((long)s.p.n_fluid, MPI_COMM_WORLD);
    if (rank == 0) {
        printf("bench_mpi: %s, %dD, %ld fluid particles, %d processes x %d threads, %d steps: "
               "%.4f s a step, %.3g PS/s\n",
               cfg.name, DIM, n, ranks, omp_get_max_threads(), steps, slowest / steps,
               (double)n * steps / slowest);
        for (int q = 0; q < ranks; q++) {
            double *r = all + 4 * q;
            printf("  rank %d: %.0f own, %.0f halo (%.1f %%), sent a step %.0f records, %.0f kB\n",
                   q, r[0], r[1], 100.0 * r[1] / r[0], r[2], r[3] / 1e3);
        }
    }
    free(all);
    solver_free(&s);
    mpi_domain_free(&d);
    MPI_Finalize();
    return 0;
}
