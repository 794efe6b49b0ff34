/* volume_correction: the geometric volume correction of model.volume_correction = geometric,
 * vcsph's own (docs/volume-correction.md). It moves the particles, not their densities, so
 * that the geometric volume of Eq. (11) matches the SPH volume m/rho particle by particle,
 * from either side, also where the flow does not fragment. */
#ifndef VCSPH_VOLUME_CORRECTION_H
#define VCSPH_VOLUME_CORRECTION_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/particles.h"
#include "scheme/physics_params.h"

#define volume_correction_lattice_sum DIM_NAME(volume_correction_lattice_sum)
#define volume_correction_apply       DIM_NAME(volume_correction_apply)

/* kappa = dr^n sum_j W(|r_j|) over the points r_j of the lattice of spacing dr (self
 * included): Eq. (11)'s reading of a regular lattice. */
double volume_correction_lattice_sum(const kernel *k, double dr);

/* The correction velocity dv of the step into p->correction of the fluid, after the geometry
 * and before bounce-back, frozen over the RK stages like the shifting velocity:
 *   e_i  = V_i sum_j W_ij / kappa - 1 off S_F; in S_F the Shepard average of the interior
 *          neighbours' e (0 with none: the free surface itself, drops);
 *   dv_i = -h U_max sum_j (e_j - e_i) grad_i W_ij V_j, Eq. (7)'s scale, no tangential
 *          projection in S_F (the free surface must move for the volume to change), none
 *          where lambda < 0.4, and at most U_max / 2.
 * The particles then move with u + du + dv, and their density is resampled along dv
 * (rhs.c, physics/volume_correction.h); masses and velocities are left alone. Writes
 * p->volume_mismatch of the fluid and the ghosts. */
void volume_correction_apply(const physics_params *pp, particles *p, const neighbour_list *nl);

#endif
