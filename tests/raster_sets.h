/* raster_sets: the particle sets of the graphical method's tests and tables (test_raster.c,
 * raster_tables.c): lattice blocks, discs and balls, perturbed and compressed blocks, and the
 * raster's volume and eps_GM of a set. Include after <cmocka.h>. */
#ifndef VCSPH_TEST_RASTER_SETS_H
#define VCSPH_TEST_RASTER_SETS_H

#include "diag/raster.h"
#include "noise.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

static const double dr = 0.01;

/* ---- particle sets ------------------------------------------------------------------------- */

typedef struct {
    size_t n, cap;
    double *x[3];
} cloud;

static inline void cloud_init(cloud *c)
{
    c->n = 0;
    c->cap = 1024;
    for (int d = 0; d < 3; d++) {
        c->x[d] = malloc(c->cap * sizeof(double));
        assert_non_null(c->x[d]);
    }
}

static inline void cloud_free(cloud *c)
{
    for (int d = 0; d < 3; d++) free(c->x[d]);
}

static inline void cloud_add(cloud *c, double x, double y, double z)
{
    if (c->n == c->cap) {
        c->cap *= 2;
        for (int d = 0; d < 3; d++) {
            c->x[d] = realloc(c->x[d], c->cap * sizeof(double));
            assert_non_null(c->x[d]);
        }
    }
    c->x[0][c->n] = x;
    c->x[1][c->n] = y;
    c->x[2][c->n] = z;
    c->n++;
}

/* n[0] x n[1] (x n[2]) particles of spacing s, the first at o + s/2: the lattice of sec. 2.1
 * when o = 0 and s = dr. */
static inline void add_block(cloud *c, int dim, const int n[3], double s, const double o[3])
{
    for (int k = 0; k < (dim == 3 ? n[2] : 1); k++)
        for (int j = 0; j < n[1]; j++)
            for (int i = 0; i < n[0]; i++)
                cloud_add(c, o[0] + (i + 0.5) * s, o[1] + (j + 0.5) * s,
                          dim == 3 ? o[2] + (k + 0.5) * s : 0.0);
}

static inline double gm_volume(int dim, const cloud *c, const double size[3],
                               const raster_params *rp)
{
    char err[256];
    double v = -1.0;
    int rc = raster_volume(dim, c->n, c->x, dr, size, rp, &v, err, sizeof err);
    if (rc) fail_msg("raster_volume: %s", err);
    return v;
}

static inline double eps_gm(int dim, const cloud *c, const double size[3], const raster_params *rp)
{
    return gm_volume(dim, c, size, rp) / ((double)c->n * pow(dr, dim)) - 1.0;
}

/* The initial lattice of sec. 2.1: N rows filling the bottom of the tank wall to wall,
 * 2N x N particles in 2D, N x N x N in 3D, free surface on top, 8 dr below the lid; particles
 * displaced by up to a dr along each axis (uniformly) when a > 0. */
static inline double lattice_block_eps(int dim, int N, double a, uint64_t seed,
                                       const raster_params *rp)
{
    cloud c;
    cloud_init(&c);
    int n[3] = {dim == 3 ? N : 2 * N, N, N};
    double size[3] = {n[0] * dr, (N + 8) * dr, n[2] * dr};
    add_block(&c, dim, n, dr, (double[3]){0.0, 0.0, 0.0});
    for (size_t i = 0; a > 0.0 && i < c.n; i++)
        for (int d = 0; d < dim; d++)
            c.x[d][i] = fmin(fmax(c.x[d][i] + a * dr * noise(&seed), 0.0), size[d]);
    double e = eps_gm(dim, &c, size, rp);
    cloud_free(&c);
    return e;
}

/* All the lattice points within R of a lattice point in the middle of a tank 4 (R + 5 dr)
 * wide, farther than 2c from the walls. */
static inline void add_lattice_disc(cloud *c, int dim, int R_dr, double size[3])
{
    int m = R_dr + 5;
    for (int d = 0; d < 3; d++) size[d] = 4 * m * dr;
    double o = (2 * m + 0.5) * dr;
    for (int k = (dim == 3 ? -m : 0); k <= (dim == 3 ? m : 0); k++)
        for (int j = -m; j <= m; j++)
            for (int i = -m; i <= m; i++)
                if (i * i + j * j + k * k <= R_dr * R_dr)
                    cloud_add(c, o + i * dr, o + j * dr, dim == 3 ? o + k * dr : 0.0);
}

static inline double lattice_disc_eps(int dim, int R_dr, const raster_params *rp)
{
    cloud c;
    cloud_init(&c);
    double size[3];
    add_lattice_disc(&c, dim, R_dr, size);
    double e = eps_gm(dim, &c, size, rp);
    cloud_free(&c);
    return e;
}

/* Two blocks of 8 x 8 (x 8) lattice particles side by side along x, the facing rows of
 * particles gap + dr apart (so that their discs are `gap` apart), in the middle of a tank. */
static inline double two_blocks_volume(int dim, double gap, int blocks, const raster_params *rp)
{
    cloud c;
    cloud_init(&c);
    int n[3] = {8, 8, 8};
    double margin = (2.0 * rp->smoothing + 2.0) * dr;
    double size[3] = {16 * dr + gap + 2 * margin, 8 * dr + 2 * margin, 8 * dr + 2 * margin};
    add_block(&c, dim, n, dr, (double[3]){margin, margin, margin});
    if (blocks == 2) add_block(&c, dim, n, dr, (double[3]){margin + 8 * dr + gap, margin, margin});
    double v = gm_volume(dim, &c, size, rp);
    cloud_free(&c);
    return v;
}

#endif
