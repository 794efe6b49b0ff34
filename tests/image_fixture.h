/* image_fixture: the folder, the frame and the pixel and text readers of io/image's tests
 * (test_image.c, test_image_text.c). Include after <cmocka.h>. */
#ifndef VCSPH_TEST_IMAGE_FIXTURE_H
#define VCSPH_TEST_IMAGE_FIXTURE_H

#include "io/font5x7.h"
#include "io/image.h"

#include "png_read.h"
#include "temp_dir.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* ---------------------------------------------------------------------------------------- */
/* Fixture: a fresh directory under $TMPDIR (else /tmp) per test, removed afterwards          */

typedef temp_fixture fixture;

static inline int setup(void **state) { return temp_fixture_setup(state, "vcsph-image"); }

static inline int teardown(void **state) { return temp_fixture_teardown(state); }

static inline const char *path_in(fixture *fx, const char *name)
{
    return temp_fixture_path(fx, name);
}

static inline bool exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* ---------------------------------------------------------------------------------------- */
/* Frames and pixels                                                                         */

enum { WIDE = 400 }; /* a 1 m wide tank at 400 px/m */

/* A 1 m x 0.5 m tank, colours over [-1, 1], no particles */
static inline image_frame tank_frame(void)
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
static inline void pixel_of(const image_layout *l, const image_frame *f, double x, double y,
                            uint32_t *i, uint32_t *j)
{
    double u = l->tank_left + x * l->scale, v = l->tank_top + (f->height - y) * l->scale;
    assert_true(u >= 0 && v >= 0);
    *i = (uint32_t)floor(u);
    *j = (uint32_t)floor(v);
}

/* The tank point at the centre of the tank's pixel (i, j) counted from its top-left corner */
static inline void centre_of(const image_layout *l, const image_frame *f, int i, int j, double *x,
                             double *y)
{
    *x = (i + 0.5) / l->scale;
    *y = f->height - (j + 0.5) / l->scale;
}

static inline image_layout layout_of(const image_frame *f, int wide)
{
    image_layout l;
    char err[256] = "";
    if (image_layout_of(f, wide, &l, err, sizeof err) != 0) fail_msg("layout: %s", err);
    return l;
}

/* Writes f, reads it back and checks its size against the layout. */
static inline png_rgb write_and_read(fixture *fx, const char *name, const image_frame *f, int wide)
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

static inline bool is_red(const uint8_t *p) { return p[0] > 150 && p[1] < 80 && p[2] < 80; }
static inline bool is_blue(const uint8_t *p) { return p[2] > 150 && p[0] < 100 && p[1] < 120; }
static inline bool is_white(const uint8_t *p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; }
static inline bool is_dark(const uint8_t *p) { return p[0] < 80 && p[1] < 80 && p[2] < 80; }

static inline bool is_whiteish(const uint8_t *p)
{
    int lo = p[0] < p[1] ? p[0] : p[1], hi = p[0] > p[1] ? p[0] : p[1];
    lo = p[2] < lo ? p[2] : lo;
    hi = p[2] > hi ? p[2] : hi;
    return lo >= 220 && hi - lo <= 20;
}

static inline bool same_colour(const uint8_t *p, const unsigned char c[3])
{
    return p[0] == c[0] && p[1] == c[1] && p[2] == c[2];
}

static inline void print_pixel(const char *what, const uint8_t *p)
{
    print_message("%s: (%d, %d, %d)\n", what, p[0], p[1], p[2]);
}

/* ---------------------------------------------------------------------------------------- */
/* Text in the image                                                                         */

enum { DOT = 2, CELL = (FONT5X7_WIDTH + 1) * DOT }; /* the font scaled 2x (io/image.h) */

/* The image pixel of dot (k, r) (column, row of the glyph) of character i of a text at (x, y):
 * upright, (x, y) is the first character's top-left pixel; written upwards, its bottom-left
 * pixel (the glyph's top on the left). */
static inline void dot_pixel(uint32_t x, uint32_t y, bool up, int i, int k, int r, long *u, long *v)
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
static inline bool text_at(const png_rgb *img, uint32_t x, uint32_t y, const char *s, bool up)
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
static inline bool find_text(const png_rgb *img, const char *s, bool up, uint32_t x0, uint32_t x1,
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
static inline double text_centre(uint32_t x, const char *s)
{
    return x + (strlen(s) * CELL - DOT) / 2.0;
}

#endif
