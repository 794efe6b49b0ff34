/* Integration: a tank at rest with delta-SPH (N = 20, 1 s, 2D), and with the default scheme's
 * shifting and volume correction (N = 10, 10 s). The hydrostatic initial state
 * of sec. 2.1 must stay at rest: each figure asserted is its measured value times a stated
 * margin, or a round-off bound, both given beside it. Also: the run is byte-identical on 1 and 2
 * threads (docs/architecture.md).
 */
#include "app/simulation.h"

#include <float.h>
#include <hdf5.h>
#include <omp.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <unistd.h>
#include <cmocka.h>

#include "check.h"
#include "same_file.h"
#include "table.h"
#include "temp_dir.h"

static const double gravity = 9.81, depth = 0.2, rho0 = 1000.0, length = 0.4;

static const char still_tank_case[] = "[case]\n"
                                      "name = still\n"
                                      "dim = 2\n"
                                      "t_end = 1.0\n"
                                      "[tank]\n"
                                      "length = 0.4\n"
                                      "height = 0.3\n"
                                      "[liquid]\n"
                                      "height = 0.2\n"
                                      "[model]\n"
                                      "scheme = delta\n"
                                      "edbc = false\n"
                                      "[numerics]\n"
                                      "resolution = 20\n"
                                      "[output]\n"
                                      "timeseries_every = 0.01\n"
                                      "snapshot_every = 0.5\n";

static char out_dir[256];

