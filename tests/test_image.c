/* Unit tests of io/image: particle images read back through libpng. Colours are checked at the
 * pixels where the documented mapping (io/image.h) puts the particles, the outline and the
 * colour bar; bad input is refused without leaving a file behind. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* mkdtemp, in temp_dir.h */
#endif

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "image_fixture.h"

/* ---------------------------------------------------------------------------------------- */
/* Size and layout                                                                           */

/* The tank is pixels_wide wide and as tall as its aspect ratio says; the margins do not
 * depend on the tank. */
static void test_dimensions(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame();
    image_layout l = layout_of(&f, WIDE);
    assert_int_equal(l.tank_width, WIDE);
    assert_int_equal(l.tank_height, 200);
    assert_close(l.scale, 400.0, 1e-12);
    png_rgb a = write_and_read(fx, "a.png", &f, WIDE);

    f.height = 0.75; /* 300 px tall: the image grows by 100 rows, not a column */
    png_rgb b = write_and_read(fx, "b.png", &f, WIDE);
    assert_int_equal(b.height - a.height, 100);
    assert_int_equal(b.width, a.width);

    f.height = 0.5; /* 3/4 of the pixels: 100 columns and 50 rows fewer */
    png_rgb c = write_and_read(fx, "c.png", &f, 300);
    assert_int_equal(a.width - c.width, 100);
    assert_int_equal(a.height - c.height, 50);

    f.width = 3.0; /* a flat tank: 400 x 67 px, the bar keeps room for its three labels */
    f.height = 0.5;
    image_layout flat = layout_of(&f, WIDE);
    assert_int_equal(flat.tank_height, 67);
    assert_true(flat.bar_height >= 3 * 18);
    png_rgb d = write_and_read(fx, "d.png", &f, WIDE);
    assert_true(d.width > (uint32_t)WIDE);

    png_rgb_free(&a);
    png_rgb_free(&b);
    png_rgb_free(&c);
    png_rgb_free(&d);
}

/* ---------------------------------------------------------------------------------------- */
/* Particles                                                                                 */

/* vmax is red, vmin blue, the middle white-ish, NaN grey, beyond vmax clamped to vmax, each at
 * the pixel the mapping gives; a disc of radius 4 px covers 3 px from its centre and not 5. */
static void test_particle_colours(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame(); /* radius 0.01 m = 4 px */
    image_layout l = layout_of(&f, WIDE);
    double x[5], y[5];
    const double value[5] = {1.0, -1.0, 0.0, NAN, 7.0};
    const int at[5][2] = {{100, 100}, {300, 100}, {200, 40}, {200, 160}, {50, 50}};
    for (int k = 0; k < 5; k++) centre_of(&l, &f, at[k][0], at[k][1], &x[k], &y[k]);
    f.x = x;
    f.y = y;
    f.value = value;
    f.n = 5;
    png_rgb img = write_and_read(fx, "p.png", &f, WIDE);

    uint32_t i, j;
    pixel_of(&l, &f, x[0], y[0], &i, &j);
    assert_int_equal(i, l.tank_left + 100);
    assert_int_equal(j, l.tank_top + 100);
    print_pixel("vmax", png_pixel(&img, i, j));
    assert_true(is_red(png_pixel(&img, i, j)));
    assert_true(is_red(png_pixel(&img, i + 3, j)));
    assert_true(is_red(png_pixel(&img, i, j - 3)));
    assert_true(is_white(png_pixel(&img, i + 5, j)));
    assert_true(is_white(png_pixel(&img, i, j + 5)));

    pixel_of(&l, &f, x[1], y[1], &i, &j);
    print_pixel("vmin", png_pixel(&img, i, j));
    assert_true(is_blue(png_pixel(&img, i, j)));

    pixel_of(&l, &f, x[2], y[2], &i, &j);
    print_pixel("middle", png_pixel(&img, i, j));
    assert_true(is_whiteish(png_pixel(&img, i, j)));
    assert_false(is_white(png_pixel(&img, i, j))); /* still visible on the background */

    pixel_of(&l, &f, x[3], y[3], &i, &j);
    const uint8_t *p = png_pixel(&img, i, j);
    assert_true(p[0] == p[1] && p[1] == p[2] && p[0] > 80 && p[0] < 200);

    unsigned char top[3];
    image_colour(1.0, top);
    pixel_of(&l, &f, x[4], y[4], &i, &j);
    assert_true(same_colour(png_pixel(&img, i, j), top));
    png_rgb_free(&img);
}

