/* Tests of the rotating tank frame (docs/case-file.md [motion], src/boundary/frame.h) through
 * whole runs: a centrifuge whose free surface must become the circle of constant centrifugal
 * potential with the liquid at rest in the tank, the energy budget of a rolling tank, and a
 * small roll against linear sloshing theory. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "check.h"
#include "table.h"
#include "run_case.h"
#include "linear_sloshing.h"

#define PI 3.14159265358979323846

/* ---- rigid rotation ------------------------------------------------------------------------ */

/* A 0.2 x 0.1 m tank spins at W = 5 rad/s about an axis 0.3 m above its bottom centre, without
 * gravity (a centrifuge: in 2D the only steady rotation with a free surface). The table's
 * linear roll angle is a constant angular velocity. The liquid, 0.04 m deep and very viscous
 * (nu = 1e-2 m^2/s, so that the sloshing the start excites decays at 2 nu k^2 ~ 5 /s), is
 * flung away from the axis: at rest in the tank, its free surface is the circle
 * |x - c| = r0 of constant centrifugal potential W^2 r^2 / 2, with r0 set by the area. At
 * 1 s the gauges read it within 0.21 dr (measured, at x = 0.19 m), bound 0.5 dr (2.4x), and
 * the largest speed is 0.24 % of W r0 (measured), bound 0.6 % (2.5x). */
static const char centrifuge[] =
    "[case]\nname = centrifuge\nt_end = 1.0\n[tank]\nlength = 0.2\nheight = 0.1\n"
    "[liquid]\nheight = 0.04\n[fluid]\nviscosity = 1.0e-2\ngravity = 0.0\n"
    "[numerics]\nresolution = 10\nsound_speed = 16\n"
    "[probes]\ngauges = 0.01, 0.05, 0.1, 0.15, 0.19\n[output]\ntimeseries_every = 0.05\n"
    "[motion]\ntype = table\ncenter = 0.1 0.3\n"; /* file = the table, appended */
enum { GAUGES = 5 };
static const double gauge_x[GAUGES] = {0.01, 0.05, 0.1, 0.15, 0.19};
#define SPIN 5.0

/* Area of {0 <= x <= L, y below the circle of radius r0 about (L/2, yc)}:
 * L yc - int_{-L/2}^{L/2} sqrt(r0^2 - u^2) du. */
static double area_below_circle(double r0, double L, double yc)
{
    double a = 0.5 * L;
    double chord = a * sqrt(r0 * r0 - a * a) + r0 * r0 * asin(a / r0);
    return L * yc - chord;
}

static void test_centrifuge_surface_is_a_circle(void **state)
{
    (void)state;
    const double L = 0.2, yc = 0.3, area = L * 0.04, dr = 0.04 / 10;
    /* the table: roll = W t over 4 s */
    char dir[64], table_path[128], text[2048];
    run_case_folder(dir);
    snprintf(table_path, sizeof table_path, "%s/spin.csv", dir);
    FILE *f = fopen(table_path, "w");
    assert_non_null(f);
    fputs("t,roll\n", f);
    for (int k = 0; k <= 8; k++) fprintf(f, "%.17g,%.17g\n", 0.5 * k, SPIN * 0.5 * k);
    assert_int_equal(fclose(f), 0);
    snprintf(text, sizeof text, "%sfile = %s\n", centrifuge, table_path);
    /* the radius that holds the liquid's area, by bisection (the area falls as r0 grows) */
    double lo = yc - 0.1, hi = yc;
    for (int k = 0; k < 100; k++) {
        double mid = 0.5 * (lo + hi);
        if (area_below_circle(mid, L, yc) > area)
            lo = mid;
        else
            hi = mid;
    }
    const double r0 = 0.5 * (lo + hi);
    char run_dir[64], path[128];
    table series, probes;
    run_case_text(text, NULL, 0, run_dir, &series);
    snprintf(path, sizeof path, "%s/probes.csv", run_dir);
    assert_int_equal(table_read(&probes, path), 0);
    size_t last = probes.n_rows - 1;
    for (int g = 0; g < GAUGES; g++) {
        char name[16];
        snprintf(name, sizeof name, "gauge_%d", g + 1);
        double u = gauge_x[g] - 0.5 * L, depth = table_column(&probes, name)[last];
        double expected = yc - sqrt(r0 * r0 - u * u);
        print_message("x = %.2f m: depth %.5f m, circle %.5f m (%+.3f dr)\n", gauge_x[g], depth,
                      expected, (depth - expected) / dr);
        assert_close(depth, expected, 0.5 * dr);
    }
    /* at rest in the tank: the largest speed a small fraction of the walls' W r0 */
    double umax = table_column(&series, "umax")[series.n_rows - 1];
    print_message("u_max = %.3g m/s = %.3f %% of W r0\n", umax, 100.0 * umax / (SPIN * r0));
    assert_true(umax < 0.006 * SPIN * r0);
    table_free(&series);
    table_free(&probes);
}

/* ---- the energy budget of a rolling tank ---------------------------------------------------- */

