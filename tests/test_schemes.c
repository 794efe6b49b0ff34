/* Integration: the schemes with shifting (delta-plus, delta-ALE, delta-plus-ALE of Table 1)
 * on a short SAP heave run (N = 20, 0.1 s): they run, and the total mass stays exact with
 * variable masses (Eq. 3 with eta = 1: the mass fluxes between fluid particles are
 * antisymmetric pair terms, walls exchange none), |mass_err| < 1e-12 (round-off of the sums
 * over 3440 particles and ~700 steps is ~1e-14). */
#include "app/simulation.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "check.h"
#include "table.h"
#include "run_case.h"

static const char sap_case[] = "[case]\nname = sap\ndim = 2\nt_end = 0.1\n"
                               "[tank]\nlength = 0.1172\nheight = 0.0272\n"
                               "[liquid]\nheight = 0.0136\n"
                               "[fluid]\nviscosity = 1.0e-5\n"
                               "[motion]\ntype = heave\namplitude = 0.0043\n"
                               "period = 0.07692307692307693\n"
                               "[numerics]\nresolution = 20\nsound_speed = 10\ndensity_bound = 0.5\n"
                               "[output]\ntimeseries_every = 0.005\n";

static void run_scheme(const char *scheme)
{
    char set[64], dir[64];
    snprintf(set, sizeof set, "model.scheme=%s", scheme);
    const char *overrides[] = {set};
    table t;
    run_case_text(sap_case, overrides, 1, dir, &t);
    const double *mass_err = table_column(&t, "mass_err"), *eta = table_column(&t, "eta");
    double worst = 0.0;
    for (size_t r = 0; r < t.n_rows; r++) worst = fmax(worst, fabs(mass_err[r]));
    printf("%s: %zu rows, max |mass_err| = %.2e, eta at the end %g\n", scheme, t.n_rows, worst,
           eta[t.n_rows - 1]);
    assert_true(worst < 1e-12);
    if (!strcmp(scheme, "delta-ale")) assert_true(eta[t.n_rows - 1] == 1.0);
    table_free(&t);
}

static void test_delta_plus(void **state)
{
    (void)state;
    run_scheme("delta-plus");
}

static void test_delta_ale(void **state)
{
    (void)state;
    run_scheme("delta-ale");
}

static void test_delta_plus_ale(void **state)
{
    (void)state;
    run_scheme("delta-plus-ale");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_delta_plus),
        cmocka_unit_test(test_delta_ale),
        cmocka_unit_test(test_delta_plus_ale),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
