/* A free drop of water under surface tension at water's viscosity (docs/surface-tension.md):
 * the 24 x 16 mm rectangle of the outside check, and the 1.5 : 1 ellipse of the same area,
 * 2D, weightless, sigma = 0.0727 N/m, nu = 1e-6, at N = 30 (R / dr = 20.7) over 0.8 s, 2.3
 * periods of Lamb's mode 2, omega^2 = 6 sigma / (rho R^3) (Lamb 1932, art. 275, in 2D):
 * - angular momentum about the centre of mass: |L| / (M R u_max), u_max the largest speed of
 *   the run, near zero (a free body: nothing exerts a moment on it; what is left comes from
 *   the particles' moves of the shifting and the ALE terms), below bounds_of's 3x the
 *   measured figure;
 * - the mode-2 period from the zero crossings of I_xx - I_yy, the second moments of the
 *   particle positions about their centre (which the drop's rotation would not fool, as it
 *   fools the width), within bounds_of's share of the period of the same shape computed by
 *   tools/drop-reference (potential flow, boundary integrals, water's viscosity through the
 *   normal viscous stress), measured the same way over the same window. Lamb's linear period
 *   is not the reference at these amplitudes: the finite-amplitude shift is +3.0 % for the
 *   ellipse and +7.6 % for the rectangle, whose corners also excite higher modes
 *   (docs/surface-tension.md); the runs print both;
 * - |eps_v1| below bounds_of's figure: a drop that swells fails it;
 * - the free-surface count within 10 % of the perimeter over dr, the count of a smooth surface
 *   sampled at the particle spacing: at most 1.1 x the initial shape's (the surface energy
 *   sigma P cannot exceed the initial one, nothing feeding the drop), at least 0.9 x that of
 *   a circle (the least perimeter of the area) cut from the lattice, whose staircase exposes
 *   2 sqrt(2) / pi = 0.90 of a smooth circle's count (its boundary points lie on the
 *   diagonals' length 4 sqrt(2) R, not 2 pi R). A roughening surface leaves that band upwards
 *   (before the fix: 196 -> 501 at N = 40, against 220), a surface the detection loses
 *   downwards.
 * Before the force took its normal, curvature and interface function from the surface
 * (scheme/surface_tension.c), the rectangle reached eps_v1 = +0.9 % at 0.5 s and its surface
 * particles rose by half. */
#include "diag/freesurface.h"
#include "diag/volume.h"
#include "io/csv_read.h"
#include "scheme/solver.h"

#include <math.h>
#include <setjmp.h>
#include <stdbool.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "check.h"
#include "laplace.h"
#include "slope.h"

#define SIGMA 0.0727 /* N/m */
#define RHO   1000.0

/* The resolution and the duration: the test's, or the command line's (tools/validate-drop
 * runs the outside check's N = 40 over 1.5 s through the same checks). */
static int resolution = 30;
static double t_end = 0.8;

/* The drop centred in a 0.1 m square tank. */
static void start_drop(config *cfg, solver *s, const char *shape, double length, double height,
                       const char *scheme)
{
    char text[1024], err[1024];
    snprintf(text, sizeof text,
             "[case]\nname = drop\ndim = 2\nt_end = %g\n[tank]\nlength = 0.1\nheight = 0.1\n"
             "[liquid]\nshape = %s\nlength = %.17g\nheight = %.17g\nx0 = %.17g\ny0 = %.17g\n"
             "[fluid]\nviscosity = 1.0e-6\nsurface_tension = %g\ngravity = 0\n"
             "[model]\nscheme = %s\n[numerics]\nresolution = %d\nsound_speed = 5\n",
             t_end, shape, length, height, 0.05 - 0.5 * length, 0.05 - 0.5 * height, SIGMA, scheme,
             resolution);
    if (config_load_string(cfg, text, "test", NULL, 0, err, sizeof err)) fail_msg("%s", err);
    if (solver_init(s, cfg, err, sizeof err)) fail_msg("%s", err);
}

typedef struct {
    double mass, centre[DIM];
    double moment_xx_minus_yy; /* I_xx - I_yy about the centre */
    double angular;            /* L_z about the centre */
    double umax;
    double ekin; /* J per unit width */
} drop_state;

