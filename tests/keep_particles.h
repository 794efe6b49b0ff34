/* keep_particles: a test's cut of the liquid it set up: the fluid particles for which keep()
 * holds stay, compacted in place with their state. Include after "scheme/solver.h". */
#ifndef VCSPH_TEST_KEEP_PARTICLES_H
#define VCSPH_TEST_KEEP_PARTICLES_H

#include <stdbool.h>

typedef bool (*particle_keep)(const double *x, const double *centre, double radius);

static inline void keep_particles(solver *s, particle_keep keep, const double *centre,
                                  double radius)
{
    particles *p = &s->p;
    size_t k = 0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        double x[DIM];
        for (int d = 0; d < DIM; d++) x[d] = p->x[d][i];
        if (!keep(x, centre, radius)) continue;
        for (int d = 0; d < DIM; d++) {
            p->x[d][k] = p->x[d][i];
            p->u[d][k] = p->u[d][i];
        }
        p->m[k] = p->m[i];
        p->rho[k] = p->rho[i];
        p->p[k] = p->p[i];
        p->vol[k] = p->vol[i];
        p->id[k] = p->id[i];
        k++;
    }
    p->n_fluid = p->n_total = k;
}

#endif
