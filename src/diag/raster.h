/* raster: the graphical method of the paper, Eq. (15) (sec. 3.2; theory §9): the liquid
 * drawn on a grid of pixels (voxels) of side dr / k and the covered pixels counted.
 * Dimension-free at run time (dim = 2 or 3); docs/graphical-method.md has the rules compared
 * and the figures behind the defaults. */
#ifndef VCSPH_RASTER_H
#define VCSPH_RASTER_H

#include <stddef.h>

typedef struct {
    int k;            /* pixels per particle spacing: pixel side dr / k (theory §9: k >= 4) */
    double radius;    /* disc (ball) radius / dr: every pixel this close to a particle is
                         liquid; 0: no discs */
    double smoothing; /* smoothing length / dr of the colour function C = sum_j W_j V_p;
                         every pixel with C >= 1/2 is liquid; 0: no colour function */
    double particle_volume; /* V_p, each particle's volume (m^n, m^2 in 2D); 0: dr^n. The
                               lattice's cell, whose spacing across a tank that holds no
                               whole number of dr differs from dr, so that C = 1 inside */
    double spacing[3];      /* the lattice's spacing per axis (m), the pixel side then being
                               spacing / k from the wall at 0, so that every cell edge of a
                               lattice that starts at that wall is a pixel edge and its flat
                               surface is read where it is; the last layer, cut by the far
                               wall, counts with its part inside. 0: pixels of about dr / k
                               sized to fit the box */
} raster_params;

/* The chosen rule: the colour function of a Wendland C2 kernel of smoothing length dr,
 * thresholded at 1/2, together with discs of radius dr/2 (so that a lone particle keeps its
 * cell's footprint); k = 8 in 2D, 4 in 3D (docs/graphical-method.md). */
raster_params raster_params_default(int dim);

/* Covered volume (m^n; m^2 per unit width in 2D) of the n particles at positions
 * x[0..dim)[0..n), rasterised over the tank box [0, size[d]] (walls at 0 and size[d]); the
 * pixels are of side spacing / k (rp->spacing) or sized to fit the box, dr / k or a hair
 * less. The walls act as mirrors, as the ghost particles do (theory §5). eps_GM (Eq. 15) is
 * this volume over that of the initial configuration, minus 1 (graphical_error, volume.h).
 * The result does not depend on the number of threads. Returns 0, or -1 with a message in err
 * (bad argument, grid too large, out of memory). */
int raster_volume(int dim, size_t n, double *const x[3], double dr, const double size[3],
                  const raster_params *rp, double *volume, char *err, size_t err_len);

/* The liquid pixels of a raster, or of a part of it, by kind (bit d set: on the last layer of
 * axis d, which counts with its part inside the box), and what turns them into a volume.
 * Counts are integers: the parts of a raster drawn by several processes add up exactly. */
typedef struct {
    int dim;
    unsigned long long count[8];
    double last[3];      /* the part of the last layer of each axis inside the box */
    double pixel_volume; /* m^n */
} raster_count;

/* How far from a particle its discs and colour function reach (m). */
double raster_reach(const raster_params *rp, double dr);

/* raster_volume's liquid pixels whose centres lie at x in [x_lo, x_hi) (x along axis 0;
 * -INFINITY and INFINITY for the whole box): the part of the raster that one process draws
 * when the liquid is split along x among processes (docs/mpi.md). The particles given must
 * hold every particle within raster_reach of that range, in their global order (a process's
 * left halo, its own particles, its right halo); each pixel then sums the same sources in
 * the same order as the whole raster does, and the parts' counts add up to its count. */
int raster_count_part(int dim, size_t n, double *const x[3], double dr, const double size[3],
                      const raster_params *rp, double x_lo, double x_hi, raster_count *c, char *err,
                      size_t err_len);

/* The covered volume of counted pixels (m^n). */
double raster_count_volume(const raster_count *c);

#endif
