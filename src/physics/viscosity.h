/* viscosity: the viscous force F^v of Eq. (4) with the Smagorinsky eddy viscosity and its
 * van Driest damping near walls (sec. 2.2; theory §3). */
#ifndef VCSPH_VISCOSITY_H
#define VCSPH_VISCOSITY_H

#include "core/vec.h"

#define SMAGORINSKY_CS    0.18 /* C_S, sec. 2.2 */
#define VAN_DRIEST_A_PLUS 26.0

#define VISCOSITY_K (2.0 * (DIM + 2)) /* K = 2(n + 2) of Eq. (4) */

/* K (mu + mu^T_ij) pi_ij grad_i W_ij V_j, K = 2(n+2), pi_ij = u_ji . r_ji / |r_ji|^2
 * (force per unit volume on i). Particles approaching each other (pi < 0) are pushed apart. */
static inline vec viscosity_pair(double mu_eff, vec u_ji, vec r_ji, double r2, double f_ij,
                                 double vol_j)
{
    double pi_ij = vec_dot(u_ji, r_ji) / r2;
    return vec_scale(r_ji, VISCOSITY_K * mu_eff * pi_ij * f_ij * vol_j);
}

/* Harmonic mean 2 a b / (a + b) used for mu^T_ij and delta_ij (Eqs. 4, 5); 0 when both are 0,
 * and never above `cap` (the stability bounds of sec. 2.2). */
static inline double harmonic_mean_capped(double a, double b, double cap)
{
    double s = a + b;
    double mean = s > 0.0 ? 2.0 * a * b / s : 0.0;
    return mean < cap ? mean : cap;
}

/* Van Driest factor f = 1 - exp(-y+/A+). The paper's wall stress tau_w = mu u_t / y gives
 * u_tau = sqrt(nu u_t / y) and y+ = y u_tau / nu = sqrt(u_t y / nu) (theory §3). */
static inline double van_driest_factor(double wall_distance, double tangential_speed, double nu)
{
    double y_plus = sqrt(tangential_speed * wall_distance / nu);
    return 1.0 - exp(-y_plus / VAN_DRIEST_A_PLUS);
}

/* nu^T_i = (C_S l f)^2 ||D_i||: the damping multiplies the length scale, so it enters squared
 * (theory §3, inferred). */
static inline double eddy_viscosity(double filter_length, double damping, double strain_norm)
{
    double ls = SMAGORINSKY_CS * filter_length * damping;
    return ls * ls * strain_norm;
}

#endif
