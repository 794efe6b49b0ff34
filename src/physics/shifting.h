/* shifting: the particle shifting velocity of Eq. (7) (Sun et al. 2019), pair term and
 * limiter. */
#ifndef VCSPH_SHIFTING_H
#define VCSPH_SHIFTING_H

#include "core/vec.h"

#define SHIFTING_R 0.2 /* R of Eq. (7) */

/* Lambda below which a particle gets no shifting (theory §4). */
#define SHIFTING_LAMBDA_MIN 0.4

/* [1 + R (W_ij / W(dr))^4] grad_i W_ij V_j: summed over j and multiplied by -xi h U_max it
 * is du*_i; the anti-clustering R term pushes harder on near neighbours. */
static inline vec shifting_pair(double w_ij, double w_dr, vec r_ji, double f_ij, double vol_j)
{
    double q = w_ij / w_dr, q2 = q * q;
    return vec_scale(r_ji, (1.0 + SHIFTING_R * q2 * q2) * f_ij * vol_j);
}

/* The part of a concentration gradient s (1/m) beyond the floor |grad rho| / rho:
 * s (1 - floor / |s|), nothing below it. A liquid in a pressure gradient is compressed by
 * |grad p| / (rho c0^2) = |grad rho| / rho per metre. The particle arrangement with which SPH
 * balances that gradient carries a concentration gradient of the same order (in hydrostatics,
 * rows off their lattice by a thousandth of dr near the bottom and the surface band). That is
 * the scheme's equilibrium, not a disorder: moving it away fights the pressure force, and
 * through the relative-speed bound of Eq. (7) the fight feeds a current that grows from
 * round-off in a tank at rest (docs/volume-correction.md, "A liquid at rest"). vcsph's
 * addition to Eq. (7). A disorder of 1 % of dr has a gradient 1e-2 / dr, one to two orders of
 * magnitude above the floor g / c0^2 of a tank at rest. */
/* The floor: |grad rho| / rho (1/m) of a particle, from the step's renormalised density
 * gradient. */
static inline double compression_gradient(vec grad_rho, double rho)
{
    return vec_norm(grad_rho) / rho;
}

static inline vec gradient_beyond_floor(vec s, double floor)
{
    double norm = vec_norm(s);
    return norm > floor ? vec_scale(s, 1.0 - floor / norm) : vec_zero();
}

/* Eq. (7), second line: |du| = min(|du*|, max_j |u_ij| / 2, U_max / 2) along du*. */
static inline vec shifting_limit(vec du, double max_relative_speed, double u_max)
{
    double norm = vec_norm(du), cap = 0.5 * max_relative_speed;
    if (0.5 * u_max < cap) cap = 0.5 * u_max;
    return norm > cap ? vec_scale(du, cap / norm) : du;
}

/* model.surface_unpacking (vcsph's, not the paper's): a free-surface particle whose kernel sum
 * S_i = sum_j W_ij V_i0 exceeds S_flat, that of a flat lattice surface's top row, sits in a
 * layer packed tighter than the liquid: more particles per unit of surface than a lattice row
 * (they hold V_i0 S_flat / S_i each, what eps_fs counts). Eq. (7) cannot thin such a layer: its
 * shift is tangential there and a gradient has no component along an evenly packed line. This
 * shift moves the particle inwards along its unit normal at SURFACE_UNPACK_RATE U_max per unit
 * of excess S_i / S_flat - 1, bounded like du* by Eq. (7)'s limit (a particle moving with its
 * neighbours is not pushed through them), so that the layer hands its surplus to the liquid
 * below, where the geometric volume correction counts it (docs/volume.md, "The surface layer"). */
#define SURFACE_UNPACK_RATE 0.1

static inline vec surface_unpacking_shift(double sum_ratio, double speed, vec unit_normal,
                                          double max_relative_speed, double u_max)
{
    double excess = sum_ratio - 1.0;
    if (excess <= 0.0) return vec_zero();
    return shifting_limit(vec_scale(unit_normal, -speed * excess), max_relative_speed, u_max);
}

/* Near the free surface the normal component is removed, so that shifting does not move the
 * surface (theory §4): (I - n (x) n) du. */
static inline vec shifting_tangential(vec du, vec normal)
{
    return vec_axpy(du, -vec_dot(du, normal), normal);
}

#endif
