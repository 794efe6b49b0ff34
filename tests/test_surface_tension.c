/* Surface tension, the geometry of one step (paper sec. 2.2, theory §4,
 * docs/surface-tension.md): the interface function integrates to 1 across a flat surface,
 * the curvature of a circle (sphere) of radius R is (d - 1) / R, and the force is zero in the
 * interior and sums to zero on a body of liquid. */
#include "diag/freesurface.h"
#include "scheme/solver.h"

#include <float.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <cmocka.h>

#include "check.h"
#include "laplace.h"

#define SIGMA 0.5 /* N/m */

/* A weightless patch: the circle (sphere) inscribed in a cube of side 2R, of R / dr = n,
 * centred in a tank of side 6R, or the flat liquid block of a tank when flat. */
static void load_case(config *cfg, solver *s, double radius, int n, int flat, const char *scheme)
{
    char text[1024], err[1024];
    double side = 6.0 * radius;
    if (flat)
        snprintf(text, sizeof text,
                 "[case]\nname = flat\ndim = %d\nt_end = 1\n[tank]\nlength = %.17g\n"
                 "height = %.17g\nwidth = %.17g\n[liquid]\nheight = %.17g\n[fluid]\ngravity = 0\n"
                 "surface_tension = %g\n[model]\nscheme = %s\n[numerics]\nresolution = %d\n"
                 "sound_speed = 1\n",
                 DIM, side, side, side / 2, 2.0 * radius, SIGMA, scheme, 2 * n);
    else
        snprintf(text, sizeof text,
                 "[case]\nname = patch\ndim = %d\nt_end = 1\n[tank]\nlength = %.17g\n"
                 "height = %.17g\nwidth = %.17g\n[liquid]\nshape = ellipse\nheight = %.17g\n"
                 "length = %.17g\nx0 = %.17g\ny0 = %.17g\n[fluid]\ngravity = 0\n"
                 "surface_tension = %g\n[model]\nscheme = %s\n[numerics]\nresolution = %d\n"
                 "sound_speed = 1\n",
                 DIM, side, side, side, 2.0 * radius, 2.0 * radius, 2.0 * radius, 2.0 * radius,
                 SIGMA, scheme, 2 * n);
    if (config_load_string(cfg, text, "test", NULL, 0, err, sizeof err)) fail_msg("%s", err);
    if (solver_init(s, cfg, err, sizeof err)) fail_msg("%s", err);
}

/* Across the flat surface of a lattice block, sum delta V per unit area is 1 (the
 * calibration of theory §4; the block's 6R is a whole number of dr here), and the curvature
 * is zero: every normal is vertical. Both to round-off: the sum of n_fluid terms within
 * n_fluid DBL_EPSILON (2.7e-13 in 2D, 8.0e-12 in 3D; measured -1.7e-15 and 5.4e-14), and
 * |kappa| dr, a sum over a particle's neighbours (about 50 in 2D, 113 in 3D) of terms of
 * order 1, within 128 DBL_EPSILON = 2.8e-14 (measured 4.3e-16 and 1.3e-15). */
static void test_flat_surface(void **state)
{
    (void)state;
    config cfg;
    solver s;
    load_case(&cfg, &s, 0.05, 10, 1, "delta");
    assert_int_equal(solver_prepare(&s, cfg.t_end), 0);
    const particles *p = &s.p;
    double area = DIM == 2 ? s.tank.size[0] : s.tank.size[0] * s.tank.size[DIM - 1];
    double sum = 0.0, kappa_max = 0.0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        sum += p->interface[i] * p->vol[i];
        if (fabs(p->curvature[i]) > kappa_max) kappa_max = fabs(p->curvature[i]);
    }
    printf("%dD flat block: sum delta V / area - 1 = %.2e, max |kappa| dr = %.2e\n", DIM,
           sum / area - 1.0, kappa_max * s.dv.dr);
    assert_close(sum / area, 1.0, (double)p->n_fluid * DBL_EPSILON);
    assert_true(kappa_max * s.dv.dr < 128.0 * DBL_EPSILON);
    solver_free(&s);
}

/* Mean curvature of the patch, weighted by delta V as the force weighs it, and the spread of
 * the free-surface particles' values about (d - 1) / R. */
