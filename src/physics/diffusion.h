/* diffusion: the density diffusion D^rho of Eq. (5) (delta-SPH with the LES-type coefficient). */
#ifndef VCSPH_DIFFUSION_H
#define VCSPH_DIFFUSION_H

#include "core/vec.h"

/* 2 delta_ij [(rho_j - rho_i) - 1/2 (<grad rho>^L_i + <grad rho>^L_j) . r_ji] F_ij V_j:
 * the renormalized gradients remove the linear part of the density field, so a hydrostatic
 * column is not diffused. */
static inline double diffusion_rho_pair(double delta_ij, double rho_i, double rho_j, vec grad_i,
                                        vec grad_j, vec r_ji, double f_ij, double vol_j)
{
    double linear = 0.5 * vec_dot(vec_add(grad_i, grad_j), r_ji);
    return 2.0 * delta_ij * ((rho_j - rho_i) - linear) * f_ij * vol_j;
}

/* nu^delta_i = (C_delta l)^2 ||D_i|| (Eq. 5) */
static inline double diffusion_coefficient(double c_delta, double filter_length, double strain_norm)
{
    double ls = c_delta * filter_length;
    return ls * ls * strain_norm;
}

#endif
