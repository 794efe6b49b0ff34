/* eos: the linear equation of state of Eq. (3) and its internal energy (theory §10). */
#ifndef VCSPH_EOS_H
#define VCSPH_EOS_H

#include <math.h>

/* p = c0^2 (rho - rho0), Eq. (3). The right-hand side's lanes take a fluid neighbour's p as
 * this function of its rho (scheme/rhs_lanes.h), which solver_update_eos and EdBC keep to the
 * bit: an equation of state changed here is changed there. */
static inline double eos_pressure(double rho, double rho0, double c0)
{
    return c0 * c0 * (rho - rho0);
}

static inline double eos_density(double p, double rho0, double c0) { return rho0 + p / (c0 * c0); }

/* Specific internal energy of the linear EOS: e = int p/rho^2 drho from rho0
 *   = c0^2 (ln(rho/rho0) + rho0/rho - 1)   (docs/outputs.md, theory §10) */
static inline double eos_internal_energy(double rho, double rho0, double c0)
{
    return c0 * c0 * (log(rho / rho0) + rho0 / rho - 1.0);
}

#endif
