/* A run's output folder and its restarts, as a user meets them with the real binary:
 * - one run at a time per folder: a second is refused (exit 2) with the other's process id,
 *   and the lock of a process that is gone does not block;
 * - a new run into a folder with another run's outputs is refused (exit 2); --overwrite
 *   removes exactly the files a run writes (a user's file stays) and runs;
 * - a finished run is extended by --restart with a later t_end to the bit of a run made in
 *   one go (its end checkpoint, rows on exact multiples of the interval), with the motion
 *   table it started with, whatever happened to the table's file since;
 * - a restart from an older checkpoint says that it drops the rows after it;
 * - a second interrupt stops at once, says so, and exits 128 + the signal (130: Ctrl-C). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>

#include "check.h"
#include "table.h"
#include "temp_dir.h"
#include "vcsph_child.h"

extern char **environ;

typedef temp_fixture fixture;

static int setup(void **state) { return temp_fixture_setup(state, "vcsph-folder"); }

static int teardown(void **state) { return temp_fixture_teardown(state); }

static const char slosh_case[] = "[case]\n"
                                 "name = slosh\n"
                                 "t_end = 0.1\n"
                                 "[tank]\n"
                                 "length = 0.2\n"
                                 "height = 0.1\n"
                                 "[liquid]\n"
                                 "height = 0.05\n"
                                 "[motion]\n"
                                 "type = table\n"
                                 "file = wave.csv\n"
                                 "[numerics]\n"
                                 "resolution = 8\n"
                                 /* `auto` would take the table's peak up to t_end */
                                 "sound_speed = 10\n"
                                 "[output]\n"
                                 "timeseries_every = 0.01\n"
                                 "snapshot_every = 0.04\n"
                                 "image_every = 0\n";

/* A sway of 5 mm at 2 Hz as a table of t, x, y, with y offset by `lift` (a changed table). */
static void write_wave(fixture *fx, const char *name, double lift)
{
    FILE *f = fopen(temp_fixture_path(fx, name), "w");
    assert_non_null(f);
    fprintf(f, "t,x,y\n");
    for (int k = 0; k <= 100; k++)
        fprintf(f, "%.17g,%.17g,%.17g\n", 0.01 * k, 0.005 * sin(2.0 * M_PI * 2.0 * 0.01 * k), lift);
    fclose(f);
}

static void write_case(fixture *fx)
{
    text_file_write(temp_fixture_path(fx, "slosh.ini"), slosh_case);
    write_wave(fx, "wave.csv", 0.0);
}

static int run_vcsph(fixture *fx, const char *const *args)
{
    return vcsph_child_run(fx->dir, args, environ);
}

static char *read_in(fixture *fx, const char *name)
{
    return text_file_read(temp_fixture_path(fx, name));
}

static void assert_output_holds(fixture *fx, const char *what)
{
    char *err = read_in(fx, "stderr.txt");
    assert_contains(err, what);
    free(err);
}

static int file_exists(fixture *fx, const char *name)
{
    struct stat st;
    return stat(temp_fixture_path(fx, name), &st) == 0;
}

static void test_second_run_refused_while_first_holds_the_lock(void **state)
{
    fixture *fx = *state;
    write_case(fx);
    /* this process plays the other run: it holds the folder's lock as a run does */
    assert_int_equal(mkdir(temp_fixture_path(fx, "res"), 0777), 0);
    int fd = open(temp_fixture_path(fx, "res/.vcsph.lock"), O_RDWR | O_CREAT, 0666);
    assert_true(fd >= 0);
    assert_int_equal(flock(fd, LOCK_EX | LOCK_NB), 0);
    char pid[32];
    int len = snprintf(pid, sizeof pid, "%ld\n", (long)getpid());
    assert_int_equal(write(fd, pid, (size_t)len), len);
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "-o", "res", "--quiet", NULL}), 2);
    char named[64];
    snprintf(named, sizeof named, "in use by another vcsph run (process %ld)", (long)getpid());
    assert_output_holds(fx, named);
    assert_false(file_exists(fx, "res/timeseries.csv"));
    /* the holder ends: its lock file stays, and blocks nothing */
    close(fd);
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "-o", "res", "--quiet", NULL}), 0);
}

static void test_earlier_run_refused_or_overwritten(void **state)
{
    fixture *fx = *state;
    write_case(fx);
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "-o", "res", "--quiet", NULL}), 0);
    /* 0, 0.04, 0.08 and the end 0.1 */
    assert_true(file_exists(fx, "res/snapshots/000003.h5"));
    text_file_write(temp_fixture_path(fx, "res/notes.txt"), "mine\n");
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "--set", "case.t_end=0.05", "-o",
                                            "res", "--quiet", NULL}),
        2);
    assert_output_holds(fx, "holds another run's outputs");
    assert_output_holds(fx, "--overwrite");
    assert_true(file_exists(fx, "res/snapshots/000003.h5"));
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "--set", "case.t_end=0.05", "-o",
                                            "res", "--overwrite", "--quiet", NULL}),
        0);
    /* the shorter run's snapshots only (0, 0.04, 0.05), and the user's file */
    assert_true(file_exists(fx, "res/snapshots/000002.h5"));
    assert_false(file_exists(fx, "res/snapshots/000003.h5"));
    assert_true(file_exists(fx, "res/notes.txt"));
    char *xmf = read_in(fx, "res/snapshots.xmf");
    assert_null(strstr(xmf, "000003.h5"));
    free(xmf);
}