static drop_state measure(const particles *p)
{
    drop_state d = {0};
    for (size_t i = 0; i < p->n_fluid; i++) {
        d.mass += p->m[i];
        for (int a = 0; a < DIM; a++) d.centre[a] += p->m[i] * p->x[a][i];
    }
    for (int a = 0; a < DIM; a++) d.centre[a] /= d.mass;
    for (size_t i = 0; i < p->n_fluid; i++) {
        double rx = p->x[0][i] - d.centre[0], ry = p->x[1][i] - d.centre[1];
        d.moment_xx_minus_yy += p->m[i] * (rx * rx - ry * ry);
        d.angular += p->m[i] * (rx * p->u[1][i] - ry * p->u[0][i]);
        double speed = sqrt(p->u[0][i] * p->u[0][i] + p->u[1][i] * p->u[1][i]);
        if (speed > d.umax) d.umax = speed;
        d.ekin += 0.5 * p->m[i] * speed * speed;
    }
    return d;
}

/* Zero crossings of I_xx - I_yy, by linear interpolation, and the mode-2 period from them:
 * from the second crossing on, since the first half period is the corners rounding off. */
typedef struct {
    double t_end, previous_t, previous;
    double crossing[64];
    int crossings;
} crossings;

static void add_sample(crossings *c, double t, double moment)
{
    if (t > c->t_end) return;
    if (c->previous_t >= 0.0 && (c->previous < 0.0) != (moment < 0.0) && c->crossings < 64)
        c->crossing[c->crossings++] = t - (t - c->previous_t) * moment / (moment - c->previous);
    c->previous_t = t;
    c->previous = moment;
}

static double mode2_period(const crossings *c)
{
    assert_true(c->crossings >= 4);
    return 2.0 * (c->crossing[c->crossings - 1] - c->crossing[1]) / (c->crossings - 2);
}

static void reference_row(void *ctx, const csv_summary *s, char **fields, int n_fields)
{
    int t = csv_summary_column(s, "t"), m = csv_summary_column(s, "moment_xx_minus_yy");
    assert_true(t >= 0 && m >= 0 && t < n_fields && m < n_fields);
    add_sample(ctx, atof(fields[t]), atof(fields[m]));
}

/* The reference period over [0, t_end] from tests/data/drop/<name>.csv: the columns t and
 * moment_xx_minus_yy of `tools/drop-reference --shape <name> --viscosity 1e-6 --csv FILE`
 * (docs/surface-tension.md gives the commands), a drop of the rectangle's area
 * (R = 11.05 mm), scaled to radius R as sqrt(rho R^3 / sigma) scales. */
static double reference_period(const char *name, double radius)
{
    char path[512];
    snprintf(path, sizeof path, "%s/tests/data/drop/%s.csv", VCSPH_SOURCE_DIR, name);
    crossings c = {.t_end = t_end, .previous_t = -1.0};
    csv_summary table;
    assert_int_equal(csv_summary_read(path, &table, reference_row, &c), 0);
    csv_summary_free(&table);
    double reference_radius = sqrt(0.024 * 0.016 / M_PI);
    return mode2_period(&c) * pow(radius / reference_radius, 1.5);
}

static size_t count_free_surface(const particles *p)
{
    size_t n = 0;
    for (size_t i = 0; i < p->n_fluid; i++) n += p->surface[i] == SURFACE_FREE;
    return n;
}

/* Ramanujan's second formula, exact to 1e-6 at the aspect 1.5 */
static double ellipse_perimeter(double a, double b)
{
    double h = pow((a - b) / (a + b), 2);
    return M_PI * (a + b) * (1.0 + 3.0 * h / (10.0 + sqrt(4.0 - 3.0 * h)));
}

