/* probes.csv in a still tank (2D and 3D), at t = 0 and at the end (0.3 s): a wave gauge reads
 * the filling height H (the liquid fraction integrated along the gauge's line gives the liquid
 * volume over the column), and so does its level (the surface's height on the line), and a pressure
 * probe at depth d reads rho0 g d (the Shepard interpolation is exact for the linear hydrostatic
 * field; the rest is the settling of the lattice). Probes in the middle and on a side wall (where
 * the ghosts complete the kernel), and a sensor of 8 cm on the side wall, whose mean over its face
 * of the linear field is the value at its centre (the quadrature's own check: test_sensor). The
 * bounds are about 3x the measured worst (a run at rest, the same on every machine up to the
 * round-off of its libm):
 * - gauges: measured 0.0098 dr (2D, N = 20) and 0.0156 dr (3D, N = 10), the same at t = 0 as
 *   at the end: the integration's own error; bounds 0.025 dr and 0.045 dr;
 * - levels (the colour function's 1/2 on the gauge's line): measured 0.0163 dr (2D) and
 *   0.0047 dr (3D), the lattice's settling and the colour's own error on a lattice; bounds
 *   0.05 dr and 0.015 dr;
 * - pressure: measured +0.58 % (2D) and +0.38 % (3D) at the end, 0.004 % at t = 0; bounds
 *   1.5 % and 1.1 %.
 * probes.csv's rows follow probes.every, not timeseries.csv's: every step with 0 (one row per
 * step, the step count of timeseries.csv), or at the exact multiples of its interval; with
 * probes.filter each sensor's filtered signal follows as sensor_k, starting at rest at the
 * first raw sample (the filter's own responses: test_sensor_filter). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "check.h"
#include "table.h"
#include "run_case.h"

#define DEPTH_H 0.35

static void check_still_tank(int dim, int resolution, double gauge_tol, double level_tol,
                             double p_tol)
{
    char text[1024];
    const char *z = dim == 3 ? " 0.05" : "";
    snprintf(text, sizeof text,
             "[case]\nname = still\ndim = %d\nt_end = 0.3\n"
             "[tank]\nlength = 1.0\nheight = 1.0\nwidth = 0.1\n[liquid]\nheight = %g\n"
             "[model]\nscheme = delta-plus-ale\n"
             "[numerics]\nresolution = %d\nsound_speed = 20.0\n"
             "[probes]\ngauges = 0.0, 0.3, 0.5, 1.0\n"
             "pressure = 0.5 0.175%s; 0.0 0.1%s; 0.31 0.05%s; 0.0 0.1%s d=0.08\n"
             "[output]\ntimeseries_every = 0.05\n",
             dim, DEPTH_H, resolution, z, z, z, z);
    char dir[64], path[128];
    table ts, pr;
    run_case_text(text, NULL, 0, dir, &ts);
    snprintf(path, sizeof path, "%s/probes.csv", dir);
    assert_int_equal(table_read(&pr, path), 0);
    assert_int_equal(pr.n_rows, ts.n_rows); /* one row per time-series row */
    assert_int_equal(pr.n_columns, 1 + 4 + 4 + 4);
    double dr = DEPTH_H / resolution, g = 9.81, rho0 = 1000.0;
    const double probe_y[4] = {0.175, 0.1, 0.05, 0.1};
    for (size_t row = 0; row < pr.n_rows; row += pr.n_rows - 1) {
        printf("%dD, t = %g s:", dim, pr.column[0][row]);
        for (int k = 1; k <= 4; k++) {
            double gauge = pr.column[k][row];
            printf(" gauge %.5f m (H %+.4f dr)", gauge, (gauge - DEPTH_H) / dr);
            assert_close(gauge, DEPTH_H, gauge_tol * dr);
        }
        for (int k = 0; k < 4; k++) {
            double p = pr.column[5 + k][row], expected = rho0 * g * (DEPTH_H - probe_y[k]);
            printf(" p %.1f Pa (%+.3f %%)", p, 100.0 * (p / expected - 1.0));
            assert_close(p / expected, 1.0, p_tol);
        }
        for (int k = 0; k < 4; k++) {
            double level = pr.column[9 + k][row];
            printf(" level %.5f m (H %+.4f dr)", level, (level - DEPTH_H) / dr);
            assert_close(level, DEPTH_H, level_tol * dr);
        }
        printf("\n");
    }
    table_free(&pr);
    table_free(&ts);
}

/* The still tank to 0.02 s with rows of timeseries.csv every 0.01 s and probes.csv every
 * `every` s, a sensor on the side wall filtered at 50 Hz (first order). */
static void run_probe_rows(const char *every, table *ts, table *pr)
{
    char text[1024], dir[64], path[128];
    snprintf(text, sizeof text,
             "[case]\nname = rows\nt_end = 0.02\n[tank]\nlength = 1.0\nheight = 1.0\n"
             "[liquid]\nheight = %g\n[numerics]\nresolution = 10\nsound_speed = 20.0\n"
             "[probes]\npressure = 0.0 0.1 d=0.08\nevery = %s\nfilter = first-order\n"
             "cutoff = 50\n[output]\ntimeseries_every = 0.01\n",
             DEPTH_H, every);
    run_case_text(text, NULL, 0, dir, ts);
    snprintf(path, sizeof path, "%s/probes.csv", dir);
    assert_int_equal(table_read(pr, path), 0);
    assert_int_equal(ts->n_rows, 3);
    assert_int_equal(pr->n_columns, 3); /* t, pressure_1, sensor_1 */
    /* the sensor starts at rest at its first sample, then lags the raw signal */
    assert_true(pr->column[2][0] == pr->column[1][0]);
}

static void test_rows_every_step(void **state)
{
    (void)state;
    table ts, pr;
    run_probe_rows("0", &ts, &pr);
    const double *steps = table_column(&ts, "step");
    printf("%zu rows of probes.csv over %g steps\n", pr.n_rows, steps[ts.n_rows - 1]);
    assert_int_equal(pr.n_rows, (size_t)steps[ts.n_rows - 1] + 1);
    for (size_t row = 1; row < pr.n_rows; row++)
        assert_true(pr.column[0][row] > pr.column[0][row - 1]);
    table_free(&pr);
    table_free(&ts);
}

static void test_rows_at_their_interval(void **state)
{
    (void)state;
    table ts, pr;
    run_probe_rows("0.004", &ts, &pr);
    assert_int_equal(pr.n_rows, 6);
    for (size_t row = 0; row < pr.n_rows; row++)
        assert_close(pr.column[0][row], 0.004 * row, 1e-12);
    table_free(&pr);
    table_free(&ts);
}

static void test_still_tank_2d(void **state)
{
    (void)state;
    check_still_tank(2, 20, 0.025, 0.05, 0.015);
}

static void test_still_tank_3d(void **state)
{
    (void)state;
    check_still_tank(3, 10, 0.045, 0.015, 0.011);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_still_tank_2d),
        cmocka_unit_test(test_still_tank_3d),
        cmocka_unit_test(test_rows_every_step),
        cmocka_unit_test(test_rows_at_their_interval),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
