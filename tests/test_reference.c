/* Reference outputs: short runs of every case file, the five schemes, surface tension, the
 * capillary patch, both eta controls and a restart, compared byte for byte with what the code
 * wrote when they were recorded (tests/data/reference/, one text per run). The redesign of the
 * code's structure (docs/architecture.md) must not change a result; this test is what says so.
 *
 * Each reference holds the run's CSV files verbatim (timeseries, events, dissipation,
 * probes), the XDMF index of the snapshots, and, for every snapshot, one line per dataset and
 * attribute with its type, length and a 64-bit FNV-1a hash of its bytes (h5_digest.h; the snapshots
 * themselves would weigh megabytes). Left out: the version attribute, log.txt (wall times), images
 * (the PNG encoder's bytes depend on the zlib build), and the checkpoint, whose exactness is
 * test_restart's and which the restart run here reads back. The runs go through the vcsph binary,
 * so the test does not depend on the code's internal interfaces.
 *
 * A change of results that is meant (a physics fix) writes the references again:
 *   VCSPH_WRITE_REFERENCE=1 build/tests/test_reference
 * and says in its commit why the outputs changed; a refactoring never does. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include <dirent.h>

#include "check.h"
#include "h5_digest.h"
#include "temp_dir.h"
#include "vcsph_child.h"

#define REFERENCE_DIR VCSPH_SOURCE_DIR "/tests/data/reference"

typedef struct {
    const char *name;      /* the reference's file name */
    const char *case_file; /* relative to the source tree */
    const char *set[10];   /* --set overrides, NULL-ended */
} reference_run;

/* Every run writes a few time-series rows, a snapshot at its end and none of the images. */
#define OUTPUTS "output.image_every=0"
#define SAP(scheme)                                                                                \
    {                                                                                              \
        "sap-" scheme, "cases/sap-re494.ini",                                                      \
        {                                                                                          \
            "model.scheme=" scheme, "case.t_end=0.02", "numerics.resolution=8",                    \
                "output.snapshot_every=0.02", "output.timeseries_every=0.005", OUTPUTS, NULL       \
        }                                                                                          \
    }

static const reference_run runs[] = {
    {"default",
     "cases/default.ini",
     {"case.t_end=0.1", "numerics.resolution=8", "output.snapshot_every=0.05",
      "output.timeseries_every=0.01", "output.graphical=true", OUTPUTS, NULL}},
    {"inm1",
     "cases/inm1.ini",
     {"case.t_end=0.1", "numerics.resolution=8", "output.snapshot_every=0.1",
      "output.timeseries_every=0.02", OUTPUTS, NULL}},
    {"inm2",
     "cases/inm2.ini",
     {"case.t_end=0.1", "numerics.resolution=8", "output.snapshot_every=0.1",
      "output.timeseries_every=0.02", OUTPUTS, NULL}},
    {"inm2-3d",
     "cases/inm2-3d.ini",
     {"case.t_end=0.03", "numerics.resolution=8", "output.snapshot_every=0.03",
      "output.timeseries_every=0.01", OUTPUTS, NULL}},
    {"sap",
     "cases/sap.ini", /* surface tension, We = 25 */
     {"case.t_end=0.02", "numerics.resolution=8", "output.snapshot_every=0.02",
      "output.timeseries_every=0.005", OUTPUTS, NULL}},
    {"upm",
     "cases/upm.ini",
     {"case.t_end=0.02", "numerics.resolution=8", "output.snapshot_every=0.02",
      "output.timeseries_every=0.005", OUTPUTS, NULL}},
    SAP("standard"),
    SAP("delta"),
    SAP("delta-plus"),
    SAP("delta-ale"),
    SAP("delta-plus-ale"),
    {"sap-adaptive",
     "cases/sap-re494.ini", /* the adaptive control and EdBC acting */
     {"model.eta_control=adaptive", "model.eta_threshold=0.001", "model.edbc=true",
      "case.t_end=0.05", "numerics.resolution=8", "output.snapshot_every=0.05",
      "output.timeseries_every=0.005", OUTPUTS, NULL}},
    {"patch",
     "tests/data/reference/patch.ini", /* test_capillary's ellipse */
     {"output.snapshot_every=0.02", OUTPUTS, NULL}},
    {"roll",
     "cases/roll.ini", /* the rotating frame; recorded when rotation came, not by 617b8b5 */
     {"case.t_end=0.1", "numerics.resolution=8", "output.snapshot_every=0.1",
      "output.timeseries_every=0.02", OUTPUTS, NULL}},
};

/* The run's outputs as the digest text (the file header's comment says what is in it). */
static char *digest_of_run(const char *dir)
{
    static const char *const csv_files[] = {"timeseries.csv", "events.csv", "dissipation.csv",
                                            "probes.csv",     "loads.csv",  "snapshots.xmf"};
    char *text = NULL, path[512];
    size_t len = 0;
    FILE *out = open_memstream(&text, &len);
    assert_non_null(out);
    for (size_t k = 0; k < sizeof csv_files / sizeof csv_files[0]; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, csv_files[k]);
        char *content = text_file_read(path);
        fprintf(out, "== %s (%zu bytes)\n%s", csv_files[k], strlen(content), content);
        free(content);
    }
    snprintf(path, sizeof path, "%s/snapshots", dir);
    struct dirent **names;
    int n = scandir(path, &names, NULL, alphasort);
    for (int k = 0; k < n; k++) {
        if (strstr(names[k]->d_name, ".h5")) {
            snprintf(path, sizeof path, "%s/snapshots/%s", dir, names[k]->d_name);
            fprintf(out, "== snapshots/%s\n", names[k]->d_name);
            h5_digest(out, path, dir);
        }
        free(names[k]);
    }
    if (n >= 0) free(names);
    assert_int_equal(fclose(out), 0);
    return text;
}