/* The bounds of a run of `shape`, each at most 3x what this test's run (N = 30, 0.8 s)
 * measured; tools/validate-drop's longer, finer runs (N = 40, 1.5 s) and any other from the
 * command line take the larger figures below.
 * - |L| / (M R u_max): measured 4.0e-5 (rectangle), 2.9e-6 (ellipse); at N = 40 over 1.5 s
 *   4.4e-5 and 1.26e-4, the ellipse's growing along the run;
 * - the mode-2 period against tools/drop-reference: measured -3.7 % (rectangle, whose corners
 *   excite higher modes; bound 5 %, 1.35x) and +1.3 % (ellipse; 3.9 %); 5 % for other runs;
 * - max |eps_v1|: measured 0.188 % and 0.125 %; bounds 0.5 % and 0.375 %, 0.5 % for other
 *   runs (a drop that swells fails it). */
typedef struct {
    double angular, period, eps;
} drop_bounds;

static drop_bounds bounds_of(const char *shape)
{
    bool own = resolution == 30 && t_end == 0.8, box = strcmp(shape, "box") == 0;
    if (!own) return (drop_bounds){box ? 1.3e-4 : 3.8e-4, 0.05, 0.005};
    return box ? (drop_bounds){1.2e-4, 0.05, 0.005} : (drop_bounds){9e-6, 0.039, 0.00375};
}

static void check_drop(const char *shape, const char *reference, double length, double height,
                       double perimeter, const char *scheme)
{
    config cfg;
    solver s;
    start_drop(&cfg, &s, shape, length, height, scheme);
    double radius = equivalent_radius(&s);
    double lamb = 2.0 * M_PI / sqrt(6.0 * SIGMA / (RHO * pow(radius, 3)));
    double umax = 0.0, worst_angular = 0.0, worst_eps = 0.0, mass = 0.0;
    size_t free0 = 0, free_lo = SIZE_MAX, free_hi = 0;
    crossings c = {.t_end = cfg.t_end, .previous_t = -1.0};
    while (s.t < cfg.t_end) {
        assert_int_equal(solver_prepare(&s, cfg.t_end), 0);
        volume_errors ve;
        volume_compute(&s.p, s.dv.cell_volume, s.scratch, NULL, &ve);
        if (fabs(ve.eps_v1) > worst_eps) worst_eps = fabs(ve.eps_v1);
        size_t n_free = count_free_surface(&s.p);
        if (s.t >= 0.1) {
            if (free0 == 0) free0 = n_free;
            if (n_free < free_lo) free_lo = n_free;
            if (n_free > free_hi) free_hi = n_free;
        }
        drop_state d = measure(&s.p);
        mass = d.mass;
        if (d.umax > umax) umax = d.umax;
        if (fabs(d.angular) > worst_angular) worst_angular = fabs(d.angular);
        add_sample(&c, s.t, d.moment_xx_minus_yy);
        solver_advance(&s, cfg.t_end);
    }
    double period = mode2_period(&c), expected = reference_period(reference, radius);
    double angular = worst_angular / (mass * radius * umax);
    printf("%s, %s, R/dr = %.1f: |L|/(M R u_max) %.2e, mode-2 period %.4f s from %d zero "
           "crossings after the first, reference %.4f s (%+.1f %%), Lamb %.4f s (%+.1f %%), "
           "max |eps_v1| %.3f %%, free surface %zu..%zu (%zu at 0.1 s), u_max %.3f m/s\n",
           shape, scheme, radius / s.dv.dr, angular, period, c.crossings - 1, expected,
           100.0 * (period / expected - 1.0), lamb, 100.0 * (period / lamb - 1.0),
           100.0 * worst_eps, free_lo, free_hi, free0, umax);
    drop_bounds bound = bounds_of(shape);
    assert_true(angular < bound.angular);
    assert_close(period / expected, 1.0, bound.period);
    assert_true(worst_eps < bound.eps);
    /* The outside check's bound: the count within 10 % of its value at 0.1 s. The ellipse cut
       from the lattice shows its staircase until 0.22 s (N = 30: 106 particles, where the
       smooth ellipse has 119 of spacing dr), so that value is low for it; since the
       correction moves each body's surface at one normal speed it holds all the same (N = 30:
       +9.4 %, N = 40: +8.1 %). Beside it, the bound by the perimeter: not above 1.1 x the
       initial perimeter over dr (the surface energy cannot exceed its initial value), not
       below 0.9 x a lattice circle's count. */
    double lo = 0.9 * 4.0 * sqrt(2.0) * radius / s.dv.dr, hi = 1.1 * perimeter / s.dv.dr;
    printf("free surface: %zu..%zu against [%.0f, %.0f] (0.9 x a lattice circle's count, 1.1 x "
           "the initial perimeter over dr) and [%.0f, %.0f] (+-10 %% of its value at 0.1 s)\n",
           free_lo, free_hi, lo, hi, 0.9 * (double)free0, 1.1 * (double)free0);
    assert_true((double)free_lo >= lo && (double)free_hi <= hi);
    assert_true((double)free_lo >= 0.9 * (double)free0 && (double)free_hi <= 1.1 * (double)free0);
    solver_free(&s);
}

