/* The vcsph command as a user meets it, continued from test_cli.c: warnings that let a run go
 * on (docs/checks.md), `vcsph volume` against the run's own time series, the graphical method
 * after a restart, and the version in every output. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/config.h"
#include "io/hdf5_attr.h"

#include "check.h"
#include "table.h"
#include "vcsph_child.h"
#include "cli_fixture.h"

/* ---- warnings: the run goes on (docs/checks.md) --------------------------------------------- */

typedef struct {
    const char *name;
    const char *set[6];    /* --set values after the base case */
    const char *expect[3]; /* substrings of the one warning line */
} warn_case;

static const warn_case warn_cases[] = {
    /* c0 = 2 m/s: hydrostatic +12 % at the bottom (within 0.2), but below Eq. (6)'s
     * 10 sqrt(g H) = 7.004 m/s (H = 0.05 m, a tank at rest) */
    {"warn_low_c0", {"numerics.sound_speed=2", NULL}, {"numerics.sound_speed", "Eq. (6)", "7.004"}},
    /* 3D, 2 cm wide at dr = 6.25 mm: 3 particles across z */
    {"warn_few_particles",
     {"case.dim=3", "tank.width=0.02", NULL},
     {"tank.width", "3 particles across z", "fewer than 8"}},
    /* a sway of 0.5 m in a 0.2 m long tank, slow enough (T = 100 s) to warn of nothing else */
    {"warn_large_amplitude",
     {"motion.type=sway", "motion.amplitude=0.5", "motion.period=100", NULL},
     {"motion.amplitude", "+-0.5 m", "unit error"}},
    /* 4 "degrees" of roll written as 4 rad, slow enough to warn of nothing else */
    {"warn_large_angle",
     {"motion.type=roll", "motion.angle=4", "motion.period=100", NULL},
     {"motion.angle", "229.2 degrees", "unit error"}},
};
#define N_WARN (sizeof warn_cases / sizeof warn_cases[0])

/* `vcsph check` and a short `vcsph run` (t_end = 5 ms) of a warn_case: exit 0, and
 * exactly one line on stderr, "vcsph: warning: ..." naming the key; check still prints the
 * derived numbers and the estimates. */
static void test_warning(void **state)
{
    fixture *fx = *state;
    const warn_case *wc = fx->row;
    write_file(fx, "warn.ini", BASE_CASE);
    {
        for (int run = 0; run < 2; run++) {
            const char *args[24] = {run ? "run" : "check", "warn.ini"};
            int n = 2;
            if (run) {
                static const char *const run_args[] = {"-o", "res", "--quiet", "--set",
                                                       "case.t_end=0.005"};
                for (size_t k = 0; k < 5; k++) args[n++] = run_args[k];
            }
            for (int k = 0; wc->set[k]; k++) {
                args[n++] = "--set";
                args[n++] = wc->set[k];
            }
            args[n] = NULL;
            int rc = run_vcsph(fx, args);
            char *out = read_file(fx, "stdout.txt"), *err = read_file(fx, "stderr.txt");
            if (rc) print_error("%s (%s): stderr:\n%s", wc->name, args[0], err);
            assert_int_equal(rc, 0);
            if (count_lines(err) != 1 || strncmp(err, "vcsph: warning: ", 16))
                fail_msg("%s (%s): expected one warning line, got:\n%s", wc->name, args[0], err);
            for (int k = 0; k < 3 && wc->expect[k]; k++) assert_contains(err, wc->expect[k]);
            if (!run) {
                assert_contains(out, "base: valid");
                assert_contains(out, "memory estimate");
                assert_contains(out, "wall time est.");
            }
            free(out);
            free(err);
        }
    }
    /* the run's log has the warning and the estimates too */
    char *log = read_file(fx, "res/log.txt");
    assert_contains(log, "vcsph: warning: ");
    assert_contains(log, wc->expect[0]);
    assert_contains(log, "memory estimate");
    assert_contains(log, "wall time estimate");
    free(log);
}

/* `vcsph volume` on the snapshots of a run with output.graphical = true prints, for each
 * snapshot, the eps_v1 and eps_gm of the time-series row of the same time: the same
 * definitions computed from the same state (round-off of the printed digits only). eps_gm
 * is Eq. (15)'s ratio of the pixel count to the initial configuration's: exactly 0 at t = 0.
 * Its free-surface count is the row's too; the packing's own figures: test_volume. */
