/* energy: sums over the fluid for the time series. */
#include "diag/energy.h"
#include "core/reduce.h"
#include "physics/eos.h"

typedef enum { TERM_EKIN, TERM_EPOT, TERM_EINT, TERM_MASS, TERM_VOLUME, TERM_MOMENT } term;

/* One particle's share of a global sum; `axis` for the first moments m x_d. */
static inline double term_value(const solver *s, term t, int axis, size_t i)
{
    const particles *p = &s->p;
    switch (t) {
    case TERM_EKIN: return 0.5 * p->m[i] * vec_norm2(vec_load(p->u, i));
    case TERM_EPOT: return p->m[i] * s->cfg->gravity * p->x[1][i];
    case TERM_EINT: return p->m[i] * eos_internal_energy(p->rho[i], s->pp.rho0, s->pp.c0);
    case TERM_MASS: return p->m[i];
    case TERM_VOLUME: return p->m[i] / p->rho[i];
    case TERM_MOMENT: return p->m[i] * p->x[axis][i];
    }
    return 0.0;
}

/* The terms go to scratch, then one sum in the fixed order of the reduce module. */
static double sum_term(solver *s, term t, int axis)
{
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < s->p.n_fluid; i++) s->scratch[i] = term_value(s, t, axis, i);
    return reduce_sum(s->scratch, s->p.n_fluid);
}

void diagnostics_compute(solver *s, diagnostics *out)
{
    const particles *p = &s->p;
    size_t n = p->n_fluid;
    out->ekin = sum_term(s, TERM_EKIN, 0);
    out->epot = sum_term(s, TERM_EPOT, 0);
    out->eint = sum_term(s, TERM_EINT, 0);
    out->mass = sum_term(s, TERM_MASS, 0);
    out->vol_sph = sum_term(s, TERM_VOLUME, 0);
    for (int d = 0; d < 3; d++)
        out->com[d] = d < DIM ? sum_term(s, TERM_MOMENT, d) / out->mass : 0.0;
    out->xmin = reduce_min(p->x[0], n);
    out->xmax = reduce_max(p->x[0], n);
    out->ymax = reduce_max(p->x[1], n);
    out->rho_min = reduce_min(p->rho, n);
    out->rho_max = reduce_max(p->rho, n);
    out->umax = solver_max_speed(s);
}