static void curvature_figures(const solver *s, double radius, double *weighted, double *rms_free)
{
    const particles *p = &s->p;
    double expected = (DIM - 1) / radius, w = 0.0, wk = 0.0, e2 = 0.0;
    size_t n_free = 0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        w += p->interface[i] * p->vol[i];
        wk += p->interface[i] * p->vol[i] * p->curvature[i];
        if (p->surface[i] != SURFACE_FREE) continue;
        double e = p->curvature[i] / expected - 1.0;
        e2 += e * e;
        n_free++;
    }
    *weighted = wk / w / expected - 1.0;
    *rms_free = sqrt(e2 / (double)n_free);
}

/* The same patch with its particles on shells of spacing dr (rings in 2D, Fibonacci spheres
 * in 3D): a smooth surface, as a relaxed patch has. */
static void place_on_shells(solver *s, double radius)
{
    particles *p = &s->p;
    double dr = s->dv.dr, centre = 3.0 * radius, m = p->m[0], rho = p->rho[0];
    size_t k = 0;
    for (int shell = 0; (shell + 0.5) * dr < radius; shell++) {
        double r = radius - (shell + 0.5) * dr;
        long count =
            DIM == 2 ? lround(2.0 * M_PI * r / dr) : lround(4.0 * M_PI * r * r / (dr * dr));
        if (count < 1) count = 1;
        for (long a = 0; a < count; a++, k++) {
            assert_true(k < (size_t)s->dv.n_fluid);
            vec x = vec_zero();
#if DIM == 2
            double angle = 2.0 * M_PI * (a + 0.5 * shell) / (double)count;
            x.c[0] = r * cos(angle);
            x.c[1] = r * sin(angle);
#else
            double z = 1.0 - (2.0 * a + 1.0) / (double)count, ring = sqrt(1.0 - z * z);
            double angle = M_PI * (3.0 - sqrt(5.0)) * (double)a + shell;
            x.c[0] = r * ring * cos(angle);
            x.c[1] = r * ring * sin(angle);
            x.c[2] = r * z;
#endif
            for (int d = 0; d < DIM; d++) {
                p->x[d][k] = centre + x.c[d];
                p->u[d][k] = 0.0;
            }
            p->m[k] = m;
            p->rho[k] = rho;
            p->vol[k] = m / rho;
            p->id[k] = (int64_t)k;
        }
    }
    p->n_fluid = p->n_total = k;
}

/* The curvature of a patch of R / dr = n: the delta-weighted mean (what sets the Laplace
 * pressure) against (d - 1) / R, the rms over the free-surface particles, and the worst of
 * them against (d - 1) / (R - dr/2), the curvature of the outermost particles' own surface. */
typedef struct {
    double weighted, rms, worst;
} curvature_row;

static curvature_row patch_curvature(int n, int on_shells)
{
    config cfg;
    solver s;
    double radius = 0.05;
    /* the shells replace the particles: load a case with more of them, so that the solver's
       work arrays hold the shells (2D: the flat block; 3D: the ellipsoid spanning the width) */
    load_case(&cfg, &s, radius, n, on_shells && DIM == 2, "delta");
    if (on_shells)
        place_on_shells(&s, radius);
    else
        cut_ball(&s, radius);
    assert_int_equal(solver_prepare(&s, cfg.t_end), 0);
    curvature_row row = {0.0, 0.0, 0.0};
    double r_eq = on_shells ? radius : equivalent_radius(&s);
    curvature_figures(&s, r_eq, &row.weighted, &row.rms);
    double outer = (DIM - 1) / (r_eq - 0.5 * s.dv.dr);
    for (size_t i = 0; i < s.p.n_fluid; i++)
        if (s.p.surface[i] == SURFACE_FREE) {
            double e = fabs(s.p.curvature[i] / outer - 1.0);
            if (e > row.worst) row.worst = e;
        }
    printf("| %dD | %-7s | %2d | %+6.2f %% | %6.2f %% | %7.3f %% |\n", DIM,
           on_shells ? "shells" : "lattice", n, 100.0 * row.weighted, 100.0 * row.rms,
           100.0 * row.worst);
    solver_free(&s);
    return row;
}