static void test_rectangle_delta_plus(void **state)
{
    (void)state;
    check_drop("box", "rectangle", 0.024, 0.016, 2.0 * (0.024 + 0.016), "delta-plus");
}

/* the ellipse of the rectangle's area, semi-axes in the ratio 1.5 : 1 */
static void test_ellipse_delta_plus_ale(void **state)
{
    (void)state;
    double b = sqrt(0.024 * 0.016 / (1.5 * M_PI)), a = 1.5 * b;
    check_drop("ellipse", "ellipse", 2.0 * a, 2.0 * b, ellipse_perimeter(a, b), "delta-plus-ale");
}

/* The surface energy sigma sum delta V at t = 0 against sigma x the ellipse's perimeter
 * (Ramanujan's second formula, exact to 1e-6 at this aspect); the measure reads 0.98 of the
 * perimeter on smooth circles at R / dr = 20 (docs/surface-tension.md), so 5 %. */
static void test_ellipse_surface_energy(void **state)
{
    (void)state;
    double b = sqrt(0.024 * 0.016 / (1.5 * M_PI)), a = 1.5 * b;
    config cfg;
    solver s;
    start_drop(&cfg, &s, "ellipse", 2.0 * a, 2.0 * b, "delta-plus-ale");
    assert_int_equal(solver_prepare(&s, cfg.t_end), 0);
    double esurf = surface_tension_energy(&s.st, &s.p, s.scratch, NULL);
    double perimeter = ellipse_perimeter(a, b);
    printf("surface energy at t = 0: %.6f J, sigma x perimeter %.6f J (%+.1f %%)\n", esurf,
           SIGMA * perimeter, 100.0 * (esurf / (SIGMA * perimeter) - 1.0));
    assert_close(esurf / (SIGMA * perimeter), 1.0, 0.05);
    solver_free(&s);
}

/* The circle's run in blocks of BLOCK_LENGTH from BLOCK_START on */
#define BLOCK_START  0.5
#define BLOCK_LENGTH 0.25
#define MAX_BLOCKS   64

/* Student's t, one-sided 99 %, for dof = 1 .. 10 degrees of freedom; beyond 10, 10's (larger
 * than the true quantile, so the bound errs towards passing a steady run) */
static double t_quantile_99(int dof)
{
    static const double t[10] = {31.82, 6.965, 4.541, 3.747, 3.365,
                                 3.143, 2.998, 2.896, 2.821, 2.764};
    return t[(dof < 1 ? 1 : dof > 10 ? 10 : dof) - 1];
}

/* Whether the growth rate of ln y over the blocks is not significantly positive: slope <= t
 * s_slope, one-sided 99 %. Prints it. */
static bool not_growing(const char *what, const double *t, const double *y, int n)
{
    double ln_y[MAX_BLOCKS], error;
    for (int k = 0; k < n; k++) ln_y[k] = log(y[k]);
    double rate = least_squares_slope(t, ln_y, n, &error), bound = t_quantile_99(n - 2) * error;
    printf("%s: growth rate %+.3f /s over %d blocks, standard error %.3f, 99 %% bound %.3f /s\n",
           what, rate, n, error, bound);
    return rate <= bound;
}

