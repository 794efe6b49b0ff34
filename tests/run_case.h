/* run_case: runs a case given as text in a fresh temporary folder and reads its time series
 * back, for the integration tests. Include after <cmocka.h>, "check.h" and "table.h". */
#ifndef VCSPH_TEST_RUN_CASE_H
#define VCSPH_TEST_RUN_CASE_H

#include "app/simulation.h"
#include "temp_dir.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The folders the runs of this test made: remembered (dir) and removed with everything in them
 * when the test exits (dir NULL), whether it passed or not, unless VCSPH_KEEP_TEST_OUTPUT is
 * set (to look at a failed run). */
static inline void run_case_folders(const char *dir)
{
    enum { MAX_FOLDERS = 64 };
    static char folders[MAX_FOLDERS][64];
    static int n;
    if (dir) {
        if (n < MAX_FOLDERS) snprintf(folders[n++], sizeof folders[0], "%s", dir);
        return;
    }
    const char *keep = getenv("VCSPH_KEEP_TEST_OUTPUT");
    for (int k = 0; k < n && !(keep && *keep); k++) temp_dir_remove(folders[k]);
}

static inline void run_case_remove_folders(void) { run_case_folders(NULL); }

/* A new folder for a run under $TMPDIR or /tmp (its path in dir, 64 bytes), removed when the
 * test exits. */
static inline void run_case_folder(char dir[64])
{
    static bool registered;
    assert_int_equal(temp_dir_make(dir, 64, "vcsph-test"), 0);
    if (!registered) registered = atexit(run_case_remove_folders) == 0;
    run_case_folders(dir);
}

/* Runs cfg quietly in a new folder (run_case_folder) and reads dir/timeseries.csv into t. */
static inline void run_case_config(const config *cfg, char dir[64], table *t)
{
    run_case_folder(dir);
    run_options opt = {dir, true, false, NULL, "vcsph"};
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

/* Loads the case file cases/NAME.ini of the source tree with the --set style overrides. */
static inline void run_case_load_file(const char *name, const char *const *overrides,
                                      int n_overrides, config *cfg)
{
    char path[512], err[1024];
    snprintf(path, sizeof path, "%s/cases/%s.ini", VCSPH_SOURCE_DIR, name);
    if (config_load(cfg, path, overrides, n_overrides, err, sizeof err)) fail_msg("%s", err);
}

/* Loads cases/NAME.ini with the overrides (run_case_load_file) and runs it (run_case_config). */
static inline void run_case_file(const char *name, const char *const *overrides, int n_overrides,
                                 char dir[64], table *t)
{
    config cfg;
    run_case_load_file(name, overrides, n_overrides, &cfg);
    run_case_config(&cfg, dir, t);
}

#endif
