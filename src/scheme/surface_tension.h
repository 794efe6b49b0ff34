/* surface_tension: the single-phase CSF force F^st = -sigma kappa n delta_Sigma of the paper
 * (sec. 2.2), computed at every RK stage from the stage's positions (the region S_F is the
 * step's). docs/surface-tension.md gives the method, its accuracy, why it is not frozen over
 * the step like the diffusive terms, and where it departs from the C-CSF of Vergnaud et al.
 * 2022. */
#ifndef VCSPH_SURFACE_TENSION_H
#define VCSPH_SURFACE_TENSION_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/particles.h"
#include "core/reduce.h"
#include "core/vec.h"
#include "scheme/bodies.h"

/* The flat-surface calibration of the interface function, from a lattice half-space. */
typedef struct {
    double sigma;         /* N/m; 0: off */
    double dr;            /* particle spacing */
    double flat_integral; /* sum over the layers of 2 |sum grad W V| dr on a flat lattice */
    double lambda_min;    /* the normal uses L^-1 where lambda exceeds this (theory §2) */
} surface_tension_params;

/* What one body of liquid sums for the balance of its force and moment, in two folds over
 * its particles (bodies_sum): first the net force, sum delta V and the delta V-weighted
 * centre of its surface, then, with those, the net moment about that centre and the
 * inertia sum delta V (|r|^2 I - r r) (2D: their z components alone). */
enum {
    BALANCE_FORCE = 0,
    BALANCE_WEIGHT = DIM,
    BALANCE_CENTRE = DIM + 1,
    BALANCE_FIRST = 2 * DIM + 1, /* doubles a body of the first fold */
    BALANCE_MOMENT = 0,
    BALANCE_INERTIA = 3,
    BALANCE_SECOND = 12 /* of the second */
};

/* Work arrays of the force, kept between calls so that a stage never allocates. They hold the
 * fluid and an MPI run's halo: a wall's image has no entry of its own and reads its source's
 * (mirrored, for a vector), as the particle store's FIELD_SOURCES_ONLY fields would; the
 * images of a narrow 3D tank are 40-60 % of its fluid. */
typedef struct {
    size_t capacity;        /* particles: the fluid and the halo */
    double *smooth[DIM];    /* the normal's Shepard average over the free surface */
    double *band_sum;       /* sum W V over S_F, self included: what delta V spreads over */
    size_t body_capacity;   /* bodies */
    double *first, *second; /* the balance's sums, BALANCE_FIRST and BALANCE_SECOND a body */
} surface_tension_work;

/* Room the caller lends to one surface_tension_compute, over the fluid and the halo, whose
 * contents before the call do not matter and after it are of no use: the solver lends the
 * stage's rates (solver_surface_tension_room), which hold nothing while the force is computed,
 * DIM + 1 doubles a particle less to hold. */
typedef struct {
    double *normal[DIM]; /* the normal of S_F at the stage's positions */
    double *kappa;       /* the curvature of the free-surface particles */
} surface_tension_room;

#define surface_tension_setup   DIM_NAME(surface_tension_setup)
#define surface_tension_compute DIM_NAME(surface_tension_compute)
#define surface_tension_reserve DIM_NAME(surface_tension_reserve)
#define surface_tension_free    DIM_NAME(surface_tension_free)
#define surface_tension_power   DIM_NAME(surface_tension_power)
#define surface_tension_energy  DIM_NAME(surface_tension_energy)

surface_tension_params surface_tension_setup(const kernel *k, double dr, double sigma,
                                             double lambda_min);

/* Makes room in w for n_sources particles (the fluid and the halo: particles_images_begin) and
 * n_bodies bodies (the lent room is the caller's). Returns 0, or -1 when out of memory. */
int surface_tension_reserve(surface_tension_work *w, size_t n_sources, size_t n_bodies);
void surface_tension_free(surface_tension_work *w);

/* Fills p->interface (delta_Sigma, 1/m, normalised so that it integrates to 1 across a flat
 * lattice surface), p->curvature and p->st_force (the force on each fluid particle, N) from
 * the current positions, with the step's S_F (step_fields_geometry) and bodies (bodies_find); a
 * wall's image reads its source's interface function (particle_source_scalar); w holds room for the
 * fluid and the halo (surface_tension_reserve). On every body of liquid that touches no wall, the
 * force and its moment sum to zero exactly, as the continuum's do: each such body gets its discrete
 * residuals removed, so that its momentum and angular momentum are conserved. Across processes
 * through d (the halo's work arrays, the bodies' sums; NULL: one process). */
void surface_tension_compute(const surface_tension_params *st, const kernel *k, particles *p,
                             const neighbour_list *nl, const bodies *b, const bodies_domain *d,
                             surface_tension_work *w, surface_tension_room room);

/* The surface energy sigma sum delta V (J; per unit width in 2D): sigma times the discrete
 * interface area, whose measure delta integrates to 1 across a flat surface. Needs this
 * step's surface_tension_compute. */
double surface_tension_energy(const surface_tension_params *st, const particles *p, double *scratch,
                              const reducer *r);

/* The power of the force on the fluid, sum F^st . u (W), in a fixed order (r: over the
 * processes, as the energy's). */
double surface_tension_power(const particles *p, double *scratch, const reducer *r);

#endif
