/* raster_tables: the figures of docs/graphical-method.md, printed. The argument names the
 * tables by letters (b lattice block, d lattice disc/ball, s smooth disc/ball, r rotated block,
 * p perturbed block, c compressed block, g gaps between blobs, l thin sheets, t timings) and
 * the dimensions by digits, e.g. `build/tests/raster_tables bdt23`. Not a test: it asserts nothing
 * beyond what test_raster does. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raster_sets.h"

/* ---- tables for docs/graphical-method.md -------------------------------------------------- */

typedef struct {
    const char *name;
    double radius, smoothing;
} rule;

static const rule rules[] = {
    {"disc dr/sqrt(2)", 0.70710678118654752, 0.0},
    {"disc dr/sqrt(pi)", 0.56418958354775628, 0.0},
    {"ball dr sqrt(3)/2", 0.86602540378443865, 0.0},
    {"ball dr (3/(4 pi))^(1/3)", 0.62035049089940001, 0.0},
    {"C >= 1/2, h_c = 0.8 dr", 0.0, 0.8},
    {"C >= 1/2, h_c = 1 dr", 0.0, 1.0},
    {"C >= 1/2, h_c = 1.3 dr", 0.0, 1.3},
    {"C >= 1/2, h_c = 0.8 dr, discs dr/2", 0.5, 0.8},
    {"C >= 1/2, h_c = 1 dr, discs dr/2", 0.5, 1.0},
    {"C >= 1/2, h_c = 1.3 dr, discs dr/2", 0.5, 1.3},
};
#define N_RULES (sizeof rules / sizeof rules[0])

/* A disc of concentric rings 1, 2, .. R dr in radius, round(2 pi j) particles on ring j (a
 * ball of shells, round(4 pi j^2 + pi/3) particles each on a Fibonacci sphere): a smooth
 * surface, each particle dr^n of space, N dr^n within 0.2 % of the disc of radius R + dr/2. */
static double smooth_disc_eps(int dim, int R, const raster_params *rp)
{
    cloud c;
    cloud_init(&c);
    double o = (2 * R + 6.37) * dr, size[3] = {2 * o, 2 * o, 2 * o};
    cloud_add(&c, o, o, dim == 3 ? o : 0.0);
    for (int j = 1; j <= R; j++) {
        if (dim == 2) {
            int m = (int)lround(2 * PI * j);
            for (int i = 0; i < m; i++) {
                double a = 2 * PI * (i + 0.5 * (j % 2)) / m;
                cloud_add(&c, o + j * dr * cos(a), o + j * dr * sin(a), 0.0);
            }
        } else {
            int m = (int)lround(4 * PI * j * j + PI / 3);
            double golden = PI * (3.0 - sqrt(5.0));
            for (int i = 0; i < m; i++) {
                double z = 1.0 - (2 * i + 1.0) / m, rr = sqrt(1.0 - z * z), a = i * golden + j;
                cloud_add(&c, o + j * dr * rr * cos(a), o + j * dr * rr * sin(a), o + j * dr * z);
            }
        }
    }
    double e = eps_gm(dim, &c, size, rp);
    cloud_free(&c);
    return e;
}

/* A block of N x N (x N) lattice particles turned by 30 degrees about z (and 20 about x in 3D),
 * floating in the middle of a tank 2N wide: free surface all round, oblique to the pixels. */
static double rotated_block_eps(int dim, int N, const raster_params *rp)
{
    cloud c;
    cloud_init(&c);
    double size[3] = {2 * N * dr, 2 * N * dr, 2 * N * dr};
    double a = 30.0 * PI / 180.0, b = dim == 3 ? 20.0 * PI / 180.0 : 0.0;
    for (int k = 0; k < (dim == 3 ? N : 1); k++)
        for (int j = 0; j < N; j++)
            for (int i = 0; i < N; i++) {
                double p[3] = {(i + 0.5 - 0.5 * N) * dr, (j + 0.5 - 0.5 * N) * dr,
                               dim == 3 ? (k + 0.5 - 0.5 * N) * dr : 0.0};
                double q0 = cos(a) * p[0] - sin(a) * p[1], q1 = sin(a) * p[0] + cos(a) * p[1];
                double r1 = cos(b) * q1 - sin(b) * p[2], r2 = sin(b) * q1 + cos(b) * p[2];
                cloud_add(&c, N * dr + q0, N * dr + r1, dim == 3 ? N * dr + r2 : 0.0);
            }
    double e = eps_gm(dim, &c, size, rp);
    cloud_free(&c);
    return e;
}

