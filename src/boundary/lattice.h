/* lattice: the initial particles on a regular lattice (sec. 2.1). */
#ifndef VCSPH_LATTICE_H
#define VCSPH_LATTICE_H

#include "core/config.h"
#include "core/derived.h"
#include "core/particles.h"

#define lattice_fill DIM_NAME(lattice_fill)

/* Fills the fluid part of p with the lattice points first .. end - 1 of the lattice order
 * (all of them: 0, dv->n_fluid; a process of an MPI run: its share): positions (i + 1/2)
 * spacing in the liquid box (or in the ellipse inscribed in it, liquid.shape),
 * p = rho0 |g| (H - y), rho from the EOS, m = rho dr^n, ids = the index in lattice order.
 * Returns 0, or -1 when out of memory or the count disagrees with derived_compute's. */
int lattice_fill(particles *p, const config *cfg, const derived *dv, size_t first, size_t end);

#endif
