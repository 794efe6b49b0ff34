/* `vcsph plot OUTDIR` (README.md): the real binary plots a real run and hand-written output
 * folders; every PNG it names is read back and must hold a drawn curve. Bad input exits 2
 * without writing anything; a missing gnuplot exits 1 and says so. The tests that need gnuplot
 * skip without it. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "png_read.h"
#include "temp_dir.h"
#include "test_filter.h"
#include "vcsph_child.h"

extern char **environ;

/* ---- fixture: one temporary folder per test ------------------------------------------------- */

static int setup(void **state) { return temp_fixture_setup(state, "vcsph-plot"); }

static int teardown(void **state) { return temp_fixture_teardown(state); }

/* ---- helpers -------------------------------------------------------------------------------- */

static void path_in(const char *dir, const char *name, char *buf, size_t size)
{
    assert_true((size_t)snprintf(buf, size, "%s/%s", dir, name) < size);
}

static void write_file(const char *dir, const char *name, const char *text)
{
    char path[1024];
    path_in(dir, name, path, sizeof path);
    text_file_write(path, text);
}

/* The whole file as a string (empty if it cannot be read); free() it. */
static char *read_text(const char *dir, const char *name)
{
    char path[1024];
    path_in(dir, name, path, sizeof path);
    return text_file_read(path);
}

static bool exists(const char *dir, const char *name)
{
    char path[1024];
    struct stat st;
    path_in(dir, name, path, sizeof path);
    return lstat(path, &st) == 0;
}

static void make_dir(const char *dir, const char *name)
{
    char path[1024];
    path_in(dir, name, path, sizeof path);
    assert_int_equal(mkdir(path, 0777), 0);
}

/* Runs vcsph with args (NULL-ended) in `dir` (vcsph_child.h); with `path` non-NULL, PATH is
 * that in the child's environment. */
static int run_vcsph(const char *dir, const char *const *args, const char *path)
{
    /* the environment, PATH replaced when asked */
    int n_env = 0;
    while (environ[n_env]) n_env++;
    char **envp = calloc((size_t)n_env + 2, sizeof *envp), path_var[512];
    assert_non_null(envp);
    int k = 0;
    for (int i = 0; i < n_env; i++)
        if (!path || strncmp(environ[i], "PATH=", 5)) envp[k++] = environ[i];
    if (path) {
        snprintf(path_var, sizeof path_var, "PATH=%s", path);
        envp[k++] = path_var;
    }
    int rc = vcsph_child_run(dir, args, envp);
    free(envp);
    return rc;
}

static bool gnuplot_installed(void)
{
    const char *path = getenv("PATH");
    char *copy = strdup(path ? path : "");
    assert_non_null(copy);
    bool found = false;
    for (char *save, *d = strtok_r(copy, ":", &save); d && !found; d = strtok_r(NULL, ":", &save)) {
        char exe[1024];
        snprintf(exe, sizeof exe, "%s/gnuplot", *d ? d : ".");
        found = access(exe, X_OK) == 0;
    }
    free(copy);
    return found;
}

/* Data rows of a CSV file in dir (0 when it is missing). */
static int csv_rows(const char *dir, const char *name)
{
    char *text = read_text(dir, name);
    int n = count_lines(text);
    free(text);
    return n > 1 ? n - 1 : 0;
}

/* A plot, not a blank page: a decodable PNG of the asked size with pixels that are neither
 * white (axes, text) nor grey (a coloured curve: gnuplot's first line colours are not grey). */
static void assert_png_drawn(const char *images, const char *png)
{
    char path[1024];
    path_in(images, png, path, sizeof path);
    png_rgb img;
    if (png_read_rgb(path, &img)) fail_msg("%s is missing or not a PNG that libpng decodes", path);
    assert_true(img.width > 100 && img.height > 100);
    long inked = 0, coloured = 0;
    for (uint32_t y = 0; y < img.height; y++)
        for (uint32_t x = 0; x < img.width; x++) {
            const uint8_t *p = png_pixel(&img, x, y);
            inked += p[0] < 250 || p[1] < 250 || p[2] < 250;
            coloured += abs(p[0] - p[1]) > 40 || abs(p[1] - p[2]) > 40 || abs(p[0] - p[2]) > 40;
        }
    png_rgb_free(&img);
    if (inked == 0 || coloured == 0)
        fail_msg("%s looks blank: %ld inked pixels, %ld coloured", png, inked, coloured);
}

/* Runs `vcsph plot run_dir` in dir and checks that exactly the PNG files in `expected` (NULL
 * ended) were named on stdout's one line and drawn. */
