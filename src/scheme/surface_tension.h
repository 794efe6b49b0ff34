/* surface_tension: the single-phase CSF force F^st = -sigma kappa n delta_Sigma of the paper
 * (sec. 2.2), computed once per step from the positions and frozen over the RK stages like
 * the other per-step terms (sec. 2.4). docs/surface-tension.md gives the method, its
 * accuracy and where it departs from the C-CSF of Vergnaud et al. 2022. */
#ifndef VCSPH_SURFACE_TENSION_H
#define VCSPH_SURFACE_TENSION_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/particles.h"

/* The flat-surface calibration of the interface function, from a lattice half-space. */
typedef struct {
    double sigma;         /* N/m; 0: off */
    double dr;            /* particle spacing */
    double flat_integral; /* sum over the layers of 2 |sum grad W V| dr on a flat lattice */
} surface_tension_params;

#define surface_tension_setup   DIM_NAME(surface_tension_setup)
#define surface_tension_compute DIM_NAME(surface_tension_compute)
#define surface_tension_power   DIM_NAME(surface_tension_power)
#define surface_tension_energy  DIM_NAME(surface_tension_energy)

surface_tension_params surface_tension_setup(const kernel *k, double dr, double sigma);

/* Fills p->interface (delta_Sigma, 1/m, normalised so that it integrates to 1 across a flat
 * lattice surface), p->curvature and p->st_force (the force on each fluid particle, N) from
 * this step's normals and S_F (fields_geometry), and mirrors normal and interface into the
 * ghosts. The force on every body of liquid that touches no wall sums to zero exactly: each
 * such body gets its round-off residual removed, so that its momentum is conserved. Returns
 * 0, or -1 when out of memory. */
int surface_tension_compute(const surface_tension_params *st, const kernel *k, particles *p,
                            const neighbour_list *nl);

/* The surface energy sigma sum delta V (J; per unit width in 2D): sigma times the discrete
 * interface area, whose measure delta integrates to 1 across a flat surface. Needs this
 * step's surface_tension_compute. */
double surface_tension_energy(const surface_tension_params *st, const particles *p,
                              double *scratch);

/* The power of the frozen force on the fluid, sum F^st . u (W), in a fixed order. */
double surface_tension_power(const particles *p, double *scratch);

#endif
