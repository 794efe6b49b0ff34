/* energy: global diagnostics of the liquid: energy budget terms (theory §10), mass, SPH
 * volume, centre of mass, angular momentum about it, extent, extreme speed and density. */
#ifndef VCSPH_ENERGY_H
#define VCSPH_ENERGY_H

#include "scheme/solver.h"

typedef struct {
    double ekin, epot, eint; /* J (per unit width in 2D) */
    double mass, vol_sph;    /* sum m, sum m / rho */
    double com[3];
    double angmom[3]; /* sum m (x - com) x u (kg m^2/s; per unit width in 2D, z alone) */
    double xmin, xmax, ymax;
    double umax, rho_min, rho_max;
} diagnostics;

#define diagnostics_compute DIM_NAME(diagnostics_compute)

/* Every sum in a fixed order (reduce module). */
void diagnostics_compute(solver *s, diagnostics *out);

#endif