/* Every row of timeseries.csv at a multiple of `every`, to the round-off of k * every. */
static void assert_rows_on_multiples(const table *t, double every)
{
    const double *time = table_column(t, "t");
    for (size_t r = 0; r < t->n_rows; r++) {
        double k = round(time[r] / every);
        assert_close(time[r], k * every, 1e-12);
    }
}

static void test_finished_run_extended_as_one_run(void **state)
{
    fixture *fx = *state;
    write_case(fx);
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "-o", "parts", "--quiet", NULL}),
        0);
    /* the copy of the table, named by case.ini */
    char *copy = read_in(fx, "parts/motion_table.csv"), *original = read_in(fx, "wave.csv");
    assert_string_equal(copy, original);
    free(copy);
    free(original);
    char *ini = read_in(fx, "parts/case.ini");
    assert_contains(ini, "parts/motion_table.csv");
    free(ini);
    /* both the table and its copy change: the restart runs with the stored one */
    write_wave(fx, "wave.csv", 0.001);
    write_wave(fx, "parts/motion_table.csv", 0.002);
    assert_int_equal(run_vcsph(fx, (const char *const[]){"run", "--restart", "parts/checkpoint.h5",
                                                         "--set", "case.t_end=0.2", NULL}),
                     0);
    char *out = read_in(fx, "stdout.txt");
    assert_null(strstr(out, "rewinding")); /* nothing after the end checkpoint to drop */
    free(out);
    write_wave(fx, "wave.csv", 0.0);
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "--set", "case.t_end=0.2", "-o",
                                            "whole", "--quiet", NULL}),
        0);
    char *a = read_in(fx, "parts/timeseries.csv"), *b = read_in(fx, "whole/timeseries.csv");
    assert_true(strlen(a) > 0);
    assert_string_equal(a, b);
    free(a);
    free(b);
    table t;
    assert_int_equal(table_read(&t, temp_fixture_path(fx, "whole/timeseries.csv")), 0);
    assert_int_equal(t.n_rows, 21);
    assert_rows_on_multiples(&t, 0.01);
    table_free(&t);
}

static void copy_file(fixture *fx, const char *from, const char *to)
{
    FILE *in = fopen(temp_fixture_path(fx, from), "rb");
    assert_non_null(in);
    FILE *out = fopen(temp_fixture_path(fx, to), "wb");
    assert_non_null(out);
    char buf[65536];
    for (size_t n; (n = fread(buf, 1, sizeof buf, in)) > 0;)
        assert_int_equal(fwrite(buf, 1, n, out), n);
    fclose(in);
    assert_int_equal(fclose(out), 0);
}

static void test_restart_from_older_checkpoint_says_what_it_drops(void **state)
{
    fixture *fx = *state;
    write_case(fx);
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "slosh.ini", "--set", "case.t_end=0.05", "-o",
                                            "res", "--quiet", NULL}),
        0);
    copy_file(fx, "res/checkpoint.h5", "at-0.05.h5");
    assert_int_equal(
        run_vcsph(fx, (const char *const[]){"run", "--restart", "res/checkpoint.h5", "--set",
                                            "case.t_end=0.1", "--quiet", NULL}),
        0);
    /* as if the run had been killed at 0.1 with its last checkpoint at 0.05 */
    copy_file(fx, "at-0.05.h5", "res/checkpoint.h5");
    assert_int_equal(run_vcsph(fx, (const char *const[]){"run", "--restart", "res/checkpoint.h5",
                                                         "--set", "case.t_end=0.1", NULL}),
                     0);
    char *out = read_in(fx, "stdout.txt"), *log = read_in(fx, "res/log.txt");
    assert_contains(out, "rewinding to t = 0.05 s removes 5 rows of timeseries.csv up to "
                         "t = 0.1 s");
    assert_contains(log, "rewinding to t = 0.05 s");
    free(out);
    free(log);
}

static void test_second_interrupt_stops_at_once(void **state)
{
    fixture *fx = *state;
    write_case(fx);
    pid_t pid = vcsph_child_spawn(
        fx->dir,
        (const char *const[]){"run", "slosh.ini", "--set", "case.t_end=100", "-o", "res", NULL},
        environ, "stdout.txt", "stderr.txt");
    /* wait until it is under way: its first rows are there */
    for (int k = 0; k < 600; k++) {
        char *series = read_in(fx, "res/timeseries.csv");
        int rows = 0;
        for (const char *c = series; *c; c++) rows += *c == '\n';
        free(series);
        if (rows > 3) break;
        nanosleep(&(struct timespec){0, 50000000}, NULL);
    }
    /* two SIGINTs sent at once merge into one pending signal (POSIX does not queue them), and
       a step of this small case ends long before a person's second Ctrl-C could come: a
       SIGTERM with the SIGINT cannot merge with it. Whichever the kernel delivers second ends
       the run: 128 + 2 = 130 or 128 + 15 = 143. */
    kill(pid, SIGINT);
    kill(pid, SIGTERM);
    int status = vcsph_child_wait(pid);
    assert_true(WIFEXITED(status));
    int rc = WEXITSTATUS(status);
    printf("SIGINT and SIGTERM together: exit %d\n", rc);
    assert_true(rc == 128 + SIGINT || rc == 128 + SIGTERM);
    assert_output_holds(fx, "second interrupt: stopped at once");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_second_run_refused_while_first_holds_the_lock, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(test_earlier_run_refused_or_overwritten, setup, teardown),
        cmocka_unit_test_setup_teardown(test_finished_run_extended_as_one_run, setup, teardown),
        cmocka_unit_test_setup_teardown(test_restart_from_older_checkpoint_says_what_it_drops,
                                        setup, teardown),
        cmocka_unit_test_setup_teardown(test_second_interrupt_stops_at_once, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
