/* Unit tests of io/image's frame: the outline, the colour bar, the axes in metres and the
 * percent bar, and their text, read back through libpng (the particles: test_image.c). */
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
/* Outline, colour bar, text                                                                 */

/* The tank has a dark 2-px outline just outside it, and nothing inside an empty frame. */
static void test_outline_and_empty_frame(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame(); /* n = 0, no arrays */
    image_layout l = layout_of(&f, WIDE);
    png_rgb img = write_and_read(fx, "e.png", &f, WIDE);
    uint32_t left = l.tank_left, top = l.tank_top, right = left + l.tank_width - 1,
             bottom = top + l.tank_height - 1, mid_i = left + l.tank_width / 2,
             mid_j = top + l.tank_height / 2;
    for (uint32_t d = 1; d <= 2; d++) {
        assert_true(is_dark(png_pixel(&img, left - d, mid_j)));
        assert_true(is_dark(png_pixel(&img, right + d, mid_j)));
        assert_true(is_dark(png_pixel(&img, mid_i, top - d)));
        assert_true(is_dark(png_pixel(&img, mid_i, bottom + d)));
        assert_true(is_dark(png_pixel(&img, left - d, top - d))); /* closed corners */
        assert_true(is_dark(png_pixel(&img, right + d, bottom + d)));
    }
    assert_true(is_white(png_pixel(&img, left - 3, mid_j)));
    assert_true(is_white(png_pixel(&img, mid_i, bottom + 3)));
    for (uint32_t j = top; j <= bottom; j++)
        for (uint32_t i = left; i <= right; i++)
            if (!is_white(png_pixel(&img, i, j))) fail_msg("tank pixel (%u, %u) not white", i, j);
    png_rgb_free(&img);
}

/* The bar runs from red (vmax) at the top to blue (vmin) at the bottom, white-ish between, and
 * the text is black: the title at the top left, tick labels right of the bar. */
static void test_colour_bar_and_text(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame();
    image_layout l = layout_of(&f, WIDE);
    assert_true(l.bar_left > l.tank_left + l.tank_width + 2);
    assert_true(l.bar_left + l.bar_width < l.width);
    assert_true(l.bar_height >= l.tank_height);
    png_rgb img = write_and_read(fx, "bar.png", &f, WIDE);
    uint32_t i = l.bar_left + l.bar_width / 2;
    assert_true(is_red(png_pixel(&img, i, l.bar_top + 1)));
    assert_true(is_blue(png_pixel(&img, i, l.bar_top + l.bar_height - 2)));
    assert_true(is_whiteish(png_pixel(&img, i, l.bar_top + l.bar_height / 2)));
    for (int k = 1; k < l.bar_height; k++) { /* red minus blue falls down the bar */
        const uint8_t *a = png_pixel(&img, i, l.bar_top + k - 1),
                      *b = png_pixel(&img, i, l.bar_top + k);
        assert_true(b[0] - b[2] <= a[0] - a[2]);
    }

    /* black pixels in the title line left of the bar, in the tick labels right of it */
    int title = 0, ticks = 0;
    for (uint32_t j = 0; j < (uint32_t)l.tank_top - 2; j++)
        for (uint32_t k = 0; k < (uint32_t)l.bar_left; k++) title += is_dark(png_pixel(&img, k, j));
    for (uint32_t j = 0; j < img.height; j++)
        for (uint32_t k = l.bar_left + l.bar_width + 1; k < img.width; k++)
            ticks += is_dark(png_pixel(&img, k, j));
    assert_true(title > 100); /* "inm1  t = 12.345 s": 16 characters of 2x2 dots */
    assert_true(ticks > 100);
    png_rgb_free(&img);

    /* a title that would run into the bar label pushes the tank down a line */
    f.title = "a long title for a narrow tank";
    image_layout narrow = layout_of(&f, 200);
    image_layout narrow_untitled = layout_of(
        &(image_frame){.width = 1, .height = 0.5, .vmin = 0, .vmax = 1, .label = "eps_Vi"}, 200);
    assert_true(narrow.tank_top > narrow_untitled.tank_top);
    img = write_and_read(fx, "narrow.png", &f, 200);
    png_rgb_free(&img);
}

/* The tick steps are 1, 2 or 5 times a power of ten, the smallest that gives at most
 * max_ticks ticks in the range; an impossible range has none. */