static void plot_and_check(const char *dir, const char *run_dir, const char *const *expected)
{
    int rc = run_vcsph(dir, (const char *const[]){"plot", run_dir, NULL}, NULL);
    char *out = read_text(dir, "stdout.txt"), *err = read_text(dir, "stderr.txt");
    if (rc) print_error("stderr:\n%s", err);
    assert_int_equal(rc, 0);
    assert_string_equal(err, "");
    assert_int_equal(count_lines(out), 1);
    char images[1024], images_in[1024];
    snprintf(images_in, sizeof images_in, "%s/images", run_dir);
    path_in(dir, images_in, images, sizeof images);
    assert_true(exists(images, "plot.gp")); /* kept, for a user to edit and rerun */
    static const char *const all[] = {"volume.png",      "energy.png", "density.png", "liquid.png",
                                      "dissipation.png", "probes.png", "loads.png"};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++) {
        bool want = false;
        for (int i = 0; expected[i]; i++) want |= !strcmp(expected[i], all[k]);
        if (want != (strstr(out, all[k]) != NULL))
            fail_msg("%s %s in the report:\n%s", all[k], want ? "missing" : "unexpected", out);
        if (want) assert_png_drawn(images, all[k]);
    }
    free(out);
    free(err);
}

/* ---- a real run ----------------------------------------------------------------------------- */

/* The INM1 tank of the paper (L = 1 m, H = 0.35 m) at N = 8, swayed with a short period so
 * that 0.3 s hold three complete periods for dissipation.csv; two gauges and one pressure
 * probe for probes.csv. */
static const char tiny_sway[] = "[case]\n"
                                "name = plot_test\n"
                                "t_end = 0.3\n"
                                "experiment_dissipation = 0.05\n"
                                "[tank]\n"
                                "length = 1.0\n"
                                "height = 1.0\n"
                                "[liquid]\n"
                                "height = 0.35\n"
                                "[motion]\n"
                                "type = sway\n"
                                "amplitude = 0.002\n"
                                "period = 0.1\n"
                                "[probes]\n"
                                "gauges = 0.1, 0.5\n"
                                "pressure = 0.5 0.1\n"
                                "[numerics]\n"
                                "resolution = 8\n"
                                "[output]\n"
                                "timeseries_every = 0.01\n";

static void test_gnuplot_real_run(void **state)
{
    const char *dir = ((temp_fixture *)*state)->dir;
    if (!gnuplot_installed()) skip();
    write_file(dir, "tiny.ini", tiny_sway);
    int rc = run_vcsph(dir, (const char *const[]){"run", "tiny.ini", "-o", "run", "--quiet", NULL},
                       NULL);
    if (rc) {
        char *err = read_text(dir, "stderr.txt");
        print_error("vcsph run: %s", err);
        free(err);
    }
    assert_int_equal(rc, 0);
    /* probes.csv and dissipation.csv are plotted when the run wrote rows into them */
    char run[1024];
    path_in(dir, "run", run, sizeof run);
    const char *expected[8] = {"volume.png", "energy.png", "density.png", "liquid.png"};
    int n = 4;
    if (csv_rows(run, "dissipation.csv") > 0) expected[n++] = "dissipation.png";
    if (csv_rows(run, "probes.csv") > 0) expected[n++] = "probes.png";
    expected[n++] = "loads.png"; /* every run writes loads.csv */
    plot_and_check(dir, "run", expected);
    char images[1024];
    path_in(run, "images", images, sizeof images);
    char *script = read_text(images, "plot.gp");
    assert_contains(script, "'plot_test: "); /* titles name the case */
    /* eps_gm is not computed (output.graphical = false), esurf is 0 (no surface tension) */
    assert_true(strstr(script, "column('eps_gm')") == NULL);
    assert_true(strstr(script, "column('esurf')") == NULL);
    if (csv_rows(run, "dissipation.csv") > 0) {
        assert_contains(script, "'P / dW'");           /* motion.decay = 0 */
        assert_contains(script, "title 'experiment'"); /* experiment_dissipation > 0 */
    }
    if (csv_rows(run, "probes.csv") > 0) assert_contains(script, "gauge 2: x = 0.5 m");
    free(script);
}

/* ---- hand-written output folders: every plot, every option ---------------------------------- */

/* Five rows of docs/outputs.md's columns and the two that vcsph adds; eps_gm computed in some rows
 * only, eta switched on at t = 0.2, a surface energy. */
