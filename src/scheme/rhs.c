/* rhs: continuity, pressure and viscous forces, gravity, ALE terms and masses (Eqs. 3, 4). */
#include "scheme/rhs.h"
#include "physics/ale.h"
#include "physics/continuity.h"
#include "physics/volume_correction.h"
#include "scheme/momentum.h"

/* One particle's sums. `les`, `ale` and `variable_mass` are compile-time constants at each
 * call below, so the loop is specialised once per loop, never tested per pair
 * (docs/architecture.md). With ale (shifting on, Eq. 3): the particles move with u + du, the
 * continuity equation gains -rho_i du_ji . grad W V_j and the flux div(rho du), the momentum
 * equation rho (du . grad) u, and with variable masses dm/dt = eta [div(rho du) V_i + D^m]. */
static inline void rhs_particle(const physics_params *pp, const particles *p,
                                const neighbour_list *nl, size_t i, const tank_frame *frame,
                                const bool les, const bool ale, const bool variable_mass,
                                double eta, const rates *out)
{
    const kernel *k = &pp->k;
    momentum_particle mi = momentum_particle_of(pp, p, i);
    vec xi = vec_load(p->x, i), ui = mi.u, dui = mi.shift;
    double rhoi = p->rho[i], vi = p->vol[i];
    double drho = 0.0, mass_flux = 0.0;
    vec force = vec_zero(); /* per unit volume */
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
            drho += flux * vj;
            if (variable_mass && !particle_is_wall_image(p, j)) mass_flux += flux * vi * vj;
        }
        drho += continuity_pair(rhoi, transport_ji, pr.r_ji, pr.f, vj);
        force = momentum_pair_add(force, pp, p, &mi, &pr, les, ale);
    }
    vec transport = vec_add(ui, dui);
    if (pp->volume_correction) { /* the particle moves through the density field */
        vec dvi = vec_load(p->correction, i);
        transport = vec_add(transport, dvi);
        drho += volume_correction_resampling(dvi, vec_load(p->grad_rho, i));
    }
    out->drho[i] = drho + p->diff_rho[i];
    vec acc = vec_axpy(frame_body_force(frame, xi, ui), 1.0 / rhoi, force);
    /* the surface-tension force on the particle at this stage: m a sums it exactly */
    if (pp->surface_tension) acc = vec_axpy(acc, 1.0 / p->m[i], vec_load(p->st_force, i));
    for (int d = 0; d < DIM; d++) {
        out->du[d][i] = acc.c[d];
        out->dx[d][i] = transport.c[d];
    }
    /* Eq. (3): dm/dt = eta [div(rho du) V_i + D^m] (fluid pairs only: the total is exact) */
    out->dm[i] = variable_mass ? eta * (mass_flux + p->diff_m[i]) : 0.0;
}

#define RHS_LOOP(les, ale, mass)                                                                   \
    _Pragma("omp parallel for schedule(static)") for (size_t i = 0; i < p->n_fluid; i++)           \
        rhs_particle(pp, p, nl, i, frame, les, ale, mass, eta, out)

void rhs_compute(const physics_params *pp, const particles *p, const neighbour_list *nl,
                 const tank_frame *frame, double eta, const rates *out)
{
    /* variable masses come only with shifting (Table 1: eta = 1 implies xi = 1) */
    int variant = (pp->les ? 4 : 0) + (pp->shifting ? 2 : 0) + (pp->shifting && eta > 0.0);
    switch (variant) {
    case 0: RHS_LOOP(false, false, false); break;
    case 2: RHS_LOOP(false, true, false); break;
    case 3: RHS_LOOP(false, true, true); break;
    case 4: RHS_LOOP(true, false, false); break;
    case 6: RHS_LOOP(true, true, false); break;
    default: RHS_LOOP(true, true, true); break;
    }
}
