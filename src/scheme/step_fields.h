/* step_fields: the per-step fields frozen over the RK stages (sec. 2.4): the matrix L of Eq. (10)
 * and lambda, renormalized gradients, ||D||, eddy viscosity, the diffusion coefficient and
 * the density diffusion D^rho of Eq. (5). */
#ifndef VCSPH_STEP_FIELDS_H
#define VCSPH_STEP_FIELDS_H

#include "boundary/tank.h"
#include "core/cells.h"
#include "core/particles.h"
#include "scheme/physics_params.h"

#define step_fields_geometry                DIM_NAME(step_fields_geometry)
#define step_fields_shifting_and_correction DIM_NAME(step_fields_shifting_and_correction)
#define step_fields_frozen_terms            DIM_NAME(step_fields_frozen_terms)

/* The geometry of the step (needs the ghosts refreshed): L, lambda, the normal, sum W,
 * sum W V, the renormalized density and velocity gradients, nu_t, nu_delta (fluid); the free
 * surface and S_F follow from these (diag/freesurface.h). */
void step_fields_geometry(const physics_params *pp, const tank *t, particles *p,
                          const neighbour_list *nl);

/* The density diffusion D^rho and, with `mass` (variable masses), D^m of Eq. (5), frozen over
 * the step dt, which bounds each particle's D^rho so that the step is stable (diffusion.h).
 * A pass takes NULL where there is none (C_delta = 0). */
typedef struct {
    bool mass;
    double dt;
} step_diffusion;

/* The rows whose diffusion a pass sums: none, those that reach no wall image (or halo
 * particle: neighbour_row_has_ghosts), those that reach one, or all. */
typedef enum {
    DIFFUSION_ROWS_NONE,
    DIFFUSION_ROWS_OFF_WALLS,
    DIFFUSION_ROWS_AT_WALLS,
    DIFFUSION_ROWS_ALL
} diffusion_rows;

static inline bool diffusion_rows_include(diffusion_rows rows, bool at_wall)
{
    return rows == DIFFUSION_ROWS_ALL ||
           rows == (at_wall ? DIFFUSION_ROWS_AT_WALLS : DIFFUSION_ROWS_OFF_WALLS);
}

/* The shifting velocity du of Eq. (7) (`shift`) and the volume correction's dv (`correct`,
 * volume_correction.h, after its mismatch e), frozen over the RK stages (sec. 2.4), for the
 * fluid; computed after EdBC has corrected the densities, since the volumes weigh them. Both
 * sum over the same neighbours, so one pass computes each row's geometry once for the two,
 * and for the `diffusion` of the `rows` (step_fields_frozen_terms does the others): the rows that
 * reach a wall image only once the images hold their diffusion fields
 * (tank_mirror_diffusion_fields). */
void step_fields_shifting_and_correction(const physics_params *pp, particles *p,
                                         const neighbour_list *nl, bool shift, bool correct,
                                         const step_diffusion *diffusion, diffusion_rows rows);

/* The other terms frozen over the RK stages, after the shifting velocity and bounce-back:
 * the ghosts' copies of the per-step fields, then the `diffusion` of the `rows` (0 where
 * `diffusion` is NULL). `frame`: the tank frame at the step's start, whose body force the
 * ghosts' hydrostatic density gradient follows. */
void step_fields_frozen_terms(const physics_params *pp, particles *p, const neighbour_list *nl,
                              const tank_frame *frame, const step_diffusion *diffusion,
                              diffusion_rows rows);

#endif
