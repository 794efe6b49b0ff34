/* Tests of the case-file parser (docs/case-file.md) on bad input: one test per kind (each must
 * give exit status 2 and a message naming file, line and key), required keys missing, lines too
 * long, unreadable files. Good input: test_config.c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "config_case.h"

/* Every missing required key in one message (one line), each with where it belongs. */
static void test_missing_keys_in_one_message(void **state)
{
    (void)state;
    static const char *const required[] = {"case.t_end", "tank.length", "tank.height",
                                           "liquid.height", "numerics.resolution"};
    config c;
    char err[ERR_LEN];
    assert_int_equal(load_text(&c, "", NULL, 0, err), 2);
    for (size_t i = 0; i < sizeof required / sizeof required[0]; i++)
        assert_contains(err, required[i]);
    assert_contains(err, "5 required keys missing");
    assert_contains(err, "section [numerics] missing too");
    assert_null(strchr(err, '\n'));

    /* two of them, in sections that are there: at the first one's section header */
    const char *text = "[case]\nt_end = 1\n[tank]\nlength = 1\n[liquid]\n[numerics]\n";
    assert_int_equal(load_text(&c, text, NULL, 0, err), 2);
    assert_contains(err, "bad.ini:3: 3 required keys missing: ");
    assert_contains(err, "tank.height (in [tank], line 3: a length > 0 (m))");
    assert_contains(err, "liquid.height (in [liquid], line 5");
    assert_contains(err, "numerics.resolution (in [numerics], line 6");
    assert_null(strstr(err, "case.t_end"));
    assert_null(strstr(err, "tank.length"));
    /* --set may give them */
    const char *set[] = {"tank.height=1", "liquid.height=0.5", "numerics.resolution=10"};
    assert_int_equal(load_text(&c, text, set, 3, err), 0);
}

/* ---- bad input: status 2 and one message with file, line and key ------------------------- */

typedef struct {
    const char *name;
    const char *text;
    const char *set[3];
    int n_set;
    const char *expect[4];
} bad_case;

/* A bad file without overrides: its name, its text, what the message must contain. */
#define BAD(name, text, ...)                                                                       \
    {                                                                                              \
        name, text, {0}, 0, { __VA_ARGS__ }                                                        \
    }