static void test_volume_command_matches_series(void **state)
{
    fixture *fx = *state;
    write_file(fx, "tiny.ini", TINY_CASE);
    int rc = run_vcsph(
        fx, (const char *const[]){"run", "tiny.ini", "--set", "output.graphical=true", "--set",
                                  "output.snapshot_every=0.01", "-o", "res", "--quiet", NULL});
    assert_int_equal(rc, 0);
    rc = run_vcsph(fx, (const char *const[]){"volume", "res/snapshots/000000.h5",
                                             "res/snapshots/000003.h5", "res/snapshots/000005.h5",
                                             NULL});
    char *out = read_file(fx, "stdout.txt");
    assert_int_equal(rc, 0);
    char path[512];
    path_in(fx, "res/timeseries.csv", path, sizeof path);
    table ts;
    assert_int_equal(table_read(&ts, path), 0);
    const double *t = table_column(&ts, "t"), *eps_v1 = table_column(&ts, "eps_v1");
    const double *eps_gm = table_column(&ts, "eps_gm");
    const double *n_free = table_column(&ts, "n_free_surface");
    const double *eps_fs = table_column(&ts, "eps_fs");
    const char header[] = "t,eps_v1,eps_gm,n_free_surface,n_clumped,nearest_free,nearest_band,"
                          "nearest_interior,eps_fs\n";
    assert_true(strncmp(out, header, strlen(header)) == 0);
    assert_true(t[0] == 0.0 && eps_gm[0] == 0.0);
    int rows = 0;
    for (const char *line = next_line(out); line && *line; line = next_line(line)) {
        double tv, e1, egm, nearest[3], efs;
        long free_surface, clumped;
        assert_int_equal(sscanf(line, "%lf,%lf,%lf,%ld,%ld,%lf,%lf,%lf,%lf", &tv, &e1, &egm,
                                &free_surface, &clumped, &nearest[0], &nearest[1], &nearest[2],
                                &efs),
                         9);
        assert_true(clumped >= 0 && clumped <= free_surface);
        /* the tiny case's lattice barely moves in 0.05 s: every nearest neighbour near dr */
        for (int c = 0; c < 3; c++) assert_true(nearest[c] > 0.8 && nearest[c] < 1.2);
        size_t r = 0;
        while (r < ts.n_rows && fabs(t[r] - tv) > 1e-12) r++;
        if (r == ts.n_rows) fail_msg("no time-series row at t = %g", tv);
        assert_false(isnan(eps_gm[r]));
        assert_close(e1, eps_v1[r], 1e-12);
        assert_close(egm, eps_gm[r], 1e-12);
        assert_close(efs, eps_fs[r], 1e-12);
        /* the packing's free surface is the run's: the same count as the time series' */
        assert_close((double)free_surface, n_free[r], 0.0);
        rows++;
    }
    assert_int_equal(rows, 3);
    table_free(&ts);
    free(out);
    /* not a snapshot: exit 2 with a message */
    write_file(fx, "junk.h5", "not hdf5");
    assert_int_equal(run_vcsph(fx, (const char *const[]){"volume", "junk.h5", NULL}), 2);
}

/* A restart measures eps_gm against the initial lattice's count, as the run it continues:
 * a sloshing run stopped at 0.3 s (its last checkpoint, a period end where every run cuts its
 * step) and continued to 0.45 s writes the same eps_gm column, to the bit, as the same run
 * made in one go (its count by then differs from the initial one: a reference taken from the
 * restarted state would show). */
