/* Integration: the five schemes of Table 1 on a short SAP heave run (paper sec. 5.1.1 at
 * N = 20, 0.4 s = 5.2 periods; case as cases/sap.ini). One ctest entry per scheme:
 * `test_schemes SCHEME`; `test_schemes switch` is the eta switch test.
 *
 * Every scheme runs to the end and keeps the total mass exact: |mass_err| < 1e-12 at every
 * row. With variable masses (eta = 1, Eq. 3) the mass fluxes between fluid particles are
 * antisymmetric pair terms and walls exchange none, so only round-off remains: ~1e-14 for
 * sums over 3440 particles and ~2500 steps.
 *
 * The switch (theory §8): delta-plus-ALE with eta_threshold = 0.002 must switch at least once
 * and keep max |eps_v1| < 0.006, three times the threshold (the figure): eps_v1
 * oscillates within each period by about 0.2 % at this resolution, so it passes the
 * threshold before the switch turns it.
 *
 * The adaptive control (`test_schemes adaptive`, eta_control.h) against the paper's switch on
 * the same SAP case run to 0.8 s (10.4 periods) at the paper's threshold, 0.01: the adaptive
 * control must keep max |eps_v1| below the switch's with no more regime changes (the issue's
 * requirement), and the mass exact with eta between 0 and 1. At N = 20 the switch turns
 * eta to 1 at 0.70 s and eps_v1 reaches +1.37 % by 0.79 s (+1.55 % at 0.875 s); the
 * adaptive control ends its eta = 0 regime at 0.46 s and stays within 0.43 %
 * (docs/validation.md). 0.8 s rather than the 1.0 s it ran before: the longest test of the
 * suite, and what it compares has happened by then. */
#include "app/simulation.h"

#include <omp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "check.h"
#include "table.h"
#include "run_case.h"

/* density_bound as in cases/sap.ini: impacts beyond Eq. (6) at the paper's c0 = 10 m/s; the
 * paper's schemes and controls alone, without vcsph's volume correction */
static const char sap_case[] = "[case]\nname = sap\ndim = 2\nt_end = 0.4\n"
                               "[tank]\nlength = 0.1172\nheight = 0.0272\n"
                               "[liquid]\nheight = 0.0136\n"
                               "[fluid]\nviscosity = 1.0e-5\n"
                               "[motion]\ntype = heave\namplitude = 0.0043\n"
                               "period = 0.07692307692307693\n"
                               "[model]\nedbc = with-eta0\nvolume_correction = none\n"
                               "[numerics]\nresolution = 20\nsound_speed = 10\n"
                               "density_bound = 0.5\n"
                               "[output]\ntimeseries_every = 0.005\n";

static const char *scheme_under_test;

static double max_abs(const double *x, size_t n)
{
    double worst = 0.0;
    for (size_t r = 0; r < n; r++) worst = fmax(worst, fabs(x[r]));
    return worst;
}

/* Rows of events.csv in dir whose event is `name`. */
static int count_events(const char *dir, const char *name)
{
    char path[128], line[512], field[64];
    snprintf(path, sizeof path, "%s/events.csv", dir);
    snprintf(field, sizeof field, ",%s,", name);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    int n = 0;
    while (fgets(line, sizeof line, f))
        if (strstr(line, field)) n++;
    fclose(f);
    return n;
}

static void test_scheme_runs_with_mass_exact(void **state)
{
    (void)state;
    const char *scheme = scheme_under_test;
    char set[64], dir[64];
    snprintf(set, sizeof set, "model.scheme=%s", scheme);
    const char *overrides[] = {set};
    table t;
    run_case_text(sap_case, overrides, 1, dir, &t);
    const double *eta = table_column(&t, "eta"), *eps = table_column(&t, "eps_v1");
    double worst = max_abs(table_column(&t, "mass_err"), t.n_rows);
    printf("%s: %zu rows to t = %g s, max |mass_err| = %.2e, max |eps_v1| = %.3f %%, "
           "eta at the end %g\n",
           scheme, t.n_rows, table_column(&t, "t")[t.n_rows - 1], worst,
           100.0 * max_abs(eps, t.n_rows), eta[t.n_rows - 1]);
    assert_close(table_column(&t, "t")[t.n_rows - 1], 0.4, 1e-12);
    assert_true(worst < 1e-12);
    /* Table 1: eta = 1 in delta-ALE, 0 in the schemes without variable masses */
    double expected_eta = !strcmp(scheme, "delta-ale") ? 1.0 : 0.0;
    if (strcmp(scheme, "delta-plus-ale"))
        for (size_t r = 0; r < t.n_rows; r++) assert_true(eta[r] == expected_eta);
    table_free(&t);
}

