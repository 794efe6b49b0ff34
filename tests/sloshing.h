/* sloshing: the period of a free sloshing oscillation from a time series, for the tests that
 * compare it with linear theory or between runs. Include after <cmocka.h>, "table.h" and
 * "run_case.h". */
#ifndef VCSPH_TEST_SLOSHING_H
#define VCSPH_TEST_SLOSHING_H

#include <math.h>

/* Free sloshing in the INM tank (1 m long, H = 0.35 m, 2D, delta-SPH, N = 16): one period of
 * sway, A = 1 cm, at the first natural period excites the first mode, which then rings. */
static const char free_sloshing_case[] = "[case]\nname = free-sloshing\ndim = 2\nt_end = 6.6\n"
                                         "[tank]\nlength = 1.0\nheight = 1.0\n"
                                         "[liquid]\nheight = 0.35\n"
                                         "[motion]\ntype = sway\namplitude = 0.01\n"
                                         "period = 1.2651\nduration = 1.2651\n"
                                         "[model]\nscheme = delta\n"
                                         "[numerics]\nresolution = 16\nsound_speed = 20\n"
                                         "[output]\ntimeseries_every = 0.01\n";

/* free_sloshing_case's first natural period by linear theory (theory §11):
 * T1 = 2 pi / sqrt(g k tanh(k H)), k = pi / L = 1.2651 s. */
static inline double free_sloshing_t1(void)
{
    double k = M_PI / 1.0;
    return 2.0 * M_PI / sqrt(9.81 * k * tanh(k * 0.35));
}

/* The mean spacing of the upward crossings of com_x through its mean, over the rows after
 * `after` (s, once the forcing has stopped); the number of whole cycles in *cycles. */
static inline double com_x_period(const table *t, double after, int *cycles)
{
    const double *time = table_column(t, "t"), *com_x = table_column(t, "com_x");
    double mean = 0.0, first = NAN, last = NAN;
    size_t count = 0;
    for (size_t r = 0; r < t->n_rows; r++)
        if (time[r] > after) mean += com_x[r], count++;
    mean /= (double)count;
    int crossings = 0;
    for (size_t r = 1; r < t->n_rows; r++) {
        double a = com_x[r - 1] - mean, b = com_x[r] - mean;
        if (time[r - 1] < after || !(a < 0.0 && b >= 0.0)) continue;
        double tc = time[r - 1] + (time[r] - time[r - 1]) * (-a) / (b - a);
        if (crossings++ == 0) first = tc;
        last = tc;
    }
    *cycles = crossings - 1;
    return (last - first) / (crossings - 1);
}

/* free_sloshing_case with the --set style overrides, run: the period of com_x after the
 * forcing (t > 1.5 s) over at least min_cycles cycles, printed beside linear theory's T1 with
 * `label`. */
static inline double free_sloshing_period(const char *const *overrides, int n_overrides,
                                          int min_cycles, const char *label)
{
    char dir[64];
    table t;
    run_case_text(free_sloshing_case, overrides, n_overrides, dir, &t);
    int cycles;
    double period = com_x_period(&t, 1.5, &cycles), t1 = free_sloshing_t1();
    assert_true(cycles >= min_cycles);
    printf("%s: period %.4f s over %d cycles, linear theory %.4f s (%+.2f %%)\n", label, period,
           cycles, t1, 100.0 * (period / t1 - 1.0));
    table_free(&t);
    return period;
}

#endif
