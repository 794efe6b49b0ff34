/* packing: how closely the free-surface particles sit, from the positions: the one part of the
 * liquid's geometry that Eq. (12) cannot see (it counts S_F at V_i0), and the cause of the
 * graphical method's reading below it where the surface clumps (docs/graphical-method.md,
 * "Why, and what was tried"). Particle code: compiled for DIM = 2 and 3. */
#ifndef VCSPH_PACKING_H
#define VCSPH_PACKING_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/particles.h"
#include "core/run_team.h"

#include "diag/packing_figures.h"

#define surface_packing_compute   DIM_NAME(surface_packing_compute)
#define surface_nearest_quantiles DIM_NAME(surface_nearest_quantiles)

/* From this step's neighbour list and free surface (p->surface), on one process. `scratch`
 * holds n_fluid doubles; the means are summed in index order, the same for any thread count. */
void surface_packing_compute(const kernel *k, const particles *p, const neighbour_list *nl,
                             double dr, double *scratch, surface_packing *out);

/* The median and the 5th percentile (quantile.h) of the free-surface particles' nearest fluid
 * neighbour within 2h, in units of dr (1 on the top row of the initial lattice), over the
 * particles of every process of `team` (NULL: this one alone): on the process that writes
 * (run_team.h), NaN on the others and where no free-surface particle has a neighbour.
 * `scratch` holds n_fluid doubles. Collective. */
void surface_nearest_quantiles(const kernel *k, const particles *p, const neighbour_list *nl,
                               double dr, const run_team *team, double *scratch, double *median,
                               double *p05);

#endif
