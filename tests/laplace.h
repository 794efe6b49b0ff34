/* laplace: the pressure inside a weightless patch (2D) or ball (3D) under surface tension, for
 * the tests that compare it with the Young-Laplace jump (sigma / R, 2 sigma / R). Include after
 * <cmocka.h> with DIM defined. */
#ifndef VCSPH_TEST_LAPLACE_H
#define VCSPH_TEST_LAPLACE_H

#include "scheme/solver.h"

#include <math.h>

/* Mean pressure of the particles within R/2 of the liquid's centre of mass. */
static inline double core_pressure(const solver *s, double radius)
{
    const particles *p = &s->p;
    double c[DIM] = {0.0}, mass = 0.0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        for (int d = 0; d < DIM; d++) c[d] += p->m[i] * p->x[d][i];
        mass += p->m[i];
    }
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        double r2 = 0.0;
        for (int d = 0; d < DIM; d++) r2 += pow(p->x[d][i] - c[d] / mass, 2);
        if (r2 > 0.25 * radius * radius) continue;
        sum += p->p[i];
        n++;
    }
    return sum / (double)n;
}

/* Steps s to t_end and returns its core pressure averaged over time from `from` on. */
static inline double settled_core_pressure(solver *s, double t_end, double radius, double from)
{
    double sum = 0.0, weight = 0.0;
    while (s->t < t_end) {
        assert_int_equal(solver_step(s, t_end), 0);
        if (s->t >= from) {
            sum += core_pressure(s, radius) * s->last_dt;
            weight += s->last_dt;
        }
    }
    return sum / weight;
}

#endif
