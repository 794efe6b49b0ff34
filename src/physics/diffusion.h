/* diffusion: the density diffusion D^rho of Eq. (5) (delta-SPH with the LES-type coefficient). */
#ifndef VCSPH_DIFFUSION_H
#define VCSPH_DIFFUSION_H

#include "core/vec.h"

/* The rate at which D^rho pulls rho_i towards its neighbours: the coefficient of -rho_i in the
 * pair term below, 2 delta_ij F_ij V_j for one pair. */
static inline double diffusion_rate_pair(double delta_ij, double f_ij, double vol_j)
{
    return 2.0 * delta_ij * f_ij * vol_j;
}

/* 2 delta_ij [(rho_j - rho_i) - 1/2 (<grad rho>^L_i + <grad rho>^L_j) . r_ji] F_ij V_j:
 * the renormalized gradients remove the linear part of the density field, so a hydrostatic
 * column is not diffused. */
static inline double diffusion_rho_pair(double delta_ij, double rho_i, double rho_j, vec grad_i,
                                        vec grad_j, vec r_ji, double f_ij, double vol_j)
{
    double linear = 0.5 * vec_dot(vec_add(grad_i, grad_j), r_ji);
    return diffusion_rate_pair(delta_ij, f_ij, vol_j) * ((rho_j - rho_i) - linear);
}

/* D^rho is frozen over the RK stages (paper sec. 2.4), so a step applies it as one explicit
 * Euler step of dt. With the rate a_i = sum of diffusion_rate_pair, every eigenvalue of that
 * step lies in [0, 2 a_i] (Gershgorin), and it is stable when a_i dt <= 1: the factor that
 * brings a_i dt down to 1, or 1. At the paper's cap delta_ij = 0.1 l c0 a lattice has
 * a_i dt = 1.7 at K_c = 1.2, and a clump of particles a hair apart (F_ij at its peak)
 * several times that: the step then amplifies the difference of their densities
 * (docs/choices.md). */
static inline double diffusion_stability_factor(double rate, double dt)
{
    return rate * dt > 1.0 ? 1.0 / (rate * dt) : 1.0;
}

/* nu^delta_i = (C_delta l)^2 ||D_i|| (Eq. 5) */
static inline double diffusion_coefficient(double c_delta, double filter_length, double strain_norm)
{
    double ls = c_delta * filter_length;
    return ls * ls * strain_norm;
}

#endif
