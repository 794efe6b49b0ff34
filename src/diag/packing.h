/* packing: how closely the free-surface particles sit, from the positions: the one part of the
 * liquid's geometry that Eq. (12) cannot see (it counts S_F at V_i0), and the cause of the
 * graphical method's reading below it where the surface clumps (docs/graphical-method.md,
 * "Controlled runs"). Particle code: compiled for DIM = 2 and 3. */
#ifndef VCSPH_PACKING_H
#define VCSPH_PACKING_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/particles.h"

#include "diag/packing_figures.h"

#define surface_packing_compute DIM_NAME(surface_packing_compute)

/* From this step's neighbour list and free surface (p->surface), on one process. `scratch`
 * holds n_fluid doubles; the means are summed in index order, the same for any thread count. */
void surface_packing_compute(const kernel *k, const particles *p, const neighbour_list *nl,
                             double dr, double *scratch, surface_packing *out);

#endif