/* A circular drop at rest, R = 11.05 mm (the rectangle's area) and R / dr = N / 2: the
 * discrete force is not exactly zero on a circle of particles, and what it drives are the
 * spurious currents. The outside check asks that they do not grow over 2 s at R / dr = 20
 * and 40. They are steady, not still: the fastest particle and the kinetic energy of a
 * window swing by a third between realizations of the same run (the start moved by 1e-12 dr,
 * docs/surface-tension.md), so comparing two windows decides by chance. The run from 0.5 s
 * on is cut into blocks of 0.25 s; the logarithms of each block's largest speed and of its
 * mean kinetic energy are fitted with a line in time, and each slope, a growth rate, must
 * not exceed its one-sided 99 % bound, t s_slope with n - 2 degrees of freedom: a steady run
 * passes but for one chance in a hundred, and the growth this check was written for fails
 * (before the volume correction moved each body's surface at one normal speed,
 * volume_correction.c, R / dr = 20's largest speed went 2.4 times up from [0.5, 1] s to
 * [1.5, 2] s and its energy about six times, rates near 1 /s and 2 /s; delta-SPH's circle,
 * which grows without shifting, fails it, docs/surface-tension.md). The capillary numbers
 * mu u_max / sigma of [0.5, 1] s and of the last quarter are printed as before. `make test`
 * runs R / dr = 20 (test_drop_circle), tools/validate-drop also 40. */
static void test_circle_at_rest(void **state)
{
    (void)state;
    double diameter = 2.0 * sqrt(0.024 * 0.016 / M_PI);
    config cfg;
    solver s;
    start_drop(&cfg, &s, "ellipse", diameter, diameter, "delta-plus-ale");
    double mu = RHO * 1.0e-6, early = 0.0, late = 0.0;
    double block_t[MAX_BLOCKS], block_umax[MAX_BLOCKS] = {0}, block_energy[MAX_BLOCKS] = {0};
    long block_steps[MAX_BLOCKS] = {0};
    int blocks = (int)floor((cfg.t_end - BLOCK_START) / BLOCK_LENGTH + 1e-9);
    assert_true(blocks >= 3 && blocks <= MAX_BLOCKS);
    while (s.t < cfg.t_end) {
        assert_int_equal(solver_prepare(&s, cfg.t_end), 0);
        drop_state d = measure(&s.p);
        if (s.t >= 0.5 && s.t <= 1.0 && d.umax > early) early = d.umax;
        if (s.t >= 0.75 * cfg.t_end && d.umax > late) late = d.umax;
        int k = (int)floor((s.t - BLOCK_START) / BLOCK_LENGTH);
        if (s.t >= BLOCK_START && k < blocks) {
            block_umax[k] = fmax(block_umax[k], d.umax);
            block_energy[k] += d.ekin;
            block_steps[k]++;
        }
        solver_advance(&s, cfg.t_end);
    }
    for (int k = 0; k < blocks; k++) {
        assert_true(block_steps[k] > 0);
        block_t[k] = BLOCK_START + (k + 0.5) * BLOCK_LENGTH;
        block_energy[k] /= (double)block_steps[k];
    }
    printf("circle at rest, R/dr = %.1f, %g s: capillary number mu u_max / sigma %.2e over "
           "[0.5, 1] s, %.2e over the last quarter (u_max %.4f and %.4f m/s); mean kinetic "
           "energy %.2e J in the first block, %.2e in the last\n",
           0.5 * diameter / s.dv.dr, cfg.t_end, mu * early / SIGMA, mu * late / SIGMA, early, late,
           block_energy[0], block_energy[blocks - 1]);
    bool speed_steady = not_growing("largest speed", block_t, block_umax, blocks);
    bool energy_steady = not_growing("kinetic energy", block_t, block_energy, blocks);
    assert_true(speed_steady);
    assert_true(energy_steady);
    solver_free(&s);
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rectangle_delta_plus),
        cmocka_unit_test(test_ellipse_delta_plus_ale),
        cmocka_unit_test(test_ellipse_surface_energy),
    };
    const struct CMUnitTest circle[] = {cmocka_unit_test(test_circle_at_rest)};
    if (argc >= 3) { /* tools/validate-drop: test_drop N t_end [circle] */
        resolution = atoi(argv[1]);
        t_end = atof(argv[2]);
        if (argc == 4 && strcmp(argv[3], "circle") == 0)
            return cmocka_run_group_tests(circle, NULL, NULL);
    }
    return cmocka_run_group_tests(tests, NULL, NULL);
}
