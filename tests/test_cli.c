/* The vcsph command as a user meets it (README.md and docs/case-file.md): the real binary, run in a
 * temporary folder with its stdout and stderr in files. Bad input of every kind exits 2 with one
 * message naming where the mistake is and writes nothing; `check` prints the derived numbers and
 * writes nothing; `run` writes the files of README.md with the time series of docs/outputs.md; a
 * numerical breakdown exits 3 and leaves a snapshot and an event behind. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/config.h"
#include "io/hdf5_attr.h"

#include "check.h"
#include "table.h"
#include "vcsph_child.h"
#include "cli_fixture.h"

/* ---- bad input: exit 2, one message that says where, nothing written (docs/architecture.md)
 * ------------- */

typedef struct {
    const char *name;
    const char *case_text; /* written to bad.ini */
    const char *args[14];  /* after the binary's name; "res" is the output folder */
    const char *expect[4]; /* substrings of stderr: file:line, key, hint */
} bad_case;

#define RUN_BAD "run", "bad.ini", "-o", "res", "--quiet"

static const bad_case bad_cases[] = {
    {"unknown_section",
     BASE_CASE "[bogus]\nkey = 1\n",
     {RUN_BAD, NULL},
     {"bad.ini:11:", "[bogus]"}},
    {"unknown_key_did_you_mean",
     "[case]\nname = base\nt_end = 0.05\n[tank]\nlength = 0.2\nheight = 0.1\nlenght = 0.3\n"
     "[liquid]\nheight = 0.05\n[numerics]\nresolution = 8\n",
     {RUN_BAD, NULL},
     {"bad.ini:7:", "tank.lenght", "did you mean", "tank.length"}},
    /* two swapped letters are one edit: "heigth" is nearer "height" than "length" */
    {"swapped_letters_did_you_mean",
     "[case]\nname = base\nt_end = 0.05\n[tank]\nlength = 0.2\nheigth = 0.1\n"
     "[liquid]\nheight = 0.05\n[numerics]\nresolution = 8\n",
     {RUN_BAD, NULL},
     {"bad.ini:6:", "tank.heigth", "did you mean 'tank.height'"}},
    /* a missing key has no line of its own: the message points at its section's header */
    {"missing_required_key",
     "[case]\nname = base\nt_end = 0.05\n[tank]\nlength = 0.2\nheight = 0.1\n[liquid]\n"
     "height = 0.05\n[numerics]\n",
     {RUN_BAD, NULL},
     {"bad.ini:9:", "numerics.resolution", "required"}},
    {"negative_tank_length",
     "[case]\nname = base\nt_end = 0.05\n[tank]\nlength = -0.2\nheight = 0.1\n[liquid]\n"
     "height = 0.05\n[numerics]\nresolution = 8\n",
     {RUN_BAD, NULL},
     {"bad.ini:5:", "tank.length", "-0.2"}},
    {"liquid_higher_than_tank",
     "[case]\nname = base\nt_end = 0.05\n[tank]\nlength = 0.2\nheight = 0.1\n[liquid]\n"
     "height = 0.15\n[numerics]\nresolution = 8\n",
     {RUN_BAD, NULL},
     {"bad.ini:8:", "liquid.height", "tank.height"}},
    {"resolution_3",
     "[case]\nname = base\nt_end = 0.05\n[tank]\nlength = 0.2\nheight = 0.1\n[liquid]\n"
     "height = 0.05\n[numerics]\nresolution = 3\n",
     {RUN_BAD, NULL},
     {"bad.ini:10:", "numerics.resolution", "= 3"}},
    {"dim_4",
     "[case]\nname = base\ndim = 4\nt_end = 0.05\n[tank]\nlength = 0.2\nheight = 0.1\n"
     "[liquid]\nheight = 0.05\n[numerics]\nresolution = 8\n",
     {RUN_BAD, NULL},
     {"bad.ini:3:", "case.dim", "2 or 3"}},
    {"unknown_scheme",
     BASE_CASE "[model]\nscheme = delta-plus-all\n",
     {RUN_BAD, NULL},
     {"bad.ini:12:", "model.scheme", "delta-plus-all", "delta-plus-ale"}},
    /* --set values have no file line: the message names --set and the key instead */
    {"malformed_set",
     BASE_CASE,
     {RUN_BAD, "--set", "numerics.resolution", NULL},
     {"--set", "numerics.resolution", "section.key=value"}},
    {"set_unknown_key",
     BASE_CASE,
     {RUN_BAD, "--set", "numerics.resolutoin=12", NULL},
     {"--set", "numerics.resolutoin", "did you mean", "numerics.resolution"}},
    /* sanity checks of the derived numbers (derived_check, docs/checks.md), by `run` and
     * `check` alike: a case whose first step breaks a bound, or that would never end, names
     * the key to change and its numbers. c0 = 0.5 m/s: rho0 (1 + g H / c0^2) = 2.96 rho0 at
     * the bottom at t = 0, outside rho0 (1 +- 0.2) */
    {"density_at_t0_run",
     BASE_CASE "sound_speed = 0.5\n",
     {RUN_BAD, NULL},
     {"bad.ini:11: numerics.sound_speed = 0.5:", "numerics.density_bound", "2962 kg/m^3"}},
    {"density_at_t0_check",
     BASE_CASE "sound_speed = 0.5\n",
     {"check", "bad.ini", NULL},
     {"bad.ini:11: numerics.sound_speed = 0.5:", "numerics.density_bound", "2962 kg/m^3"}},
    /* 3D, 4 mm wide at dr = 6.25 mm: one particle across z */
    {"one_particle_across_run",
     BASE_CASE,
     {RUN_BAD, "--set", "case.dim=3", "--set", "tank.width=0.004", NULL},
     {"--set: tank.width = 0.004:", "1 particle(s) across z", "at least 2"}},
    {"one_particle_across_check",
     BASE_CASE,
     {"check", "bad.ini", "--set", "case.dim=3", "--set", "tank.width=0.004", NULL},
     {"--set: tank.width = 0.004:", "1 particle(s) across z", "at least 2"}},
    /* 1e30 s at dt = 1.6 ms */
    {"too_many_steps_t_end",
     BASE_CASE,
     {RUN_BAD, "--set", "case.t_end=1e30", NULL},
     {"--set: case.t_end = 1e+30:", "steps, more than 1e+10"}},
    /* a sway of 1e30 m: g_max = A w^2 = 4e31 m/s^2, dt_a = 0.25 sqrt(h / g_max) ~ 4e-18 s */
    {"too_many_steps_amplitude",
     BASE_CASE,
     {"check", "bad.ini", "--set", "motion.type=sway", "--set", "motion.amplitude=1e30", "--set",
      "motion.period=1", NULL},
     {"bad.ini:3: case.t_end = 0.05:", "more than 1e+10", "motion.amplitude"}},
    /* absurd cases (docs/checks.md), refused unless --insist. c0 = 1e10 m/s, 5e8 times Eq.
     * (6)'s: dt = K_c h / c0 ~ 2.5e-13 s, 4e9 steps of 256 particles to 1 ms, weeks */
    {"absurd_sound_speed",
     BASE_CASE,
     {"check", "bad.ini", "--set", "numerics.sound_speed=1e10", "--set", "case.t_end=0.001", NULL},
     {"--set: numerics.sound_speed = 10000000000:", "times Eq. (6)'s", "days", "--insist"}},
    /* a period of 1 ns (s for ns?): g_max = A w^2 = 4e17 m/s^2 sets c0 ~ 2e9 m/s (auto),
     * 6e8 steps to 5 ms, days; `check`, which would not run it were the check missing */
    {"absurd_acceleration",
     BASE_CASE "[motion]\ntype = sway\namplitude = 0.01\nperiod = 1e-9\n",
     {"check", "bad.ini", "--set", "case.t_end=0.005", NULL},
     {"bad.ini:14: motion.period = 1e-09:", "g_max", "days", "--insist"}},
    /* a sway of 1 um at 10 kHz: g_max = 3948 m/s^2, c0 (auto) = 199 m/s, dt = 13 us: fewer
     * than 8 steps a period */
    {"unresolved_period",
     BASE_CASE "[motion]\ntype = sway\namplitude = 1e-6\nperiod = 1e-4\n",
     {RUN_BAD, NULL},
     {"bad.ini:14: motion.period = 0.0001:", "time steps", "at least 20 steps a period",
      "--insist"}},
    /* the remaining three have no line or key to name: the file, command or option it is */
    {"case_file_missing",
     BASE_CASE,
     {"run", "missing.ini", "-o", "res", "--quiet", NULL},
     {"missing.ini", "cannot open"}},
    {"unknown_command",
     BASE_CASE,
     {"frobnicate", "bad.ini", "-o", "res", NULL},
     {"frobnicate", "run, check"}},
    {"unknown_option",
     BASE_CASE,
     {"run", "bad.ini", "-o", "res", "--frob", NULL},
     {"--frob", "--set"}},
};
#define N_BAD (sizeof bad_cases / sizeof bad_cases[0])

