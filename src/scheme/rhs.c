/* rhs: continuity, pressure and viscous forces, gravity, ALE terms and masses (Eqs. 3, 4). */
#include "scheme/rhs.h"
#include "physics/volume_correction.h"
#include "scheme/rhs_sums.h"

/* Particle i's rates from its neighbour sums. */
static inline void rhs_particle_finish(const physics_params *pp, const particles *p, size_t i,
                                       const tank_frame *frame, const bool variable_mass,
                                       double eta, rhs_sums s, const rates *out)
{
    vec xi = vec_load(p->x, i), ui = vec_load(p->u, i), dui = vec_load(p->shift, i);
    double drho = s.drho;
    vec transport = vec_add(ui, dui);
    if (pp->volume_correction) { /* the particle moves through the density field */
        vec dvi = vec_load(p->correction, i);
        transport = vec_add(transport, dvi);
        drho += volume_correction_resampling(dvi, vec_load(p->grad_rho, i));
    }
    out->drho[i] = drho + p->diff_rho[i];
    vec acc = vec_axpy(frame_body_force(frame, xi, ui), 1.0 / p->rho[i], s.force);
    /* the surface-tension force on the particle at this stage: m a sums it exactly */
    if (pp->surface_tension) acc = vec_axpy(acc, 1.0 / p->m[i], vec_load(p->st_force, i));
    for (int d = 0; d < DIM; d++) {
        out->du[d][i] = acc.c[d];
        out->dx[d][i] = transport.c[d];
    }
    /* Eq. (3): dm/dt = eta [div(rho du) V_i + D^m] (fluid pairs only: the total is exact) */
    out->dm[i] = variable_mass ? eta * (s.mass_flux + p->diff_m[i]) : 0.0;
}

/* The particles [i0, end), at most LANES of them: in lanes where `lanes` and there are LANES,
 * else one by one. `les`, `ale` and `variable_mass` are compile-time constants at each call
 * below, so the code is specialised once per variant, never tested per pair
 * (docs/architecture.md). With ale (shifting on, Eq. 3): the particles move with u + du, the
 * continuity equation gains -rho_i du_ji . grad W V_j and the flux div(rho du), the momentum
 * equation rho (du . grad) u, and with variable masses dm/dt = eta [div(rho du) V_i + D^m]. */
__attribute__((always_inline)) static inline void
rhs_block_variant(const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i0,
                  size_t end, const tank_frame *frame, const bool lanes, const bool les,
                  const bool ale, const bool variable_mass, double eta, const rates *out)
{
    rhs_sums s[LANES];
    size_t n = end - i0;
    if (lanes && n == LANES)
        rhs_lanes_sums(pp, p, nl, i0, les, ale, variable_mass, s);
    else
        for (size_t l = 0; l < n; l++)
            s[l] = rhs_particle_sums(pp, p, nl, i0 + l, les, ale, variable_mass);
    for (size_t l = 0; l < n; l++)
        rhs_particle_finish(pp, p, i0 + l, frame, variable_mass, eta, s[l], out);
}

__attribute__((always_inline)) static inline void
rhs_block(const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i0,
          size_t end, const tank_frame *frame, double eta, const rates *out, const bool lanes)
{
#define RHS_VARIANT(les, ale, mass)                                                                \
    rhs_block_variant(pp, p, nl, i0, end, frame, lanes, les, ale, mass, eta, out)
    /* variable masses come only with shifting (Table 1: eta = 1 implies xi = 1) */
    int variant = (pp->les ? 4 : 0) + (pp->shifting ? 2 : 0) + (pp->shifting && eta > 0.0);
    switch (variant) {
    case 0: RHS_VARIANT(false, false, false); break;
    case 2: RHS_VARIANT(false, true, false); break;
    case 3: RHS_VARIANT(false, true, true); break;
    case 4: RHS_VARIANT(true, false, false); break;
    case 6: RHS_VARIANT(true, true, false); break;
    default: RHS_VARIANT(true, true, true); break;
    }
#undef RHS_VARIANT
}

/* The lanes' form (core/lanes.h: compiled for AVX2, run where the processor has it). */
LANES_TARGET static void rhs_block_lanes(const physics_params *pp, const particles *p,
                                         const neighbour_list *nl, size_t i0, size_t end,
                                         const tank_frame *frame, double eta, const rates *out)
{
    rhs_block(pp, p, nl, i0, end, frame, eta, out, true);
}

static void rhs_block_scalar(const physics_params *pp, const particles *p, const neighbour_list *nl,
                             size_t i0, size_t end, const tank_frame *frame, double eta,
                             const rates *out)
{
    rhs_block(pp, p, nl, i0, end, frame, eta, out, false);
}

void rhs_compute(const physics_params *pp, const particles *p, const neighbour_list *nl,
                 const tank_frame *frame, double eta, const rates *out)
{
    bool lanes = lanes_in_use();
    size_t n = p->n_fluid;
    /* blocks of LANES particles; each particle's rates are its own, whichever thread computes them
     */
#pragma omp parallel for schedule(static)
    for (size_t i0 = 0; i0 < n; i0 += LANES) {
        size_t end = i0 + LANES < n ? i0 + LANES : n;
        if (lanes)
            rhs_block_lanes(pp, p, nl, i0, end, frame, eta, out);
        else
            rhs_block_scalar(pp, p, nl, i0, end, frame, eta, out);
    }
}
