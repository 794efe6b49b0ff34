/* Integration: free sloshing in the INM tank (1 m long, H = 0.35 m, 2D, delta-SPH, N = 16).
 * A short sway (one period, A = 1 cm) excites the first mode; afterwards the liquid's centre
 * of mass oscillates with the first natural period, which linear theory gives as
 * T1 = 2 pi / sqrt(g k tanh(k H)), k = pi / L = 1.2651 s (theory §11, paper Fig. 6). The wave
 * is small (A/L = 1 %), so the nonlinear shift of the period is well below 0.1 %; 1 % bounds
 * the discretisation error at this coarse N (measured: 0.3 %). This checks the dynamics end
 * to end: pressure, gravity, walls, the moving-frame force and the time integration. */
#include "app/simulation.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <cmocka.h>

#include "check.h"
#include "table.h"
#include "run_case.h"

static const char free_sloshing_case[] = "[case]\nname = free-sloshing\ndim = 2\nt_end = 6.6\n"
                                         "[tank]\nlength = 1.0\nheight = 1.0\n"
                                         "[liquid]\nheight = 0.35\n"
                                         "[motion]\ntype = sway\namplitude = 0.01\n"
                                         "period = 1.2651\nduration = 1.2651\n"
                                         "[model]\nscheme = delta\n"
                                         "[numerics]\nresolution = 16\nsound_speed = 20\n"
                                         "[output]\ntimeseries_every = 0.01\n";

static void test_first_mode_period(void **state)
{
    (void)state;
    char dir[64];
    table t;
    run_case_text(free_sloshing_case, NULL, 0, dir, &t);
    const double *time = table_column(&t, "t"), *com_x = table_column(&t, "com_x");
    /* upward zero crossings of com_x about its mean, after the forcing has stopped */
    double mean = 0.0;
    size_t count = 0;
    for (size_t r = 0; r < t.n_rows; r++)
        if (time[r] > 1.5) mean += com_x[r], count++;
    mean /= (double)count;
    double first = NAN, last = NAN;
    int crossings = 0;
    for (size_t r = 1; r < t.n_rows; r++) {
        double a = com_x[r - 1] - mean, b = com_x[r] - mean;
        if (time[r - 1] < 1.5 || !(a < 0.0 && b >= 0.0)) continue;
        double tc = time[r - 1] + (time[r] - time[r - 1]) * (-a) / (b - a);
        if (crossings++ == 0) first = tc;
        last = tc;
    }
    assert_true(crossings >= 4);
    double period = (last - first) / (crossings - 1);
    double k = M_PI / 1.0, t1 = 2.0 * M_PI / sqrt(9.81 * k * tanh(k * 0.35));
    printf("free sloshing: period %.4f s over %d cycles, linear theory %.4f s (%.2f %%)\n", period,
           crossings - 1, t1, 100.0 * (period / t1 - 1.0));
    assert_close(t1, 1.2651, 1e-4);
    assert_close(period, t1, 0.01 * t1);
    table_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_first_mode_period)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