/* Bad input's answer (docs/architecture.md): exit status 2, one line on stderr holding every
 * `expect` (up to 4, NULL-ended), nothing on stdout and nothing written but the case file. */
static void assert_refused(fixture *fx, int rc, const char *name, const char *const *expect)
{
    char *out = read_file(fx, "stdout.txt"), *err = read_file(fx, "stderr.txt");
    if (rc != 2) print_error("%s: stderr:\n%s", name, err);
    assert_int_equal(rc, 2);
    for (int k = 0; k < 4 && expect[k]; k++) assert_contains(err, expect[k]);
    assert_int_equal(count_lines(err), 1); /* "one clear message" */
    assert_string_equal(out, "");
    /* nothing written: no output folder, and nothing else in the working folder */
    assert_false(exists(fx, "res"));
    assert_folder_holds(fx, (const char *const[]){"bad.ini", "stdout.txt", "stderr.txt", NULL});
    free(out);
    free(err);
}

static void test_bad_input(void **state)
{
    fixture *fx = *state;
    const bad_case *bc = fx->row;
    write_file(fx, "bad.ini", bc->case_text);
    int rc = run_vcsph(fx, bc->args);
    assert_refused(fx, rc, bc->name, bc->expect);
}

/* `mpirun -np P vcsph run`, P > 1, would be P whole runs into one folder: refused like bad
 * input (docs/mpi.md), under Open MPI's launcher and under a PMI one (MPICH, Slurm) */
