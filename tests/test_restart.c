/* Checkpoints and `vcsph run --restart` (README.md, docs/architecture.md), with the real binary as
 * a user meets it. A short delta-plus-ALE sloshing run (2D, N = 10, adaptive eta control with its
 * history, EdBC toggled with eta = 0, probes, dissipation per period, snapshots and images) is
 * stopped and continued:
 * - SIGTERM once it has made progress: exit 4 with a checkpoint, then --restart;
 * - kill -9 at a few times (one of them twice, the restarted run killed again), then
 *   --restart from the last checkpoint written every output.checkpoint_every wall seconds;
 * and the outputs must be byte for byte those of the same run never stopped: timeseries.csv,
 * events.csv, dissipation.csv, probes.csv, snapshots.xmf, images, and every dataset of every
 * snapshot (their "case" attribute names the output folder, which differs).
 * A run that breaks down keeps its last good checkpoint. Damaged and forged checkpoints and
 * disallowed --set: test_restart_refused.c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <hdf5.h>
#include <math.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "restart_group.h"

/* ---- (a) SIGTERM -------------------------------------------------------------------------- */

static void test_sigterm_then_restart_is_exact(void **state)
{
    (void)state;
    pid_t pid = spawn_vcsph((const char *const[]){"run", "slosh.ini", "-o", "term", NULL}, "term");
    assert_true(wait_for_size(pid, "term/timeseries.csv", PROGRESS_BYTES));
    long delay = random_ms(300);
    printf("SIGTERM %ld ms after the run passed %d bytes of time series\n", delay, PROGRESS_BYTES);
    sleep_ms(delay);
    assert_int_equal(kill(pid, SIGTERM), 0);
    int status = vcsph_child_wait(pid);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 4); /* RUN_INTERRUPTED */
    char *out = read_in_group("term.out");
    if (!strstr(out, "stopped by SIGTERM") || !strstr(out, "--restart term/checkpoint.h5"))
        fail_msg("no clear message on stdout:\n%s", out);
    free(out);
    restart_and_compare("term", "term-restart");
    char *log = read_in_group("term/log.txt");
    assert_non_null(strstr(log, "stopped by SIGTERM"));
    assert_non_null(strstr(log, "restarted from the checkpoint"));
    free(log);
}

static void test_kill9_then_restart_is_exact(void **state)
{
    (void)state;
    for (int round = 0; round < 3; round++) {
        char dir[32], log[48], checkpoint[64];
        snprintf(dir, sizeof dir, "kill%d", round);
        snprintf(log, sizeof log, "kill%d", round);
        snprintf(checkpoint, sizeof checkpoint, "%s/checkpoint.h5", dir);
        run_and_kill((const char *const[]){"run", "slosh.ini", "-o", dir, "--quiet", NULL}, dir,
                     log);
        if (round == 1) { /* the restarted run killed too: its checkpoints continue the first's */
            snprintf(log, sizeof log, "kill%d-again", round);
            run_and_kill((const char *const[]){"run", "--restart", checkpoint, "--quiet", NULL},
                         dir, log);
        }
        snprintf(log, sizeof log, "kill%d-restart", round);
        restart_and_compare(dir, log);
    }
}

/* ---- (f) a breakdown keeps the last good checkpoint --------------------------------------- */

/* A heaving tank whose liquid passes density_bound = 2 % within a few steps (the heave's
 * start and its extra effective gravity), with a checkpoint after every step. */
static const char breakdown_case[] = "[case]\nname = heave\nt_end = 0.5\n"
                                     "[tank]\nlength = 0.2\nheight = 0.1\n"
                                     "[liquid]\nheight = 0.05\n"
                                     "[motion]\ntype = heave\namplitude = 0.02\nperiod = 0.2\n"
                                     "[numerics]\nresolution = 8\nsound_speed = 10\n"
                                     "density_bound = 0.02\n"
                                     "[output]\ntimeseries_every = 0\nsnapshot_every = 0.1\n"
                                     "checkpoint_every = 1e-9\n";

/* The first line of a run's stderr that holds "breakdown at", without its folder. */
static char *breakdown_line(const char *log)
{
    char *err = read_in_group(log);
    const char *at = strstr(err, "breakdown at");
    if (!at) fail_msg("%s: no breakdown:\n%s", log, err);
    char *line = strndup(at, strcspn(at, "\n"));
    free(err);
    return line;
}

static int64_t checkpoint_step(const char *name)
{
    char path[600], err[512];
    path_in(name, path, sizeof path);
    checkpoint_data cd;
    if (checkpoint_read(path, &cd, err, sizeof err)) fail_msg("%s", err);
    const checkpoint_array *a = checkpoint_find(&cd, "solver_i64", CHECKPOINT_I64, 4,
                                                "dim,n_fluid,step,n_edbc", err, sizeof err);
    if (!a) fail_msg("%s", err);
    int64_t step = ((const int64_t *)a->data)[2];
    checkpoint_data_free(&cd);
    return step;
}

/* docs/architecture.md: a breakdown exits 3 and leaves the checkpoint of the step
 * before it, which continues into the same breakdown, and leaves it again. */
static void test_breakdown_keeps_the_last_good_checkpoint(void **state)
{
    (void)state;
    write_in_group("heave.ini", breakdown_case, strlen(breakdown_case));
    int rc = run_vcsph((const char *const[]){"run", "heave.ini", "-o", "broken", "--quiet", NULL},
                       "broken");
    assert_int_equal(rc, 3);
    char *first = breakdown_line("broken.err");
    const char *at_step = strstr(first, "step ");
    assert_non_null(at_step);
    long step = strtol(at_step + 5, NULL, 10);
    assert_true(step >= 3); /* good steps, each checkpointed, came before it */
    assert_int_equal(checkpoint_step("broken/checkpoint.h5"), step - 1);

    char path[600];
    path_in("broken/checkpoint.h5", path, sizeof path);
    size_t len;
    char *saved = read_all(path, &len);
    assert_non_null(saved);
    rc = run_vcsph(
        (const char *const[]){"run", "--restart", "broken/checkpoint.h5", "--quiet", NULL},
        "broken-restart");
    assert_int_equal(rc, 3);
    char *again = breakdown_line("broken-restart.err");
    assert_string_equal(first, again); /* the same time, step, particle and density */
    size_t len_after;
    char *after = read_all(path, &len_after);
    assert_non_null(after);
    assert_true(len_after == len && memcmp(saved, after, len) == 0);
    free(first);
    free(again);
    free(saved);
    free(after);
}

int main(void)
{
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sigterm_then_restart_is_exact),
        cmocka_unit_test(test_kill9_then_restart_is_exact),
        cmocka_unit_test(test_breakdown_keeps_the_last_good_checkpoint),
    };
    return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
