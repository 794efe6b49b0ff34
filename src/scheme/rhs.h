/* rhs: the right-hand side of Eq. (3) for the fluid particles at one RK stage. */
#ifndef VCSPH_RHS_H
#define VCSPH_RHS_H

#include "core/cells.h"
#include "core/particles.h"
#include "core/vec.h"
#include "boundary/frame.h"
#include "scheme/physics_params.h"

/* Time derivatives of the integrated fluid state (core/particles.h, PARTICLE_INTEGRATED):
 * dx = dr/dt = u + du, du = du/dt, drho = drho/dt, dm = dm/dt. */
#define RATE_SCALAR(name) double *d##name;
#define RATE_VECTOR(name) double *d##name[DIM];
typedef struct {
    PARTICLE_INTEGRATED(RATE_SCALAR, RATE_VECTOR)
} rates;

#define rhs_compute DIM_NAME(rhs_compute)

/* Needs fluid p, vol, u_wall and the ghosts refreshed for this stage, and the frozen per-step
 * fields. `frame` gives the body force of the tank frame at each particle (boundary/frame.h,
 * theory §6: g - a_tank(t) for a translating tank);
 * eta in [0, 1] weighs the mass equation of Eq. (3) (0: constant masses; the frozen D^m must
 * have been computed when eta > 0). */
void rhs_compute(const physics_params *pp, const particles *p, const neighbour_list *nl,
                 const tank_frame *frame, double eta, const rates *out);
/* (Four or eight particles at a time in SIMD lanes where core/lanes_switch.h's lanes_width() says
 * so: the same bits, scheme/rhs_lanes.h.) */

#endif
