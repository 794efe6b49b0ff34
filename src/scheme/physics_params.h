/* physics_params: the constants the pair loops need, gathered once per run. */
#ifndef VCSPH_PHYSICS_PARAMS_H
#define VCSPH_PHYSICS_PARAMS_H

#include "core/kernel.h"
#include <stdbool.h>

typedef struct {
    kernel k;
    double dr;
    double rho0, c0;
    double nu;                 /* kinematic viscosity */
    double filter_length;      /* l = 2h, the LES filter length (sec. 2.2) */
    double c_delta;            /* C_delta of Eq. (5); 0: no density diffusion (Standard SPH) */
    double delta_cap;          /* upper bound of delta_ij: delta l c0 = 0.1 l c0 (sec. 2.2) */
    double nu_t_cap;           /* upper bound of mu^T_ij / rho0: 0.1 l c0 / K (sec. 2.2) */
    double lambda_renormalize; /* use L^-1 in gradients only when lambda exceeds this */
    double normal_reference;   /* |L^-1 sum grad W V| on a flat lattice surface (theory §4) */
    bool shifting;             /* xi = 1 of Table 1: particle shifting, Eq. (7), ALE terms */
    bool volume_correction;    /* model.volume_correction = geometric (volume_correction.h) */
    double lattice_kernel_sum; /* kappa = dr^n sum W on a lattice, Eq. (11) at rest */
    double surface_kernel_sum; /* dr^n sum W of a flat lattice surface's top row (eps_fs) */
    double shift_u_max;        /* U_max of Eq. (7): the reference speed c0 / 10 of Eq. (6) */
    double w_dr;               /* W(dr) of Eq. (7) */
    double unpack_speed;       /* model.surface_unpacking: SURFACE_UNPACK_RATE U_max, else 0 */
    double surface_sum_scale;  /* V_i0 / surface_kernel_sum: S_i / S_flat per unit sum W_ij */
    double delta_c0_h;         /* delta c0 h of D^m, Eq. (5) */
    bool les;                  /* Smagorinsky eddy viscosity */
    bool van_driest;           /* damp it near no-slip walls */
    bool surface_tension;      /* sigma > 0: the force p->st_force joins the momentum */
} physics_params;

#endif
