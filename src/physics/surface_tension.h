/* surface_tension: the pair math of the single-phase CSF force F^st = -sigma kappa n delta
 * (paper sec. 2.2; theory §4; the method and its choices: docs/surface-tension.md). */
#ifndef VCSPH_PHYSICS_SURFACE_TENSION_H
#define VCSPH_PHYSICS_SURFACE_TENSION_H

#include "core/vec.h"

/* Sums of the tangential divergence of the normal at particle i. */
typedef struct {
    double num; /* sum (n_j - n_i) . t_ji F V_j */
    double den; /* sum |t_ji|^2 F V_j */
} curvature_sums;

/* One neighbour's share: t_ji = (I - n_i n_i) r_ji is the part of r_ji in the tangent plane
 * of i. Only tangential differences of n measure the curvature; the normal direction is
 * sampled by a few layers of unequal normals and would bias it (docs/surface-tension.md). */
static inline void curvature_pair(curvature_sums *s, vec n_i, vec n_j, vec r_ji, double f,
                                  double vol_j)
{
    vec t_ji = vec_axpy(r_ji, -vec_dot(n_i, r_ji), n_i);
    double fv = f * vol_j;
    s->num += vec_dot(vec_sub(n_j, n_i), t_ji) * fv;
    s->den += vec_norm2(t_ji) * fv;
}

/* kappa = div_s n = (d - 1) sum (n_j - n_i) . t_ji F V_j / sum |t_ji|^2 F V_j: for n varying
 * linearly along the surface, (d - 1) / R on a circle (d = 2) or a sphere (d = 3) of radius R
 * whatever the truncation of the kernel support, as long as it is symmetric in the tangent
 * plane. Bounded by (d - 1) / dr: no surface is resolved more sharply than a particle. */
static inline double curvature_value(const curvature_sums *s, int dim, double dr)
{
    if (!(s->den > 0.0)) return 0.0;
    double kappa = (dim - 1) * s->num / s->den;
    double cap = (dim - 1) / dr;
    return kappa > cap ? cap : kappa < -cap ? -cap : kappa;
}

/* The force on particle i, F^st V_i = -sigma kappa delta V n (N; N/m in 2D). */
static inline vec csf_force(double sigma, double kappa, double delta, double vol, vec n)
{
    return vec_scale(n, -sigma * kappa * delta * vol);
}

#endif
