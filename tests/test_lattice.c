/* The initial lattice (sec. 2.1): liquid.shape = box fills the liquid box exactly as it always
 * has; liquid.shape = ellipse keeps the lattice points inside the inscribed ellipse (2D) or
 * ellipsoid (3D), and case_numbers counts exactly the particles lattice_fill places. */
#include "boundary/lattice.h"
#include "core/derived.h"
#include "scheme/case_numbers.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <cmocka.h>

#include "check.h"

#define STR_(x)  #x
#define STR(x)   STR_(x)
#define DIM_TEXT STR(DIM)

/* A droplet of radius R = 0.1 m, R / dr = 20 (resolution 40 across 2R), lifted off the bottom,
 * gravity 0: a disc in 2D, a ball in 3D (the tank width 2R is the ellipsoid's z extent). */
static const char droplet_case[] = "[case]\nname = droplet\ndim = " DIM_TEXT "\nt_end = 1\n"
                                   "[tank]\nlength = 0.4\nheight = 0.4\nwidth = 0.2\n"
                                   "[liquid]\nheight = 0.2\nlength = 0.2\nx0 = 0.1\ny0 = 0.1\n"
                                   "shape = ellipse\n"
                                   "[fluid]\ngravity = 0\n"
                                   "[numerics]\nresolution = 40\nsound_speed = 10\n";
static const double droplet_r = 0.1, droplet_centre[3] = {0.2, 0.2, 0.1};

/* A dam-break-like box whose length is not a whole number of dr (0.7234 m = 72.34 dr), so
 * that the x spacing differs from dr, with a hydrostatic pressure. */
static const char box_case[] = "[case]\nname = box\ndim = " DIM_TEXT "\nt_end = 1\n"
                               "[tank]\nlength = 1.0\nheight = 0.5\nwidth = 0.3\n"
                               "[liquid]\nheight = 0.2\nlength = 0.7234\nx0 = 0.05\n"
                               "[numerics]\nresolution = 20\n";

static void load(config *cfg, const char *text, const char *const *set, int n_set)
{
    char err[1024];
    if (config_load_string(cfg, text, "test", set, n_set, err, sizeof err)) fail_msg("%s", err);
}

/* case_numbers, then lattice_fill, which must place exactly dv->n_fluid particles. */
static void fill(const config *cfg, derived *dv, particles *p)
{
    char err[1024];
    motion mo;
    if (motion_init(&mo, cfg, err, sizeof err)) fail_msg("%s", err);
    case_numbers(cfg, &mo, dv);
    motion_free(&mo);
    if (derived_check(cfg, dv, err, sizeof err)) fail_msg("%s", err);
    assert_int_equal(particles_init(p, 0), 0);
    assert_int_equal(lattice_fill(p, cfg, dv, 0, (size_t)dv->n_fluid), 0);
    assert_int_equal((long)p->n_fluid, dv->n_fluid);
    assert_int_equal(p->n_total, p->n_fluid);
}

static void test_droplet(void **state)
{
    (void)state;
    config cfg;
    load(&cfg, droplet_case, NULL, 0);
    derived dv;
    particles p;
    fill(&cfg, &dv, &p);
    double dr = dv.dr, r = droplet_r;
    assert_close(r / dr, 20.0, 1e-12);
#if DIM == 2
    double expected = M_PI * r * r / (dr * dr);
#else
    double expected = 4.0 / 3.0 * M_PI * r * r * r / (dr * dr * dr);
#endif
    printf("%dD droplet, R/dr = 20: %ld particles, %.1f expected (%+.3f %%)\n", DIM, dv.n_fluid,
           expected, 100.0 * ((double)dv.n_fluid / expected - 1.0));
    assert_close((double)dv.n_fluid / expected, 1.0, 0.01);

    /* every particle inside the circle (sphere), at rest, a cell's volume and mass each */
    double com[DIM] = {0}, mass = 0.0;
    for (size_t i = 0; i < p.n_fluid; i++) {
        double d2 = 0.0;
        for (int d = 0; d < DIM; d++) {
            double s = p.x[d][i] - droplet_centre[d];
            d2 += s * s;
            com[d] += p.x[d][i];
            assert_true(p.u[d][i] == 0.0);
        }
        if (!(d2 <= r * r * (1.0 + 1e-12)))
            fail_msg("particle %zu at distance %.6g R from the centre", i, sqrt(d2) / r);
        assert_int_equal(p.id[i], (int64_t)i);
        assert_true(p.p[i] == 0.0 && p.rho[i] == cfg.density); /* gravity 0: no pressure */
        assert_close(p.m[i], cfg.density * dv.cell_volume, 1e-15);
        mass += p.m[i];
    }
    /* the kept points are symmetric about the centre */
    for (int d = 0; d < DIM; d++)
        assert_close(com[d] / (double)p.n_fluid, droplet_centre[d], 1e-12);
    /* the spacing is dr on every axis here, and V0, M_L follow from the count */
    assert_close(dv.cell_volume, pow(dr, DIM), 1e-12 * pow(dr, DIM));
    assert_true(dv.v0 == (double)dv.n_fluid * dv.cell_volume);
    assert_true(dv.mass_liquid == cfg.density * dv.v0);
    assert_close(mass / dv.mass_liquid, 1.0, 1e-12);
    particles_free(&p);
}

