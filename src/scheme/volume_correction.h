/* volume_correction: the geometric volume correction of model.volume_correction = geometric,
 * vcsph's own (docs/volume-correction.md). It moves the particles, not their densities, so
 * that the geometric volume of Eq. (11) matches the SPH volume m/rho particle by particle,
 * from either side, also where the flow does not fragment. */
#ifndef VCSPH_VOLUME_CORRECTION_H
#define VCSPH_VOLUME_CORRECTION_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/particles.h"
#include "scheme/bodies.h"
#include "scheme/physics_params.h"

/* The sums of one step per body (bodies.h), kept between steps so that a step rarely
 * allocates. */
typedef struct {
    size_t capacity; /* bodies */
    double *sums;    /* per body: sum V dv . n over its S_F, and sum V over it */
} volume_correction_work;

#define volume_correction_mismatch       DIM_NAME(volume_correction_mismatch)
#define volume_correction_band           DIM_NAME(volume_correction_band)
#define volume_correction_ghost_mismatch DIM_NAME(volume_correction_ghost_mismatch)
#define volume_correction_velocity_from  DIM_NAME(volume_correction_velocity_from)
#define volume_correction_per_body       DIM_NAME(volume_correction_per_body)
#define volume_correction_free           DIM_NAME(volume_correction_free)

/* The correction velocity dv of the step into p->correction of the fluid, after the geometry
 * and before bounce-back, frozen over the RK stages like the shifting velocity, in four
 * passes (each reads at the neighbours what the one before wrote):
 *   e_i  = V_i sum_j W_ij / kappa - 1 off S_F; in S_F the Shepard average of the interior
 *          neighbours' e (0 with none: the free surface itself, drops);
 *   dv_i = -h U_max sum_j (e_j - e_i) grad_i W_ij V_j, Eq. (7)'s scale, none where
 *          lambda < 0.4, and at most U_max / 2;
 *   in S_F, the component of dv along the surface's normal is replaced by its V-weighted
 *          mean over the particle's body (b): the surface must move for the volume to
 *          change, but the correction changes each body's volume, not its shape.
 * The particles then move with u + du + dv, and their density is resampled along dv
 * (rhs.c, physics/volume_correction.h); masses and velocities are left alone.
 * volume_correction_mismatch writes e off S_F, volume_correction_band e in S_F,
 * volume_correction_ghost_mismatch e of the walls' images (after an MPI run's halo has
 * its sources' e), volume_correction_velocity_from dv, volume_correction_per_body the normal
 * component in S_F (the bodies' sums through d, NULL on one process; returns 0,
 * or -1 when out of memory). */
void volume_correction_mismatch(const physics_params *pp, particles *p);
void volume_correction_band(const physics_params *pp, particles *p, const neighbour_list *nl);
void volume_correction_ghost_mismatch(particles *p);
/* dv of fluid particle i, for lambda >= 0.4 (below, the pass sets 0 without a row), from its
 * sum over its row of sum_j (e_j - e_i) grad_i W_ij V_j (volume_correction_pair), which the
 * pass sums beside the shifting over the same row (step_fields_shifting_and_correction,
 * step_fields.h). */
vec volume_correction_velocity_from(const physics_params *pp, const particles *p, size_t i,
                                    vec sum);
int volume_correction_per_body(particles *p, const bodies *b, const bodies_domain *d,
                               volume_correction_work *w);
void volume_correction_free(volume_correction_work *w);

#endif
