/* laplace: the pressure inside a weightless patch (2D) or ball (3D) under surface tension, for
 * the tests that compare it with the Young-Laplace jump (sigma / R, 2 sigma / R). Include after
 * <cmocka.h> with DIM defined. */
#ifndef VCSPH_TEST_LAPLACE_H
#define VCSPH_TEST_LAPLACE_H

#include "scheme/solver.h"

#include "keep_particles.h"

#include <math.h>
#include <stdio.h>

/* The patches' liquid: water-like, with sigma = 1 N/m; R = 5 cm in a tank of side 6R */
#define PATCH_SIGMA  1.0 /* N/m */
#define PATCH_RHO    1000.0
#define PATCH_RADIUS 0.05 /* m */

/* A weightless patch of the ellipse (3D: the elliptic cylinder across the width) inscribed in
 * length x height, centred in a tank of side 0.3 m, delta-plus-SPH without LES, c0 = 2 m/s,
 * ready to step. */
static inline void start_patch(config *cfg, solver *s, double length, double height, int resolution,
                               double nu, double t_end)
{
    char text[1024], err[1024];
    snprintf(text, sizeof text,
             "[case]\nname = patch\ndim = %d\nt_end = %g\n[tank]\nlength = 0.3\nheight = 0.3\n"
             "%s[liquid]\nshape = ellipse\nheight = %.17g\nlength = %.17g\nx0 = %.17g\n"
             "y0 = %.17g\n[fluid]\ndensity = %g\nviscosity = %g\ngravity = 0\n"
             "surface_tension = %g\n[model]\nscheme = delta-plus\nles = false\n"
             "[numerics]\nresolution = %d\nsound_speed = 2\n[output]\ntimeseries_every = 0.005\n",
             DIM, t_end, DIM == 3 ? "width = 0.3\n" : "", height, length, 0.15 - 0.5 * length,
             0.15 - 0.5 * height, PATCH_RHO, nu, PATCH_SIGMA, resolution);
    if (config_load_string(cfg, text, "test", NULL, 0, err, sizeof err)) fail_msg("%s", err);
    if (solver_init(s, cfg, err, sizeof err)) fail_msg("%s", err);
}

/* Whether x lies within `radius` of centre, its boundary included. */
static inline bool within_ball(const double *x, const double *centre, double radius)
{
    double r2 = 0.0;
    for (int d = 0; d < DIM; d++) r2 += (x[d] - centre[d]) * (x[d] - centre[d]);
    return r2 <= radius * radius;
}

/* Keeps the particles within `radius` of the point (3 radius, 3 radius[, 3 radius]), the centre
 * of the tanks these tests cut a circle (2D) or a ball (3D) from: a patch clear of every wall
 * (a 3D case's ellipsoid spans the tank's width; for a 2D circle of that radius, a no-op). */
static inline void cut_ball(solver *s, double radius)
{
    const double centre[3] = {3.0 * radius, 3.0 * radius, 3.0 * radius};
    keep_particles(s, within_ball, centre, radius);
}

/* The radius of the disc (ball) of the particles' volume, n dr^d. */
static inline double equivalent_radius(const solver *s)
{
    double v = (double)s->p.n_fluid * s->dv.cell_volume;
    return DIM == 2 ? sqrt(v / M_PI) : cbrt(3.0 * v / (4.0 * M_PI));
}

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
