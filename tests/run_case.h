/* run_case: runs a case given as text in a fresh temporary folder and reads its time series
 * back, for the integration tests. Include after <cmocka.h>, "check.h" and "table.h". */
#ifndef VCSPH_TEST_RUN_CASE_H
#define VCSPH_TEST_RUN_CASE_H

#include "app/simulation.h"

#include <stdio.h>
#include <stdlib.h>

/* Runs cfg quietly in a new folder under /tmp (its path in dir, 64 bytes) and reads
 * dir/timeseries.csv into t. */
static inline void run_case_config(const config *cfg, char dir[64], table *t)
{
    snprintf(dir, 64, "/tmp/vcsph-test-XXXXXX");
    assert_non_null(mkdtemp(dir));
    run_options opt = {dir, true};
    assert_int_equal(simulation_run(cfg, &opt), RUN_OK);
    char path[128];
    snprintf(path, sizeof path, "%s/timeseries.csv", dir);
    assert_int_equal(table_read(t, path), 0);
}

/* Loads `text` with the --set style overrides and runs it (run_case_config). */
static inline void run_case_text(const char *text, const char *const *overrides, int n_overrides,
                                 char dir[64], table *t)
{
    config cfg;
    char err[1024];
    if (config_load_string(&cfg, text, "test case", overrides, n_overrides, err, sizeof err))
        fail_msg("%s", err);
    run_case_config(&cfg, dir, t);
}

/* The same for the case file cases/NAME.ini of the source tree. */
static inline void run_case_file(const char *name, const char *const *overrides, int n_overrides,
                                 char dir[64], table *t)
{
    char path[512], err[1024];
    snprintf(path, sizeof path, "%s/cases/%s.ini", VCSPH_SOURCE_DIR, name);
    config cfg;
    if (config_load(&cfg, path, overrides, n_overrides, err, sizeof err)) fail_msg("%s", err);
    run_case_config(&cfg, dir, t);
}

#endif
