/* fields: the per-step fields frozen over the RK stages (sec. 2.4): the matrix L of Eq. (10)
 * and lambda, renormalized gradients, ||D||, eddy viscosity, the diffusion coefficient and
 * the density diffusion D^rho of Eq. (5). */
#ifndef VCSPH_FIELDS_H
#define VCSPH_FIELDS_H

#include "boundary/tank.h"
#include "core/cells.h"
#include "core/particles.h"
#include "scheme/physics_params.h"

#define fields_compute DIM_NAME(fields_compute)

/* Needs the ghosts refreshed; fills lambda, grad_rho, nu_t, nu_delta of fluid and ghosts and
 * diff_rho of the fluid. */
void fields_compute(const physics_params *pp, const tank *t, particles *p, const neighbour_list *nl,
                    vec g_eff);

#endif