static const char series[] =
    "t,step,dt,n_fluid,eps_v1,eps_v2,eps_v3,eps_gm,eps_sph,mass_err,eta,edbc,n_edbc,"
    "n_free_surface,ekin,epot,eint,work_in,ediss,com_x,com_y,com_z,xmin,xmax,ymax,umax,"
    "rho_min,rho_max,esurf,work_st\n"
    "0,0,0,100,-0.001,-0.001,0.001,-0.0012,0,0,0,1,0,10,0,600,1.7,0,0,0.5,0.17,0,0,1,0.35,0,"
    "1000,1008,0.01,0\n"
    "0.1,10,0.01,100,-0.004,-0.004,0.002,,0,0,0,1,2,10,0.2,600.1,1.7,0.4,0.1,0.51,0.17,0,0,1,"
    "0.36,0.5,999,1009,0.011,0.001\n"
    "0.2,20,0.01,100,-0.011,-0.01,0.003,-0.0105,0,0,1,0,0,11,0.3,600.2,1.8,0.8,0.3,0.52,0.17,0,"
    "0,1,0.37,0.6,998,1010,0.012,0.002\n"
    "0.3,30,0.01,100,-0.006,-0.006,0.002,,0,0,1,0,0,11,0.2,600.1,1.7,1.2,0.6,0.5,0.17,0,0,1,"
    "0.36,0.5,999,1009,0.011,0.002\n"
    "0.4,40,0.01,100,-0.003,-0.003,0.001,-0.0031,0,0,1,0,0,10,0.1,600,1.7,1.6,0.9,0.49,0.17,0,"
    "0,1,0.35,0.4,1000,1008,0.01,0.002\n";

/* The eta switch's detail holds a comma: quoted, as the run writes it. */
static const char events[] = "t,event,detail\n"
                             "0.1,speed_above_c0_over_10,U_max = 2 m/s\n"
                             "0.2,eta_switch,\"eta = 1: eps_v1 = -0.011, threshold 0.01\"\n";

static const char dissipation[] = "period,t_start,t_end,e_diss,power,power_norm\n"
                                  "1,0,0.2,0.3,1.5,0.25\n";

static const char probes[] = "t,gauge_1,pressure_1,pressure_2\n"
                             "0,0.35,2450,1000\n"
                             "0.1,0.36,2460,1010\n"
                             "0.2,0.37,2470,1030\n";

/* A 2D run's loads: the moment is mz alone. */
static const char loads[] = "t,fx,fy,mx,my,mz,fx_inertial,fy_inertial,mx_inertial,my_inertial,"
                            "mz_inertial,px,py,bx,by\n"
                            "0,0,-392,0,0,0,0,-392,0,0,0,0,0,0,-392\n"
                            "0.1,5,-393,0,0,1.5,5,-393,0,0,1.5,0.1,0,4,-392\n"
                            "0.2,-3,-391,0,0,-1,-3,-391,0,0,-1,0.05,0,-2,-392\n";

static void write_run(const char *dir, const char *name, bool optional_files)
{
    char run[1024];
    make_dir(dir, name);
    path_in(dir, name, run, sizeof run);
    write_file(run, "timeseries.csv", series);
    if (!optional_files) return;
    write_file(run, "events.csv", events);
    write_file(run, "dissipation.csv", dissipation);
    write_file(run, "probes.csv", probes);
    write_file(run, "loads.csv", loads);
}

static const char *const every_plot[] = {"volume.png", "energy.png", "density.png",
                                         "liquid.png", "probes.png", "dissipation.png",
                                         "loads.png",  NULL};

/* Without case.ini, in a folder whose name needs quoting in a gnuplot script (the script
 * refers to its data by relative paths, so no name reaches gnuplot but in a title). */
static void test_gnuplot_every_file_without_case(void **state)
{
    const char *dir = ((temp_fixture *)*state)->dir;
    if (!gnuplot_installed()) skip();
    const char *name = "it's a \"run\"";
    write_run(dir, name, true);
    plot_and_check(dir, name, every_plot);
    char images[1024], images_in[1024];
    snprintf(images_in, sizeof images_in, "%s/images", name);
    path_in(dir, images_in, images, sizeof images);
    char *script = read_text(images, "plot.gp");
    assert_contains(script, "'it''s a \"run\": volume");    /* the folder's name as the title */
    assert_contains(script, "set arrow from 0.2, graph 0"); /* the eta switch, not the speed */
    assert_true(strstr(script, "set arrow from 0.1,") == NULL);
    assert_contains(script, "column('eps_gm')");       /* eps_gm has values */
    assert_contains(script, "column('esurf')");        /* esurf is not 0 */
    assert_contains(script, "EPOT0 = 600\n");          /* E_pot from its first value */
    assert_contains(script, "'P / dW'");               /* no case: no decay */
    assert_true(strstr(script, "experiment") == NULL); /* no case: no experiment */
    assert_contains(script, "column('pressure_2')");
    free(script);
}