/* Later particles are drawn over earlier ones. */
static void test_drawing_order(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame();
    image_layout l = layout_of(&f, WIDE);
    double x[2], y[2];
    centre_of(&l, &f, 100, 100, &x[0], &y[0]);
    centre_of(&l, &f, 104, 100, &x[1], &y[1]); /* overlaps the first by half */
    const double value[2] = {-1.0, 1.0};
    f.x = x;
    f.y = y;
    f.value = value;
    f.n = 2;
    png_rgb img = write_and_read(fx, "o.png", &f, WIDE);
    uint32_t i0 = l.tank_left + 100, i1 = l.tank_left + 104, j = l.tank_top + 100;
    assert_true(is_blue(png_pixel(&img, i0 - 2, j))); /* only the first */
    assert_true(is_red(png_pixel(&img, i0 + 2, j)));  /* both: the second wins */
    assert_true(is_red(png_pixel(&img, i1, j)));
    png_rgb_free(&img);

    const double swapped[2] = {1.0, -1.0};
    f.value = swapped;
    img = write_and_read(fx, "o2.png", &f, WIDE);
    assert_true(is_blue(png_pixel(&img, i0 + 2, j)));
    png_rgb_free(&img);
}

/* A radius below a pixel still draws the pixel holding the centre, and only pixels nearby. */
static void test_small_radius(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame();
    f.radius = 0.0;
    image_layout l = layout_of(&f, WIDE);
    const double x = 0.3001, y = 0.2002, value = 1.0; /* off the pixel centres */
    f.x = &x;
    f.y = &y;
    f.value = &value;
    f.n = 1;
    png_rgb img = write_and_read(fx, "s.png", &f, WIDE);
    uint32_t i, j;
    pixel_of(&l, &f, x, y, &i, &j);
    assert_true(is_red(png_pixel(&img, i, j)));
    assert_true(is_white(png_pixel(&img, i + 2, j)));
    assert_true(is_white(png_pixel(&img, i - 2, j)));
    assert_true(is_white(png_pixel(&img, i, j + 2)));
    assert_true(is_white(png_pixel(&img, i, j - 2)));
    png_rgb_free(&img);
}

/* Particles outside the tank are drawn as far as the image reaches; far-away and non-finite
 * ones neither crash nor draw. */
static void test_outside_tank(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame();
    image_layout l = layout_of(&f, WIDE);
    /* 0: 8 px left of the left wall, in the margin; 1: straddling the image's left edge;
     * 2: far away; 3: huge; 4: NaN position */
    const double x[5] = {-0.02, -l.tank_left / l.scale, -50.0, 1e300, NAN};
    const double y[5] = {0.25, 0.1, 0.25, -1e300, 0.25};
    const double value[5] = {1.0, -1.0, 1.0, 1.0, 1.0};
    f.x = x;
    f.y = y;
    f.value = value;
    f.n = 5;
    f.radius = 0.005; /* 2 px */
    png_rgb img = write_and_read(fx, "out.png", &f, WIDE);
    uint32_t i, j;
    pixel_of(&l, &f, x[0], y[0], &i, &j);
    assert_true(i < (uint32_t)l.tank_left - 2); /* outside the tank and its outline */
    assert_true(is_red(png_pixel(&img, i, j)));
    pixel_of(&l, &f, x[1] + 1e-9, y[1], &i, &j); /* centred on the image's left edge */
    assert_int_equal(i, 0);
    assert_true(is_blue(png_pixel(&img, 0, j)));
    assert_true(is_blue(png_pixel(&img, 1, j)));
    png_rgb_free(&img);
}

/* ---------------------------------------------------------------------------------------- */
/* Bad input and files                                                                       */

static void assert_refused(fixture *fx, const image_frame *f, int wide, const char *what)
{
    char err[256] = "";
    const char *path = path_in(fx, "bad.png");
    assert_int_equal(image_write_particles(path, f, wide, err, sizeof err), -1);
    if (!strstr(err, what)) fail_msg("error '%s' does not say '%s'", err, what);
    assert_false(exists(path));
    assert_false(exists(path_in(fx, "bad.png.tmp")));
}

static void test_bad_range_refused(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame();
    f.vmin = f.vmax = 0.5;
    assert_refused(fx, &f, WIDE, "range");
    f.vmin = 1.0;
    f.vmax = -1.0;
    assert_refused(fx, &f, WIDE, "range");
    f.vmin = NAN;
    assert_refused(fx, &f, WIDE, "range");
    f.vmin = 0.0;
    f.vmax = INFINITY;
    assert_refused(fx, &f, WIDE, "range");
}