static void test_nice_step(void **state)
{
    (void)state;
    /* exact: the step is m / 10^k, which rounds like the literal */
    assert_true(image_nice_step(0.0, 0.1172, 8) == 0.02); /* 0, 0.02 .. 0.1: 6 ticks */
    assert_true(image_nice_step(0.0, 1.0, 8) == 0.2);     /* 0.1 would give 11 */
    assert_true(image_nice_step(0.0, 0.5, 8) == 0.1);     /* 6 ticks, the ends included */
    assert_true(image_nice_step(0.0, 0.75, 8) == 0.1);    /* 8 */
    assert_true(image_nice_step(0.0, 3.0, 8) == 0.5);     /* 0.2 would give 16 */
    assert_true(image_nice_step(0.0, 1e-3, 8) == 2e-4);
    assert_true(image_nice_step(0.0, 250.0, 8) == 50.0);
    assert_true(image_nice_step(0.1, 0.9, 8) == 0.2);  /* 0.1 .. 0.9 by 0.1 is 9 */
    assert_true(image_nice_step(-2.0, 2.0, 8) == 1.0); /* the per-cent bar of +-2 % */
    assert_true(image_nice_step(-0.02, 0.02, 8) == 0.01);
    assert_true(image_nice_step(-1.0, 1.0, 8) == 0.5); /* 5 ticks */
    assert_true(image_nice_step(0.0, 1.0, 2) == 1.0);  /* 0.5 would give 3 */
    assert_true(image_nice_step(3.0, 3.5, 8) == 0.1);  /* away from 0 */
    assert_true(image_nice_step(1e6, 1e6 + 7, 8) == 1.0);
    /* about 4 to 8 ticks over ranges of every size and offset */
    for (int e = -6; e <= 6; e++)
        for (int k = 1; k <= 100; k++) {
            double lo = 0.037 * k * pow(10, e), hi = lo + 0.0931 * k * pow(10, e);
            double step = image_nice_step(lo, hi, 8);
            double n = floor(hi / step + 1e-9) - ceil(lo / step - 1e-9) + 1;
            if (!(n >= 3 && n <= 8)) fail_msg("[%g, %g]: step %g gives %g ticks", lo, hi, step, n);
            double m = step / pow(10, floor(log10(step) + 1e-9));
            assert_true(fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 || fabs(m - 5) < 1e-9);
        }
    assert_true(image_nice_step(1.0, 1.0, 8) == 0);
    assert_true(image_nice_step(1.0, 0.0, 8) == 0);
    assert_true(image_nice_step(0.0, NAN, 8) == 0);
    assert_true(image_nice_step(-INFINITY, 0.0, 8) == 0);
    assert_true(image_nice_step(-1e308, 1e308, 8) == 0); /* hi - lo overflows */
    assert_true(image_nice_step(0.0, 1.0, 1) == 0);
}

/* The axes: numbers in metres centred under their tick marks below the tank and beside them
 * left of it, the labels "x (m)" under the numbers and "y (m)", written upwards, left of them;
 * the colour bar of a per-cent frame is numbered in per cent at nice values. */
