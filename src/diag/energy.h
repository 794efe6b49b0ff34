/* energy: global diagnostics of the liquid: energy budget terms (theory §10), mass, SPH
 * volume, centre of mass, angular momentum about it, extent, extreme speed and density. */
#ifndef VCSPH_ENERGY_H
#define VCSPH_ENERGY_H

#include "core/particles.h"
#include "core/reduce.h"

typedef struct {
    double ekin, epot, eint; /* J (per unit width in 2D) */
    double mass, vol_sph;    /* sum m, sum m / rho */
    double com[3];
    double angmom[3]; /* sum m (x - com) x u (kg m^2/s; per unit width in 2D, z alone) */
    double xmin, xmax, ymax;
    double umax, rho_min, rho_max;
} diagnostics;

/* What the energy terms need beyond the particles. */
typedef struct {
    double gravity;  /* |g| along -y, for the potential energy */
    double rho0, c0; /* the EOS, for the internal energy */
} energy_params;

#define diagnostics_compute DIM_NAME(diagnostics_compute)
#define fluid_max_speed     DIM_NAME(fluid_max_speed)

/* Every sum in a fixed order (reduce module), over the processes through r (NULL: one
 * process); scratch holds n_fluid doubles. */
void diagnostics_compute(const particles *p, const energy_params *ep, double *scratch,
                         const reducer *r, diagnostics *out);
/* Largest |u| of this process's fluid (through scratch, n_fluid doubles). */
double fluid_max_speed(const particles *p, double *scratch);

#endif
