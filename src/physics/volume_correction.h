/* volume_correction: the pair math of the geometric volume correction
 * (docs/volume-correction.md). */
#ifndef VCSPH_PHYSICS_VOLUME_CORRECTION_H
#define VCSPH_PHYSICS_VOLUME_CORRECTION_H

#include "core/vec.h"

/* e_i = V_i sum_j W_ij / kappa - 1: the SPH volume m_i / rho_i over the geometric volume
 * 1 / sum_j W_ij of Eq. (11), relative to the lattice, where kappa = dr^n sum_lattice W is
 * what Eq. (11) reads on a regular lattice of cell volume dr^n (theory §1: 1.0012 in 2D at
 * h/dr = 2). Positive where the particles are packed closer than their density says. */
static inline double volume_mismatch(double vol_sph, double kernel_sum, double lattice_sum)
{
    return vol_sph * kernel_sum / lattice_sum - 1.0;
}

/* (e_j - e_i) grad_i W_ij V_j: summed over j it is the SPH gradient of e, and multiplied
 * by -h U the correction velocity, which moves particles from where they are packed too
 * close (e > 0) towards where they are spread too far (e < 0): the geometric density then
 * diffuses, de/dt = h U lap e, from either side. The difference form matters: the pressure
 * form (e_i + e_j) is attractive where e < 0 and clumps the particles there (the tensile
 * instability), as a patch expanded by 1 % showed. */
static inline vec volume_correction_pair(double e_i, double e_j, vec r_ji, double f_ij,
                                         double vol_j)
{
    return vec_scale(r_ji, (e_j - e_i) * f_ij * vol_j);
}

/* d rho_i / dt of a particle moved by the correction velocity dv through the density field:
 * dv . <grad rho>_i (the renormalized gradient of the step). The correction rearranges the
 * particles; the density field, and with it the pressure, stays where it is. (The flux form
 * of the shifting's ALE terms would do the same in the interior, but at the free surface,
 * where the correction, unlike the shifting, moves along the normal, the truncated kernel
 * makes it a spurious source: 2 rho dv . sum grad W V.) */
static inline double volume_correction_resampling(vec dv, vec grad_rho)
{
    return vec_dot(dv, grad_rho);
}

#endif