static void test_axes_and_percent_bar(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame(); /* 1 m x 0.5 m at 400 px/m: ticks every 0.2 m and 0.1 m */
    f.percent = true;
    f.vmin = -0.02;
    f.vmax = 0.02;
    image_layout l = layout_of(&f, WIDE);
    png_rgb img = write_and_read(fx, "axes.png", &f, WIDE);
    uint32_t x = 0, y = 0, right = l.tank_left + l.tank_width - 1,
             bottom = l.tank_top + l.tank_height - 1;

    /* x: "0.4" centred on its mark at column tank_left + 160, under the outline */
    uint32_t col = l.tank_left + 160;
    assert_true(is_dark(png_pixel(&img, col, bottom + 3)));
    assert_true(is_white(png_pixel(&img, col - 1, bottom + 4)));
    assert_true(is_white(png_pixel(&img, col + 1, bottom + 4)));
    if (!find_text(&img, "0.4", false, 0, img.width, bottom + 3, img.height, &x, &y))
        fail_msg("no x number 0.4 under the tank");
    assert_close(text_centre(x, "0.4"), col, 1.0);
    uint32_t x_numbers = y;
    assert_true(find_text(&img, "0.0", false, 0, img.width, bottom + 3, img.height, &x, &y));
    assert_close(text_centre(x, "0.0"), l.tank_left, 1.0);
    assert_true(find_text(&img, "1.0", false, 0, img.width, bottom + 3, img.height, &x, &y));
    assert_close(text_centre(x, "1.0"), right, 1.0);
    assert_false(find_text(&img, "0.5", false, 0, img.width, bottom + 3, img.height, &x, &y));
    if (!find_text(&img, "x (m)", false, 0, img.width, x_numbers + 1, img.height, &x, &y))
        fail_msg("no x label under the numbers");
    assert_close(text_centre(x, "x (m)"), l.tank_left + l.tank_width / 2.0, 2.0);

    /* y: "0.2" at row tank_top + 120, right-aligned left of its mark */
    uint32_t row = l.tank_top + 120;
    assert_true(is_dark(png_pixel(&img, l.tank_left - 3, row)));
    assert_true(is_white(png_pixel(&img, l.tank_left - 4, row - 1)));
    if (!find_text(&img, "0.2", false, 0, l.tank_left, l.tank_top - 8, bottom, &x, &y))
        fail_msg("no y number 0.2 left of the tank");
    assert_close(y + (FONT5X7_HEIGHT * DOT - 1) / 2.0, row, 1.0);
    assert_true(x + 3 * CELL - DOT < (uint32_t)l.tank_left - 2);
    uint32_t y_numbers = x;
    assert_true(find_text(&img, "0.5", false, 0, l.tank_left, 0, bottom, &x, &y));
    assert_true(find_text(&img, "0.0", false, 0, l.tank_left, 0, img.height, &x, &y));
    if (!find_text(&img, "y (m)", true, 0, y_numbers, l.tank_top, img.height, &x, &y))
        fail_msg("no y label left of the numbers");
    assert_close(y - (5 * CELL - DOT - 1) / 2.0, l.tank_top + l.tank_height / 2.0, 2.0);

    /* the bar: -2 % .. 2 % by 1 %, at the rows of their values */
    uint32_t beyond = l.bar_left + l.bar_width + 1;
    const char *percent[5] = {"2 %", "1 %", "0 %", "-1 %", "-2 %"};
    for (int k = 0; k < 5; k++) {
        uint32_t expected = l.bar_top + (uint32_t)lround(k * (l.bar_height - 1) / 4.0);
        assert_true(is_dark(png_pixel(&img, l.bar_left + l.bar_width, expected)));
        /* "2 %" is also the end of "-2 %": the first found from the top is the top one */
        if (!find_text(&img, percent[k], false, beyond, img.width, 0, img.height, &x, &y))
            fail_msg("no bar number '%s'", percent[k]);
        assert_close(y + (FONT5X7_HEIGHT * DOT - 1) / 2.0, expected, 1.0);
    }
    assert_false(find_text(&img, "0.02", false, beyond, img.width, 0, img.height, &x, &y));
    png_rgb_free(&img);

    /* without per cent, the values themselves */
    f.percent = false;
    img = write_and_read(fx, "fractions.png", &f, WIDE);
    assert_true(find_text(&img, "0.02", false, beyond, img.width, 0, img.height, &x, &y));
    assert_true(find_text(&img, "-0.01", false, beyond, img.width, 0, img.height, &x, &y));
    assert_false(find_text(&img, "2 %", false, beyond, img.width, 0, img.height, &x, &y));
    png_rgb_free(&img);
}

/* Narrow images get fewer ticks, so that the numbers never touch; a tank a few pixels wide
 * still draws. */
static void test_ticks_fit(void **state)
{
    fixture *fx = *state;
    image_frame f = tank_frame();
    image_layout l = layout_of(&f, 200); /* 0.2 m would be 40 px apart: too close */
    png_rgb img = write_and_read(fx, "narrow.png", &f, 200);
    uint32_t x = 0, y = 0, bottom = l.tank_top + l.tank_height - 1;
    assert_true(find_text(&img, "0.5", false, 0, img.width, bottom + 3, img.height, &x, &y));
    assert_false(find_text(&img, "0.2", false, 0, img.width, bottom + 3, img.height, &x, &y));
    png_rgb_free(&img);
    for (int wide = 1; wide <= 40; wide += 13) {
        img = write_and_read(fx, "tiny.png", &f, wide);
        png_rgb_free(&img);
    }
    f.width = 3.0; /* a flat tank: 400 x 67 px */
    img = write_and_read(fx, "flat.png", &f, WIDE);
    png_rgb_free(&img);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_outline_and_empty_frame, setup, teardown),
        cmocka_unit_test_setup_teardown(test_colour_bar_and_text, setup, teardown),
        cmocka_unit_test(test_nice_step),
        cmocka_unit_test_setup_teardown(test_axes_and_percent_bar, setup, teardown),
        cmocka_unit_test_setup_teardown(test_ticks_fit, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