/* The lattice block with spacing dr (1 - e), N = 20: eps_GM - ((1 - e)^n - 1). */
static double compressed_block_error(int dim, int N, double e, const raster_params *rp)
{
    cloud c;
    cloud_init(&c);
    int n[3] = {dim == 3 ? N : 2 * N, N, N};
    double s = dr * (1.0 - e);
    double size[3] = {n[0] * s, (N + 8) * dr, n[2] * s};
    add_block(&c, dim, n, s, (double[3]){0.0, 0.0, 0.0});
    double got = eps_gm(dim, &c, size, rp);
    cloud_free(&c);
    return got - (pow(1.0 - e, dim) - 1.0);
}

typedef double (*config_fn)(int dim, int variant, const raster_params *rp);

static double cfg_block(int dim, int N, const raster_params *rp)
{
    return lattice_block_eps(dim, N, 0.0, 0, rp);
}
static double cfg_disc(int dim, int R, const raster_params *rp)
{
    return lattice_disc_eps(dim, R, rp);
}
static double cfg_smooth(int dim, int R, const raster_params *rp)
{
    return smooth_disc_eps(dim, R, rp);
}
static double cfg_rotated(int dim, int N, const raster_params *rp)
{
    return rotated_block_eps(dim, N, rp);
}
static double cfg_perturbed(int dim, int percent, const raster_params *rp)
{
    double sum = 0.0;
    for (uint64_t seed = 1; seed <= 3; seed++)
        sum += lattice_block_eps(dim, 20, 0.01 * percent, seed, rp);
    return sum / 3.0;
}
static double cfg_compressed(int dim, int N, const raster_params *rp)
{
    return compressed_block_error(dim, N, 0.01, rp);
}

static void table(const char *title, config_fn f, const int *variants, int n_variants,
                  const char *vname, const char *which)
{
    const int ks[2] = {4, 8};
    for (int dim = 2; dim <= 3; dim++) {
        if (!strchr(which, '0' + dim)) continue;
        printf("\n%s, %dD (%%)\n\n| rule |", title, dim);
        for (int ik = 0; ik < 2; ik++)
            for (int v = 0; v < n_variants; v++) printf(" k=%d %s%d |", ks[ik], vname, variants[v]);
        printf("\n|---|");
        for (int c = 0; c < 2 * n_variants; c++) printf("---:|");
        printf("\n");
        for (size_t r = 0; r < N_RULES; r++) {
            printf("| %s |", rules[r].name);
            for (int ik = 0; ik < 2; ik++)
                for (int v = 0; v < n_variants; v++) {
                    raster_params rp = {
                        .k = ks[ik], .radius = rules[r].radius, .smoothing = rules[r].smoothing};
                    printf(" %+.2f |", 100.0 * f(dim, variants[v], &rp));
                    fflush(stdout);
                }
            printf("\n");
        }
    }
}

static void gap_table(const char *which)
{
    for (int dim = 2; dim <= 3; dim++) {
        if (!strchr(which, '0' + dim)) continue;
        raster_params rp = raster_params_default(dim);
        double one = two_blocks_volume(dim, 4.0 * dr, 1, &rp);
        printf("\nbridge between two blocks of 8^%d particles, %dD, k = %d, h_c = %g dr, in %% of "
               "one block\n\n| gap / dr |",
               dim, dim, rp.k, rp.smoothing);
        for (int i = 0; i <= 9; i++) printf(" %.2f |", 0.25 * i);
        printf("\n|---|");
        for (int i = 0; i <= 9; i++) printf("---:|");
        printf("\n| bridge |");
        for (int i = 0; i <= 9; i++) {
            double v = two_blocks_volume(dim, 0.25 * i * dr, 2, &rp);
            printf(" %+.2f |", 100.0 * (v - 2.0 * one) / one);
        }
        printf("\n");
    }
}

/* A floating sheet `rows` lattice rows thick (dr apart), its particles `spacing` dr apart
 * along it (40 in 2D, 20 x 20 per layer in 3D): eps_GM against its particles' dr^n each. */
