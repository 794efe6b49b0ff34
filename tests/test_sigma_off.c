/* Surface tension off (fluid.surface_tension = 0, the default) changes nothing: two short
 * delta-plus-ALE runs (2D SAP, 3D sway) end in exactly the state that the solver reaches
 * without the surface-tension code, bit for bit. The references in tests/data/sigma_off/ are
 * written by this same file (VCSPH_WRITE_REFERENCE=1) built against a tree without the
 * surface-tension code: when a change moves the solver's results without surface tension, they
 * are written again from the commit before it with only the change's non-surface-tension files
 * applied, and the commit says so (git log tests/data/sigma_off). Each line is one particle,
 * in C's exact %a notation. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "check.h"
#include "io/snapshot_read.h"
#include "table.h"
#include "run_case.h"

#define FIELDS 4
static const char *const field_names[FIELDS] = {"position", "velocity", "density", "mass"};
static const int field_components[FIELDS] = {3, 3, 1, 1}; /* at most: dim for vectors */

/* The final state of the case run with the overrides, as text: one line per particle. */
static char *final_state(const char *case_file, const char *const *overrides, int n_overrides)
{
    config cfg;
    char err[1024], dir[64];
    if (config_load(&cfg, case_file, overrides, n_overrides, err, sizeof err)) fail_msg("%s", err);
    run_case_folder(dir);
    run_options opt = {dir, true, false, NULL, "vcsph"};
    assert_int_equal(simulation_run(&cfg, &opt), RUN_OK);
    char path[128];
    snprintf(path, sizeof path, "%s/snapshots/000001.h5", dir);
    snapshot_info info;
    if (snapshot_read_info(path, &info, err, sizeof err)) fail_msg("%s", err);
    size_t n = info.n;
    double *columns[8];
    int n_columns = 0;
    for (int f = 0; f < FIELDS; f++) {
        int comp = field_components[f] == 3 ? info.dim : 1;
        for (int c = 0; c < comp; c++) columns[n_columns + c] = malloc(n * sizeof(double));
        if (snapshot_read_doubles(path, field_names[f], comp, columns + n_columns, n, err,
                                  sizeof err))
            fail_msg("%s", err);
        n_columns += comp;
    }
    /* the particles in the snapshot's order (sorted by cell, deterministic) */
    size_t line = 40 * (size_t)n_columns + 2, len = 0;
    char *text = malloc(n * line + 1);
    for (size_t i = 0; i < n; i++) {
        for (int c = 0; c < n_columns; c++)
            len += (size_t)sprintf(text + len, c ? " %a" : "%a", columns[c][i]);
        text[len++] = '\n';
    }
    text[len] = '\0';
    for (int c = 0; c < n_columns; c++) free(columns[c]);
    snapshot_info_free(&info);
    return text;
}

static void check_case(const char *name, const char *case_file, const char *const *overrides,
                       int n_overrides)
{
    char *state = final_state(case_file, overrides, n_overrides);
    char path[512];
    snprintf(path, sizeof path, "%s/tests/data/sigma_off/%s.txt", VCSPH_SOURCE_DIR, name);
    if (getenv("VCSPH_WRITE_REFERENCE")) {
        FILE *f = fopen(path, "w");
        assert_non_null(f);
        fputs(state, f);
        fclose(f);
    }
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t cap = strlen(state) + 2; /* a longer reference reads as different */
    char *reference = malloc(cap + 1);
    size_t len = fread(reference, 1, cap, f);
    reference[len] = '\0';
    fclose(f);
    size_t lines = 0;
    for (const char *c = state; *c; c++) lines += *c == '\n';
    printf("%s: %zu particles, final state %s the reference\n", name, lines,
           strcmp(state, reference) == 0 ? "identical to" : "DIFFERENT from");
    assert_string_equal(state, reference);
    free(reference);
    free(state);
}

/* The solver of that commit had no volume correction, which delta-plus-ALE now has by
 * default (docs/volume-correction.md): off, the rest must still be bit for bit the same. */
#define CORRECTION_OFF "model.volume_correction=none"

static void test_sap_2d(void **state)
{
    (void)state;
    static const char *const set[] = {"case.t_end=0.05", "numerics.resolution=8",
                                      "output.snapshot_every=0.05", CORRECTION_OFF};
    check_case("sap-2d", VCSPH_SOURCE_DIR "/cases/sap-re494.ini", set, 4);
}

static void test_sway_3d(void **state)
{
    (void)state;
    static const char *const set[] = {"case.t_end=0.02", "numerics.resolution=5",
                                      "output.snapshot_every=0.02", CORRECTION_OFF};
    check_case("sway-3d", VCSPH_SOURCE_DIR "/tests/data/sigma_off/sway-3d.ini", set, 4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sap_2d),
        cmocka_unit_test(test_sway_3d),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
