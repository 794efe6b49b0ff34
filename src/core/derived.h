/* derived: the numbers that follow from a case (spacing, smoothing length, particle counts,
 * sound speed, time-step limits, reference energies); printed by `vcsph check`. */
#ifndef VCSPH_DERIVED_H
#define VCSPH_DERIVED_H

#include "core/config.h"

#include <stdbool.h>
#include <stdio.h>

typedef struct {
    double dr, h;        /* spacing H/N and smoothing length */
    long n_axis[3];      /* lattice particles along x, y, z (z: 1 in 2D) */
    double spacing[3];   /* lattice spacing per axis: dr along y; along x (z) the liquid length
                            (tank width) over a whole number of particles, within dr/(2 n) of dr */
    long n_fluid;        /* the lattice points kept (derived_lattice_point); 0, uncounted,
                            when derived_check refuses the lattice as too large */
    double v0;           /* initial liquid volume (per unit width in 2D): the box
                            L H W; for liquid.shape = ellipse, N x the cell
                            volume, the volume the particles stand for */
    double cell_volume;  /* a particle's initial volume, V_i0 (sec. 2.1): v0 / N
                            for the box, the product of the spacings for the
                            ellipse */
    double g_max;        /* largest effective gravity of the motion */
    double c0;           /* sound speed, given or 10 sqrt(2 g_max H) (Eq. 6) */
    double u_tank_max;   /* largest tank speed of the motion (motion_max_speed) */
    double c0_eq6;       /* Eq. (6)'s estimate, 10 max(sqrt(g_max H), U_max) with
                            U_max = u_tank_max: the sanity check's lower bound */
    double excursion[3]; /* half the range of the tank's driven displacement per axis */
    double k_c;          /* CFL number (Table 1 unless given) */
    double dt_v, dt_c, dt_a, dt_st, dt; /* Eq. (8); dt_a estimated with g_max */
    double mass_liquid;                 /* M_L = rho0 L H W (W = 1 in 2D); rho0 v0 for the
                                           ellipse */
    double omega;                       /* 2 pi / T, 0 without periodic motion */
    double t_sloshing1;                 /* first linear sloshing period along x (theory §11) */
    double response_period;             /* period of the flow's response: T in sway, 2T in
                                           heave (parametric, half the forcing frequency),
                                           else t_sloshing1; the adaptive eta control averages
                                           eps_V1 over it */
    double d_energy, d_power;           /* dE = M_L (A w)^2 / 2 (a rotation adds (g Theta / w)^2),
                                           dW = dE / T (Table 3) */
    double dissipation_norm;            /* the energy per period that normalises dissipation.csv
                                           (theory §10): dE, so that power_norm = P / dW; with
                                           motion.decay > 0, dE_P = M_L g 2A (UPM, Fig. 27) */
} derived;

/* What the numbers of a case take from the scheme and the tank's motion, which core does not
 * know: scheme/case_numbers.c finds them (case_numbers). */
typedef struct {
    double k_c;          /* CFL number: numerics.cfl, or Table 1's for the scheme */
    double g_max;        /* largest effective gravity of the motion up to t_end */
    double u_tank_max;   /* largest tank speed up to t_end */
    double excursion[3]; /* half the range of the tank's driven displacement per axis */
} derived_inputs;

void derived_compute(const config *cfg, const derived_inputs *in, derived *out);
/* The initial lattice, one predicate for derived_compute (which counts n_fluid with it) and
 * lattice_fill (which places the particles with it), so that the two always agree. Point
 * (c0, c1, c2) of the liquid box lattice, 0 <= ck < n_axis[k] (c2 = 0 in 2D), sits at
 * x = (x0, y0, 0) + (c + 1/2) spacing (x[2] = 0 in 2D); returns whether it is liquid at t = 0:
 * always for liquid.shape = box, inside the inscribed ellipse (ellipsoid) for ellipse. */
bool derived_lattice_point(const config *cfg, const derived *dv, long c0, long c1, long c2,
                           double x[3]);
/* Thresholds of the sanity checks before a run (docs/checks.md). */
#define DERIVED_MIN_ACROSS 2    /* particles across the liquid per axis: fewer is an error */
#define DERIVED_FEW_ACROSS 8    /* ... fewer is a warning */
#define DERIVED_MAX_STEPS  1e10 /* estimated steps t_end / dt: more is an error */
/* Whether the derived numbers make a runnable case (a lattice of at most INT32_MAX points, which
 * the solver's int32 particle indices can number; a sound speed > 0: `auto` needs gravity
 * or motion; a response period > 0 for the adaptive eta control; at least DERIVED_MIN_ACROSS
 * particles across each dimension of the liquid; at most DERIVED_MAX_STEPS steps of the dt
 * estimate to t_end; a hydrostatic density at the bottom, rho0 (1 + g_max H / c0^2), within
 * numerics.density_bound). The one check of `vcsph check` and of every run (solver_init).
 * Returns 0, or 2 with the key to change ("section.name") in *key and the reason in why. */
int derived_problem(const config *cfg, const derived *dv, const char **key, char *why,
                    size_t why_len);
/* The same as one message, "section.name: why". */
int derived_check(const config *cfg, const derived *dv, char *err, size_t err_len);
/* The warnings of a runnable case, each a message without prefix passed to emit(msg, ctx):
 * c0 below Eq. (6)'s estimate dv->c0_eq6, fewer than DERIVED_FEW_ACROSS particles across a
 * dimension of the liquid, a tank excursion larger than the tank along that axis. `vcsph
 * check` and the start of `vcsph run` print them as "vcsph: warning: ...". Returns their
 * number. */
int derived_warnings(const config *cfg, const derived *dv, void (*emit)(const char *msg, void *ctx),
                     void *ctx);
/* Prints the derived numbers, one per line, for `vcsph check`. */
void derived_print(const config *cfg, const derived *dv, FILE *out);

#endif