static void test_eta_switch(void **state)
{
    (void)state;
    const char *overrides[] = {"model.scheme=delta-plus-ale", "model.eta_threshold=0.002"};
    char dir[64];
    table t;
    run_case_text(sap_case, overrides, 2, dir, &t);
    const double *eta = table_column(&t, "eta"), *eps = table_column(&t, "eps_v1");
    int switches = count_events(dir, "eta_switch"), changes = 0;
    for (size_t r = 1; r < t.n_rows; r++) changes += eta[r] != eta[r - 1];
    double worst = max_abs(eps, t.n_rows);
    printf("switch: %d eta switches (%d seen in the time series), max |eps_v1| = %.3f %%\n",
           switches, changes, 100.0 * worst);
    assert_true(switches >= 1);
    assert_true(changes >= 1 && changes <= switches);
    assert_true(worst < 0.006);
    table_free(&t);
}

/* What test_adaptive_against_switch reads off one control's run. */
typedef struct {
    int switches;
    double worst, eta_min, eta_max, mass, t_last;
} control_result;

static control_result run_control(const char *control)
{
    const char *overrides[] = {"model.scheme=delta-plus-ale", "model.eta_threshold=0.01",
                               "case.t_end=0.8", control};
    char dir[64];
    table t;
    run_case_text(sap_case, overrides, 4, dir, &t);
    control_result r = {count_events(dir, "eta_switch"),
                        max_abs(table_column(&t, "eps_v1"), t.n_rows),
                        1.0,
                        0.0,
                        max_abs(table_column(&t, "mass_err"), t.n_rows),
                        table_column(&t, "t")[t.n_rows - 1]};
    const double *eta = table_column(&t, "eta");
    for (size_t row = 0; row < t.n_rows; row++) {
        r.eta_min = fmin(r.eta_min, eta[row]);
        r.eta_max = fmax(r.eta_max, eta[row]);
    }
    table_free(&t);
    return r;
}

/* The two controls run at once, one thread each (one in a child process): on the 2 cores
 * that this test holds, that is faster than one after the other on two threads. */
static void test_adaptive_against_switch(void **state)
{
    (void)state;
    const char *controls[2] = {"model.eta_control=threshold", "model.eta_control=adaptive"};
    control_result r[2];
    int link[2];
    assert_int_equal(pipe(link), 0);
    fflush(NULL);
    pid_t child = fork();
    assert_true(child >= 0);
    omp_set_num_threads(1);
    if (child == 0) {
        close(link[0]);
        control_result mine = run_control(controls[1]);
        ssize_t n = write(link[1], &mine, sizeof mine);
        run_case_remove_folders(); /* _exit skips atexit */
        _exit(n == (ssize_t)sizeof mine ? 0 : 1);
    }
    close(link[1]);
    r[0] = run_control(controls[0]);
    ssize_t n = read(link[0], &r[1], sizeof r[1]);
    close(link[0]);
    int status;
    assert_int_equal(waitpid(child, &status, 0), child);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    assert_int_equal(n, (ssize_t)sizeof r[1]);
    for (int k = 0; k < 2; k++) {
        printf("%s: %d regime changes, max |eps_v1| %.3f %%, eta in [%g, %g], "
               "max |mass_err| %.1e\n",
               controls[k] + 18, r[k].switches, 100.0 * r[k].worst, r[k].eta_min, r[k].eta_max,
               r[k].mass);
        assert_close(r[k].t_last, 0.8, 1e-12);
        assert_true(r[k].mass < 1e-12);
        assert_true(r[k].eta_min >= 0.0 && r[k].eta_max <= 1.0);
    }
    assert_true(r[1].switches <= r[0].switches);
    assert_true(r[1].worst < r[0].worst);
}

int main(int argc, char **argv)
{
    static const char *const schemes[] = {"standard", "delta", "delta-plus", "delta-ale",
                                          "delta-plus-ale"};
    const char *what = argc > 1 ? argv[1] : "";
    if (!strcmp(what, "switch")) {
        const struct CMUnitTest tests[] = {cmocka_unit_test(test_eta_switch)};
        return cmocka_run_group_tests(tests, NULL, NULL);
    }
    if (!strcmp(what, "adaptive")) {
        const struct CMUnitTest tests[] = {cmocka_unit_test(test_adaptive_against_switch)};
        return cmocka_run_group_tests(tests, NULL, NULL);
    }
    for (size_t s = 0; s < sizeof schemes / sizeof schemes[0]; s++)
        if (!strcmp(what, schemes[s])) {
            scheme_under_test = schemes[s];
            const struct CMUnitTest tests[] = {cmocka_unit_test(test_scheme_runs_with_mass_exact)};
            return cmocka_run_group_tests(tests, NULL, NULL);
        }
    fprintf(stderr, "usage: test_schemes standard|delta|delta-plus|delta-ale|delta-plus-ale|switch|"
                    "adaptive\n");
    return 2;
}