static void test_mpi_launch_refused(void **state)
{
    fixture *fx = *state;
    write_file(fx, "bad.ini", BASE_CASE);
    const char *const args[] = {RUN_BAD, NULL};
    assert_refused(
        fx, run_vcsph_with(fx, args, "OMPI_COMM_WORLD_SIZE=2"), "mpirun",
        (const char *const[]){"one of 2 MPI processes", "docs/mpi.md", "one process", NULL});
    assert_refused(fx, run_vcsph_with(fx, args, "PMI_SIZE=4"), "PMI",
                   (const char *const[]){"one of 4 MPI processes", NULL});
    /* a launcher's single process runs */
    const char *const alone[] = {"run", "bad.ini", "-o", "alone", "--quiet", NULL};
    assert_int_equal(run_vcsph_with(fx, alone, "OMPI_COMM_WORLD_SIZE=1"), 0);
}

/* ---- vcsph check ---------------------------------------------------------------------------- */

/* The number after `label` at the start of a line of `text` ("dr      0.00625 m"). */
static double printed_value(const char *text, const char *label)
{
    size_t n = strlen(label);
    for (const char *line = text; line; line = next_line(line)) {
        if (strncmp(line, label, n) || line[n] != ' ') continue;
        char *end;
        double v = strtod(line + n, &end);
        if (end != line + n) return v;
    }
    fail_msg("no line \"%s <number>\" in:\n%s", label, text);
    return NAN;
}

/* Relative rounding of a number printed with `digits` significant digits (%.<digits>g):
 * at most half a unit of the last digit, i.e. 5 10^-digits of the value. */
static double printed_tol(double value, int digits)
{
    return 5.0 * pow(10.0, -digits) * fabs(value);
}