static double sheet_eps(int dim, int rows, double spacing, const raster_params *rp)
{
    cloud c;
    cloud_init(&c);
    int along = dim == 3 ? 20 : 40;
    double size[3] = {(along + 8) * dr, (rows + 8) * dr, (along + 8) * dr};
    for (int k = 0; k < (dim == 3 ? along : 1); k++)
        for (int j = 0; j < rows; j++)
            for (int i = 0; i < along; i++)
                cloud_add(&c, (4 + i * spacing) * dr, (4 + j) * dr,
                          dim == 3 ? (4 + k * spacing) * dr : 0.0);
    double e = eps_gm(dim, &c, size, rp);
    cloud_free(&c);
    return e;
}

static void sheet_table(const char *which)
{
    const int rows[4] = {1, 2, 3, 5};
    const double spacings[3] = {1.0, 0.8, 0.7};
    for (int dim = 2; dim <= 3; dim++) {
        if (!strchr(which, '0' + dim)) continue;
        raster_params rp = raster_params_default(dim);
        printf("\nthin sheet, %dD, eps_GM (%%) by rows and spacing along it\n\n| rows |", dim);
        for (int s = 0; s < 3; s++) printf(" %.1f dr |", spacings[s]);
        printf("\n|---|---:|---:|---:|\n");
        for (int r = 0; r < 4; r++) {
            printf("| %d |", rows[r]);
            for (int s = 0; s < 3; s++)
                printf(" %+.2f |", 100.0 * sheet_eps(dim, rows[r], spacings[s], &rp));
            printf("\n");
        }
    }
}

static void timing_table(const char *which)
{
    for (int dim = 2; dim <= 3; dim++) {
        if (!strchr(which, '0' + dim)) continue;
        cloud c;
        cloud_init(&c);
        int n[3] = {dim == 3 ? 50 : 250, dim == 3 ? 40 : 200, 50};
        double size[3] = {n[0] * dr, 1.5 * n[1] * dr, n[2] * dr};
        add_block(&c, dim, n, dr, (double[3]){0.0, 0.0, 0.0});
        for (int k = 4; k <= 8; k += 4) {
            raster_params rp = raster_params_default(dim);
            rp.k = k;
            double best = INFINITY;
            for (int rep = 0; rep < 3; rep++) {
                double t0 = omp_get_wtime();
                gm_volume(dim, &c, size, &rp);
                best = fmin(best, omp_get_wtime() - t0);
            }
            double pixels = 1.0;
            for (int d = 0; d < dim; d++) pixels *= ceil(size[d] / (dr / k) - 1e-9);
            printf("timing %dD, %zu particles, k = %d, %.3g pixels, %d threads: %.3f s\n", dim, c.n,
                   k, pixels, omp_get_max_threads(), best);
        }
        cloud_free(&c);
    }
}

static void print_tables(const char *what)
{
    const int Ns[3] = {10, 20, 40}, R[1] = {10}, N20[1] = {20}, pert[2] = {5, 20};
    if (strchr(what, 'b')) table("lattice block, eps_GM", cfg_block, Ns, 3, "N=", what);
    if (strchr(what, 'd')) table("lattice disc (ball), eps_GM", cfg_disc, R, 1, "R/dr=", what);
    if (strchr(what, 's'))
        table("smooth disc (ball) of rings (shells), eps_GM", cfg_smooth, R, 1, "R/dr=", what);
    if (strchr(what, 'r')) table("rotated block, eps_GM", cfg_rotated, N20, 1, "N=", what);
    if (strchr(what, 'p'))
        table("perturbed block N = 20, mean eps_GM of 3", cfg_perturbed, pert, 2, "a%=", what);
    if (strchr(what, 'c'))
        table("compressed block, e = 1 %, eps_GM - ((1-e)^n - 1)", cfg_compressed, N20, 1,
              "N=", what);
    if (strchr(what, 'g')) gap_table(what);
    if (strchr(what, 'l')) sheet_table(what);
    if (strchr(what, 't')) timing_table(what);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr,
                "usage: raster_tables TABLES (letters bdsrpcglt, digits 2 3: e.g. bdt23)\n");
        return 2;
    }
    print_tables(argv[1]);
    return 0;
}
