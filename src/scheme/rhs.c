/* rhs: continuity, pressure and viscous forces, gravity, ALE terms and masses (Eqs. 3, 4). With
 * ale (shifting on, Eq. 3): the particles move with u + du, the continuity equation gains
 * -rho_i du_ji . grad W V_j and the flux div(rho du), the momentum equation rho (du . grad) u,
 * and with variable masses dm/dt = eta [div(rho du) V_i + D^m]. The sums of each particle are
 * scheme/rhs_particle.h's; here they run one particle at a time, or in SIMD lanes
 * (scheme/rhs_lanes.h) where the processor has them, with the same bits. */
#include "scheme/rhs.h"
#include "core/lanes_switch.h"
#include "scheme/rhs_particle.h"

/* blocks of particles for the threads, so that the variant is chosen once per block */
#define RHS_SCALAR_BLOCK 8

__attribute__((always_inline)) static inline void
rhs_block_variant(const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i0,
                  size_t end, const tank_frame *frame, const bool les, const bool ale,
                  const bool variable_mass, double eta, const rates *out)
{
    for (size_t i = i0; i < end; i++) {
        rhs_sums s = rhs_particle_sums(pp, p, nl, i, les, ale, variable_mass);
        rhs_particle_finish(pp, p, i, frame, variable_mass, eta, s, out);
    }
}

static void rhs_block_scalar(const physics_params *pp, const particles *p, const neighbour_list *nl,
                             size_t i0, size_t end, const tank_frame *frame, double eta,
                             const rates *out)
{
    RHS_FOR_VARIANT(pp, eta, RHS_BLOCK_VARIANT)
}

void rhs_compute(const physics_params *pp, const particles *p, const neighbour_list *nl,
                 const tank_frame *frame, double eta, const rates *out)
{
    switch (lanes_width()) {
    case 8: rhs_compute_lanes8(pp, p, nl, frame, eta, out); return;
    case 4: rhs_compute_lanes4(pp, p, nl, frame, eta, out); return;
    default: break;
    }
    size_t n = p->n_fluid;
    /* each particle's rates are its own, whichever thread computes them */
#pragma omp parallel for schedule(static)
    for (size_t i0 = 0; i0 < n; i0 += RHS_SCALAR_BLOCK)
        rhs_block_scalar(pp, p, nl, i0, i0 + RHS_SCALAR_BLOCK < n ? i0 + RHS_SCALAR_BLOCK : n,
                         frame, eta, out);
}
