/* Tests of the case-file parser (docs/case-file.md) on good input: defaults, a full file,
 * overrides, and the round trip config_write -> config_load. Bad input: test_config_errors.c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <dirent.h>
#include <string.h>
#include <unistd.h>

#include <ini.h>

#include "core/config.h"

#include "config_case.h"

/* ---- good files --------------------------------------------------------------------------- */

static void test_minimal_gives_defaults(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    int rc = config_load(&c, DATA_DIR "/minimal.ini", NULL, 0, err, sizeof err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_string_equal(c.name, "minimal"); /* the file's name without ".ini" */
    assert_int_equal(c.dim, 2);
    assert_true(c.t_end == 1.0);
    assert_true(c.tank_length == 1.0 && c.tank_height == 0.5 && c.tank_width == 1.0);
    assert_true(c.liquid_height == 0.2);
    assert_true(c.liquid_length == 1.0); /* default: the tank length */
    assert_true(c.liquid_x0 == 0.0 && c.liquid_y0 == 0.0);
    assert_int_equal(c.liquid_shape, LIQUID_BOX); /* the whole box, as before the key */
    assert_true(c.density == 1000.0 && c.viscosity == 1.0e-6);
    assert_true(c.surface_tension == 0.0 && c.gravity == 9.81);
    assert_int_equal(c.motion, MOTION_NONE);
    assert_true(c.amplitude == 0.0 && c.period == 0.0 && c.decay == 0.0);
    assert_true(c.phase == 0.0 && c.duration == 0.0);
    assert_string_equal(c.motion_file, "");
    assert_int_equal(c.scheme, SCHEME_DELTA_PLUS_ALE);
    /* auto, resolved for delta-plus-ALE (docs/case-file.md) */
    assert_int_equal(c.edbc, EDBC_WITH_ETA0);
    assert_int_equal(c.volume_correction, VOLUME_CORRECTION_GEOMETRIC);
    assert_true(c.eta_threshold == 0.01);
    assert_int_equal(c.eta_control, ETA_CONTROL_THRESHOLD);
    assert_true(c.les);
    assert_int_equal(c.wall, WALL_NO_SLIP);
    assert_int_equal(c.resolution, 20);
    assert_true(c.h_over_dr == 2.0);                   /* 2D default */
    assert_true(c.sound_speed == 0.0 && c.cfl == 0.0); /* auto */
    assert_int_equal(c.n_gauges, 0);
    assert_int_equal(c.n_pressure_probes, 0);
    assert_string_equal(c.output_dir, "out/minimal");
    assert_true(c.timeseries_every == 0.0 && c.snapshot_every == 0.0 && c.image_every == 0.0);
    assert_true(c.checkpoint_every == 600.0);
    assert_false(c.graphical);
}

static void test_3d_default_h_over_dr(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    const char *set[] = {"case.dim=3"};
    assert_int_equal(load_text(&c, MINIMAL, set, 1, err), 0);
    assert_true(c.h_over_dr == 1.5);
    const char *set2[] = {"case.dim=3", "numerics.h_over_dr=1.2"};
    assert_int_equal(load_text(&c, MINIMAL, set2, 2, err), 0);
    assert_true(c.h_over_dr == 1.2);
}

static void test_full_file(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    int rc = config_load(&c, DATA_DIR "/full.ini", NULL, 0, err, sizeof err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_string_equal(c.name, "full-test");
    assert_int_equal(c.dim, 3);
    assert_true(c.t_end == 12.5);
    assert_true(c.tank_length == 1.2 && c.tank_height == 0.6 && c.tank_width == 0.3);
    assert_true(c.liquid_height == 0.25 && c.liquid_length == 0.8);
    assert_true(c.liquid_x0 == 0.1 && c.liquid_y0 == 0.05);
    assert_int_equal(c.liquid_shape, LIQUID_ELLIPSE);
    assert_true(c.density == 998.2 && c.viscosity == 1.0e-5);
    assert_true(c.surface_tension == 0.0728 && c.gravity == 9.80665);
    assert_int_equal(c.motion, MOTION_TABLE);
    assert_true(c.amplitude == 0.02 && c.period == 1.5 && c.decay == 0.1);
    assert_true(c.phase == 0.5 && c.duration == 10.0);
    /* Not readable from the test's directory, so found beside the case file. */
    assert_true(strcmp(c.motion_file, DATA_DIR "/motion.csv") == 0 ||
                strcmp(c.motion_file, "motion.csv") == 0);
    assert_int_equal(c.scheme, SCHEME_DELTA_ALE);
    assert_int_equal(c.edbc, EDBC_WITH_ETA0);
    assert_true(c.eta_threshold == 0.02);
    assert_int_equal(c.eta_control, ETA_CONTROL_ADAPTIVE);
    assert_false(c.les);
    assert_int_equal(c.wall, WALL_FREE_SLIP);
    assert_int_equal(c.resolution, 40);
    assert_true(c.h_over_dr == 1.8 && c.sound_speed == 25.0 && c.cfl == 1.5);
    assert_int_equal(c.n_gauges, 3);
    assert_true(c.gauges[0] == 0.1 && c.gauges[1] == 0.6 && c.gauges[2] == 1.1);
    assert_int_equal(c.n_pressure_probes, 2);
    assert_true(c.pressure_probes[0][0] == 0.0 && c.pressure_probes[0][1] == 0.1);
    assert_true(c.pressure_probes[0][2] == 0.15 && c.pressure_probes[1][0] == 1.2);
    assert_true(c.pressure_probes[1][1] == 0.2 && c.pressure_probes[1][2] == 0.15);
    /* the first is a sensor of 1 cm on the wall x = 0, the second a point on x = L */
    assert_true(c.pressure_probes[0][3] == 0.01 && c.pressure_probes[1][3] == 0.0);
    assert_int_equal(config_wall_axis(&c, c.pressure_probes[0]), 0);
    assert_string_equal(c.output_dir, "results/full-test-run");
    assert_true(c.timeseries_every == 0.01 && c.snapshot_every == 0.5);
    assert_true(c.image_every == 0.25 && c.checkpoint_every == 0.0);
    assert_true(c.graphical);
}

/* BOM, CRLF, '#' and ';' comments, blank lines, indentation, "key: value" and an empty list
 * are all plain INI that a hand-edited file may hold. */
static void test_tolerated_syntax(void **state)
{
    (void)state;
    const char *text = "\xEF\xBB\xBF# a comment\r\n[case] ; the case\r\n  t_end: 2\r\n\r\n"
                       "[tank]\nlength = 1\nheight = 1\n[liquid]\nheight = 0.5\n"
                       "[numerics]\nresolution = 10\ncfl = 2\n[probes]\ngauges =\n"
                       "pressure = 0.5 0.5;0.25 0.25 ; two points\n";
    config c;
    char err[ERR_LEN];
    int rc = load_text(&c, text, NULL, 0, err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_true(c.t_end == 2.0 && c.cfl == 2.0);
    assert_int_equal(c.n_gauges, 0);
    assert_int_equal(c.n_pressure_probes, 2);
    assert_true(c.pressure_probes[1][0] == 0.25 && c.pressure_probes[1][2] == 0.0);
}

static void test_overrides_in_order(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    /* The file lacks the required resolution: an override may give it. */
    const char *text =
        "[case]\nt_end = 1\n[tank]\nlength = 1\nheight = 1\n[liquid]\nheight = 0.5\n";
    const char *set[] = {" numerics.resolution = 30 ", "model.scheme=delta",
                         "model.scheme=standard",      "case.name=sap",
                         "motion.type=sway",           "motion.period=1.25"};
    int rc = load_text(&c, text, set, 6, err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_int_equal(c.resolution, 30);
    assert_int_equal(c.scheme, SCHEME_STANDARD);  /* the last one wins */
    assert_string_equal(c.output_dir, "out/sap"); /* the default follows the name */
    assert_int_equal(c.motion, MOTION_SWAY);
    assert_true(c.period == 1.25);
}

static void test_motion_file_from_current_directory(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    const char *set[] = {"motion.type=table", "motion.file=" DATA_DIR "/motion.csv"};
    assert_int_equal(load_text(&c, MINIMAL, set, 2, err), 0);
    assert_string_equal(c.motion_file, DATA_DIR "/motion.csv");
}

static void test_names(void **state)
{
    (void)state;
    assert_string_equal(config_scheme_name(SCHEME_STANDARD), "standard");
    assert_string_equal(config_scheme_name(SCHEME_DELTA), "delta");
    assert_string_equal(config_scheme_name(SCHEME_DELTA_PLUS), "delta-plus");
    assert_string_equal(config_scheme_name(SCHEME_DELTA_ALE), "delta-ale");
    assert_string_equal(config_scheme_name(SCHEME_DELTA_PLUS_ALE), "delta-plus-ale");
    assert_string_equal(config_motion_name(MOTION_NONE), "none");
    assert_string_equal(config_motion_name(MOTION_SWAY), "sway");
    assert_string_equal(config_motion_name(MOTION_HEAVE), "heave");
    assert_string_equal(config_motion_name(MOTION_TABLE), "table");
    assert_string_equal(config_edbc_name(EDBC_OFF), "false");
    assert_string_equal(config_edbc_name(EDBC_ON), "true");
    assert_string_equal(config_edbc_name(EDBC_WITH_ETA0), "with-eta0");
    assert_string_equal(config_volume_correction_name(VOLUME_CORRECTION_NONE), "none");
    assert_string_equal(config_volume_correction_name(VOLUME_CORRECTION_GEOMETRIC), "geometric");
    assert_string_equal(config_eta_control_name(ETA_CONTROL_THRESHOLD), "threshold");
    assert_string_equal(config_eta_control_name(ETA_CONTROL_ADAPTIVE), "adaptive");
    assert_string_equal(config_wall_name(WALL_NO_SLIP), "no-slip");
    assert_string_equal(config_wall_name(WALL_FREE_SLIP), "free-slip");
    assert_string_equal(config_liquid_shape_name(LIQUID_BOX), "box");
    assert_string_equal(config_liquid_shape_name(LIQUID_ELLIPSE), "ellipse");
}

/* ---- round trip --------------------------------------------------------------------------- */

static void assert_round_trip(const config *a)
{
    char *text = config_text(a);
    assert_non_null(text);
    config b;
    char err[ERR_LEN];
    int rc = config_load_string(&b, text, "written", NULL, 0, err, sizeof err);
    if (rc) print_error("%s\n%s", err, text);
    assert_int_equal(rc, 0);
    assert_memory_equal(a, &b, sizeof b);
    free(text);
}

static void test_round_trip_minimal_and_full(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    assert_int_equal(config_load(&c, DATA_DIR "/minimal.ini", NULL, 0, err, sizeof err), 0);
    assert_round_trip(&c);
    assert_int_equal(config_load(&c, DATA_DIR "/full.ini", NULL, 0, err, sizeof err), 0);
    assert_round_trip(&c);
}

/* Numbers that print badly with %g, a negative zero, a subnormal, and the most probes. */
static void test_round_trip_awkward_values(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    const char *set[] = {"case.t_end=0.30000000000000004",
                         "motion.phase=-0.0",
                         "fluid.viscosity=5e-324",
                         "motion.type=heave",
                         "motion.period=0.1",
                         "numerics.sound_speed=12.3456789012345678",
                         "probes.gauges=0.1 0.2,0.3"};
    int rc = load_text(&c, MINIMAL, set, 7, err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_round_trip(&c);

    static char points[65 * 80];
    size_t used = 0;
    for (int i = 0; i < CONFIG_PROBES_MAX; i++)
        used +=
            (size_t)snprintf(points + used, sizeof points - used,
                             "%s0.%d 0.1%d 0.123456789012345%d", i ? "; " : "", i + 1, i, i % 10);
    char text[sizeof points + 256];
    snprintf(text, sizeof text, MINIMAL "[probes]\npressure = %s\n", points);
    const char *three_d[] = {"case.dim=3"};
    rc = load_text(&c, text, three_d, 1, err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_int_equal(c.n_pressure_probes, CONFIG_PROBES_MAX);
    assert_round_trip(&c);

    snprintf(text, sizeof text, MINIMAL "[probes]\npressure = %s; 0.5 0.1 0.1\n", points);
    assert_int_equal(load_text(&c, text, three_d, 1, err), 2);
    assert_contains(err, "more than 64 pressure probes");
}

/* liquid.shape: box by default, ellipse from the file or --set, each written back. */
static void test_liquid_shape(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    assert_int_equal(load_text(&c, MINIMAL, NULL, 0, err), 0);
    assert_int_equal(c.liquid_shape, LIQUID_BOX);
    assert_int_equal(load_text(&c, MINIMAL "[liquid]\nshape = box\n", NULL, 0, err), 0);
    assert_int_equal(c.liquid_shape, LIQUID_BOX);
    int rc = load_text(&c, MINIMAL "[liquid]\nshape = ellipse\n", NULL, 0, err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_int_equal(c.liquid_shape, LIQUID_ELLIPSE);
    const char *set[] = {"liquid.shape=ellipse", "liquid.y0=0.1", "fluid.gravity=0"};
    rc = load_text(&c, MINIMAL, set, 3, err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_int_equal(c.liquid_shape, LIQUID_ELLIPSE);
    assert_round_trip(&c);
}

/* motion.center: the tank's bottom centre by default (z at mid-width in 3D), as given
 * otherwise; a 3D point given without z takes the mid-width; the resolved case writes it back. */
static void test_motion_center(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    assert_int_equal(
        load_text(&c, MINIMAL "[motion]\ntype = roll\nangle = 0.1\nperiod = 1\n", NULL, 0, err), 0);
    assert_true(c.motion == MOTION_ROLL && c.motion_center[0] == 0.5 && c.motion_center[1] == 0.0 &&
                c.motion_center[2] == 0.0);
    assert_round_trip(&c);
    const char *three_d[] = {"case.dim=3", "tank.width=0.3", "motion.center=0.2 0.1"};
    int rc = load_text(&c, MINIMAL, three_d, 3, err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_true(c.motion_center[0] == 0.2 && c.motion_center[1] == 0.1 &&
                c.motion_center[2] == 0.15);
    assert_round_trip(&c);
}

/* model.edbc and model.volume_correction default to auto, resolved by the scheme: with-eta0
 * and geometric for delta-plus-ALE, false and none for the other four (the paper's Fig. 7
 * baseline); an explicit value is kept whatever the scheme; the resolved case says the
 * resolved value, never auto. */
static void test_scheme_dependent_defaults(void **state)
{
    (void)state;
    static const char *const schemes[] = {"standard", "delta", "delta-plus", "delta-ale",
                                          "delta-plus-ale"};
    config c;
    char err[ERR_LEN], set[64];
    for (int k = 0; k < 5; k++) {
        snprintf(set, sizeof set, "model.scheme=%s", schemes[k]);
        const char *sets[] = {set};
        assert_int_equal(load_text(&c, MINIMAL, sets, 1, err), 0);
        bool plus_ale = k == 4;
        assert_int_equal(c.edbc, plus_ale ? EDBC_WITH_ETA0 : EDBC_OFF);
        assert_int_equal(c.volume_correction,
                         plus_ale ? VOLUME_CORRECTION_GEOMETRIC : VOLUME_CORRECTION_NONE);
        assert_round_trip(&c);
        const char *explicit[] = {set, "model.edbc=true", "model.volume_correction=geometric"};
        assert_int_equal(load_text(&c, MINIMAL, explicit, 3, err), 0);
        assert_int_equal(c.edbc, EDBC_ON);
        assert_int_equal(c.volume_correction, VOLUME_CORRECTION_GEOMETRIC);
        explicit[2] = "model.volume_correction=none";
        assert_int_equal(load_text(&c, MINIMAL, explicit, 3, err), 0);
        assert_int_equal(c.volume_correction, VOLUME_CORRECTION_NONE);
    }
    const char *bad[] = {"model.volume_correction=khayyer"};
    assert_int_equal(load_text(&c, MINIMAL, bad, 1, err), 2);
    assert_non_null(strstr(err, "model.volume_correction"));
}

/* Every key of docs/case-file.md is written, each section once, in the order of docs/case-file.md.
 */
static void test_write_has_every_key(void **state)
{
    (void)state;
    config c;
    char err[ERR_LEN];
    assert_int_equal(config_load(&c, DATA_DIR "/minimal.ini", NULL, 0, err, sizeof err), 0);
    char *text = config_text(&c);
    assert_non_null(text);
    static const char *const order[] = {"[case]",  "[tank]",     "[liquid]", "[fluid]", "[motion]",
                                        "[model]", "[numerics]", "[probes]", "[output]"};
    const char *at = text;
    for (size_t i = 0; i < sizeof order / sizeof order[0]; i++) {
        const char *hit = strstr(at, order[i]);
        assert_non_null(hit);
        at = hit;
    }
    int n_keys = 0;
    for (const char *line = text; line && *line; line = strchr(line, '\n')) {
        if (*line == '\n') line++;
        if (*line && *line != ';' && *line != '[' && *line != '\n') n_keys++;
    }
    /* docs/case-file.md plus numerics.density_bound, liquid.shape, case.experiment_dissipation,
       model.volume_correction and motion.angle, angle_phase, center */
    assert_int_equal(n_keys, 51);
    assert_non_null(strstr(text, "\nsound_speed      = auto ;"));
    assert_non_null(strstr(text, "\nh_over_dr        = 2 ;"));
    assert_non_null(strstr(text, "\nlength           = 1 ;"));
    assert_non_null(strstr(text, "\nshape            = box ;"));
    free(text);
}

/* case.name defaults to the case file's base name without its extension (the characters a
 * name may not hold made '_'), "case" for a string; a given name wins. output.dir follows. */
static void test_name_defaults_to_file_name(void **state)
{
    (void)state;
    static const struct {
        const char *file, *name;
    } rows[] = {
        {"sway-a5.ini", "sway-a5"},     {"run.v2.ini", "run.v2"}, {"noext", "noext"},
        {"odd name!.ini", "odd_name_"}, {"_x.ini", "case-_x"},    {".hidden", "case-.hidden"},
    };
    char dir[] = "/tmp/vcsph_test_name_XXXXXX";
    assert_non_null(mkdtemp(dir));
    config c;
    char err[ERR_LEN], path[512], out[600];
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, rows[i].file);
        FILE *f = fopen(path, "w");
        assert_non_null(f);
        fputs(MINIMAL, f);
        fclose(f);
        int rc = config_load(&c, path, NULL, 0, err, sizeof err);
        if (rc) print_error("%s\n", err);
        assert_int_equal(rc, 0);
        assert_string_equal(c.name, rows[i].name);
        snprintf(out, sizeof out, "out/%s", rows[i].name);
        assert_string_equal(c.output_dir, out);
        const char *named[] = {"case.name=given"};
        assert_int_equal(config_load(&c, path, named, 1, err, sizeof err), 0);
        assert_string_equal(c.name, "given");
        unlink(path);
    }
    rmdir(dir);
    assert_int_equal(load_text(&c, MINIMAL, NULL, 0, err), 0);
    assert_string_equal(c.name, "case");
    assert_string_equal(c.output_dir, "out/case");
    assert_int_equal(load_text(&c, MINIMAL "[case]\nname = named\n", NULL, 0, err), 0);
    assert_string_equal(c.name, "named");
}

/* '#' starts a comment as ';' does: on a line of its own, and after white space in a value;
 * inside a word it is kept. */
static void test_hash_comments(void **state)
{
    (void)state;
    const char *text = "# a case\n" MINIMAL "  # indented comment\n"
                       "[output]  # the outputs\n"
                       "dir = out/run#2   # the second run\n"
                       "timeseries_every = 0.5 # s\n"
                       "[probes]\ngauges = 0.25, 0.5 # two gauges\n";
    config c;
    char err[ERR_LEN];
    int rc = load_text(&c, text, NULL, 0, err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_string_equal(c.output_dir, "out/run#2");
    assert_true(c.timeseries_every == 0.5);
    assert_int_equal(c.n_gauges, 2);
    assert_round_trip(&c);
    /* a path that would read back as a comment is refused, as with ';' */
    const char *set[] = {"output.dir=out/a #b"};
    assert_int_equal(load_text(&c, MINIMAL, set, 1, err), 2);
    assert_contains(err, "output.dir");
    assert_contains(err, "'#'");
    const char *first[] = {"output.dir=#b"};
    assert_int_equal(load_text(&c, MINIMAL, first, 1, err), 2);
    assert_contains(err, "output.dir");
}

static void test_repo_cases_load(void **state)
{
    (void)state;
    DIR *dir = opendir(VCSPH_SOURCE_DIR "/cases");
    if (!dir) skip();
    for (struct dirent *e; (e = readdir(dir));) {
        size_t n = strlen(e->d_name);
        if (n < 5 || strcmp(e->d_name + n - 4, ".ini") != 0) continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/cases/%s", VCSPH_SOURCE_DIR, e->d_name);
        config c;
        char err[ERR_LEN];
        int rc = config_load(&c, path, NULL, 0, err, sizeof err);
        if (rc) print_error("%s\n", err);
        assert_int_equal(rc, 0);
        assert_round_trip(&c);
    }
    closedir(dir);
}

/* inih's options are library globals: the parser sets its own and puts the old ones back. */
static void test_inih_options_restored(void **state)
{
    (void)state;
    bool multiline = ini_allow_multiline;
    int max_line = ini_max_line;
    config c;
    char err[ERR_LEN];
    assert_int_equal(load_text(&c, MINIMAL, NULL, 0, err), 0);
    assert_int_equal(load_text(&c, "[bad\n", NULL, 0, err), 2);
    assert_int_equal(ini_allow_multiline, multiline);
    assert_int_equal(ini_max_line, max_line);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_minimal_gives_defaults),
        cmocka_unit_test(test_3d_default_h_over_dr),
        cmocka_unit_test(test_full_file),
        cmocka_unit_test(test_tolerated_syntax),
        cmocka_unit_test(test_overrides_in_order),
        cmocka_unit_test(test_motion_file_from_current_directory),
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_name_defaults_to_file_name),
        cmocka_unit_test(test_hash_comments),
        cmocka_unit_test(test_round_trip_minimal_and_full),
        cmocka_unit_test(test_round_trip_awkward_values),
        cmocka_unit_test(test_liquid_shape),
        cmocka_unit_test(test_motion_center),
        cmocka_unit_test(test_scheme_dependent_defaults),
        cmocka_unit_test(test_write_has_every_key),
        cmocka_unit_test(test_inih_options_restored),
        cmocka_unit_test(test_repo_cases_load),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
