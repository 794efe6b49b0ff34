/* momentum: the force of one neighbour in the momentum equation of Eq. (3), shared by the
 * right-hand side (scheme/rhs.c) and the wall loads (scheme/loads.c), so that the loads are
 * the forces the liquid is actually integrated with. */
#ifndef VCSPH_MOMENTUM_H
#define VCSPH_MOMENTUM_H

#include "core/pair.h"
#include "core/particles.h"
#include "physics/ale.h"
#include "physics/pressure.h"
#include "physics/viscosity.h"
#include "scheme/physics_params.h"

/* What the momentum terms need of particle i. */
typedef struct {
    vec u, shift;       /* velocity (also the viscous term's), shifting velocity du */
    double p, nu_t, mu; /* pressure, eddy viscosity, rho0 nu */
} momentum_particle;

static inline momentum_particle momentum_particle_of(const physics_params *pp, const particles *p,
                                                     size_t i)
{
    momentum_particle m = {vec_load(p->u, i), vec_load(p->shift, i), p->p[i], p->nu_t[i],
                           pp->rho0 * pp->nu};
    return m;
}

/* force + the force per unit volume on particle i from its neighbour pr->j: with shifting
 * (`ale`) the ALE term rho (du . grad) u, then the pressure gradient, then the viscous term
 * with LES's eddy viscosity (`les`); added one by one in this order, as the sums of Eq. (3)
 * always have been. */
__attribute__((always_inline)) static inline vec
momentum_pair_add(vec force, const physics_params *pp, const particles *p,
                  const momentum_particle *mi, const pair *pr, const bool les, const bool ale)
{
    size_t j = pr->j;
    double vj = p->vol[j];
    if (ale) {
        vec u_ji = vec_sub(vec_load(p->u, j), mi->u);
        force = vec_add(
            force, ale_momentum_pair(p->rho[j], u_ji, vec_load(p->shift, j), pr->r_ji, pr->f, vj));
    }
    force = vec_add(force, pressure_pair(mi->p, p->p[j], pr->r_ji, pr->f, vj));
    double mu_eff = mi->mu;
    if (les) mu_eff += pp->rho0 * harmonic_mean_capped(mi->nu_t, p->nu_t[j], pp->nu_t_cap);
    vec uw_ji = vec_sub(particle_viscous_velocity(p, j), mi->u);
    return vec_add(force, viscosity_pair(mu_eff, uw_ji, pr->r_ji, pr->r2, pr->f, vj));
}

#endif
