/* Integration: Standard SPH on a short SAP heave run (paper sec. 4.1, 5.1.1) at low
 * resolution: Re = 494 (nu = 1e-5), no surface tension, A = 4.3 mm, f = 13 Hz, c0 = 10 m/s,
 * N = 20, 0.5 s (6.5 periods). The paper (sec. 5.1.1, Figs. 7, 10): Standard SPH keeps
 * |eps_V1| below 1 %, since its continuity equation is the time derivative of Eq. (11)
 * (Eqs. 13, 14). Asserted at every time-series row. */
#include "app/simulation.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <cmocka.h>

#include "check.h"
#include "table.h"
#include "run_case.h"

static const char sap_case[] =
    "[case]\nname = sap-standard\ndim = 2\nt_end = 0.5\n"
    "[tank]\nlength = 0.1172\nheight = 0.0272\n"
    "[liquid]\nheight = 0.0136\n"
    "[fluid]\nviscosity = 1.0e-5\n"
    "[motion]\ntype = heave\namplitude = 0.0043\n"
    "period = 0.07692307692307693\n"
    "[model]\nscheme = standard\nedbc = false\n"
    "[numerics]\nresolution = 20\nsound_speed = 10\ndensity_bound = 0.5\n"
    "[output]\ntimeseries_every = 0.005\n";

static void test_standard_sph_keeps_volume(void **state)
{
    (void)state;
    char dir[64];
    table t;
    run_case_text(sap_case, NULL, 0, dir, &t);
    const double *eps = table_column(&t, "eps_v1"), *time = table_column(&t, "t");
    const double *n_free = table_column(&t, "n_free_surface");
    double worst = 0.0;
    for (size_t r = 0; r < t.n_rows; r++) {
        assert_false(isnan(eps[r]));
        worst = fmax(worst, fabs(eps[r]));
    }
    printf("SAP, Standard SPH, N = 20, %zu rows to t = %g s: max |eps_V1| = %.3g %%, final %.3g "
           "%%, free-surface particles at the end %g\n",
           t.n_rows, time[t.n_rows - 1], 100.0 * worst, 100.0 * eps[t.n_rows - 1],
           n_free[t.n_rows - 1]);
    assert_close(time[t.n_rows - 1], 0.5, 1e-12);
    assert_true(worst < 0.01);
    table_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_standard_sph_keeps_volume)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