static void test_check_prints_derived_numbers(void **state)
{
    fixture *fx = *state;
    /* L/dr = 0.21 / (0.05/8) = 33.6, not an integer: 34 columns, spaced L/34 so that the
     * lattice fills the liquid box exactly (derived.c) */
    const double L = 0.21, H = 0.05, g = 9.81, A = 0.01, T = 0.8, nu = 1.0e-6, rho0 = 1000.0;
    const int N = 8;
    write_file(fx, "check.ini",
               "[case]\nname = checked\nt_end = 2.0\n"
               "[tank]\nlength = 0.21\nheight = 0.1\n"
               "[liquid]\nheight = 0.05\n"
               "[motion]\ntype = sway\namplitude = 0.01\nperiod = 0.8\n"
               "[numerics]\nresolution = 8\n");
    int rc = run_vcsph(fx, (const char *const[]){"check", "check.ini", NULL});
    char *out = read_file(fx, "stdout.txt"), *err = read_file(fx, "stderr.txt");
    if (rc) print_error("stderr:\n%s", err);
    assert_int_equal(rc, 0);
    assert_string_equal(err, "");

    /* Expected figures from theory: dr = H/N; h = 2 dr in 2D (docs/case-file.md); sway a_x peaks at
     * A w^2, so g_max = sqrt(g^2 + (A w^2)^2) (theory §6) and c0 = 10 sqrt(2 g_max H) (Eq. 6);
     * dt = min(0.125 h^2/nu, 0.25 sqrt(h/g_max), K_c h/c0), K_c = 1.3 for delta-plus-ale
     * (Eq. 8, Table 1); M_L = rho0 L H, dW = M_L (A w)^2 / (2 T) (Table 3). */
    const double dr = H / N, h = 2.0 * dr, w = 2.0 * M_PI / T;
    const double g_max = sqrt(g * g + pow(A * w * w, 2)), c0 = 10.0 * sqrt(2.0 * g_max * H);
    const double dt = fmin(fmin(0.125 * h * h / nu, 0.25 * sqrt(h / g_max)), 1.3 * h / c0);
    const double m_l = rho0 * L * H, d_w = 0.5 * m_l * pow(A * w, 2) / T;
    long n_fluid = lround(L / dr) * N;
    assert_int_equal(n_fluid, 34 * 8);

    /* Tolerances: the rounding of the printed figures (%.6g, dt %.4g). The sampled g_max may
     * be low by at most (A w^2)^2 dtheta^2 / (2 g) < 1e-7 relative (test_motion), far below. */
    assert_close(printed_value(out, "dr"), dr, printed_tol(dr, 6));
    assert_close(printed_value(out, "h"), h, printed_tol(h, 6));
    assert_close(printed_value(out, "fluid particles"), (double)n_fluid, 0.0);
    assert_close(printed_value(out, "c0"), c0, printed_tol(c0, 6));
    assert_close(printed_value(out, "dt estimate"), dt, printed_tol(dt, 4));
    assert_close(printed_value(out, "M_L"), m_l, printed_tol(m_l, 6));
    assert_close(printed_value(out, "dW"), d_w, printed_tol(d_w, 6));

    /* check runs nothing and writes nothing (no out/checked) */
    assert_folder_holds(fx, (const char *const[]){"check.ini", "stdout.txt", "stderr.txt", NULL});
    free(out);
    free(err);
}

/* ---- vcsph run ------------------------------------------------------------------------------ */

/* The first columns of timeseries.csv, in order (docs/outputs.md). */
static const char *const series_columns[] = {
    "t",      "step",    "dt",       "n_fluid", "eps_v1", "eps_v2",  "eps_v3",
    "eps_gm", "eps_sph", "mass_err", "eta",     "edbc",   "n_edbc",  "n_free_surface",
    "ekin",   "epot",    "eint",     "work_in", "ediss",  "com_x",   "com_y",
    "com_z",  "xmin",    "xmax",     "ymax",    "umax",   "rho_min", "rho_max"};
#define N_SERIES_COLUMNS (int)(sizeof series_columns / sizeof series_columns[0])

