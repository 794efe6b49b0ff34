/* rhs_lanes: the right-hand side in SIMD lanes (core/lanes.h), LANES particles side by side;
 * included by scheme/rhs_lanes4.c and rhs_lanes8.c, which set LANES and RHS_COMPUTE_LANES. The lane
 * sums transcribe rhs_particle_sums (scheme/rhs_particle.h) operation by operation, each pair
 * function of src/physics (named in its comments) written out in lane types in the same order,
 * so every width gives the scalar form's bits; tests/test_lanes.c holds them to it. */
#include "core/lane_pairs.h"
#include "core/team_loop.h"
#include "scheme/rhs_particle.h"

/* The same sums for the particles i0 .. i0 + LANES - 1, one per lane (core/lanes.h): every
 * operation is the scalar one's, in the same order, so the sums are the same to the bit. A lane
 * whose row has ended, or whose neighbour lies beyond 2h, leaves its sums as they are. */
__attribute__((always_inline)) static inline void
rhs_lanes_sums(const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i0,
               const bool les, const bool ale, const bool variable_mass, rhs_sums out[LANES])
{
    lane_vec ui = lane_vec_load(p->u, i0);
    lane_vec dui = lane_vec_load(p->shift, i0);
    lane_real rhoi = lane_load(p->rho, i0), vi = lane_load(p->vol, i0);
    lane_real pi = lane_load(p->p, i0), nu_ti = lane_load(p->nu_t, i0);
    lane_real drho = lane_broadcast(0.0), mass_flux = lane_broadcast(0.0);
    lane_vec force = lane_vec_zero();
    /* whether any of the rows reaches a ghost: most blocks' rows lie away from the walls */
    bool ghosts = false;
    for (int l = 0; l < LANES; l++) ghosts |= neighbour_row_has_ghosts(nl, i0 + (size_t)l);
    const size_t images = particles_images_begin(p);
    const double c0_2 = pp->c0 * pp->c0; /* eos_pressure's c0 * c0 */
    lane_pair pr;
    FOR_EACH_LANE_PAIR (&pp->k, p->x, nl, i0, pr) {
        const int32_t *j = pr.j;
        lane_mask within = pr.within;
        lane_vec r_ji = pr.r_ji;
        lane_real f = pr.f, r2 = pr.r2;
        lane_real vj = lane_gather(p->vol, j);
        lane_vec uj = lane_vec_gather(p->u, j);
        lane_vec u_ji = lane_vec_sub(uj, ui);
        lane_vec transport_ji = u_ji;
        lane_vec duj;
        lane_real rhoj;
        if (ale) {
            duj = lane_vec_gather(p->shift, j);
            rhoj = lane_gather(p->rho, j);
            transport_ji = lane_vec_add(u_ji, lane_vec_sub(duj, dui));
            /* ale_flux_pair */
            lane_real flux =
                lane_vec_dot(lane_vec_axpy(lane_vec_scale(dui, rhoi), rhoj, duj), r_ji) * f;
            drho = lane_select(within, drho + flux * vj, drho);
            if (variable_mass) {
                lane_mask fluid;
                for (int l = 0; l < LANES; l++)
                    fluid[l] = particle_is_wall_image(p, (size_t)j[l]) ? 0 : -1;
                mass_flux = lane_select(within & fluid, mass_flux + flux * vi * vj, mass_flux);
            }
        }
        /* continuity_pair */
        drho = lane_select(within, drho + -rhoi * lane_vec_dot(transport_ji, r_ji) * f * vj, drho);
        /* momentum_pair_add */
        if (ale)
            force = lane_vec_add_where(
                within, force, lane_vec_scale(u_ji, rhoj * lane_vec_dot(duj, r_ji) * f * vj));
        /* with ALE, a fluid or halo neighbour's p is eos_pressure of its rho, which is
           gathered already (solver_update_eos and EdBC keep p = c0^2 (rho - rho0) to the bit),
           one gather of ten less: 4 % of the lanes; a wall image's p is its own
           (tank_refresh_ghosts), read below; without ALE rho_j is not gathered, p_j is */
        lane_real pj = ale ? c0_2 * (rhoj - pp->rho0) : lane_gather(p->p, j);
        lane_real mu_eff = lane_broadcast(pp->rho0 * pp->nu);
        if (les) {
            lane_real nu_tj = lane_gather(p->nu_t, j);
            lane_real sum = nu_ti + nu_tj;
            lane_real mean = lane_select(sum > 0.0, 2.0 * nu_ti * nu_tj / sum, lane_broadcast(0.0));
            mean = lane_select(mean < pp->nu_t_cap, mean, lane_broadcast(pp->nu_t_cap));
            mu_eff += pp->rho0 * mean;
        }
        /* the viscous term's velocity (particle_viscous_velocity): a fluid or halo
           neighbour's own, a wall image's no-slip or free-slip image; and a wall image's p.
           Looked for only in blocks whose rows reach a ghost */
        lane_vec uwj = uj;
        if (ghosts)
            for (int l = 0; l < LANES; l++)
                if ((size_t)j[l] >= images) {
                    if (ale) pj[l] = p->p[j[l]];
                    vec uw = particle_viscous_velocity(p, (size_t)j[l]);
                    for (int d = 0; d < DIM; d++) uwj.c[d][l] = uw.c[d];
                }
        force = lane_vec_add_where(within, force, lane_vec_scale(r_ji, -(pi + pj) * f * vj));
        lane_vec uw_ji = lane_vec_sub(uwj, ui);
        lane_real pi_ij = lane_vec_dot(uw_ji, r_ji) / r2;
        force = lane_vec_add_where(within, force,
                                   lane_vec_scale(r_ji, VISCOSITY_K * mu_eff * pi_ij * f * vj));
    }
    for (int l = 0; l < LANES; l++) {
        out[l].drho = drho[l];
        out[l].mass_flux = mass_flux[l];
        for (int d = 0; d < DIM; d++) out[l].force.c[d] = force.c[d][l];
    }
}