static const bad_case bad_cases[] = {
    BAD("unknown section", MINIMAL "[tnak]\nlength = 2\n", "bad.ini:10: ", "unknown section [tnak]",
        "did you mean [tank]?"),
    BAD("unknown empty section", MINIMAL "\n[outptu]\n", "bad.ini:11: ", "[outptu]",
        "did you mean [output]?"),
    BAD("unknown key", "[case]\nt_end = 1\n[tank]\nlenght = 1.0\n", "bad.ini:4: ", "'tank.lenght'",
        "did you mean 'tank.length'?"),
    BAD("unknown key, no hint", MINIMAL "[fluid]\ncolour = blue\n",
        "bad.ini:11: ", "'fluid.colour'", "density, viscosity"),
    BAD("key in the wrong section", MINIMAL "[tank]\ngravity = 9.81\n",
        "bad.ini:11: ", "'tank.gravity'", "did you mean 'fluid.gravity'?"),
    BAD("missing required key",
        "[case]\nt_end = 1.0\n[tank]\nlength = 1.0\n[liquid]\nheight = 0.2\n"
        "[numerics]\nresolution = 20\n",
        "bad.ini:3: ", "tank.height", "missing", "required"),
    BAD("missing section",
        "[case]\nt_end = 1.0\n[tank]\nlength = 1.0\nheight = 0.5\n[liquid]\nheight = 0.2\n",
        "bad.ini: ", "numerics.resolution", "missing", "required"),
    BAD("bad number", "[case]\nt_end = 1\n[tank]\nlength = 1.0abc\n",
        "bad.ini:4: ", "tank.length = 1.0abc", "not a finite decimal number", "> 0 (m)"),
    BAD("empty number", "[case]\nt_end =\n",
        "bad.ini:2: ", "case.t_end = :", "not a finite decimal number"),
    BAD("infinite number", "[case]\nt_end = inf\n", "bad.ini:2: ", "case.t_end = inf"),
    BAD("nan", "[case]\nt_end = nan\n", "bad.ini:2: ", "case.t_end = nan"),
    BAD("hex float", "[case]\nt_end = 0x1p-4\n", "bad.ini:2: ", "case.t_end = 0x1p-4",
        "not a finite decimal number"),
    BAD("hex float in a list", MINIMAL "[motion]\ncenter = 0.5 0x1p-2\n",
        "bad.ini:11: ", "'0x1p-2' is not a finite decimal number"),
    BAD("overflowing number", "[case]\nt_end = 1e999\n", "bad.ini:2: ", "case.t_end = 1e999"),
    BAD("negative length", "[case]\nt_end = 1\n[tank]\nlength = -1\n",
        "bad.ini:4: tank.length = -1: must be a length > 0 (m)"),
    BAD("zero t_end", "[case]\nt_end = 0\n", "bad.ini:2: ", "case.t_end = 0", "> 0 (s)"),
    BAD("liquid higher than the tank",
        "[case]\nt_end = 1.0\n[tank]\nlength = 1.0\nheight = 0.5\n[liquid]\nheight = 0.6\n"
        "[numerics]\nresolution = 20\n",
        "bad.ini:7: ", "liquid.height = 0.6", "liquid higher than the tank"),
    BAD("liquid lifted out of the tank", MINIMAL "[liquid]\ny0 = 0.4\n",
        "bad.ini:7: ", "liquid.height", "liquid higher than the tank"),
    BAD("liquid longer than the tank", MINIMAL "[liquid]\nx0 = 0.5\n",
        "bad.ini:11: ", "liquid.x0 = 0.5", "longer than the tank"),
    BAD("negative x0", MINIMAL "[liquid]\nx0 = -0.1\n", "bad.ini:11: ", "liquid.x0", ">= 0"),
    BAD("unknown liquid shape", MINIMAL "[liquid]\nshape = circle\n",
        "bad.ini:11: liquid.shape = circle: must be one of box | ellipse"),
    BAD("misspelt liquid shape", MINIMAL "[liquid]\nshape = elipse\n",
        "bad.ini:11: liquid.shape = elipse: ", "did you mean 'ellipse'?", "box | ellipse"),
    BAD("resolution below 4", "[case]\nt_end = 1.0\n[numerics]\nresolution = 3\n",
        "bad.ini:4: ", "numerics.resolution = 3", "integer >= 4"),
    BAD("resolution not an integer", "[numerics]\nresolution = 20.5\n",
        "bad.ini:2: ", "numerics.resolution = 20.5", "not an integer"),
    BAD("dim not 2 or 3", "[case]\ndim = 4\n", "bad.ini:2: ", "case.dim = 4", "2 or 3"),
    BAD("unknown scheme", MINIMAL "[model]\nscheme = delta_plus\n", "bad.ini:11: ",
        "model.scheme = delta_plus", "did you mean 'delta-plus'?", "delta-plus-ale"),
    BAD("unknown edbc", MINIMAL "[model]\nedbc = with_eta0\n", "bad.ini:11: ", "model.edbc",
        "did you mean 'with-eta0'?"),
    BAD("boolean yes", MINIMAL "[model]\nles = yes\n", "bad.ini:11: ", "model.les = yes",
        "true or false"),
    BAD("duplicate key", "[case]\nt_end = 1\nt_end = 2\n", "bad.ini:3: ", "case.t_end",
        "first on line 2"),
    BAD("density zero", MINIMAL "[fluid]\ndensity = 0\n", "bad.ini:11: ", "fluid.density = 0"),
    BAD("viscosity zero", MINIMAL "[fluid]\nviscosity = 0\n", "bad.ini:11: ", "fluid.viscosity"),
    BAD("negative gravity", MINIMAL "[fluid]\ngravity = -9.81\n", "bad.ini:11: ", "fluid.gravity"),
    BAD("negative surface tension", MINIMAL "[fluid]\nsurface_tension = -1\n",
        "bad.ini:11: ", "fluid.surface_tension"),
    BAD("negative amplitude", MINIMAL "[motion]\namplitude = -1\n",
        "bad.ini:11: ", "motion.amplitude"),
    BAD("negative decay", MINIMAL "[motion]\ndecay = -1\n", "bad.ini:11: ", "motion.decay"),
    BAD("negative duration", MINIMAL "[motion]\nduration = -1\n",
        "bad.ini:11: ", "motion.duration"),
    BAD("sway without period", MINIMAL "[motion]\ntype = sway\namplitude = 0.01\n",
        "bad.ini:10: ", "motion.period", "missing", "> 0 (s) when motion.type = sway"),
    BAD("heave with period 0", MINIMAL "[motion]\ntype = heave\nperiod = 0\n",
        "bad.ini:12: ", "motion.period = 0", "when motion.type = heave"),
    BAD("roll without period", MINIMAL "[motion]\ntype = roll\nangle = 0.1\n",
        "bad.ini:10: ", "motion.period", "missing", "when motion.type = roll"),
    BAD("pitch in 2D", MINIMAL "[motion]\ntype = pitch\nangle = 0.1\nperiod = 1\n",
        "bad.ini:11: ", "motion.type = pitch", "3D only"),
    BAD("negative angle", MINIMAL "[motion]\nangle = -0.1\n", "bad.ini:11: ", "motion.angle"),
    BAD("motion file without a table",
        MINIMAL "[motion]\ntype = sway\namplitude = 0.05\n"
                "period = 1\nfile = sway.csv\n",
        "bad.ini:14: ", "motion.file = sway.csv",
        "applies only to motion.type = table, and the type is sway"),
    BAD("center with one coordinate", MINIMAL "[motion]\ncenter = 0.5\n",
        "bad.ini:11: ", "motion.center = 0.5", "1 coordinate"),
    BAD("center not a number", MINIMAL "[motion]\ncenter = 0.5 up\n",
        "bad.ini:11: ", "motion.center", "'up' is not a finite decimal number"),
    BAD("table without file", MINIMAL "[motion]\ntype = table\n", "bad.ini:10: ", "motion.file",
        "required when motion.type = table"),
    BAD("table with a missing file", MINIMAL "[motion]\ntype = table\nfile = no/such.csv\n",
        "bad.ini:12: ", "motion.file = no/such.csv", "cannot read"),
    BAD("eta_threshold 1", MINIMAL "[model]\neta_threshold = 1\n",
        "bad.ini:11: ", "model.eta_threshold = 1", "(0, 1)"),
    BAD("h_over_dr 5", MINIMAL "[numerics]\nh_over_dr = 5\n",
        "bad.ini:11: ", "numerics.h_over_dr = 5", "[1, 4]"),
    BAD("negative sound speed", MINIMAL "[numerics]\nsound_speed = -3\n",
        "bad.ini:11: ", "numerics.sound_speed = -3", "auto or a speed > 0"),
    BAD("cfl zero", MINIMAL "[numerics]\ncfl = 0\n", "bad.ini:11: ", "numerics.cfl = 0", "(0, 2]"),
    BAD("cfl too large", MINIMAL "[numerics]\ncfl = 2.5\n", "bad.ini:11: ", "numerics.cfl = 2.5"),
    BAD("negative output interval", MINIMAL "[output]\nsnapshot_every = -1\n",
        "bad.ini:11: ", "output.snapshot_every"),
    BAD("empty output dir", MINIMAL "[output]\ndir =\n", "bad.ini:11: ", "output.dir", "empty"),
    BAD("bad case name", "[case]\nname = a/b\n", "bad.ini:2: ", "case.name = a/b"),
    BAD("gauge outside the tank", MINIMAL "[probes]\ngauges = 0.5, 1.5\n",
        "bad.ini:11: ", "probes.gauges", "gauge 2 at x = 1.5 m is outside the tank"),
    BAD("gauge list with a stray comma", MINIMAL "[probes]\ngauges = 0.5,, 0.6\n",
        "bad.ini:11: ", "probes.gauges", "unexpected ','"),
    BAD("gauge list with ';'", MINIMAL "[probes]\ngauges = 0.5;0.6\n",
        "bad.ini:11: ", "probes.gauges", "'0.5;0.6'"),
    BAD("pressure point with 3 coordinates in 2D", MINIMAL "[probes]\npressure = 0.5 0.1 0.1\n",
        "bad.ini:11: ", "probes.pressure = 0.5 0.1 0.1", "3 coordinates but case.dim = 2"),
    BAD("pressure points of mixed sizes", MINIMAL "[probes]\npressure = 0.5 0.1; 0.5 0.1 0.1\n",
        "bad.ini:11: ", "probes.pressure", "point 2 has 3 coordinates"),
    BAD("pressure point outside the tank", MINIMAL "[probes]\npressure = 0.5 0.6\n",
        "bad.ini:11: ", "probes.pressure", "y = 0.6 m is outside the tank"),
    BAD("pressure sensor away from the walls", MINIMAL "[probes]\npressure = 0.5 0.1 d=0.01\n",
        "bad.ini:11: ", "probes.pressure", "sensor 1 (d = 0.01 m) must lie on one wall"),
    BAD("pressure sensor in a corner", MINIMAL "[probes]\npressure = 0 0 d=0.01\n",
        "bad.ini:11: ", "probes.pressure", "not on an edge or corner"),
    BAD("pressure sensor past the wall's edge", MINIMAL "[probes]\npressure = 0 0.02 d=0.05\n",
        "bad.ini:11: ", "probes.pressure", "reaches past the wall's edge at y = 0 m"),
    BAD("pressure sensor of negative diameter", MINIMAL "[probes]\npressure = 0 0.1 d=-0.01\n",
        "bad.ini:11: ", "probes.pressure", "point 1: the diameter must be a length >= 0"),
    BAD("sensor filter without sensors", MINIMAL "[probes]\nfilter = butterworth\ncutoff = 100\n",
        "bad.ini:11: ", "probes.filter", "set probes.pressure"),
    BAD("sensor filter without a cut-off",
        MINIMAL "[probes]\npressure = 0 0.1\nfilter = first-order\n", "bad.ini:", "probes.cutoff",
        "cut-off frequency (Hz) > 0"),
    BAD("sensor filter above the sampling's Nyquist frequency",
        MINIMAL "[probes]\npressure = 0 0.1\nevery = 0.001\nfilter = butterworth\ncutoff = 500\n",
        "bad.ini:14: ", "probes.cutoff",
        "not below half the sampling rate 1 / probes.every = 1000 Hz"),
    BAD("unknown sensor filter", MINIMAL "[probes]\npressure = 0 0.1\nfilter = bessel\n",
        "bad.ini:12: ", "probes.filter = bessel", "one of raw | first-order | butterworth"),
    BAD("pressure sensor diameter before the coordinates",
        MINIMAL "[probes]\npressure = 0 d=0.01 0.1\n", "bad.ini:11: ", "probes.pressure",
        "'d=0.01' is not a finite decimal number"),
    BAD("pressure points cut by a comment", MINIMAL "[probes]\npressure = 0.5 0.1 ; 0.6 0.1\n",
        "bad.ini:11: ", "probes.pressure", "starts a comment"),
    BAD("gauges cut by a '#' comment", MINIMAL "[probes]\ngauges = 0.5 # 0.6\n",
        "bad.ini:11: ", "probes.gauges", "' #' starts a comment"),
    BAD("no multi-line values", MINIMAL "[probes]\ngauges = 0.1\n   0.3\n", "bad.ini:12: ", "'0.3'",
        "expected [section], key = value"),
    BAD("line without '='", MINIMAL "[fluid]\ndensity 1000\n", "bad.ini:11: ", "'density 1000'"),
    BAD("section without ']'", MINIMAL "[fluid\n", "bad.ini:10: ", "'[fluid'", "closing ']'"),
    BAD("text after a section header", MINIMAL "[fluid] density = 1\n",
        "bad.ini:10: ", "after [fluid]"),
    BAD("key before any section", "t_end = 1\n[case]\n", "bad.ini:1: ", "'t_end'",
        "before any [section]"),
    {"override without '='",
     MINIMAL,
     {"tank.length"},
     1,
     {"--set tank.length", "section.key=value"}},
    {"override without '.'", MINIMAL, {"length=2"}, 1, {"--set length=2", "section.key=value"}},
    {"override of an unknown key",
     MINIMAL,
     {"tank.lenght=2"},
     1,
     {"--set: ", "'tank.lenght'", "did you mean 'tank.length'?"}},
    {"override of an unknown section",
     MINIMAL,
     {"tnak.length=2"},
     1,
     {"--set: ", "[tnak]", "did you mean [tank]?"}},
    {"override with a bad value",
     MINIMAL,
     {"numerics.resolution=20", "tank.length=-2"},
     2,
     {"--set: tank.length = -2: must be a length > 0 (m)"}},
    {"override that floods the tank",
     MINIMAL,
     {"liquid.height=0.9"},
     1,
     {"--set: liquid.height = 0.9", "liquid higher than the tank"}},
};
#define N_BAD (sizeof bad_cases / sizeof bad_cases[0])

