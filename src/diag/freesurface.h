/* freesurface: free-surface particles (Marrone et al. 2010, theory §4) and the region S_F
 * near them (Eq. 9, Fig. 1), from the per-step geometry (lambda, normal). */
#ifndef VCSPH_FREESURFACE_H
#define VCSPH_FREESURFACE_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/particles.h"
#include "core/vec.h"

#define FREESURFACE_LAMBDA_FREE     0.2  /* lambda <= this: free surface (theory §4) */
#define FREESURFACE_LAMBDA_INTERIOR 0.75 /* lambda > this: interior */
/* Scan radius of the umbrella test in units of dr: Marrone et al. used the kernel's h at
 * h/dr = 1.33. vcsph keeps that size in dr rather than the kernel h (2 dr here): a smaller
 * umbrella tolerates a rougher surface (a surface particle 0.27 dr below its neighbours is
 * already "covered" with a 2 dr umbrella, 0.45 dr with 1.33 dr). */
#define FREESURFACE_SCAN_OVER_DR 1.33

/* The matrix that renormalises a particle's gradients: L^-1 where L is well conditioned
 * (its smallest eigenvalue lambda above lambda_min: mat_min_eigenvalue(l) > lambda_min, or
 * mat_eigenvalues_above(l, lambda_min) where lambda itself is not wanted), else the
 * identity, the plain gradient of drops and jets (theory §2). */
static inline mat renormalization(const mat *l, bool well_conditioned)
{
    mat l_inv = mat_identity();
    if (well_conditioned) mat_inverse(l, &l_inv);
    return l_inv;
}

/* The normal out of the fluid before it is normalised, -L^-1 sum grad W V (theory §4), from
 * grad_one = sum r_ji F V_j. */
static inline vec outward_direction(const mat *l_inv, vec grad_one)
{
    return vec_scale(mat_mul_vec(l_inv, grad_one), -1.0);
}

/* v / |v| (v itself when zero); *length gets |v|. */
static inline vec unit_vector(vec v, double *length)
{
    *length = vec_norm(v);
    return *length > 0.0 ? vec_scale(v, 1.0 / *length) : v;
}

/* The unit normal out of the fluid, -L^-1 sum grad W V normalised; *length gets
 * |L^-1 sum grad W V|. */
static inline vec outward_normal(const mat *l_inv, vec grad_one, double *length)
{
    return unit_vector(outward_direction(l_inv, grad_one), length);
}

#define freesurface_flat_sums        DIM_NAME(freesurface_flat_sums)
#define freesurface_test             DIM_NAME(freesurface_test)
#define freesurface_region           DIM_NAME(freesurface_region)
#define freesurface_reference_normal DIM_NAME(freesurface_reference_normal)

/* The sums L = sum r_ji (x) r_ji F V_j and s = sum grad W V_j of a particle `depth` layers
 * below the flat top of a lattice half-space (spacing dr, cell volume dr^d). */
void freesurface_flat_sums(const kernel *k, double dr, int depth, mat *l, vec *s);

/* |L^-1 sum grad W V| of a particle on the flat surface of a lattice half-space: the typical
 * surface value of the unnormalised normal. */
double freesurface_reference_normal(const kernel *k, double dr);

/* The free surface in two passes, because the second reads the first's result at the
 * neighbours (an MPI run refreshes its halo between them). freesurface_test fills p->is_free
 * of the fluid from lambda and the normal of this step (Marrone et al. 2010), which the
 * geometry pass leaves unnormalised, -L^-1 sum grad W V, and the test normalises (its length
 * is part of the test, and kept nowhere else);
 * freesurface_region then fills p->surface (S_F: the free surface and the fluid within 2h of
 * it) and gives S_F's other particles the normal of their nearest free-surface neighbour;
 * `g`, the cells the rows were built from, tells it which rows can hold no free-surface
 * particle (it marks the cells that hold one, cells_mark). */
void freesurface_test(const kernel *k, double dr, double normal_reference, particles *p,
                      const neighbour_list *nl);
void freesurface_region(const kernel *k, particles *p, const neighbour_list *nl, cell_grid *g);

#endif
