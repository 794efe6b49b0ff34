/* energy: sums over the fluid for the time series. */
#include "diag/energy.h"
#include "core/reduce.h"
#include "physics/eos.h"
#include "physics/moment.h"

typedef enum {
    TERM_EKIN,
    TERM_EPOT,
    TERM_EINT,
    TERM_MASS,
    TERM_VOLUME,
    TERM_MOMENT,
    TERM_ANGULAR
} term;

/* m (x - centre) x u, component `axis` (2D: z alone) */
static inline double angular_momentum(const particles *p, const double centre[3], int axis,
                                      size_t i)
{
    vec r = vec_load(p->x, i);
    for (int d = 0; d < DIM; d++) r.c[d] -= centre[d];
    double l[3] = {0.0, 0.0, 0.0};
    moment_add(l, p->m[i], r, vec_load(p->u, i));
    return l[axis];
}

/* One particle's share of a global sum; `axis` for the first moments m x_d and the
 * components of the angular momentum about `centre`. */
static inline double term_value(const particles *p, const energy_params *ep, term t, int axis,
                                const double centre[3], size_t i)
{
    switch (t) {
    case TERM_EKIN: return 0.5 * p->m[i] * vec_norm2(vec_load(p->u, i));
    case TERM_EPOT: return p->m[i] * ep->gravity * p->x[1][i];
    case TERM_EINT: return p->m[i] * eos_internal_energy(p->rho[i], ep->rho0, ep->c0);
    case TERM_MASS: return p->m[i];
    case TERM_VOLUME: return p->m[i] / p->rho[i];
    case TERM_MOMENT: return p->m[i] * p->x[axis][i];
    case TERM_ANGULAR: return angular_momentum(p, centre, axis, i);
    }
    return 0.0;
}

/* The terms go to scratch, then one sum in the fixed order of the reduce module. */
static double sum_term(const particles *p, const energy_params *ep, double *scratch,
                       const reducer *r, term t, int axis, const double centre[3])
{
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) scratch[i] = term_value(p, ep, t, axis, centre, i);
    return reducer_sum(r, scratch, p->n_fluid);
}

double fluid_max_speed(const particles *p, double *scratch)
{
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) scratch[i] = vec_norm(vec_load(p->u, i));
    return reduce_max(scratch, p->n_fluid);
}

void diagnostics_compute(const particles *p, const energy_params *ep, double *scratch,
                         const reducer *r, diagnostics *out)
{
    size_t n = p->n_fluid;
    out->ekin = sum_term(p, ep, scratch, r, TERM_EKIN, 0, NULL);
    out->epot = sum_term(p, ep, scratch, r, TERM_EPOT, 0, NULL);
    out->eint = sum_term(p, ep, scratch, r, TERM_EINT, 0, NULL);
    out->mass = sum_term(p, ep, scratch, r, TERM_MASS, 0, NULL);
    out->vol_sph = sum_term(p, ep, scratch, r, TERM_VOLUME, 0, NULL);
    for (int d = 0; d < 3; d++)
        out->com[d] = d < DIM ? sum_term(p, ep, scratch, r, TERM_MOMENT, d, NULL) / out->mass : 0.0;
    for (int a = 0; a < 3; a++) /* 2D: about z alone */
        out->angmom[a] =
            DIM == 3 || a == 2 ? sum_term(p, ep, scratch, r, TERM_ANGULAR, a, out->com) : 0.0;
    out->xmin = reducer_min(r, p->x[0], n);
    out->xmax = reducer_max(r, p->x[0], n);
    out->ymax = reducer_max(r, p->x[1], n);
    out->rho_min = reducer_min(r, p->rho, n);
    out->rho_max = reducer_max(r, p->rho, n);
    double umax = fluid_max_speed(p, scratch);
    out->umax = reducer_max(r, &umax, 1);
}