static void test_bad(void **state)
{
    const bad_case *b = *state;
    config c;
    char err[ERR_LEN] = "";
    assert_int_equal(load_text(&c, b->text, b->set, b->n_set, err), 2);
    for (int i = 0; i < 4 && b->expect[i]; i++) assert_contains(err, b->expect[i]);
    assert_null(strchr(err, '\n')); /* one message, one line */
}

static void test_line_too_long(void **state)
{
    (void)state;
    static char text[10000];
    int n = snprintf(text, sizeof text, MINIMAL "[probes]\ngauges = ");
    memset(text + n, '1', sizeof text - (size_t)n - 2);
    text[sizeof text - 2] = '\n';
    config c;
    char err[ERR_LEN];
    assert_int_equal(load_text(&c, text, NULL, 0, err), 2);
    assert_contains(err, "bad.ini:11: line longer than");
}

/* Messages about a real file name its path, and motion.file is found beside it. */
static void test_errors_name_the_file(void **state)
{
    (void)state;
    char dir[] = "/tmp/vcsph_test_config_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char path[256], table[256];
    snprintf(path, sizeof path, "%s/case.ini", dir);
    snprintf(table, sizeof table, "%s/wave.csv", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("[case]\nt_end = 1\n\n[tank]  ; comment\nheight = 1\nlength = 1.0abc\n", f);
    fclose(f);
    config c;
    char err[ERR_LEN], expect[300];
    assert_int_equal(config_load(&c, path, NULL, 0, err, sizeof err), 2);
    snprintf(expect, sizeof expect, "%s:6: tank.length = 1.0abc: ", path);
    assert_contains(err, expect);

    f = fopen(path, "w");
    assert_non_null(f);
    fputs(MINIMAL "[motion]\ntype = table\nfile = wave.csv\n", f);
    fclose(f);
    f = fopen(table, "w");
    assert_non_null(f);
    fputs("t,x,y\n0,0,0\n1,0,0\n2,0,0\n3,0,0\n", f);
    fclose(f);
    int rc = config_load(&c, path, NULL, 0, err, sizeof err);
    if (rc) print_error("%s\n", err);
    assert_int_equal(rc, 0);
    assert_string_equal(c.motion_file, table);

    unlink(table);
    unlink(path);
    rmdir(dir);
    assert_int_equal(config_load(&c, path, NULL, 0, err, sizeof err), 2);
    assert_contains(err, path);
    assert_contains(err, "cannot open");
    assert_int_equal(config_load(&c, "/tmp", NULL, 0, err, sizeof err), 2);
    assert_contains(err, "/tmp: cannot read");
}

static void test_no_error_buffer(void **state)
{
    (void)state;
    config c;
    assert_int_equal(config_load_string(&c, "[nonsense]\n", NULL, NULL, 0, NULL, 0), 2);
    assert_int_equal(config_load_string(&c, MINIMAL, NULL, NULL, 0, NULL, 0), 0);
}

/* The case files shipped in cases/ follow the schema and survive the round trip. */
int main(void)
{
    static const struct CMUnitTest fixed[] = {
        cmocka_unit_test(test_missing_keys_in_one_message),
        cmocka_unit_test(test_line_too_long),
        cmocka_unit_test(test_errors_name_the_file),
        cmocka_unit_test(test_no_error_buffer),
    };
    enum { N_FIXED = sizeof fixed / sizeof fixed[0] };
    static struct CMUnitTest tests[N_FIXED + N_BAD];
    memcpy(tests, fixed, sizeof fixed);
    for (size_t i = 0; i < N_BAD; i++)
        tests[N_FIXED + i] = (struct CMUnitTest){.name = bad_cases[i].name,
                                                 .test_func = test_bad,
                                                 .initial_state = (void *)&bad_cases[i]};
    return _cmocka_run_group_tests("test_config_errors", tests, N_FIXED + N_BAD, NULL, NULL);
}