static void test_run_writes_outputs(void **state)
{
    fixture *fx = *state;
    write_file(fx, "tiny.ini", TINY_CASE);
    int rc = run_vcsph(fx, (const char *const[]){"run", "tiny.ini", "--set", "case.t_end=0.03",
                                                 "-o", "res", "--quiet", NULL});
    char *out = read_file(fx, "stdout.txt"), *err = read_file(fx, "stderr.txt");
    if (rc) print_error("stderr:\n%s", err);
    assert_int_equal(rc, 0);
    /* --quiet: nothing on the terminal, and the log file still written */
    assert_string_equal(out, "");
    assert_string_equal(err, "");
    free(out);
    free(err);

    static const char *const files[] = {"res/case.ini",      "res/timeseries.csv",
                                        "res/events.csv",    "res/log.txt",
                                        "res/snapshots.xmf", "res/snapshots/000000.h5"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++)
        if (!is_regular_file(fx, files[k])) fail_msg("%s missing or empty", files[k]);
    /* -o took the place of output.dir: no out/tiny */
    assert_folder_holds(fx,
                        (const char *const[]){"tiny.ini", "res", "stdout.txt", "stderr.txt", NULL});
    char *xmf = read_file(fx, "res/snapshots.xmf");
    assert_contains(xmf, "snapshots/000000.h5");
    free(xmf);
    char *events = read_file(fx, "res/events.csv");
    assert_true(strncmp(events, "t,event,detail\n", 15) == 0);
    free(events);

    /* case.ini is the resolved case with the override applied, and a valid case file */
    char path[512];
    path_in(fx, "res/case.ini", path, sizeof path);
    config cfg;
    char msg[1024];
    int load = config_load(&cfg, path, NULL, 0, msg, sizeof msg);
    if (load) print_error("%s\n", msg);
    assert_int_equal(load, 0);
    assert_true(cfg.t_end == 0.03); /* written so that it reads back to the same double */
    assert_int_equal(cfg.resolution, 8);
    rc = run_vcsph(fx, (const char *const[]){"check", "res/case.ini", NULL});
    if (rc) {
        err = read_file(fx, "stderr.txt");
        print_error("check res/case.ini:\n%s", err);
        free(err);
    }
    assert_int_equal(rc, 0);

    /* timeseries.csv: the columns of docs/outputs.md in order (more may come after them) */
    path_in(fx, "res/timeseries.csv", path, sizeof path);
    table ts;
    assert_int_equal(table_read(&ts, path), 0);
    assert_true(ts.n_columns >= N_SERIES_COLUMNS);
    for (int c = 0; c < N_SERIES_COLUMNS; c++) assert_string_equal(ts.names[c], series_columns[c]);
    /* rows at t = 0 and at the first step past 0.01, 0.02, and the last at t_end = 0.03 */
    assert_int_equal(ts.n_rows, 4);
    const double *t = table_column(&ts, "t"), *n_fluid = table_column(&ts, "n_fluid");
    assert_close(t[0], 0.0, 0.0);
    /* t_end is reached exactly (the last step is shortened to it); the CSV's %.10g prints
     * 0.03 as 0.03, so only the parse's rounding remains */
    assert_close(t[ts.n_rows - 1], 0.03, 1e-12);
    /* Between: one row per 0.01 s, at the first step past each multiple; no step is longer
     * than K_c h / c0 (Eq. 8) with K_c = 1.3, h = 2 dr = 0.0125 m, c0 = 10 sqrt(2 g H) */
    const double dt_c = 1.3 * 0.0125 / (10.0 * sqrt(2.0 * 9.81 * 0.05));
    for (size_t k = 1; k + 1 < ts.n_rows; k++) {
        assert_true(t[k] >= 0.01 * (double)k - 1e-12);
        assert_true(t[k] < 0.01 * (double)k + dt_c);
    }
    /* L/dr = 32 exactly: 32 x 8 particles, none lost */
    for (size_t k = 0; k < ts.n_rows; k++) assert_close(n_fluid[k], 256.0, 0.0);
    table_free(&ts);
}

/* ---- numerical breakdown -------------------------------------------------------------------- */

