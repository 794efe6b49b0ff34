/* ale: the Arbitrary-Lagrangian-Eulerian terms of Eq. (3) that come with the shifting
 * velocity du (Antuono et al. 2021; theory §3), and the mass diffusion D^m of Eq. (5). */
#ifndef VCSPH_ALE_H
#define VCSPH_ALE_H

#include "core/vec.h"

/* (rho_j du_j + rho_i du_i) . grad_i W_ij: the pair flux of div(rho du), in the continuity
 * equation (times V_j) and the mass equation (times V_i V_j). Antisymmetric in (i, j), so
 * the mass fluxes between fluid particles sum to zero. */
static inline double ale_flux_pair(double rho_i, vec du_i, double rho_j, vec du_j, vec r_ji,
                                   double f_ij)
{
    return vec_dot(vec_axpy(vec_scale(du_i, rho_i), rho_j, du_j), r_ji) * f_ij;
}

/* rho_j u_ji (du_j . grad_i W_ij) V_j: the pair form of rho (du . grad) u =
 * div(rho u (x) du) - u div(rho du) (theory §3, inferred): a uniform flow stays uniform. */
static inline vec ale_momentum_pair(double rho_j, vec u_ji, vec du_j, vec r_ji, double f_ij,
                                    double vol_j)
{
    return vec_scale(u_ji, rho_j * vec_dot(du_j, r_ji) * f_ij * vol_j);
}

/* 2 delta c0 h (m_j - m_i) F_ij sqrt(V_i V_j), Eq. (5): symmetric weights, so the mass
 * exchanged between two fluid particles is equal and opposite. */
static inline double mass_diffusion_pair(double delta_c0_h, double m_i, double m_j, double f_ij,
                                         double vol_i, double vol_j)
{
    return 2.0 * delta_c0_h * (m_j - m_i) * f_ij * sqrt(vol_i * vol_j);
}

#endif
