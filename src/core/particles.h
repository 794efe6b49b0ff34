/* particles: the SoA particle store. Fluid particles occupy [0, n_fluid), wall ghosts the
 * tail [n_fluid, n_total) (where MPI halo particles will also go, docs/architecture.md). */
#ifndef VCSPH_PARTICLES_H
#define VCSPH_PARTICLES_H

#include "core/dim.h"
#include <stddef.h>
#include <stdint.h>

typedef struct {
    size_t n_fluid, n_total, capacity;

    /* state of every particle (ghosts: mirrored from their source each RK stage) */
    int64_t *id;               /* global id of the fluid particle (a ghost: its source's) */
    double *x[DIM];            /* position, tank frame */
    double *u[DIM];            /* velocity, tank frame; ghosts: free-slip image */
    double *u_wall[DIM];       /* velocity seen by the viscous term and the velocity gradient:
                                  the fluid's own, or the ghost's no-slip / free-slip image */
    double *rho, *p, *m, *vol; /* density, pressure (EOS), mass, SPH volume m/rho */

    /* per-step fields, frozen over the RK stages (sec. 2.4); ghosts copy their source's */
    double *grad_rho[DIM];   /* renormalized density gradient <grad rho>^L */
    double *nu_t;            /* Smagorinsky eddy viscosity with van Driest damping, m^2/s */
    double *nu_delta;        /* diffusion coefficient nu^delta of Eq. (5), m^2/s */
    double *lambda;          /* smallest eigenvalue of L, Eq. (10) (fluid) */
    double *normal[DIM];     /* unit normal -L^-1 sum grad W V, out of the fluid (theory §4);
                                in S_F below the free surface, the nearest free-surface
                                neighbour's (equidistant ones averaged) */
    double *normal_raw;      /* |L^-1 sum grad W V| before normalising */
    double *kernel_sum;      /* sum_j W_ij, self included: 1 / geometric volume, Eq. (11) */
    double *gamma;           /* Gamma_i = sum_j W_ij V_j, self included, Eq. (A.2) */
    double *volume_mismatch; /* e_i = V_i sum_j W_ij / kappa - 1: SPH over geometric volume,
                                with the geometric correction only (volume_correction.h) */
    uint8_t *surface;        /* 0 interior, 1 in S_F, 2 free surface (Marrone et al. 2010) */
    uint8_t *is_free;        /* the free-surface test alone, read while `surface` is written */
    double *diff_m;          /* mass diffusion D^m of Eq. (5) (fluid) */
    double *shift[DIM];      /* shifting velocity delta-u, Eq. (7) (zero until shifting exists) */
    double *correction[DIM]; /* the geometric volume correction's velocity (zero without it;
                                ghosts: mirrored), scheme/volume_correction.h */
    double *diff_rho;        /* density diffusion D^rho of Eq. (5) (fluid) */
    /* surface tension, with fluid.surface_tension > 0 only (scheme/surface_tension.h) */
    double *interface;     /* interface function delta_Sigma, 1/m (ghosts: their source's) */
    double *curvature;     /* kappa, 1/m (fluid) */
    double *st_force[DIM]; /* F^st V_i, the surface-tension force on the particle at the
                              current RK stage, N */

    /* ghosts only, indexed g - n_fluid */
    int32_t *ghost_source; /* fluid index it mirrors */
    uint8_t *ghost_walls;  /* bit 2d: mirrored across the low wall of axis d; bit 2d+1: high */
} particles;

#define particles_init           DIM_NAME(particles_init)
#define particles_free           DIM_NAME(particles_free)
#define particles_reserve        DIM_NAME(particles_reserve)
#define particles_permute_fluid  DIM_NAME(particles_permute_fluid)
#define particles_bytes_per_slot DIM_NAME(particles_bytes_per_slot)

/* Allocates room for `capacity` particles (fluid + ghosts); all counts 0. Returns 0 or -1. */
int particles_init(particles *p, size_t capacity);
void particles_free(particles *p);
/* Grows the store to hold at least `capacity` particles, keeping the contents. */
int particles_reserve(particles *p, size_t capacity);
/* The bytes one particle slot takes in the store (every array of it). */
size_t particles_bytes_per_slot(void);
/* Reorders the persistent fluid state (id, x, u, rho, m) so that new slot k holds old
 * particle order[k]; scratch needs n_fluid doubles. */
void particles_permute_fluid(particles *p, const size_t *order, double *scratch);

#endif