/* A half-degree roll about the bottom centre at T = 1.5 s, away from the first sloshing period
 * (0.88 s), three periods: the liquid dissipates little, so that the budget's own error would
 * show. The tank frame's budget counts the work of its turning gravity and of the Euler and
 * centrifugal forces (src/scheme/integrate.c); every period's e_diss must be >= 0 within the
 * budget's accuracy. With delta-SPH the budget is the forces' work as integrated, accurate to
 * the time integration: on this run e_diss moves by at most 1.7e-5 J = 2e-3 dW per period when
 * the step is cut to 0.58 of itself (numerics.cfl = 0.75; docs/energy.md), while the third
 * period dissipates only 7e-6 J. Shifting and the geometric correction move particles without
 * a force, outside the budget, in a rolling tank as in a swaying one (docs/energy.md), hence
 * delta-SPH here. */
static void test_rolling_budget_dissipates(void **state)
{
    (void)state;
    char dir[64], path[128];
    table series, dissipation;
    run_case_text("[case]\nname = roll\nt_end = 4.5\n[tank]\nlength = 0.4\nheight = 0.3\n"
                  "[liquid]\nheight = 0.1\n[motion]\ntype = roll\nangle = 0.008726646259971648\n"
                  "period = 1.5\n[model]\nscheme = delta\n[numerics]\nresolution = 10\n"
                  "[output]\ntimeseries_every = 0.01\n",
                  NULL, 0, dir, &series);
    snprintf(path, sizeof path, "%s/dissipation.csv", dir);
    assert_int_equal(table_read(&dissipation, path), 0);
    assert_int_equal(dissipation.n_rows, 3);
    const double *norm = table_column(&dissipation, "power_norm");
    for (size_t k = 0; k < dissipation.n_rows; k++) {
        print_message("period %zu: P/dW = %.4g\n", k + 1, norm[k]);
        assert_true(norm[k] >= -2e-3); /* e_diss / dW, the period's P/dW */
    }
    assert_true(norm[0] > 0.01); /* the roll does drive the liquid */
    table_free(&series);
    table_free(&dissipation);
}

/* ---- the linear roll response ------------------------------------------------------------- */

/* The INM tank (1 m, 0.35 m of water) rolls by half a degree about its bottom centre at
 * T = 2 s, away from the first sloshing period (1.27 s), starting tilted and at rest
 * (phase pi/2: no initial rate). The gauge 5 cm from the left wall against the linear
 * solution (linear_sloshing.h): its amplitude at the forcing frequency (the Fourier
 * coefficient over the two periods, the same projection of both signals) and its largest
 * excursion (the nonlinearity is (amplitude / depth) = 3 %, the numerical damping of the free
 * modes the start excites is what the resolution adds). Measured at N = 16, the test's: 0.981
 * and 0.993, bounds 5.5 % and 2 % (2.9x); elsewhere 0.963 and 0.972 at N = 20, 0.996 and 0.910
 * over 8 s at N = 40 (docs/roll.md). */
static void test_linear_roll_response(void **state)
{
    (void)state;
    const double L = 1.0, h = 0.35, angle = 0.5 * PI / 180.0, T = 2.0, w = 2.0 * PI / T;
    char dir[64], path[128], text[1024];
    snprintf(text, sizeof text,
             "[case]\nname = roll\nt_end = 4.0\n[tank]\nlength = 1.0\nheight = 1.0\n"
             "[liquid]\nheight = 0.35\n[motion]\ntype = roll\nangle = %.17g\nperiod = 2.0\n"
             "phase = %.17g\ncenter = 0.5 0.0\n[numerics]\nresolution = 16\n"
             "[probes]\ngauges = 0.05\n[output]\ntimeseries_every = 0.01\n",
             angle, 0.5 * PI);
    const linear_tank linear = {L, h, 9.81, 0.0, angle, w, 0.5 * PI, -h}; /* docs/roll.md */
    table series, probes;
    run_case_text(text, NULL, 0, dir, &series);
    snprintf(path, sizeof path, "%s/probes.csv", dir);
    assert_int_equal(table_read(&probes, path), 0);
    const double *t = table_column(&probes, "t"), *gauge = table_column(&probes, "gauge_1");
    double c[2] = {0, 0}, s[2] = {0, 0}, most[2] = {0, 0};
    for (size_t k = 0; k + 1 < probes.n_rows; k++) { /* [0, 4 s): two whole periods */
        double eta[2] = {gauge[k] - gauge[0], linear_tank_elevation(&linear, 0.05, t[k])};
        for (int m = 0; m < 2; m++) {
            c[m] += eta[m] * cos(w * t[k]);
            s[m] += eta[m] * sin(w * t[k]);
            most[m] = fmax(most[m], fabs(eta[m]));
        }
    }
    double forced = hypot(c[0], s[0]) / hypot(c[1], s[1]), excursion = most[0] / most[1];
    print_message("forced amplitude / linear = %.4f, largest excursion / linear = %.4f "
                  "(linear: %.2f mm)\n",
                  forced, excursion, 1e3 * most[1]);
    assert_close(forced, 1.0, 0.055);
    assert_close(excursion, 1.0, 0.02);
    table_free(&series);
    table_free(&probes);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_centrifuge_surface_is_a_circle),
        cmocka_unit_test(test_rolling_budget_dissipates),
        cmocka_unit_test(test_linear_roll_response),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
