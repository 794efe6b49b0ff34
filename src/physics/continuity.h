/* continuity: the pair term of the continuity equation, Eq. (3) with du = 0. */
#ifndef VCSPH_CONTINUITY_H
#define VCSPH_CONTINUITY_H

#include "core/vec.h"

/* -rho_i u_ji . grad_i W_ij V_j, with grad_i W_ij = r_ji F_ij: particles approaching each
 * other (u_ji . r_ji < 0) raise the density. */
static inline double continuity_pair(double rho_i, vec u_ji, vec r_ji, double f_ij, double vol_j)
{
    return -rho_i * vec_dot(u_ji, r_ji) * f_ij * vol_j;
}

#endif
