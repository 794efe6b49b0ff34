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

#include "io/font5x7.h"
#include "io/image.h"

#include "check.h"
#include "png_read.h"
#include "temp_dir.h"

/* ---------------------------------------------------------------------------------------- */
/* Fixture: a fresh directory under $TMPDIR (else /tmp) per test, removed afterwards          */

typedef temp_fixture fixture;

static int setup(void **state) { return temp_fixture_setup(state, "vcsph-image"); }

static int teardown(void **state) { return temp_fixture_teardown(state); }

static const char *path_in(fixture *fx, const char *name) { return temp_fixture_path(fx, name); }

static bool exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* ---------------------------------------------------------------------------------------- */
/* Frames and pixels                                                                         */

enum { WIDE = 400 }; /* a 1 m wide tank at 400 px/m */

/* A 1 m x 0.5 m tank, colours over [-1, 1], no particles */
static image_frame tank_frame(void)
{
    return (image_frame){.radius = 0.01,
                         .width = 1.0,
                         .height = 0.5,
                         .vmin = -1.0,
                         .vmax = 1.0,
                         .label = "eps_Vi",
                         .title = "inm1",
                         .time = 12.345};
}

/* The pixel holding the tank point (x, y), by the mapping of io/image.h */
static void pixel_of(const image_layout *l, const image_frame *f, double x, double y, uint32_t *i,
                     uint32_t *j)
{
    double u = l->tank_left + x * l->scale, v = l->tank_top + (f->height - y) * l->scale;
    assert_true(u >= 0 && v >= 0);
    *i = (uint32_t)floor(u);
    *j = (uint32_t)floor(v);
}

/* The tank point at the centre of the tank's pixel (i, j) counted from its top-left corner */
static void centre_of(const image_layout *l, const image_frame *f, int i, int j, double *x,
                      double *y)
{
    *x = (i + 0.5) / l->scale;
    *y = f->height - (j + 0.5) / l->scale;
}

static image_layout layout_of(const image_frame *f, int wide)
{
    image_layout l;
    char err[256] = "";
    if (image_layout_of(f, wide, &l, err, sizeof err) != 0) fail_msg("layout: %s", err);
    return l;
}

/* Writes f, reads it back and checks its size against the layout. */
static png_rgb write_and_read(fixture *fx, const char *name, const image_frame *f, int wide)
{
    char err[256] = "";
    const char *path = path_in(fx, name);
    if (image_write_particles(path, f, wide, err, sizeof err) != 0) fail_msg("write: %s", err);
    png_rgb img;
    assert_int_equal(png_read_rgb(path, &img), 0);
    image_layout l = layout_of(f, wide);
    assert_int_equal(img.width, l.width);
    assert_int_equal(img.height, l.height);
    return img;
}

static bool is_red(const uint8_t *p) { return p[0] > 150 && p[1] < 80 && p[2] < 80; }
static bool is_blue(const uint8_t *p) { return p[2] > 150 && p[0] < 100 && p[1] < 120; }
static bool is_white(const uint8_t *p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; }
static bool is_dark(const uint8_t *p) { return p[0] < 80 && p[1] < 80 && p[2] < 80; }

static bool is_whiteish(const uint8_t *p)
{
    int lo = p[0] < p[1] ? p[0] : p[1], hi = p[0] > p[1] ? p[0] : p[1];
    lo = p[2] < lo ? p[2] : lo;
    hi = p[2] > hi ? p[2] : hi;
    return lo >= 220 && hi - lo <= 20;
}

static bool same_colour(const uint8_t *p, const unsigned char c[3])
{
    return p[0] == c[0] && p[1] == c[1] && p[2] == c[2];
}

static void print_pixel(const char *what, const uint8_t *p)
{
    print_message("%s: (%d, %d, %d)\n", what, p[0], p[1], p[2]);
}

/* ---------------------------------------------------------------------------------------- */
/* Text in the image                                                                         */

enum { DOT = 2, CELL = (FONT5X7_WIDTH + 1) * DOT }; /* the font scaled 2x (io/image.h) */

/* The image pixel of dot (k, r) (column, row of the glyph) of character i of a text at (x, y):
 * upright, (x, y) is the first character's top-left pixel; written upwards, its bottom-left
 * pixel (the glyph's top on the left). */
static void dot_pixel(uint32_t x, uint32_t y, bool up, int i, int k, int r, long *u, long *v)
{
    if (up) {
        *u = (long)x + r * DOT;
        *v = (long)y - (long)i * CELL - (k + 1) * DOT + 1;
    } else {
        *u = (long)x + (long)i * CELL + k * DOT;
        *v = (long)y + r * DOT;
    }
}

/* Whether s is drawn at (x, y) exactly: every dot of its glyphs dark, every other pixel of the
 * glyphs' cells white. */
static bool text_at(const png_rgb *img, uint32_t x, uint32_t y, const char *s, bool up)
{
    for (int i = 0; s[i]; i++) {
        const uint8_t *rows = font5x7[(unsigned char)s[i] - FONT5X7_FIRST];
        for (int r = 0; r < FONT5X7_HEIGHT; r++)
            for (int k = 0; k < FONT5X7_WIDTH; k++) {
                long u, v;
                dot_pixel(x, y, up, i, k, r, &u, &v);
                if (u < 0 || v < 0 || u + DOT > (long)img->width || v + DOT > (long)img->height)
                    return false;
                bool on = rows[r] & (1u << (FONT5X7_WIDTH - 1 - k));
                for (int d = 0; d < DOT * DOT; d++) {
                    const uint8_t *p =
                        png_pixel(img, (uint32_t)(u + d % DOT), (uint32_t)(v + d / DOT));
                    if (on ? !is_dark(p) : !is_white(p)) return false;
                }
            }
    }
    return true;
}

/* Looks for s with its anchor (text_at's (x, y)) in columns x0 .. x1 - 1 and rows y0 .. y1 - 1;
 * true with the first place found in (*x, *y). */
static bool find_text(const png_rgb *img, const char *s, bool up, uint32_t x0, uint32_t x1,
                      uint32_t y0, uint32_t y1, uint32_t *x, uint32_t *y)
{
    for (uint32_t j = y0; j < y1 && j < img->height; j++)
        for (uint32_t i = x0; i < x1 && i < img->width; i++)
            if (text_at(img, i, j, s, up)) {
                *x = i;
                *y = j;
                return true;
            }
    return false;
}

/* The column of the middle of s's ink when its first character starts at column x */
static double text_centre(uint32_t x, const char *s) { return x + (strlen(s) * CELL - DOT) / 2.0; }

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
    uint32_t x, y, right = l.tank_left + l.tank_width - 1, bottom = l.tank_top + l.tank_height - 1;

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
    uint32_t x, y, bottom = l.tank_top + l.tank_height - 1;
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
        cmocka_unit_test_setup_teardown(test_outline_and_empty_frame, setup, teardown),
        cmocka_unit_test_setup_teardown(test_colour_bar_and_text, setup, teardown),
        cmocka_unit_test(test_nice_step),
        cmocka_unit_test_setup_teardown(test_axes_and_percent_bar, setup, teardown),
        cmocka_unit_test_setup_teardown(test_ticks_fit, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bad_range_refused, setup, teardown),
        cmocka_unit_test_setup_teardown(test_other_bad_input_refused, setup, teardown),
        cmocka_unit_test_setup_teardown(test_files, setup, teardown),
        cmocka_unit_test(test_colour_map_monotone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