/* An ellipse (length 2 x height: the Lamb oscillation test) keeps the points inside
 * ((x - xc) / a)^2 + ((y - yc) / b)^2 (+ ((z - zc) / c)^2) <= 1 and no others. */
static void test_ellipse(void **state)
{
    (void)state;
    config cfg;
    const char *set[] = {"tank.length=0.5", "liquid.length=0.4", "liquid.x0=0.05"};
    load(&cfg, droplet_case, set, 3);
    derived dv;
    particles p;
    fill(&cfg, &dv, &p);
    double semi[3] = {0.2, 0.1, 0.1}, centre[3] = {0.25, 0.2, 0.1};
    for (size_t i = 0; i < p.n_fluid; i++) {
        double q = 0.0;
        for (int d = 0; d < DIM; d++) q += pow((p.x[d][i] - centre[d]) / semi[d], 2);
        assert_true(q <= 1.0 + 1e-12);
    }
    /* the box lattice has n_axis[0] n_axis[1] (n_axis[2]) points: those clearly inside are
       kept, those clearly outside are not (a point on the ellipse may go either way) */
    long inside = 0, not_outside = 0;
    for (long c2 = 0; c2 < (DIM == 3 ? dv.n_axis[2] : 1); c2++)
        for (long c1 = 0; c1 < dv.n_axis[1]; c1++)
            for (long c0 = 0; c0 < dv.n_axis[0]; c0++) {
                long c[3] = {c0, c1, c2};
                double q = 0.0;
                for (int d = 0; d < DIM; d++) {
                    double x = centre[d] - semi[d] + (c[d] + 0.5) * dv.spacing[d];
                    q += pow((x - centre[d]) / semi[d], 2);
                }
                inside += q <= 1.0 - 1e-9;
                not_outside += q <= 1.0 + 1e-9;
            }
    assert_true(inside <= dv.n_fluid && dv.n_fluid <= not_outside);
#if DIM == 2
    double expected = M_PI * semi[0] * semi[1] / (dv.dr * dv.dr);
#else
    double expected = 4.0 / 3.0 * M_PI * semi[0] * semi[1] * semi[2] / pow(dv.dr, 3);
#endif
    assert_close((double)dv.n_fluid / expected, 1.0, 0.01);
    particles_free(&p);
}

/* The box is what it was before liquid.shape: the same count, positions, volumes and mass,
 * bit for bit. */
static void test_box_unchanged(void **state)
{
    (void)state;
    config cfg;
    load(&cfg, box_case, NULL, 0);
    assert_int_equal(cfg.liquid_shape, LIQUID_BOX);
    derived dv;
    particles p;
    fill(&cfg, &dv, &p);
#if DIM == 2
    assert_int_equal(dv.n_fluid, 1440); /* 72 x 20 */
    double v0 = cfg.liquid_length * cfg.liquid_height;
#else
    assert_int_equal(dv.n_fluid, 43200); /* 72 x 20 x 30 */
    double v0 = cfg.liquid_length * cfg.liquid_height * cfg.tank_width;
#endif
    assert_true(dv.v0 == v0);
    assert_true(dv.cell_volume == v0 / (double)dv.n_fluid);
    assert_true(dv.mass_liquid == cfg.density * cfg.liquid_length * cfg.liquid_height *
                                      (DIM == 3 ? cfg.tank_width : 1.0));
    const double origin[3] = {cfg.liquid_x0, cfg.liquid_y0, 0.0};
    size_t i = 0;
    for (long c2 = 0; c2 < (DIM == 3 ? dv.n_axis[2] : 1); c2++)
        for (long c1 = 0; c1 < dv.n_axis[1]; c1++)
            for (long c0 = 0; c0 < dv.n_axis[0]; c0++, i++) {
                long c[3] = {c0, c1, c2};
                for (int d = 0; d < DIM; d++)
                    assert_true(p.x[d][i] == origin[d] + (c[d] + 0.5) * dv.spacing[d]);
                double pressure = cfg.density * cfg.gravity * (cfg.liquid_height - p.x[1][i]);
                assert_true(p.p[i] == pressure);
                assert_true(p.m[i] == p.rho[i] * dv.cell_volume);
            }
    assert_int_equal(i, p.n_fluid);
    particles_free(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_droplet),
        cmocka_unit_test(test_ellipse),
        cmocka_unit_test(test_box_unchanged),
    };
    return cmocka_run_group_tests_name("test_lattice_" DIM_TEXT "d", tests, NULL, NULL);
}
