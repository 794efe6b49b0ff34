/* derived: the numbers that follow from a case (spacing, smoothing length, particle counts,
 * sound speed, time-step limits, reference energies); printed by `vcsph check`. */
#ifndef VCSPH_DERIVED_H
#define VCSPH_DERIVED_H

#include "boundary/motion.h"
#include "core/config.h"

typedef struct {
    double dr, h;      /* spacing H/N and smoothing length */
    long n_axis[3];    /* lattice particles along x, y, z (z: 1 in 2D) */
    double spacing[3]; /* lattice spacing per axis: dr along y; along x (z) the liquid length
                          (tank width) over a whole number of particles, within dr/(2 n) of dr */
    long n_fluid;
    double v0;                          /* initial liquid volume L H W = N x the cell volume
                                           (per unit width in 2D) */
    double cell_volume;                 /* v0 / N: a particle's initial volume, V_i0 (sec. 2.1) */
    double g_max;                       /* largest effective gravity of the motion */
    double c0;                          /* sound speed, given or 10 sqrt(2 g_max H) (Eq. 6) */
    double k_c;                         /* CFL number (Table 1 unless given) */
    double dt_v, dt_c, dt_a, dt_st, dt; /* Eq. (8); dt_a estimated with g_max */
    double mass_liquid;                 /* M_L = rho0 L H W (W = 1 in 2D) */
    double omega;                       /* 2 pi / T, 0 without periodic motion */
    double t_sloshing1;                 /* first linear sloshing period along x (theory §11) */
    double response_period;             /* period of the flow's response: T in sway, 2T in
                                           heave (parametric, half the forcing frequency),
                                           else t_sloshing1; the adaptive eta control averages
                                           eps_V1 over it */
    double d_energy, d_power;           /* dE = M_L (A w)^2 / 2, dW = dE / T (Table 3) */
} derived;

void derived_compute(const config *cfg, const motion *mo, derived *out);
/* Whether the derived numbers make a runnable case (a sound speed > 0: `auto` needs gravity
 * or motion; a response period > 0 for the adaptive eta control). Returns 0, or 2 with a
 * message naming the key. */
int derived_check(const config *cfg, const derived *dv, char *err, size_t err_len);
/* Prints the derived numbers, one per line, for `vcsph check`. */
void derived_print(const config *cfg, const derived *dv, FILE *out);

#endif