static void test_graphical_after_restart(void **state)
{
    fixture *fx = *state;
    char text[1024];
    snprintf(text, sizeof text, "%s[motion]\ntype = sway\namplitude = 0.02\nperiod = 0.3\n",
             TINY_CASE);
    write_file(fx, "slosh.ini", text);
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "--set", "case.t_end=0.3", "--set",
                                            "output.graphical=true", "--set",
                                            "output.checkpoint_every=1e-9", "-o", "stopped",
                                            "--quiet", NULL}),
        0);
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "--restart", "stopped/checkpoint.h5", "--set",
                                            "case.t_end=0.45", "--quiet", NULL}),
        0);
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "--set", "output.graphical=true",
                                            "--set", "case.t_end=0.45", "-o", "whole", "--quiet",
                                            NULL}),
        0);
    table a, b;
    char path[512];
    path_in(fx, "stopped/timeseries.csv", path, sizeof path);
    assert_int_equal(table_read(&a, path), 0);
    path_in(fx, "whole/timeseries.csv", path, sizeof path);
    assert_int_equal(table_read(&b, path), 0);
    assert_int_equal(a.n_rows, b.n_rows);
    const double *ga = table_column(&a, "eps_gm"), *gb = table_column(&b, "eps_gm");
    const double *t = table_column(&b, "t");
    assert_true(t[b.n_rows - 1] > 0.449);
    assert_true(gb[b.n_rows - 1] != 0.0);
    for (size_t r = 0; r < a.n_rows; r++) assert_true(ga[r] == gb[r]);
    table_free(&a);
    table_free(&b);
}

/* ---- the version ---------------------------------------------------------------------------- */

/* The attribute vcsph_version of the HDF5 file `name` in the fixture's folder (malloc'd) */
static char *version_attribute(const fixture *fx, const char *name)
{
    char path[512];
    path_in(fx, name, path, sizeof path);
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) fail_msg("cannot open %s", name);
    char *version = hdf5_attr_read_string(file, "vcsph_version");
    H5Fclose(file);
    if (!version) fail_msg("%s has no string attribute vcsph_version", name);
    return version;
}

/* `vcsph --version` prints "vcsph VERSION" (core/version.h); a run says the same VERSION on
 * the first line of log.txt and keeps it as the attribute vcsph_version of every snapshot and
 * of checkpoint.h5. */
static void test_version_in_outputs(void **state)
{
    fixture *fx = *state;
    assert_int_equal(run_vcsph(fx, (const char *const[]){"--version", NULL}), 0);
    char *out = read_file(fx, "stdout.txt");
    if (strncmp(out, "vcsph ", 6) != 0) fail_msg("--version printed '%s'", out);
    char *nl = strchr(out, '\n');
    assert_non_null(nl);
    assert_string_equal(nl + 1, ""); /* one line */
    *nl = '\0';
    const char *version = out + 6;
    assert_true(strlen(version) > 0);
    assert_null(strchr(version, ' '));

    write_file(fx, "tiny.ini", TINY_CASE);
    int rc = run_vcsph(fx, (const char *const[]){"run", "tiny.ini", "--set", "case.t_end=0.02",
                                                 "--set", "output.checkpoint_every=1e-9", "-o",
                                                 "res", "--quiet", NULL});
    if (rc) {
        char *err = read_file(fx, "stderr.txt");
        print_error("stderr:\n%s", err);
        free(err);
    }
    assert_int_equal(rc, 0);
    static const char *const files[] = {"res/snapshots/000000.h5", "res/snapshots/000001.h5",
                                        "res/checkpoint.h5"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        char *attr = version_attribute(fx, files[k]);
        if (strcmp(attr, version) != 0)
            fail_msg("%s: vcsph_version '%s', --version '%s'", files[k], attr, version);
        free(attr);
    }
    char *log = read_file(fx, "res/log.txt"), first[256];
    snprintf(first, sizeof first, "vcsph %s: tiny, 2D, ", version);
    if (strncmp(log, first, strlen(first)) != 0)
        fail_msg("log.txt does not begin with '%s':\n%.200s", first, log);
    free(log);
    free(out);
}

int main(void)
{
    struct CMUnitTest tests[3 + N_WARN];
    tests[0] = (struct CMUnitTest)cmocka_unit_test_setup_teardown(
        test_volume_command_matches_series, setup, teardown);
    tests[1] = (struct CMUnitTest)cmocka_unit_test_setup_teardown(test_graphical_after_restart,
                                                                  setup, teardown);
    tests[2] = (struct CMUnitTest)cmocka_unit_test_setup_teardown(test_version_in_outputs, setup,
                                                                  teardown);
    for (size_t k = 0; k < N_WARN; k++)
        tests[3 + k] = (struct CMUnitTest){warn_cases[k].name, test_warning, setup, teardown,
                                           (void *)&warn_cases[k]};
    return _cmocka_run_group_tests("test_cli_outputs", tests, 3 + N_WARN, NULL, NULL);
}