/* The particles [i0, end), at most LANES of them: in lanes where there are LANES, else (the
 * last block) one by one. */
__attribute__((always_inline)) static inline void
rhs_block_variant(const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i0,
                  size_t end, const tank_frame *frame, const bool les, const bool ale,
                  const bool variable_mass, double eta, const rates *out)
{
    rhs_sums s[LANES];
    size_t n = end - i0;
    if (n == LANES)
        rhs_lanes_sums(pp, p, nl, i0, les, ale, variable_mass, s);
    else
        for (size_t l = 0; l < n; l++)
            s[l] = rhs_particle_sums(pp, p, nl, i0 + l, les, ale, variable_mass);
    for (size_t l = 0; l < n; l++)
        rhs_particle_finish(pp, p, i0 + l, frame, variable_mass, eta, s[l], out);
}

LANES_TARGET static void rhs_block_lanes(const physics_params *pp, const particles *p,
                                         const neighbour_list *nl, size_t i0, size_t end,
                                         const tank_frame *frame, double eta, const rates *out)
{
    RHS_FOR_VARIANT(pp, eta, RHS_BLOCK_VARIANT)
}

/* Each particle's rates are its own, whichever thread and block compute them (a team loop,
 * core/team_loop.h). */
void RHS_COMPUTE_LANES(const physics_params *pp, const particles *p, const neighbour_list *nl,
                       const tank_frame *frame, double eta, const rates *out)
{
    size_t n = p->n_fluid;
    _Static_assert(TEAM_CHUNK % LANES == 0, "a chunk holds whole blocks");
    TEAM_LOOP_SHARES(q, n, TEAM_CHUNK);
#pragma omp parallel
    TEAM_LOOP_FOR (&q, begin, end)
        for (size_t i0 = begin; i0 < end; i0 += LANES)
            rhs_block_lanes(pp, p, nl, i0, i0 + LANES < end ? i0 + LANES : end, frame, eta, out);
}
