/* checkpoint_io: how large a checkpoint is and how long it takes to write and to read back,
 * for the particle arrays of a 2D or 3D run (the layout of app/restart.c: id, x_d, u_d, rho,
 * m per particle, plus its scalars and the case text) at a few particle counts.
 *
 *   checkpoint_io [DIR]    (default: the current folder; the file is removed afterwards)
 *
 * Writing includes what a run pays: the HDF5 file with Fletcher32 on every chunk, the
 * whole-file hash of the header, fsync of the file and of the folder, and the rename. Reading
 * is checkpoint_read: the hash, then every dataset with its checksum. Each figure is the best
 * of REPEATS, on whatever disk DIR is on. A benchmark: it prints figures and exits 1 only if
 * a write or read fails. */
#include "io/checkpoint.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <time.h>

#define REPEATS 3

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The particle arrays and scalars of a dim-D run of n particles (values: a lattice-like
 * pattern, so that nothing compresses or repeats; no filter but Fletcher32 is used anyway). */
static int items_for(int dim, size_t n, double *values, int64_t *ids, checkpoint_item *items)
{
    static const char *const names[] = {"x_0", "x_1", "x_2", "u_0", "u_1", "u_2", "rho", "m"};
    static const double scalars[8] = {0};
    static const char case_text[2048] = "[case]\nname = bench\n";
    int k = 0;
    items[k++] = (checkpoint_item){"case", CHECKPOINT_BYTES, sizeof case_text, case_text, NULL};
    items[k++] = (checkpoint_item){"scalars", CHECKPOINT_F64, 8, scalars, NULL};
    items[k++] = (checkpoint_item){"id", CHECKPOINT_I64, n, ids, NULL};
    for (int a = 0; a < 8; a++) {
        bool vector = a < 6, used = !vector || a % 3 < dim;
        if (used) items[k++] = (checkpoint_item){names[a], CHECKPOINT_F64, n, values, NULL};
    }
    return k;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    char path[4096], err[1024];
    snprintf(path, sizeof path, "%s/bench-checkpoint.h5", dir);
    const size_t counts[] = {10000, 100000, 1000000};
    size_t n_max = counts[sizeof counts / sizeof counts[0] - 1];
    double *values = malloc(n_max * sizeof *values);
    int64_t *ids = malloc(n_max * sizeof *ids);
    if (!values || !ids) return 1;
    for (size_t i = 0; i < n_max; i++) {
        values[i] = 1e-3 * (double)i + 1.0 / (double)(i + 1);
        ids[i] = (int64_t)i;
    }
    printf("%-3s %9s %12s %10s %10s %10s\n", "dim", "particles", "bytes", "B/particle", "write ms",
           "read ms");
    for (int dim = 2; dim <= 3; dim++) {
        for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
            size_t n = counts[c];
            checkpoint_item items[16];
            int n_items = items_for(dim, n, values, ids, items);
            double best_write = 1e30, best_read = 1e30;
            for (int r = 0; r < REPEATS; r++) {
                double t0 = now();
                if (checkpoint_write(path, items, n_items, err, sizeof err)) {
                    fprintf(stderr, "checkpoint_io: %s\n", err);
                    return 1;
                }
                double t1 = now();
                checkpoint_data cd;
                if (checkpoint_read(path, &cd, err, sizeof err)) {
                    fprintf(stderr, "checkpoint_io: %s\n", err);
                    return 1;
                }
                double t2 = now();
                checkpoint_data_free(&cd);
                if (t1 - t0 < best_write) best_write = t1 - t0;
                if (t2 - t1 < best_read) best_read = t2 - t1;
            }
            struct stat st;
            if (stat(path, &st)) return 1;
            printf("%-3d %9zu %12lld %10.1f %10.2f %10.2f\n", dim, n, (long long)st.st_size,
                   (double)st.st_size / (double)n, 1e3 * best_write, 1e3 * best_read);
        }
    }
    remove(path);
    free(values);
    free(ids);
    return 0;
}