/* The first line where the two texts differ, whole, for the failure message. */
static void report_first_difference(const char *name, const char *got, const char *want)
{
    size_t at = 0, line_start = 0;
    int line = 1;
    for (; got[at] && got[at] == want[at]; at++)
        if (got[at] == '\n') line++, line_start = at + 1;
    const char *g = got + line_start, *w = want + line_start;
    int g_len = (int)strcspn(g, "\n"), w_len = (int)strcspn(w, "\n");
    print_error("%s: first difference at line %d of the digest:\n  now:       %.*s\n"
                "  reference: %.*s\n",
                name, line, g_len, g, w_len, w);
}

static void compare_with_reference(const char *name, const char *digest)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s.txt", REFERENCE_DIR, name);
    if (getenv("VCSPH_WRITE_REFERENCE")) text_file_write(path, digest);
    char *reference = text_file_read(path);
    if (strcmp(digest, reference) != 0) {
        report_first_difference(name, digest, reference);
        fail_msg("%s: outputs differ from %s", name, path);
    }
    printf("%s: %d lines of outputs identical to the reference\n", name, count_lines(digest));
    free(reference);
}

/* The child's environment: two threads, and with VCSPH_NO_LANES=1 the scalar form of the pair
 * terms rather than the SIMD one (the same bits, README.md). */
static char *const lanes_env[] = {"OMP_NUM_THREADS=2", "OMP_WAIT_POLICY=PASSIVE", NULL};
static char *const scalar_env[] = {"OMP_NUM_THREADS=2", "OMP_WAIT_POLICY=PASSIVE",
                                   "VCSPH_NO_LANES=1", NULL};

/* vcsph run CASE -o DIR --quiet --set ... (and --overwrite) in the environment env. */
static void run_vcsph(const char *dir, const char *case_file, const char *const *set,
                      char *const *env)
{
    const char *args[32] = {"run", case_file, "-o", dir, "--quiet", "--overwrite"};
    int argc = 6;
    for (; *set; set++) {
        args[argc++] = "--set";
        args[argc++] = *set;
    }
    args[argc] = NULL;
    int rc = vcsph_child_run(dir, args, env);
    if (rc != 0) {
        char err_path[512];
        snprintf(err_path, sizeof err_path, "%s/stderr.txt", dir);
        fail_msg("vcsph run %s: exit %d: %s", case_file, rc, text_file_read(err_path));
    }
}

static char group_dir[64];

static int make_group_dir(void **state)
{
    (void)state;
    return temp_dir_make(group_dir, sizeof group_dir, "vcsph-reference");
}

static int remove_group_dir(void **state)
{
    (void)state;
    const char *keep = getenv("VCSPH_KEEP_TEST_OUTPUT");
    return keep && *keep ? 0 : temp_dir_remove(group_dir);
}

/* Reference run k in the folder `folder` of the group, in the environment env, against its
 * reference. */
static void run_against_reference(size_t k, const char *folder, char *const *env)
{
    char dir[512], case_file[512];
    snprintf(dir, sizeof dir, "%s/%s", group_dir, folder);
    assert_int_equal(mkdir(dir, 0755), 0);
    snprintf(case_file, sizeof case_file, "%s/%s", VCSPH_SOURCE_DIR, runs[k].case_file);
    run_vcsph(dir, case_file, runs[k].set, env);
    char *digest = digest_of_run(dir);
    compare_with_reference(runs[k].name, digest);
    free(digest);
}

static void test_runs_match_references(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; k++)
        run_against_reference(k, runs[k].name, lanes_env);
}

/* The default case's reference through the scalar pair terms (physics/): the runs above take
 * the SIMD form wherever a machine has it, so a fault in the scalar form would pass them. */
static void test_scalar_form_matches_reference(void **state)
{
    (void)state;
    if (getenv("VCSPH_WRITE_REFERENCE")) skip(); /* the lanes' run writes it */
    run_against_reference(0, "default-scalar", scalar_env);
}

/* The default case run to 0.05 s, then extended from its checkpoint to 0.1 s: the outputs of
 * the extension, as they are after the restart. */
static void test_restart_matches_reference(void **state)
{
    (void)state;
    char dir[512], case_file[512], checkpoint[600];
    snprintf(dir, sizeof dir, "%s/restart", group_dir);
    assert_int_equal(mkdir(dir, 0755), 0);
    snprintf(case_file, sizeof case_file, "%s/cases/default.ini", VCSPH_SOURCE_DIR);
    run_vcsph(dir, case_file,
              (const char *const[]){"case.t_end=0.05", "numerics.resolution=8",
                                    "output.snapshot_every=0.025", "output.timeseries_every=0.01",
                                    OUTPUTS, NULL},
              lanes_env);
    snprintf(checkpoint, sizeof checkpoint, "%s/checkpoint.h5", dir);
    static char *const env[] = {"OMP_NUM_THREADS=1", NULL};
    int rc = vcsph_child_run(dir,
                             (const char *const[]){"run", "--restart", checkpoint, "--quiet",
                                                   "--set", "case.t_end=0.1", NULL},
                             env);
    assert_int_equal(rc, 0);
    char *digest = digest_of_run(dir);
    compare_with_reference("restart", digest);
    free(digest);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_runs_match_references),
        cmocka_unit_test(test_scalar_form_matches_reference),
        cmocka_unit_test(test_restart_matches_reference),
    };
    return cmocka_run_group_tests(tests, make_group_dir, remove_group_dir);
}