/* A case.ini with a decaying motion and a measured dissipation; its motion table does not
 * exist (plots do not need the motion); no events, a probes.csv with a header only. */
static void test_gnuplot_with_case(void **state)
{
    const char *dir = ((temp_fixture *)*state)->dir;
    if (!gnuplot_installed()) skip();
    write_run(dir, "run", false);
    char run[1024];
    path_in(dir, "run", run, sizeof run);
    write_file(run, "case.ini",
               "[case]\nname = decaying\nt_end = 0.4\nexperiment_dissipation = 0.3\n"
               "[tank]\nlength = 1.0\nheight = 1.0\n[liquid]\nheight = 0.35\n"
               "[motion]\ntype = table\nfile = gone.csv\ndecay = 0.5\n"
               "[probes]\ngauges = 0.25\n[numerics]\nresolution = 8\n");
    write_file(run, "dissipation.csv", dissipation);
    write_file(run, "probes.csv", "t,gauge_1\n");
    plot_and_check(dir, "run",
                   (const char *const[]){"volume.png", "energy.png", "density.png", "liquid.png",
                                         "dissipation.png", NULL});
    char images[1024];
    path_in(run, "images", images, sizeof images);
    char *script = read_text(images, "plot.gp");
    assert_contains(script, "'decaying: volume");
    assert_contains(script, "'P / dE_P'"); /* motion.decay > 0: normalised by dE_P */
    assert_contains(script, "0.3 with lines dt 2 lw 2 lc rgb 'black' title 'experiment'");
    assert_true(strstr(script, "set arrow") == NULL);
    free(script);
}

/* ---- bad input and a missing gnuplot -------------------------------------------------------- */

static void assert_plot_fails(const char *dir, const char *const *args, int status,
                              const char *part)
{
    int rc = run_vcsph(dir, args, NULL);
    char *out = read_text(dir, "stdout.txt"), *err = read_text(dir, "stderr.txt");
    assert_int_equal(rc, status);
    assert_contains(err, part);
    assert_int_equal(count_lines(err), 1); /* one clear message */
    assert_string_equal(out, "");
    free(out);
    free(err);
}

static void test_plot_bad_input(void **state)
{
    const char *dir = ((temp_fixture *)*state)->dir;
    assert_plot_fails(dir, (const char *const[]){"plot", "/nonexistent", NULL}, 2, "/nonexistent");
    assert_plot_fails(dir, (const char *const[]){"plot", NULL}, 2, "OUTDIR");
    assert_plot_fails(dir, (const char *const[]){"plot", "a", "b", NULL}, 2, "OUTDIR");
    write_file(dir, "file.txt", "not a run\n");
    assert_plot_fails(dir, (const char *const[]){"plot", "file.txt", NULL}, 2, "not a directory");
    /* a folder without timeseries.csv, with its header only, without a column to draw:
     * nothing is written */
    make_dir(dir, "empty");
    assert_plot_fails(dir, (const char *const[]){"plot", "empty", NULL}, 2, "timeseries.csv");
    write_file(dir, "empty/timeseries.csv", "t,step,eps_v1\n");
    assert_plot_fails(dir, (const char *const[]){"plot", "empty", NULL}, 2, "no rows");
    write_file(dir, "empty/timeseries.csv", "t,step\n0,0\n"); /* nothing to draw */
    assert_plot_fails(dir, (const char *const[]){"plot", "empty", NULL}, 2, "none of the columns");
    assert_false(exists(dir, "empty/images"));
}

/* With no gnuplot on PATH: exit 1 and a message that says so; the script is still there to be
 * run where gnuplot is. Needs no gnuplot itself. */
static void test_plot_without_gnuplot(void **state)
{
    const char *dir = ((temp_fixture *)*state)->dir;
    write_run(dir, "run", true);
    int rc = run_vcsph(dir, (const char *const[]){"plot", "run", NULL}, "/nonexistent-bin");
    char *err = read_text(dir, "stderr.txt");
    assert_int_equal(rc, 1);
    assert_contains(err, "gnuplot is not installed");
    assert_int_equal(count_lines(err), 1);
    assert_true(exists(dir, "run/images/plot.gp"));
    free(err);
}

int main(int argc, char **argv)
{
    test_filter_args(argc, argv);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_gnuplot_real_run, setup, teardown),
        cmocka_unit_test_setup_teardown(test_gnuplot_every_file_without_case, setup, teardown),
        cmocka_unit_test_setup_teardown(test_gnuplot_with_case, setup, teardown),
        cmocka_unit_test_setup_teardown(test_plot_bad_input, setup, teardown),
        cmocka_unit_test_setup_teardown(test_plot_without_gnuplot, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