static void test_breakdown_exits_3(void **state)
{
    fixture *fx = *state;
    /* A heaving tank (the case of test_restart): at t = 0 the liquid is hydrostatic, its
     * density rho0 (1 + g (H - y)/c0^2) (linear EOS, sec. 2.1) within the bound rho0 (1 +-
     * 0.02) even under g_max = g + A w^2 = 29.6 m/s^2 (1.5 %, so derived_check lets it run),
     * and the heave's start pushes it past the bound within a few steps. (A still tank at
     * c0 = 0.5 m/s, 2.96 rho0 at the bottom, is refused before the first step now: the
     * density_at_t0 rows above.) */
    const double rho0 = 1000.0, g = 9.81, H = 0.05, dr = H / 8, c0 = 10.0, bound = 0.02;
    write_file(fx, "heave.ini",
               "[case]\nname = heave\nt_end = 0.5\n"
               "[tank]\nlength = 0.2\nheight = 0.1\n"
               "[liquid]\nheight = 0.05\n"
               "[motion]\ntype = heave\namplitude = 0.02\nperiod = 0.2\n"
               "[numerics]\nresolution = 8\nsound_speed = 10\ndensity_bound = 0.02\n"
               "[output]\ntimeseries_every = 0.01\nsnapshot_every = 0.02\n");
    int rc = run_vcsph(fx, (const char *const[]){"run", "heave.ini", "-o", "res", "--quiet", NULL});
    char *err = read_file(fx, "stderr.txt");
    assert_int_equal(rc, 3); /* docs/architecture.md */

    /* "breakdown at t = <t> s, step <n>: particle id <id> ..." */
    assert_contains(err, "particle id");
    const char *at_t = strstr(err, "t = "), *at_step = strstr(err, "step ");
    const char *at_id = strstr(err, "particle id ");
    assert_non_null(at_t);
    assert_non_null(at_step);
    assert_non_null(at_id);
    char *end;
    double t_break = strtod(at_t + 4, &end);
    assert_true(end != at_t + 4);
    long step_break = strtol(at_step + 5, &end, 10);
    assert_true(end != at_step + 5);
    long id = strtol(at_id + 12, &end, 10);
    assert_true(end != at_id + 12);
    assert_true(id >= 0 && id < 256);

    /* The last snapshot that the message names exists */
    const char *snap = strstr(err, "res/snapshots/");
    assert_non_null(snap);
    char snap_name[64];
    snprintf(snap_name, sizeof snap_name, "%.*s", (int)strcspn(snap, "\n"), snap);
    assert_true(strlen(snap_name) > strlen("res/snapshots/") + 3);
    assert_true(is_regular_file(fx, snap_name));
    free(err);

    /* The time series ends on the broken state: its time and step are those of the message
     * (%.9g in the message, %.10g in the CSV: relative rounding 5e-9 + 5e-10) */
    char path[512];
    path_in(fx, "res/timeseries.csv", path, sizeof path);
    table ts;
    assert_int_equal(table_read(&ts, path), 0);
    assert_true(ts.n_rows >= 1);
    const double *t = table_column(&ts, "t"), *step = table_column(&ts, "step");
    const double *rho_max = table_column(&ts, "rho_max");
    assert_non_null(t);
    assert_non_null(step);
    assert_non_null(rho_max);
    assert_close(t[ts.n_rows - 1], t_break, 5.5e-9 * t_break);
    assert_close(step[ts.n_rows - 1], (double)step_break, 0.0);
    /* The premise: at t = 0 the deepest particle, at y = dr/2, has
     * rho0 + rho0 g (H - dr/2)/c0^2 = 1004.6 kg/m^3, inside the bound (CSV rounding 5e-10);
     * the breakdown comes later, from the flow */
    double rho_deep = rho0 + rho0 * g * (H - 0.5 * dr) / (c0 * c0);
    assert_close(t[0], 0.0, 0.0);
    assert_close(rho_max[0], rho_deep, 5e-10 * rho_deep);
    assert_true(rho_deep < (1.0 + bound) * rho0);
    assert_true(t_break > 0.0 && step_break > 0);
    table_free(&ts);

    /* events.csv has the breakdown, at the time of the message */
    char *events = read_file(fx, "res/events.csv");
    bool found = false;
    for (const char *line = events; line; line = next_line(line)) {
        double te = strtod(line, &end);
        if (end == line || strncmp(end, ",breakdown,", 11)) continue;
        assert_close(te, t_break, 5.5e-9 * t_break);
        found = true;
    }
    if (!found) fail_msg("no breakdown row in events.csv:\n%s", events);
    free(events);
}

int main(void)
{
    struct CMUnitTest tests[N_BAD + 4];
    for (size_t k = 0; k < N_BAD; k++)
        tests[k] = (struct CMUnitTest){bad_cases[k].name, test_bad_input, setup, teardown,
                                       (void *)&bad_cases[k]};
    tests[N_BAD] = (struct CMUnitTest)cmocka_unit_test_setup_teardown(
        test_check_prints_derived_numbers, setup, teardown);
    tests[N_BAD + 1] = (struct CMUnitTest)cmocka_unit_test_setup_teardown(test_run_writes_outputs,
                                                                          setup, teardown);
    tests[N_BAD + 2] =
        (struct CMUnitTest)cmocka_unit_test_setup_teardown(test_breakdown_exits_3, setup, teardown);
    tests[N_BAD + 3] = (struct CMUnitTest)cmocka_unit_test_setup_teardown(test_mpi_launch_refused,
                                                                          setup, teardown);
    return _cmocka_run_group_tests("test_cli", tests, N_BAD + 4, NULL, NULL);
}
