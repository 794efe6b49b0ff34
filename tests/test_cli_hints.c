/* What the vcsph command tells a user to do next, and what it says when a restart would do
 * nothing or ignore an edit: the hints paste as printed, a finished run's restart says it is
 * complete, an edited case.ini is named, a motion table's columns are said, and the smaller
 * commands' messages (`vcsph volume`, `--help`). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "vcsph_child.h"
#include "cli_fixture.h"

/* The rest of the line of `text` that follows `marker`, into buf; fails when there is none. */
static void line_after(const char *text, const char *marker, char *buf, size_t size)
{
    const char *at = strstr(text, marker);
    if (!at) fail_msg("no \"%s\" in:\n%s", marker, text);
    at += strlen(marker);
    snprintf(buf, size, "%.*s", (int)strcspn(at, "\n"), at);
}

/* The last row of a CSV file of the fixture, its first field (the time) as text. */
static void last_time(const fixture *fx, const char *name, char *buf, size_t size)
{
    char *text = read_file(fx, name);
    size_t len = strlen(text);
    assert_true(len > 1);
    text[len - 1] = '\0';
    const char *row = strrchr(text, '\n');
    row = row ? row + 1 : text;
    snprintf(buf, size, "%.*s", (int)strcspn(row, ","), row);
    free(text);
}

/* The tiny run into res, with its terminal output kept. */
static void tiny_run(const fixture *fx)
{
    write_file(fx, "tiny.ini", TINY_CASE);
    int rc = run_vcsph(fx, (const char *const[]){"run", "tiny.ini", "-o", "res", NULL});
    assert_int_equal(rc, 0);
}

/* The hint at the end of a run, pasted into a shell as printed (LATER replaced by a time),
 * extends the run to that time. */
static void test_extend_hint_pastes(void **state)
{
    fixture *fx = *state;
    tiny_run(fx);
    char *out = read_file(fx, "stdout.txt");
    char hint[1024], command[2048];
    line_after(out, "extend with: ", hint, sizeof hint);
    free(out);
    char *later = strstr(hint, "LATER");
    assert_non_null(later);
    snprintf(later, sizeof hint - (size_t)(later - hint), "0.07");
    snprintf(command, sizeof command, "cd '%s' && %s --quiet", fx->dir, hint);
    int status = system(command);
    assert_true(WIFEXITED(status));
    if (WEXITSTATUS(status)) fail_msg("the pasted hint `%s` exited %d", hint, WEXITSTATUS(status));
    char t[64];
    last_time(fx, "res/timeseries.csv", t, sizeof t);
    assert_string_equal(t, "0.07");
}

/* A restart of a run at its t_end says that the run is complete and how to extend it, with
 * status 0, and leaves every file as it was. */
static void test_restart_of_a_finished_run(void **state)
{
    fixture *fx = *state;
    tiny_run(fx);
    char *series = read_file(fx, "res/timeseries.csv"), *log = read_file(fx, "res/log.txt");
    int rc = run_vcsph(fx, (const char *const[]){"run", "--restart", "res/checkpoint.h5", NULL});
    assert_int_equal(rc, 0);
    char *out = read_file(fx, "stdout.txt");
    assert_contains(out, "the run in res is complete");
    assert_contains(out, "case.t_end = 0.05 s; nothing to run");
    assert_contains(out, "Extend it with: " VCSPH_BINARY " run --restart res/checkpoint.h5 --set "
                         "case.t_end=LATER");
    char *series_after = read_file(fx, "res/timeseries.csv"),
         *log_after = read_file(fx, "res/log.txt");
    assert_string_equal(series, series_after);
    assert_string_equal(log, log_after);
    free(out);
    free(series);
    free(log);
    free(series_after);
    free(log_after);
}

/* A restart after an edit of the folder's case.ini runs the checkpoint's case, and says so on
 * the terminal and in log.txt; case.ini then holds the case that ran. */
static void test_edited_case_is_named(void **state)
{
    fixture *fx = *state;
    tiny_run(fx);
    char *text = read_file(fx, "res/case.ini");
    char *line = strstr(text, "\nresolution");
    assert_non_null(line);
    char *value = strchr(line, '=');
    assert_non_null(value);
    assert_true(strncmp(value, "= 8 ", 4) == 0);
    value[2] = '9';
    write_file(fx, "res/case.ini", text);
    free(text);
    int rc = run_vcsph(fx, (const char *const[]){"run", "--restart", "res/checkpoint.h5", "--set",
                                                 "case.t_end=0.06", NULL});
    assert_int_equal(rc, 0);
    char *err = read_file(fx, "stderr.txt"), *log = read_file(fx, "res/log.txt"),
         *after = read_file(fx, "res/case.ini");
    assert_contains(err, "res/case.ini had been edited since the run wrote it");
    assert_contains(log, "res/case.ini had been edited since the run wrote it");
    assert_contains(after, "\nresolution       = 8 ");
    assert_contains(after, "\nt_end            = 0.06 ");
    free(err);
    free(log);
    free(after);
}

/* A motion table without a header is read by position, its first row kept, and the log says
 * so; a header with a misspelt column is refused before anything is written. */
