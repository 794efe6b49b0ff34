/* rhs: the right-hand side of Eq. (3) for the fluid particles at one RK stage. */
#ifndef VCSPH_RHS_H
#define VCSPH_RHS_H

#include "core/cells.h"
#include "core/particles.h"
#include "core/vec.h"
#include "boundary/frame.h"
#include "scheme/physics_params.h"

/* Time derivatives of the integrated fluid state but the position (core/particles.h,
 * PARTICLE_RATED): du = du/dt, drho = drho/dt, dm = dm/dt. The position's, dr/dt, is
 * rhs_transport_velocity of the state, recomputed where it is needed rather than stored
 * (2 or 3 doubles a particle less). */
#define RATE_SCALAR(name) double *d##name;
#define RATE_VECTOR(name) double *d##name[DIM];
typedef struct {
    PARTICLE_RATED(RATE_SCALAR, RATE_VECTOR)
} rates;

/* Whether the masses vary at this eta: Eq. (3)'s mass equation weighed by eta > 0, which comes
 * with shifting only (Table 1: eta = 1 implies xi = 1). */
static inline bool rhs_masses_vary(const physics_params *pp, double eta)
{
    return pp->shifting && eta > 0.0;
}

/* dr/dt of fluid particle i: u + du, and the geometric correction's dv with the correction on
 * (the particle moves through the density field, Eq. (3) with the shifting of Eq. (7)); of the
 * state in the store, with the step's frozen du and dv. */
static inline vec rhs_transport_velocity(const physics_params *pp, const particles *p, size_t i)
{
    vec transport = vec_add(vec_load(p->u, i), vec_load(p->shift, i));
    if (pp->volume_correction) transport = vec_add(transport, vec_load(p->correction, i));
    return transport;
}

#define rhs_compute DIM_NAME(rhs_compute)

/* Needs fluid p and vol and the ghosts refreshed for this stage, and the frozen per-step
 * fields. `frame` gives the body force of the tank frame at each particle (boundary/frame.h,
 * theory §6: g - a_tank(t) for a translating tank);
 * eta in [0, 1] weighs the mass equation of Eq. (3) (0: constant masses, and out->dm is not
 * written; the frozen D^m must have been computed when eta > 0). */
void rhs_compute(const physics_params *pp, const particles *p, const neighbour_list *nl,
                 const tank_frame *frame, double eta, const rates *out);
/* (Four or eight particles at a time in SIMD lanes where core/lanes_switch.h's lanes_width() says
 * so: the same bits, scheme/rhs_lanes.h.) */

#endif
