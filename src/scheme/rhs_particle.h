/* rhs_particle: the right-hand side of Eq. (3) for one particle, from its neighbour sums, shared
 * by the scalar form (scheme/rhs.c) and the lane forms (scheme/rhs_lanes.h), which must give the
 * same bits. */
#ifndef VCSPH_RHS_PARTICLE_H
#define VCSPH_RHS_PARTICLE_H

#include "physics/ale.h"
#include "physics/continuity.h"
#include "physics/volume_correction.h"
#include "scheme/momentum.h"
#include "scheme/rhs.h"

/* The neighbour sums of particle i: d rho/dt's pair terms, the mass flux and the force per unit
 * volume. */
typedef struct {
    double drho, mass_flux;
    vec force; /* per unit volume */
} rhs_sums;

__attribute__((always_inline)) static inline rhs_sums
rhs_particle_sums(const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i,
                  const bool les, const bool ale, const bool variable_mass)
{
    const kernel *k = &pp->k;
    momentum_particle mi = momentum_particle_of(pp, p, i);
    vec xi = vec_load(p->x, i), ui = mi.u, dui = mi.shift;
    double rhoi = p->rho[i], vi = p->vol[i];
    rhs_sums s = {0.0, 0.0, vec_zero()};
    pair pr;
    FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) {
        size_t j = pr.j;
        double vj = p->vol[j];
        vec u_ji = vec_sub(vec_load(p->u, j), ui);
        vec transport_ji = u_ji; /* (u + du)_ji: the particles move with u + du */
        if (ale) {
            vec duj = vec_load(p->shift, j);
            transport_ji = vec_add(u_ji, vec_sub(duj, dui));
            double flux = ale_flux_pair(rhoi, dui, p->rho[j], duj, pr.r_ji, pr.f);
            s.drho += flux * vj;
            if (variable_mass && !particle_is_wall_image(p, j)) s.mass_flux += flux * vi * vj;
        }
        s.drho += continuity_pair(rhoi, transport_ji, pr.r_ji, pr.f, vj);
        s.force = momentum_pair_add(s.force, pp, p, &mi, &pr, les, ale);
    }
    return s;
}

/* Particle i's rates from its neighbour sums. */
static inline void rhs_particle_finish(const physics_params *pp, const particles *p, size_t i,
                                       const tank_frame *frame, const bool variable_mass,
                                       double eta, rhs_sums s, const rates *out)
{
    vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
    double drho = s.drho;
    if (pp->volume_correction) /* the particle moves through the density field */
        drho += volume_correction_resampling(vec_load(p->correction, i), vec_load(p->grad_rho, i));
    out->drho[i] = drho + p->diff_rho[i];
    vec acc = vec_axpy(frame_body_force(frame, xi, ui), 1.0 / p->rho[i], s.force);
    /* the surface-tension force on the particle at this stage: m a sums it exactly */
    if (pp->surface_tension) acc = vec_axpy(acc, 1.0 / p->m[i], vec_load(p->st_force, i));
    for (int d = 0; d < DIM; d++) out->du[d][i] = acc.c[d];
    /* Eq. (3): dm/dt = eta [div(rho du) V_i + D^m] (fluid pairs only: the total is exact);
       with constant masses there is no dm to write (solver.h) */
    if (variable_mass) out->dm[i] = eta * (s.mass_flux + p->diff_m[i]);
}

/* Runs VARIANT(les, ale, variable_mass) with the three as compile-time constants, so that the
 * loops are specialised once per variant, never tested per pair (docs/architecture.md).
 * The masses vary only with shifting (rhs_masses_vary). */
#define RHS_FOR_VARIANT(pp, eta, VARIANT)                                                          \
    switch (((pp)->les ? 4 : 0) + ((pp)->shifting ? 2 : 0) + rhs_masses_vary(pp, eta)) {           \
    case 0: VARIANT(false, false, false); break;                                                   \
    case 2: VARIANT(false, true, false); break;                                                    \
    case 3: VARIANT(false, true, true); break;                                                     \
    case 4: VARIANT(true, false, false); break;                                                    \
    case 6: VARIANT(true, true, false); break;                                                     \
    default: VARIANT(true, true, true); break;                                                     \
    }

/* The block of particles [i0, end) of a block function whose parameters are named as
 * rhs_block_variant's: that file's rhs_block_variant for the case's variant. */
#define RHS_BLOCK_VARIANT(les, ale, mass)                                                          \
    rhs_block_variant(pp, p, nl, i0, end, frame, les, ale, mass, eta, out)

/* The lane forms, one per width (scheme/rhs_lanes4.c, rhs_lanes8.c): rhs_compute's work in
 * blocks of 4 or 8 particles, for processors with AVX2 or AVX-512 (core/lanes_switch.h). */
#define rhs_compute_lanes4 DIM_NAME(rhs_compute_lanes4)
#define rhs_compute_lanes8 DIM_NAME(rhs_compute_lanes8)
void rhs_compute_lanes4(const physics_params *pp, const particles *p, const neighbour_list *nl,
                        const tank_frame *frame, double eta, const rates *out);
void rhs_compute_lanes8(const physics_params *pp, const particles *p, const neighbour_list *nl,
                        const tank_frame *frame, double eta, const rates *out);

#endif