/* The table of docs/surface-tension.md, every row the test computes asserted against its
 * measured figures (below, as fractions; printed in per cent): the delta-weighted mean's
 * error, the rms and the worst free-surface particle, each at most 1.5x its measured value.
 * These are one geometric evaluation each, no time stepping, so between machines they move
 * by round-off only; the margin leaves room for a change that moves them a little, and a
 * change that moves them more must update the table here and in the docs. What the figures
 * say:
 * - cut out of the lattice, the delta-weighted mean of the circle and the ball is within
 *   the 10 % that surface tension needs at R / dr = 20 (1.5 x 5.6 % and 1.5 x 5.7 %); the
 *   staircase makes single particles' curvature noisy (its steps are sharper than 2h can
 *   smooth, the more so at high R / dr), and the rms and worst grow with R / dr;
 * - on shells (a smooth surface), the delta-weighted error is the dr / 2R of the outermost
 *   layer below the surface, and every free-surface particle is within a few per cent of
 *   the curvature through the outermost particles' centres. */
static const int patch_sizes[3] = {10, 20, 40};
#if DIM == 2
enum { N_PATCH_SIZES = 3 };
static const curvature_row measured[2][3] = {
    /* lattice */ {{0.0633, 0.1687, 0.2573}, {0.0557, 0.3382, 0.5962}, {0.0077, 0.6270, 1.3387}},
    /* shells */ {{0.0526, 0.0526, 0.00069}, {0.0256, 0.0256, 0.00107}, {0.0127, 0.0127, 0.00128}},
};
#else
enum { N_PATCH_SIZES = 2 };
static const curvature_row measured[2][3] = {
    /* lattice */ {{0.0665, 0.1255, 0.2436}, {0.0574, 0.2697, 0.8727}},
    /* shells */ {{0.0527, 0.0527, 0.01322}, {0.0257, 0.0257, 0.03093}},
};
#endif

static void test_patch_curvature(void **state)
{
    (void)state;
    const double margin = 1.5;
    printf("| dim | surface | R/dr | delta-weighted kappa | rms free | worst free |\n");
    for (int k = 0; k < N_PATCH_SIZES; k++)
        for (int on_shells = 0; on_shells <= 1; on_shells++) {
            curvature_row row = patch_curvature(patch_sizes[k], on_shells);
            const curvature_row *bound = &measured[on_shells][k];
            assert_true(fabs(row.weighted) <= margin * bound->weighted);
            assert_true(row.rms <= margin * bound->rms);
            assert_true(row.worst <= margin * bound->worst);
        }
}

/* The force acts in S_F only, and on a body of liquid away from the walls it sums to zero to
 * round-off; over five steps of delta-SPH (whose other forces are pair sums) the momentum of
 * a patch starting at rest stays zero to round-off of sum m |u|: within n_fluid DBL_EPSILON
 * of it, the round-off of a sum of n_fluid terms (measured 2.2e-16 in 2D, 6.9e-16 in 3D). */
static void test_momentum(void **state)
{
    (void)state;
    config cfg;
    solver s;
    load_case(&cfg, &s, 0.05, 10, 0, "delta");
    cut_ball(&s, 0.05);
    for (int step = 0; step < 5; step++) {
        assert_int_equal(solver_prepare(&s, cfg.t_end), 0);
        const particles *p = &s.p;
        vec net = vec_zero();
        double magnitude = 0.0;
        for (size_t i = 0; i < p->n_fluid; i++) {
            vec f = vec_load(p->st_force, i);
            if (p->surface[i] == SURFACE_INTERIOR) assert_true(vec_norm(f) == 0.0);
            net = vec_add(net, f);
            magnitude += vec_norm(f);
        }
        assert_true(magnitude > 0.0);
        assert_true(vec_norm(net) <= 1e-13 * magnitude);
        solver_advance(&s, cfg.t_end);
    }
    const particles *p = &s.p;
    vec momentum = vec_zero();
    double scale = 0.0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec u = vec_load(p->u, i);
        momentum = vec_axpy(momentum, p->m[i], u);
        scale += p->m[i] * vec_norm(u);
    }
    printf("%dD patch after 5 steps: |sum m u| = %.2e, sum m |u| = %.2e\n", DIM, vec_norm(momentum),
           scale);
    assert_true(scale > 0.0);
    assert_true(vec_norm(momentum) <= (double)p->n_fluid * DBL_EPSILON * scale);
    solver_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flat_surface),
        cmocka_unit_test(test_patch_curvature),
        cmocka_unit_test(test_momentum),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
