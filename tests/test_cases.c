/* The case files of cases/ (the paper's benchmarks and the default case): every one passes `vcsph
 * check` (parse, validation, derived numbers) and runs 0.05 s at N = 8 without a breakdown. The
 * files are found by listing the folder, so a new case is covered without touching this test. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "app/simulation.h"
#include "core/derived.h"
#include "scheme/case_numbers.h"

#include "check.h"
#include "table.h"
#include "run_case.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_CASES 64

/* the .ini files of cases/, sorted so that the output is stable */
static int list_cases(char names[MAX_CASES][256])
{
    DIR *d = opendir(VCSPH_SOURCE_DIR "/cases");
    assert_non_null(d);
    int n = 0;
    for (struct dirent *e; (e = readdir(d)) && n < MAX_CASES;) {
        size_t len = strlen(e->d_name);
        if (len > 4 && len < 256 && !strcmp(e->d_name + len - 4, ".ini"))
            snprintf(names[n++], 256, "%s", e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof names[0], (int (*)(const void *, const void *))strcmp);
    return n;
}

/* what `vcsph check` does: load, then the derived numbers */
static void check_case(const char *path, config *cfg)
{
    char err[1024];
    if (config_load(cfg, path, NULL, 0, err, sizeof err)) fail_msg("%s", err);
    motion mo;
    if (motion_init(&mo, cfg, err, sizeof err)) fail_msg("%s: %s", path, err);
    derived dv;
    case_numbers(cfg, &mo, &dv);
    motion_free(&mo);
    if (derived_check(cfg, &dv, err, sizeof err)) fail_msg("%s: %s", path, err);
}

static void test_every_case_checks_and_runs(void **state)
{
    (void)state;
    static char names[MAX_CASES][256];
    int n = list_cases(names);
    assert_true(n >= 7); /* default, sap, sap-re494, upm, inm1, inm2, inm2-3d */
    for (int k = 0; k < n; k++) {
        char path[512], dir[64];
        snprintf(path, sizeof path, VCSPH_SOURCE_DIR "/cases/%.200s", names[k]);
        static config cfg;
        check_case(path, &cfg);
        static const char *const tiny[] = {"case.t_end=0.05", "numerics.resolution=8"};
        char err[1024];
        if (config_load(&cfg, path, tiny, 2, err, sizeof err)) fail_msg("%s", err);
        run_case_folder(dir);
        run_options opt = {dir, true, false, NULL, "vcsph"};
        int status = simulation_run(&cfg, &opt);
        printf("%-16s %dD: checked, 0.05 s at N = 8: exit %d (%s)\n", names[k], cfg.dim, status,
               dir);
        assert_int_equal(status, RUN_OK);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_every_case_checks_and_runs)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