static int run_text(const char *text, const char *dir, int threads)
{
    config cfg;
    char err[1024];
    if (config_load_string(&cfg, text, "still-tank", NULL, 0, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    snprintf(cfg.output_dir, sizeof cfg.output_dir, "%s", dir);
    omp_set_num_threads(threads);
    run_options opt = {cfg.output_dir, true, false, NULL, "vcsph"};
    return simulation_run(&cfg, &opt);
}

static int run_case(const char *dir, int threads)
{
    return run_text(still_tank_case, dir, threads);
}

static char group_dir[200]; /* every run of the group, removed at the end */

static int setup(void **state)
{
    (void)state;
    if (temp_dir_make(group_dir, sizeof group_dir, "vcsph-still")) return -1;
    snprintf(out_dir, sizeof out_dir, "%s/run", group_dir);
    return run_case(out_dir, 2) == RUN_OK ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    return temp_dir_remove(group_dir);
}

/* The settling of the start, the spurious currents of the ghost-wall corners and the
 * dissipation stay at their measured size, each bound about 3x the figure measured here (a
 * run at rest, the same on every machine up to the round-off of its libm):
 * - max |u| < 3e-3 m/s (measured 1.07e-3 m/s, 0.076 % of sqrt(g H));
 * - centre of mass within 2.5e-4 m of H/2 (measured 8.5e-5 m);
 * - energy budget: ediss >= 0 (dissipation only) and |ediss| < 6e-4 J (measured 2.12e-4 J,
 *   1.35e-6 of M_L g H = 157 J);
 * - mass exact: constant masses, |mass_err| within the round-off of a sum of 800 terms,
 *   800 DBL_EPSILON = 1.8e-13 (measured 5.9e-15). */
static void test_rest_and_budget(void **state)
{
    (void)state;
    char path[512];
    snprintf(path, sizeof path, "%s/timeseries.csv", out_dir);
    table t;
    assert_int_equal(table_read(&t, path), 0);
    assert_true(t.n_rows > 90);
    const double *umax = table_column(&t, "umax"), *com_y = table_column(&t, "com_y");
    const double *mass_err = table_column(&t, "mass_err"), *ediss = table_column(&t, "ediss");
    const double *time = table_column(&t, "t");
    double worst_u = 0.0, worst_com = 0.0, worst_mass = 0.0, min_ediss = INFINITY;
    double max_ediss = -INFINITY;
    for (size_t r = 0; r < t.n_rows; r++) {
        worst_u = fmax(worst_u, umax[r]);
        worst_com = fmax(worst_com, fabs(com_y[r] - depth / 2));
        worst_mass = fmax(worst_mass, fabs(mass_err[r]));
        assert_true(fabs(mass_err[r]) < 800.0 * DBL_EPSILON);
        min_ediss = fmin(min_ediss, ediss[r]);
        max_ediss = fmax(max_ediss, fabs(ediss[r]));
    }
    double scale = rho0 * length * depth * gravity * depth; /* M_L g H */
    printf("still tank: max|u| = %.3g m/s (%.2g sqrt(g H)), max|com_y - H/2| = %.3g m, "
           "ediss in [%.3g, %.3g] J (%.2g M_L g H), max|mass_err| = %.3g, t_end = %g s\n",
           worst_u, worst_u / sqrt(gravity * depth), worst_com, min_ediss, max_ediss,
           max_ediss / scale, worst_mass, time[t.n_rows - 1]);
    assert_close(time[t.n_rows - 1], 1.0, 1e-12);
    assert_true(worst_u < 3e-3);
    assert_true(worst_com < 2.5e-4);
    assert_true(min_ediss >= 0.0);
    assert_true(max_ediss < 6e-4);
    table_free(&t);
}

static double *read_dataset(hid_t file, const char *name, size_t *n)
{
    hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
    hid_t s = H5Dget_space(d);
    hsize_t dims[2] = {0, 1};
    int rank = H5Sget_simple_extent_dims(s, dims, NULL);
    *n = (size_t)dims[0];
    double *v = malloc((size_t)dims[0] * (rank > 1 ? dims[1] : 1) * sizeof *v);
    H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    H5Sclose(s);
    H5Dclose(d);
    return v;
}

/* After settling (last snapshot, t = 1 s): the pressure of the bottom layer against
 * rho0 g (H - y), within 1.2 % (measured +0.44 %, 2.7x); read back through the HDF5 library. */
static void test_hydrostatic_pressure(void **state)
{
    (void)state;
    char path[512];
    snprintf(path, sizeof path, "%s/snapshots/000002.h5", out_dir);
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(file >= 0);
    double time = 0.0;
    hid_t a = H5Aopen(file, "time", H5P_DEFAULT);
    H5Aread(a, H5T_NATIVE_DOUBLE, &time);
    H5Aclose(a);
    assert_close(time, 1.0, 1e-12);
    size_t n, n2;
    double *p = read_dataset(file, "pressure", &n);
    double *x = read_dataset(file, "position", &n2);
    assert_int_equal(n, 40 * 20);
    double dr = depth / 20, sum_p = 0.0, sum_expected = 0.0;
    for (size_t i = 0; i < n; i++) {
        double y = x[2 * i + 1];
        if (y > dr) continue;
        sum_p += p[i];
        sum_expected += rho0 * gravity * (depth - y);
    }
    printf("still tank: bottom-layer pressure %.5g of hydrostatic\n", sum_p / sum_expected);
    assert_close(sum_p / sum_expected, 1.0, 0.012);
    free(p);
    free(x);
    H5Fclose(file);
}

/* The same case on one thread into a second folder with the same name gives the same bytes. */
static void test_thread_count_independent(void **state)
{
    (void)state;
    char moved[300], path_a[512], path_b[512];
    snprintf(moved, sizeof moved, "%s-2threads", out_dir);
    assert_int_equal(rename(out_dir, moved), 0);
    assert_int_equal(run_case(out_dir, 1), RUN_OK);
    const char *files[] = {"timeseries.csv", "snapshots/000001.h5", "snapshots/000002.h5",
                           "snapshots.xmf",  "events.csv",          "case.ini"};
    for (size_t k = 0; k < sizeof files / sizeof *files; k++) {
        snprintf(path_a, sizeof path_a, "%s/%s", out_dir, files[k]);
        snprintf(path_b, sizeof path_b, "%s/%s", moved, files[k]);
        if (!same_file(path_a, path_b)) fail_msg("%s differs between 1 and 2 threads", files[k]);
    }
}

/* Runs `text` on two threads into the group's folder with `suffix` and reads its time series. */
static void run_and_read_series(const char *text, const char *suffix, table *t)
{
    char dir[300], path[400];
    snprintf(dir, sizeof dir, "%s-%s", out_dir, suffix);
    assert_int_equal(run_text(text, dir, 2), RUN_OK);
    snprintf(path, sizeof path, "%s/timeseries.csv", dir);
    assert_int_equal(table_read(t, path), 0);
}

/* The same at rest in 3D (N = 8, 0.5 s, 1024 particles), each bound about 3x the measured
 * figure: max |u| < 2e-3 m/s (measured 7.2e-4 m/s, 0.073 % of sqrt(g H)), centre of mass
 * within 1.2e-4 m of H/2 (measured 4.2e-5 m), |ediss| < 1e-5 J (measured 3.45e-6 J,
 * 1.8e-6 of M_L g H = 1.96 J), mass exact within 1024 DBL_EPSILON = 2.3e-13 (measured
 * 8.9e-16). ediss dips to -3.45e-6 J here, so the strict ediss >= 0 of the 2D test is not
 * asserted in 3D. */
static void test_still_tank_3d(void **state)
{
    (void)state;
    static const char text[] = "[case]\nname = still3d\ndim = 3\nt_end = 0.5\n"
                               "[tank]\nlength = 0.2\nheight = 0.15\nwidth = 0.1\n"
                               "[liquid]\nheight = 0.1\n[model]\nscheme = delta\n"
                               "[numerics]\nresolution = 8\n[output]\ntimeseries_every = 0.01\n";
    table t;
    run_and_read_series(text, "3d", &t);
    const double h3 = 0.1, scale = 1000.0 * 0.2 * 0.1 * h3 * gravity * h3;
    const double *umax = table_column(&t, "umax"), *com_y = table_column(&t, "com_y");
    const double *mass_err = table_column(&t, "mass_err"), *ediss = table_column(&t, "ediss");
    double worst_u = 0.0, worst_com = 0.0, worst_mass = 0.0, min_ediss = INFINITY, max_ediss = 0.0;
    for (size_t r = 0; r < t.n_rows; r++) {
        worst_u = fmax(worst_u, umax[r]);
        worst_com = fmax(worst_com, fabs(com_y[r] - h3 / 2));
        worst_mass = fmax(worst_mass, fabs(mass_err[r]));
        min_ediss = fmin(min_ediss, ediss[r]);
        max_ediss = fmax(max_ediss, fabs(ediss[r]));
    }
    printf("still tank 3D: max|u| = %.3g m/s (%.2g sqrt(g H)), max|com_y - H/2| = %.3g m, "
           "max|mass_err| = %.3g, ediss in [%.3g, %.3g] J (M_L g H = %.3g J)\n",
           worst_u, worst_u / sqrt(gravity * h3), worst_com, worst_mass, min_ediss, max_ediss,
           scale);
    for (size_t r = 0; r < t.n_rows; r++) {
        assert_true(umax[r] < 2e-3);
        assert_true(fabs(com_y[r] - h3 / 2) < 1.2e-4);
        assert_true(fabs(mass_err[r]) < 1024.0 * DBL_EPSILON);
        assert_true(fabs(ediss[r]) < 1e-5);
    }
    assert_true(t.n_rows == 51);
    table_free(&t);
}

/* Shifting and the volume correction at rest: the default scheme (delta-plus-ALE, its EdBC and
 * the geometric correction) in a 0.4 x 0.3 m tank with 0.1 m of water, N = 10, 10 s. Nothing
 * does work on a liquid at rest, so the kinetic energy that the start's acoustic settling
 * excites can only decay: its largest value over the last 5 s must stay below its largest
 * over the first second. Shifting that moves away the arrangement with which SPH balances the
 * hydrostatic pressure fed a current that grew from round-off to 1.3e-3 J (3 cm/s, from
 * 7.4e-6 J at the start) by 10 s; the floor of shifting.h removes it (measured: 5.8e-7 J).
 * The energy the particles' moves relocate is booked apart, so ediss >= 0. */
static void test_shifting_stays_at_rest(void **state)
{
    (void)state;
    static const char text[] = "[case]\nname = still-shifting\nt_end = 10.0\n"
                               "[tank]\nlength = 0.4\nheight = 0.3\n[liquid]\nheight = 0.1\n"
                               "[numerics]\nresolution = 10\n[output]\ntimeseries_every = 0.05\n";
    table t;
    run_and_read_series(text, "shifting", &t);
    const double *time = table_column(&t, "t"), *ekin = table_column(&t, "ekin");
    const double *ediss = table_column(&t, "ediss"), *umax = table_column(&t, "umax");
    double start = 0.0, late = 0.0, late_u = 0.0, min_ediss = INFINITY;
    for (size_t r = 0; r < t.n_rows; r++) {
        if (time[r] <= 1.0) start = fmax(start, ekin[r]);
        if (time[r] >= 5.0) {
            late = fmax(late, ekin[r]);
            late_u = fmax(late_u, umax[r]);
        }
        min_ediss = fmin(min_ediss, ediss[r]);
    }
    printf("still tank with shifting: largest ekin %.3g J over the first second, %.3g J over "
           "5-10 s (max |u| %.3g m/s); ediss >= %.3g J\n",
           start, late, late_u, min_ediss);
    assert_close(time[t.n_rows - 1], 10.0, 1e-12);
    assert_true(late < start);
    assert_true(min_ediss >= 0.0);
    table_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rest_and_budget),
        cmocka_unit_test(test_hydrostatic_pressure),
        cmocka_unit_test(test_thread_count_independent),
        cmocka_unit_test(test_still_tank_3d),
        cmocka_unit_test(test_shifting_stays_at_rest),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
