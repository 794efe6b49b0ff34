/* A pressure sensor of finite size (probes.pressure = x y [z] d=D, docs/case-file.md) reads the
 * mean of the SPH pressure over its face. On a lattice holding p = y^2, the Shepard
 * interpolation reads y^2 plus the kernel's second moment, the same constant everywhere (up to
 * the lattice sums' errors, about 1e-3 of the kernel's, theory §1), so the sensor reads the
 * point value plus the mean of y^2 over the face:
 * - 2D, the face a segment of length D along y: D^2 / 12;
 * - 3D, the face a disc of diameter D in the y-z plane: D^2 / 16 (R^2 / 4).
 * The quadrature is exact for these polynomials; what is left is the interpolation's. */
#include "diag/probes.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "check.h"

#define DR       0.01
#define DIAMETER (10 * DR)
#define REACH    10 /* lattice half-width in dr: the face's radius and the kernel's 2h, and 1 */

/* The lattice holding p = y^2 and the probes of h = 2 dr. */
static void fill_lattice(particles *p, probes *pr)
{
    int side = 2 * REACH + 1;
    size_t n = 1;
    for (int d = 0; d < DIM; d++) n *= (size_t)side;
    assert_int_equal(particles_init(p, n), 0);
    for (size_t i = 0; i < n; i++) {
        size_t rest = i;
        for (int d = 0; d < DIM; d++) {
            p->x[d][i] = ((int)(rest % (size_t)side) - REACH) * DR;
            rest /= (size_t)side;
        }
        p->vol[i] = pow(DR, DIM);
        p->p[i] = p->x[1][i] * p->x[1][i];
    }
    p->n_fluid = p->n_total = n;
    probes_init(pr, 2.0 * DR, DR, pow(DR, DIM), 0.0); /* 3D: the gauges' line at z = 0 */
}

static void test_face_mean(void **state)
{
    (void)state;
    particles p;
    probes pr;
    fill_lattice(&p, &pr);
    /* off the lattice's nodes, so that the face does not sample them only */
    const double centre[3] = {0.3 * DR, 0.2 * DR, -0.1 * DR};
    double point = probes_pressure(&pr, &p, centre);
    double sensor = probes_sensor(&pr, &p, centre, DIAMETER, 0);
    double expected = DIAMETER * DIAMETER / (DIM == 2 ? 12.0 : 16.0);
    double y2 = centre[1] * centre[1];
    printf("%dD: point %.6e, sensor %.6e, sensor - point %.6e against %.6e (%+.3f %%)\n", DIM,
           point, sensor, sensor - point, expected, 100.0 * ((sensor - point) / expected - 1.0));
    /* the point reads y^2 + the kernel's second moment, here about (0.7 h)^2 */
    assert_true(point > y2 && point < y2 + 4.0 * DR * DR);
    assert_close((sensor - point) / expected, 1.0, 1e-3);
    particles_free(&p);
}

/* A sensor of vanishing size reads the point value. */
static void test_small_face(void **state)
{
    (void)state;
    particles p;
    probes pr;
    fill_lattice(&p, &pr);
    const double centre[3] = {0.0, 0.25 * DR, 0.0};
    double point = probes_pressure(&pr, &p, centre);
    assert_close(probes_sensor(&pr, &p, centre, 1e-9 * DR, 0) / point, 1.0, 1e-12);
    particles_free(&p);
}

/* The level on a gauge's line (probes_level): the lattice's top row is at REACH dr, and the
 * colour function of a lattice reads 1/2 at the cell edge, dr/2 above it, to the lattice
 * sums' own error at h_c = dr (measured -0.0103 dr in 2D, -0.0024 dr in 3D; bound 3x); a lone
 * particle 8 dr above the surface on the line
 * reads as the surface in 2D, where its colour peaks at W(0) dr^2 = 0.56, and not in 3D,
 * where it peaks at 0.42 and the line below it is read. */
static void test_level(void **state)
{
    (void)state;
    particles p;
    probes pr;
    fill_lattice(&p, &pr);
    const double x = 0.3 * DR, surface = (REACH + 0.5) * DR;
    double level = probes_level(&pr, &p, x);
    printf("%dD level %.6f dr against %.1f dr\n", DIM, level / DR, surface / DR);
    double tolerance = (DIM == 2 ? 0.031 : 0.0072) * DR;
    assert_close(level, surface, tolerance);
    /* particle 0, the lattice's corner far from the line, becomes the lone one above it */
    p.x[0][0] = x;
    p.x[1][0] = (REACH + 8) * DR;
    if (DIM == 3) p.x[DIM - 1][0] = 0.0;
    level = probes_level(&pr, &p, x);
    printf("%dD level with a lone particle at %d dr: %.6f dr\n", DIM, REACH + 8, level / DR);
    if (DIM == 2)
        assert_true(level > (REACH + 8) * DR && level < (REACH + 8.5) * DR);
    else
        assert_close(level, surface, tolerance);
    particles_free(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_face_mean),
        cmocka_unit_test(test_small_face),
        cmocka_unit_test(test_level),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
