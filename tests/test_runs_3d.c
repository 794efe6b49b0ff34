/* Whole 3D runs against theory, about 35 s of CPU time on one thread:
 * - free sloshing: the first mode's period in a narrow rectangular tank, against linear
 *   theory;
 * - Laplace: a weightless ball of liquid at rest under surface tension, whose inside pressure
 *   is 2 sigma / R. */
#ifndef DIM
#define DIM 3 /* the ball is stepped through the 3D solver's API */
#endif
#if DIM != 3
#error "test_runs_3d steps the 3D solver"
#endif
#include "app/simulation.h"
#include "scheme/solver.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <cmocka.h>

#include "check.h"
#include "table.h"
#include "run_case.h"
#include "laplace.h"
#include "sloshing.h"

/* The ball of R / dr = 8 cut out of the lattice, from rest, with nu = 1e-3 (Ohnesorge number
 * nu sqrt(rho / (sigma R)) = 0.14) so that the start's acoustic and capillary transients have
 * decayed by 1 s; the core pressure averaged over 1 - 2 s against 2 sigma / R = 39.8 Pa.
 * Measured: 50.3 Pa, +26.4 %. The error is the discrete force's, and falls as dr / R (about
 * 2.1 dr / R: +21 % at R / dr = 10, +17.6 % at 12): the band S_F that carries the force lies
 * one to two dr inside the surface, and there its interface function integrates along the
 * radius to 1.18 (1.000 across a flat surface), with the curvature 5.5 % above 2 / R; the
 * particles' pressure follows the radial integral of the force density to 6 %. The tolerance
 * is the measured error times a margin of 1.2: 31.7 %, which sigma halved in the case
 * (-38.3 %) does not pass. */
static void test_laplace_ball(void **state)
{
    (void)state;
    config cfg;
    solver s;
    start_patch(&cfg, &s, 2.0 * PATCH_RADIUS, 2.0 * PATCH_RADIUS, 16, 1e-3, 2.0);
    cut_ball(&s, PATCH_RADIUS);
    double radius = equivalent_radius(&s);
    double p_in = settled_core_pressure(&s, cfg.t_end, radius, 1.0),
           expected = 2.0 * PATCH_SIGMA / radius;
    printf("Laplace, ball of R/dr = %.2f (%zu particles): core pressure %.3f Pa over 1-2 s, "
           "2 sigma/R = %.3f Pa (%+.1f %%), %ld steps\n",
           radius / s.dv.dr, s.p.n_fluid, p_in, expected, 100.0 * (p_in / expected - 1.0), s.step);
    assert_close(p_in / expected, 1.0, 1.2 * 0.264);
    solver_free(&s);
}

/* Free sloshing of free_sloshing_case (sloshing.h: the INM tank, 1 m long, H = 0.35 m, one
 * period of sway, A = 1 cm) in 3D: W = 0.14 m, N = 10, delta-SPH, h / dr = 2. The first mode
 * is uniform across z, so four particles across it suffice (the run warns that the kernel
 * spans the width; at h / dr = 1.5, W = 0.28 m gave -1.26 % against -1.33 %). After the
 * forcing, com_x oscillates with T1 = 2 pi / sqrt(g k tanh(k H)), k = pi / L = 1.2651 s.
 * Measured: 1.2609 s, -0.33 %. The tolerance is the measured error times a margin of 3:
 * 1.0 %, which a tank 5 % longer (+3.25 %) does not pass. At the 3D default h / dr = 1.5 the
 * period is -1.33 % (-0.8 % in 2D): the narrower kernel's discretisation error, too close to
 * a 5 % change of length for this check. */
static void test_sloshing_period_3d(void **state)
{
    (void)state;
    const char *overrides[] = {"case.dim=3", "tank.width=0.14", "numerics.resolution=10",
                               "numerics.h_over_dr=2"};
    double period = free_sloshing_period(overrides, 4, 3, "3D free sloshing");
    double t1 = free_sloshing_t1();
    assert_close(t1, 1.2651, 1e-4);
    assert_close(period, t1, 3.0 * 0.0033 * t1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sloshing_period_3d),
        cmocka_unit_test(test_laplace_ball),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
