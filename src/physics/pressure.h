/* pressure: the pair term of the pressure force F^p, Eq. (4). */
#ifndef VCSPH_PRESSURE_H
#define VCSPH_PRESSURE_H

#include "core/vec.h"

/* -(p_j + p_i) grad_i W_ij V_j (force per unit volume on i): positive pressures push i away
 * from j, along -r_ji. */
static inline vec pressure_pair(double p_i, double p_j, vec r_ji, double f_ij, double vol_j)
{
    return vec_scale(r_ji, -(p_i + p_j) * f_ij * vol_j);
}

#endif
