/* loads: the force and moment the liquid exerts on the tank (docs/loads.md), from the wall
 * interactions that the momentum equation integrates: the pressure, viscous and ALE terms of
 * every fluid particle's pairs with the walls' images (scheme/momentum.h). Particle code:
 * compiled for DIM = 2 and 3. */
#ifndef VCSPH_LOADS_H
#define VCSPH_LOADS_H

#include "core/cells.h"
#include "core/particles.h"
#include "core/reduce.h"
#include "boundary/frame.h"
#include "scheme/physics_params.h"

typedef struct {
    double force[3];    /* N (N/m in 2D), in the tank's axes */
    double moment[3];   /* N m (N m/m in 2D) about `center`, in the tank's axes */
    double momentum[3]; /* the liquid's sum m u (kg m/s), tank frame */
    double body[3];     /* the body force on the liquid, sum m f(r, u) (N), tank frame */
} tank_loads;

#define loads_compute DIM_NAME(loads_compute)

/* The loads on the tank: minus the walls' force on each fluid particle, V_i sum_j f_ij over
 * its wall images j, summed in a fixed order, and minus its moment (x_i - center) x F_i
 * (center: the frame's); and the liquid's momentum and body force, so that the balance
 * force = body - d(momentum)/dt can be checked. Needs the state of an RK stage (neighbours,
 * ghosts, pressures); r sums over the processes (NULL: one). Returns 0, or -1 when out of memory.
 */
int loads_compute(const physics_params *pp, const particles *p, const neighbour_list *nl,
                  const tank_frame *frame, const reducer *r, tank_loads *out);

#endif
