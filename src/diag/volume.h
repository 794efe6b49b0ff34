/* volume: run-time volume errors from the particle positions (sec. 3, appendix):
 * eps_V^(1) (Eq. 12), eps_V^(2) (A.2), eps_V^(3) (A.3) and the local eps_Vi. */
#ifndef VCSPH_VOLUME_H
#define VCSPH_VOLUME_H

#include "core/cells.h"
#include "core/derived.h"
#include "core/kernel.h"
#include "core/particles.h"
#include "core/reduce.h"
#include "diag/freesurface.h"
#include "diag/raster.h"

typedef struct {
    double eps_v1, eps_v2, eps_v3;
    long n_free_surface;
} volume_errors;

#define volume_compute DIM_NAME(volume_compute)

/* From this step's geometry (kernel_sum, gamma, lambda, surface); `cell_volume` is dr^n and
 * V0 = N dr^n. `scratch` holds n_fluid doubles. Sums in the fixed order of reduce, over the
 * processes through r (NULL: this process's particles are the liquid). */
void volume_compute(const particles *p, double cell_volume, double *scratch, const reducer *r,
                    volume_errors *out);

#define volume_free_surface_packing DIM_NAME(volume_free_surface_packing)

/* eps_fs, vcsph's (not the paper's): the volume the free surface's own particles lack against
 * a flat lattice surface, over V0. Eq. (12) counts a free-surface particle at V_i0 whatever
 * its neighbours; here it counts V_i0 S_flat / S_i, S_i = sum_j W_ij (self included) and
 * S_flat the same sum of a flat lattice surface's top row (`flat_surface_sum` = dr^n S_flat,
 * kernel_lattice_sum), so that a surface packed tighter than the lattice reads negative:
 * eps_fs = sum over the free surface of (S_flat / S_i - 1) V_i0 / V0. 0 on a flat lattice
 * surface; a surface with corners reads high (a disc cut from the lattice, R = 20 dr: +0.5 %,
 * its staircase's corner particles having fewer neighbours than a flat row's). eps_v1 +
 * eps_fs is the geometric volume error with the surface's own layer measured too
 * (docs/volume.md). */
double volume_free_surface_packing(const particles *p, double cell_volume, double flat_surface_sum,
                                   double *scratch, const reducer *r);

#define volume_rate DIM_NAME(volume_rate)

/* The rate of eps_V^(1) carried by the particle motion, split by velocity: Eq. (13),
 * dVgeo_i/dt = Vgeo_i^2 sum_j v_ji . grad_i W_ij, summed over the particles off S_F and
 * divided by V0 = n_fluid dr^n, with v = u, the shifting velocity du and the volume
 * correction's dv in turn, 1/s. Needs this step's geometry, du, dv and refreshed ghosts. The
 * changes of S_F membership (a particle entering S_F counts dr^n from then on) are in none.
 * `scratch` holds n_fluid doubles. */
typedef struct {
    double u, shift, correction;
} volume_rates;
void volume_rate(const kernel *k, const particles *p, const neighbour_list *nl, double cell_volume,
                 double *scratch, const reducer *r, volume_rates *out);

#define volume_graphical DIM_NAME(volume_graphical)

/* The volume the graphical method covers, Eq. (15)'s pixel count times the pixel's size, over
 * the tank box [0, size]: the rule of raster_params_default (docs/graphical-method.md), each
 * particle of the lattice cell's volume (V0 / N) in the colour function, pixels of the
 * lattice's spacing / k along each axis (so that the initial lattice's edges are pixel edges).
 * eps_GM is this over the same count of the initial configuration, minus 1
 * (graphical_error). Returns 0, or -1 with a message. */
int volume_graphical(const particles *p, const double size[DIM], const derived *dv, double *volume,
                     char *err, size_t err_len);

#define volume_graphical_part DIM_NAME(volume_graphical_part)

/* volume_graphical's liquid pixels of one process's part of the tank along x, [x_lo, x_hi),
 * when the liquid is split among processes (docs/mpi.md): drawn from its own fluid particles
 * and its halo, in the global order: the first n_halo_before halo particles (the head of the
 * tail, the left neighbour's), the own ones, then the rest of the halo. The parts' counts add
 * up to the whole liquid's (raster_count_part). Returns 0, or -1 with a message. */
int volume_graphical_part(const particles *p, size_t n_halo_before, double x_lo, double x_hi,
                          const double size[DIM], const derived *dv, raster_count *c, char *err,
                          size_t err_len);

/* eps_GM, Eq. (15): the ratio of two pixel counts, the current one over the initial
 * configuration's, so that eps_GM(0) = 0 and the method's bias at the surface cancels. */
static inline double graphical_error(double volume, double initial_volume)
{
    return volume / initial_volume - 1.0;
}

/* Local error eps_Vi = Vgeo_i / dr^n - 1, Vgeo_i = 1 / sum_j W_ij off S_F and dr^n on S_F
 * (theory §9). */
static inline double volume_local_error(const particles *p, size_t i, double cell_volume)
{
    if (p->surface[i] != SURFACE_INTERIOR) return 0.0;
    return 1.0 / (p->kernel_sum[i] * cell_volume) - 1.0;
}

#endif