static void test_other_bad_input_refused(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame();
    assert_refused(fx, &f, 0, "pixels_wide");
    assert_refused(fx, &f, IMAGE_MAX_SIDE + 1, "pixels_wide");
    f.width = 0;
    assert_refused(fx, &f, WIDE, "tank size");
    f.width = 0.001; /* 500 times as tall as wide */
    assert_refused(fx, &f, WIDE, "too tall");
    f = tank_frame();
    f.radius = -1;
    assert_refused(fx, &f, WIDE, "radius");
    f = tank_frame();
    f.n = 3; /* no arrays */
    assert_refused(fx, &f, WIDE, "particles");
    f = tank_frame();
    char err[64] = "";
    image_layout l;
    assert_int_equal(image_layout_of(NULL, WIDE, &l, err, sizeof err), -1);
    assert_int_equal(image_write_particles(NULL, &f, WIDE, NULL, 0), -1); /* no err buffer */
}

/* The file is whole (it decodes and ends with IEND), replaces an older one, and leaves no
 * temporary file behind; a missing directory is reported with the name tried. */
static void test_files(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame();
    png_rgb img = write_and_read(fx, "f.png", &f, WIDE);
    png_rgb_free(&img);
    f.height = 0.25;
    img = write_and_read(fx, "f.png", &f, WIDE); /* over the first */
    assert_int_equal(img.height, layout_of(&f, WIDE).height);
    png_rgb_free(&img);
    assert_false(exists(path_in(fx, "f.png.tmp")));

    FILE *file = fopen(path_in(fx, "f.png"), "rb");
    assert_non_null(file);
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    unsigned char tail[12];
    assert_int_equal(fseek(file, -12, SEEK_END), 0);
    assert_int_equal(fread(tail, 1, 12, file), 12);
    fclose(file);
    assert_memory_equal(tail, iend, 12);

    char err[512] = "";
    const char *missing = path_in(fx, "no/such/dir/x.png");
    assert_int_equal(image_write_particles(missing, &f, WIDE, err, sizeof err), -1);
    assert_non_null(strstr(err, "no/such/dir/x.png.tmp"));
}

/* ---------------------------------------------------------------------------------------- */
/* Colour map                                                                                */

/* Red minus blue never falls with t and spans blue to red; the ends and middle are as
 * documented; t beyond [0, 1] is clamped and non-finite t is grey. */
static void test_colour_map_monotone(void **state)
{
    (void)state;
    enum { STEPS = 10000 };
    unsigned char c[3];
    int prev = -1000;
    for (int k = 0; k <= STEPS; k++) {
        image_colour((double)k / STEPS, c);
        int diff = c[0] - c[2];
        if (diff < prev)
            fail_msg("red - blue falls at t = %g: %d < %d", (double)k / STEPS, diff, prev);
        prev = diff;
    }
    image_colour(0.0, c);
    assert_true(is_blue(c));
    assert_true(c[2] - c[0] > 100);
    image_colour(1.0, c);
    assert_true(is_red(c));
    assert_true(c[0] - c[2] > 100);
    image_colour(0.5, c);
    assert_true(is_whiteish(c));
    assert_true(abs(c[0] - c[2]) <= 2);

    unsigned char d[3];
    image_colour(-3.0, c);
    image_colour(0.0, d);
    assert_memory_equal(c, d, 3);
    image_colour(4.0, c);
    image_colour(1.0, d);
    assert_memory_equal(c, d, 3);
    image_colour(NAN, c);
    assert_true(c[0] == c[1] && c[1] == c[2] && c[0] > 80 && c[0] < 200);
    image_colour(INFINITY, c);
    assert_true(c[0] == c[1] && c[1] == c[2]);

    /* smooth: no jump between neighbouring t of more than a few levels */
    unsigned char e[3];
    for (int k = 1; k <= 1000; k++) {
        image_colour((k - 1) / 1000.0, d);
        image_colour(k / 1000.0, e);
        for (int ch = 0; ch < 3; ch++) assert_true(abs(d[ch] - e[ch]) <= 2);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_dimensions, setup, teardown),
        cmocka_unit_test_setup_teardown(test_particle_colours, setup, teardown),
        cmocka_unit_test_setup_teardown(test_drawing_order, setup, teardown),
        cmocka_unit_test_setup_teardown(test_small_radius, setup, teardown),
        cmocka_unit_test_setup_teardown(test_outside_tank, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bad_range_refused, setup, teardown),
        cmocka_unit_test_setup_teardown(test_other_bad_input_refused, setup, teardown),
        cmocka_unit_test_setup_teardown(test_files, setup, teardown),
        cmocka_unit_test(test_colour_map_monotone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