static void test_table_columns_are_said(void **state)
{
    fixture *fx = *state;
    write_file(fx, "table.ini", TINY_CASE "[motion]\ntype = table\nfile = motion.csv\n");
    write_file(fx, "motion.csv", "0,0,0\n0.02,0.0001,0\n0.04,0.0002,0\n0.06,0.0001,0\n");
    int rc = run_vcsph(fx, (const char *const[]){"run", "table.ini", "-o", "res", NULL});
    assert_int_equal(rc, 0);
    char *log = read_file(fx, "res/log.txt");
    assert_contains(log, "columns t,x,y (no header: by position), 4 rows, t in [0, 0.06] s");
    free(log);
    write_file(fx, "motion.csv", "t,x,rol\n0,0,0\n0.02,0.0001,0\n0.04,0.0002,0\n0.06,0.0001,0\n");
    rc = run_vcsph(fx, (const char *const[]){"run", "table.ini", "-o", "bad", NULL});
    assert_int_equal(rc, 2);
    char *err = read_file(fx, "stderr.txt");
    assert_contains(err, "motion.csv:1: motion table header: 'rol' is not a column (did you mean "
                         "'roll'?)");
    free(err);
    assert_false(exists(fx, "bad"));
}

/* `vcsph volume` on a missing file and on a file that is not HDF5: one line each naming the
 * file and what is wrong, status 2, and no CSV header before it. */
static void test_volume_of_bad_files(void **state)
{
    fixture *fx = *state;
    int rc = run_vcsph(fx, (const char *const[]){"volume", "nope.h5", NULL});
    assert_int_equal(rc, 2);
    char *out = read_file(fx, "stdout.txt"), *err = read_file(fx, "stderr.txt");
    assert_string_equal(out, "");
    assert_contains(err, "nope.h5: cannot open: No such file or directory");
    free(out);
    free(err);
    write_file(fx, "text.h5", "not an HDF5 file\n");
    rc = run_vcsph(fx, (const char *const[]){"volume", "text.h5", NULL});
    assert_int_equal(rc, 2);
    out = read_file(fx, "stdout.txt");
    err = read_file(fx, "stderr.txt");
    assert_string_equal(out, "");
    assert_contains(err, "text.h5: not an HDF5 file");
    free(out);
    free(err);
}

/* --insist takes the absurd case that test_cli's absurd_sound_speed refuses: `check` passes,
 * with a warning that names the estimate of more than a day. */
static void test_insist_takes_an_absurd_case(void **state)
{
    fixture *fx = *state;
    write_file(fx, "absurd.ini", BASE_CASE);
    int rc = run_vcsph(fx, (const char *const[]){"check", "absurd.ini", "--set",
                                                 "numerics.sound_speed=1e10", "--set",
                                                 "case.t_end=0.001", "--insist", NULL});
    char *err = read_file(fx, "stderr.txt");
    if (rc) print_error("%s", err);
    assert_int_equal(rc, 0);
    assert_contains(err, "vcsph: warning: this run is estimated at");
    assert_contains(err, "days of wall time");
    free(err);
}

/* The steps of the wall time estimate against the run's own: t_end / dt plus half a step for
 * each time a step lands on (every row of timeseries.csv here, 0.01 s, some 6 steps of the
 * tiny case's dt of 1.64 ms). The tank is at rest and dt stays the acoustic one of Eq. (8), so
 * the count is exact but for the landing, which the half step averages: within 10 %
 * (measured: 33 estimated, 35 made). t_end / dt alone, 30.5, is 13 % short. */
static void test_estimate_counts_the_steps(void **state)
{
    fixture *fx = *state;
    write_file(fx, "tiny.ini", TINY_CASE);
    assert_int_equal(run_vcsph(fx, (const char *const[]){"check", "tiny.ini", NULL}), 0);
    char *out = read_file(fx, "stdout.txt");
    char line[512];
    line_after(out, "wall time est.", line, sizeof line);
    free(out);
    const char *open = strchr(line, '(');
    assert_non_null(open);
    double estimated = strtod(open + 1, NULL);
    assert_int_equal(run_vcsph(fx, (const char *const[]){"run", "tiny.ini", "-o", "res", NULL}), 0);
    out = read_file(fx, "stdout.txt");
    line_after(out, "done: ", line, sizeof line);
    free(out);
    double steps = strtod(line, NULL);
    if (!(fabs(estimated - steps) <= 0.1 * steps))
        fail_msg("estimated %g steps, the run made %g", estimated, steps);
}

/* --help names every image `vcsph plot` writes. */
static void test_help_names_every_plot(void **state)
{
    fixture *fx = *state;
    assert_int_equal(run_vcsph(fx, (const char *const[]){"--help", NULL}), 0);
    char *out = read_file(fx, "stdout.txt");
    static const char *const words[] = {"volume error and eta", "energy", "density", "liquid",
                                        "dissipation",          "probes", "loads"};
    for (size_t k = 0; k < sizeof words / sizeof words[0]; k++) assert_contains(out, words[k]);
    free(out);
    /* after a command too, as a user types it */
    assert_int_equal(run_vcsph(fx, (const char *const[]){"run", "--help", NULL}), 0);
    out = read_file(fx, "stdout.txt");
    assert_contains(out, "--restart");
    free(out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_extend_hint_pastes, setup, teardown),
        cmocka_unit_test_setup_teardown(test_restart_of_a_finished_run, setup, teardown),
        cmocka_unit_test_setup_teardown(test_edited_case_is_named, setup, teardown),
        cmocka_unit_test_setup_teardown(test_table_columns_are_said, setup, teardown),
        cmocka_unit_test_setup_teardown(test_volume_of_bad_files, setup, teardown),
        cmocka_unit_test_setup_teardown(test_insist_takes_an_absurd_case, setup, teardown),
        cmocka_unit_test_setup_teardown(test_estimate_counts_the_steps, setup, teardown),
        cmocka_unit_test_setup_teardown(test_help_names_every_plot, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
