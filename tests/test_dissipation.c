/* dissipation.csv (theory §10): the dissipated energy per excitation period.
 * - A tank at rest without gravity is an exact equilibrium: every period dissipates 0 within
 *   round-off, which checks the bookkeeping (work_in, the stored energies, the period ends).
 * - A standing wave decaying freely in a free-slip tank loses its energy as exp(-4 nu k^2 t)
 *   (linear theory, Lamb 1932 sec. 348, the free-surface boundary layer neglected): the
 *   per-period losses e_k fall by exp(-4 nu k^2 T) from one period to the next. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "check.h"
#include "table.h"
#include "run_case.h"

#include <math.h>

static void read_dissipation(const char *dir, table *d)
{
    char path[128];
    snprintf(path, sizeof path, "%s/dissipation.csv", dir);
    assert_int_equal(table_read(d, path), 0);
}

static const char rest_case[] = "[case]\nname = rest\nt_end = 1.0\n"
                                "[tank]\nlength = 1.0\nheight = 1.0\n"
                                "[liquid]\nheight = 0.35\n"
                                "[fluid]\ngravity = 0.0\n"
                                "[motion]\ntype = sway\namplitude = 0.0\nperiod = 0.25\n"
                                "[model]\nscheme = delta-plus-ale\nedbc = true\n"
                                "[numerics]\nresolution = 12\nsound_speed = 10.0\n"
                                "[output]\ntimeseries_every = 0.05\n";

static void test_rest_dissipates_nothing(void **state)
{
    (void)state;
    char dir[64];
    table ts, d;
    run_case_text(rest_case, NULL, 0, dir, &ts);
    read_dissipation(dir, &d);
    assert_int_equal(d.n_rows, 4); /* 1 s of 0.25 s periods, each complete */
    const double *e = table_column(&d, "e_diss"), *t_end = table_column(&d, "t_end");
    /* round-off of the largest energy in play: the internal energy of a 1 % compression,
       M c0^2 1e-4 / 2, times 1e-12 */
    double round_off = 1e-12 * 350.0 * 100.0 * 1e-4;
    for (size_t k = 0; k < d.n_rows; k++) {
        printf("period %zu ending at %g s: e_diss = %.3g J\n", k + 1, t_end[k], e[k]);
        assert_close(t_end[k], 0.25 * (double)(k + 1), 1e-12);
        assert_close(e[k], 0.0, round_off);
    }
    table_free(&d);
    table_free(&ts);
}

/* The first sloshing mode of a 1 m tank with 0.5 m of liquid, k = pi/L, excited by two
 * periods of sway at its own period, then left alone. nu = 0.01 m^2/s: Re = sqrt(gH) H / nu
 * = 110, nu k^2 / omega = 0.019 (weak damping, where the linear rate holds). */
static void test_standing_wave_decay(void **state)
{
    (void)state;
    const double nu = 0.01, length = 1.0, depth = 0.5, g = 9.81;
    double k = M_PI / length, omega = sqrt(g * k * tanh(k * depth)), period = 2.0 * M_PI / omega;
    char text[1024];
    snprintf(text, sizeof text,
             "[case]\nname = wave\nt_end = %.17g\n[tank]\nlength = %g\nheight = 1.0\n"
             "[liquid]\nheight = %g\n[fluid]\nviscosity = %g\n"
             "[motion]\ntype = sway\namplitude = 0.004\nperiod = %.17g\nduration = %.17g\n"
             "[model]\nscheme = delta\nedbc = false\nles = false\nwall = free-slip\n"
             "[numerics]\nresolution = 20\n[output]\ntimeseries_every = 0.05\n",
             8.0 * period, length, depth, nu, period, 2.0 * period);
    char dir[64];
    table ts, d;
    run_case_text(text, NULL, 0, dir, &ts);
    read_dissipation(dir, &d);
    assert_int_equal(d.n_rows, 8);
    const double *e = table_column(&d, "e_diss");
    /* least-squares slope of ln e_k over the free periods 4..8 (period 3 still carries the
       faster decay of the higher modes the forcing excited) */
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (size_t j = 3; j < d.n_rows; j++) {
        assert_true(e[j] > 0.0);
        double x = (double)j * period, y = log(e[j]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        n++;
    }
    double rate = -(n * sxy - sx * sy) / (n * sxx - sx * sx), theory = 4.0 * nu * k * k;
    printf("energy decay rate %.4f 1/s, linear theory 4 nu k^2 = %.4f 1/s (%+.1f %%)\n", rate,
           theory, 100.0 * (rate / theory - 1.0));
    assert_close(rate / theory, 1.0, 0.2); /* the 20 % */
    table_free(&d);
    table_free(&ts);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rest_dissipates_nothing),
        cmocka_unit_test(test_standing_wave_decay),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
