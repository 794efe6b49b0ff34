/* rhs: continuity, pressure and viscous forces, gravity (Eqs. 3, 4). */
#include "scheme/rhs.h"
#include "physics/continuity.h"
#include "physics/pressure.h"
#include "physics/viscosity.h"
#include "scheme/pair.h"

/* One particle's sums. `les` is a compile-time constant at each call below, so the loop is
 * specialised once per loop, never tested per pair (design §2). */
static inline void rhs_particle(const physics_params *pp, const particles *p,
                                const neighbour_list *nl, size_t i, vec g_eff, const bool les,
                                const rates *out)
{
    const kernel *k = &pp->k;
    vec xi = vec_load(p->x, i), ui = vec_load(p->u, i), uwi = vec_load(p->u_wall, i);
    double rhoi = p->rho[i], pi = p->p[i], nuti = p->nu_t[i];
    double mu = pp->rho0 * pp->nu;
    double drho = 0.0;
    vec force = vec_zero(); /* per unit volume */
    const int32_t *row = neighbour_row(nl, i);
    for (int32_t n = 0; n < nl->count[i]; n++) {
        pair pr;
        if (!pair_of(k, p->x, xi, row, n, &pr)) continue;
        size_t j = pr.j;
        double vj = p->vol[j];
        drho += continuity_pair(rhoi, vec_sub(vec_load(p->u, j), ui), pr.r_ji, pr.f, vj);
        force = vec_add(force, pressure_pair(pi, p->p[j], pr.r_ji, pr.f, vj));
        double mu_eff = mu;
        if (les) mu_eff += pp->rho0 * harmonic_mean_capped(nuti, p->nu_t[j], pp->nu_t_cap);
        vec uw_ji = vec_sub(vec_load(p->u_wall, j), uwi);
        force = vec_add(force, viscosity_pair(mu_eff, uw_ji, pr.r_ji, pr.r2, pr.f, vj));
    }
    out->drho[i] = drho + p->diff_rho[i];
    vec acc = vec_axpy(g_eff, 1.0 / rhoi, force);
    for (int d = 0; d < DIM; d++) {
        out->du[d][i] = acc.c[d];
        out->dx[d][i] = ui.c[d] + p->shift[d][i];
    }
    out->dm[i] = 0.0;
}

void rhs_compute(const physics_params *pp, const particles *p, const neighbour_list *nl, vec g_eff,
                 const rates *out)
{
    if (pp->les) {
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < p->n_fluid; i++) rhs_particle(pp, p, nl, i, g_eff, true, out);
    } else {
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < p->n_fluid; i++) rhs_particle(pp, p, nl, i, g_eff, false, out);
    }
}
