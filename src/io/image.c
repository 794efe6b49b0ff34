/* image: particle images rasterised here and encoded as PNG by libpng. */
#include "io/image.h"

#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/atomic_file.h"
#include "io/font5x7.h"
#include "io/io_error.h"

/* ---------------------------------------------------------------------------------------- */
/* Layout constants (pixels)                                                                 */

enum {
    TEXT_SCALE = 2, /* the 5x7 font is unreadably small at 1x on a screen-sized image */
    GLYPH_H = FONT5X7_HEIGHT * TEXT_SCALE,
    ADVANCE = (FONT5X7_WIDTH + 1) * TEXT_SCALE, /* one blank column between characters */
    LINE = (FONT5X7_HEIGHT + 2) * TEXT_SCALE,
    MARGIN = 16,     /* left, right and bottom; room for the outline and for discs overhanging */
    TEXT_TOP = 8,    /* the first text line's top row */
    TEXT_BELOW = 14, /* between the last text line and the outline (2 px) above the tank */
    OUTLINE = 2,
    BAR_GAP = 24, /* tank to bar: clear of the outline and of discs overhanging the wall */
    BAR_WIDTH = 20,
    TICK_LEN = 5,
    TICK_GAP = 4,
    /* three tick labels must fit along the bar without touching */
    BAR_MIN_HEIGHT = 3 * LINE + 10,
    TIME_GAP = 2 * ADVANCE, /* between the title and the time */
};

/* ---------------------------------------------------------------------------------------- */
/* Colours                                                                                   */

typedef struct {
    uint8_t r, g, b;
} rgb8;

static const rgb8 black = {0, 0, 0};
static const rgb8 outline_colour = {32, 32, 32};
static const rgb8 grey = {128, 128, 128}; /* non-finite values */

/* Moreland's "cool to warm" map sampled at t = 0, 1/4, 1/2, 3/4, 1, with the middle lifted to
 * a near-white. Linear interpolation between so few anchors keeps red minus blue increasing
 * (the full table's ends bend back slightly) while staying close to the original. */
enum { N_ANCHORS = 5 };
static const rgb8 anchors[N_ANCHORS] = {
    {59, 76, 192}, {141, 176, 254}, {236, 236, 236}, {244, 154, 123}, {180, 4, 38},
};

static inline uint8_t mix(uint8_t a, uint8_t b, double f)
{
    return (uint8_t)lround(a + (b - a) * f);
}

static rgb8 colour_at(double t)
{
    if (!isfinite(t)) return grey;
    if (t <= 0) return anchors[0];
    if (t >= 1) return anchors[N_ANCHORS - 1];
    double s = t * (N_ANCHORS - 1);
    int k = (int)s;
    if (k > N_ANCHORS - 2) k = N_ANCHORS - 2;
    double f = s - k;
    const rgb8 *a = &anchors[k], *b = &anchors[k + 1];
    /* Red is blue plus the rounded red-minus-blue difference: rounding red and blue each on
     * its own would let their difference step back by one level here and there. */
    uint8_t blue = mix(a->b, b->b, f);
    double diff = (a->r - a->b) + ((b->r - b->b) - (a->r - a->b)) * f;
    long red = blue + lround(diff);
    red = red < 0 ? 0 : red > 255 ? 255 : red;
    return (rgb8){(uint8_t)red, mix(a->g, b->g, f), blue};
}

void image_colour(double t, unsigned char rgb[3])
{
    rgb8 c = colour_at(t);
    rgb[0] = c.r;
    rgb[1] = c.g;
    rgb[2] = c.b;
}

/* Halves first: vmax - vmin itself may overflow for a range like [-1e308, 1e308]. The layout
 * checks that the half range is positive. */
static inline double normalise(double v, double vmin, double vmax)
{
    return (0.5 * v - 0.5 * vmin) / (0.5 * vmax - 0.5 * vmin);
}

/* ---------------------------------------------------------------------------------------- */
/* Canvas                                                                                    */

typedef struct {
    uint8_t *rgb; /* w x h x 3, rows from the top */
    int w, h;
} canvas;

static inline void put_pixel(canvas *c, int x, int y, rgb8 col)
{
    if (x < 0 || y < 0 || x >= c->w || y >= c->h) return;
    uint8_t *p = c->rgb + 3 * ((size_t)y * (size_t)c->w + (size_t)x);
    p[0] = col.r;
    p[1] = col.g;
    p[2] = col.b;
}

static inline void fill_rect(canvas *c, int x, int y, int w, int h, rgb8 col)
{
    for (int j = y; j < y + h; j++)
        for (int i = x; i < x + w; i++) put_pixel(c, i, j, col);
}

/* A frame `thickness` pixels wide just outside the rectangle (x, y, w, h), so that it never
 * hides what is inside. */
static void frame_rect(canvas *c, int x, int y, int w, int h, int thickness, rgb8 col)
{
    int t = thickness;
    fill_rect(c, x - t, y - t, w + 2 * t, t, col); /* top */
    fill_rect(c, x - t, y + h, w + 2 * t, t, col); /* bottom */
    fill_rect(c, x - t, y, t, h, col);             /* left */
    fill_rect(c, x + w, y, t, h, col);             /* right */
}

/* ---------------------------------------------------------------------------------------- */
/* Text                                                                                      */

static inline long text_width(const char *s)
{
    /* strnlen: a runaway string must not overflow the arithmetic; it fails the size check. */
    return s ? (long)strnlen(s, IMAGE_MAX_SIDE + 1) * ADVANCE : 0;
}

static void draw_char(canvas *c, int x, int y, char ch, rgb8 col)
{
    unsigned u = (unsigned char)ch;
    if (u < FONT5X7_FIRST || u > FONT5X7_LAST) u = '?';
    const uint8_t *rows = font5x7[u - FONT5X7_FIRST];
    for (int r = 0; r < FONT5X7_HEIGHT; r++)
        for (int k = 0; k < FONT5X7_WIDTH; k++)
            if (rows[r] & (1u << (FONT5X7_WIDTH - 1 - k)))
                fill_rect(c, x + k * TEXT_SCALE, y + r * TEXT_SCALE, TEXT_SCALE, TEXT_SCALE, col);
}

/* (x, y): the top-left pixel of the first character */
static void draw_text(canvas *c, int x, int y, const char *s, rgb8 col)
{
    if (!s) return;
    for (; *s && x < c->w; s++, x += ADVANCE) draw_char(c, x, y, *s, col);
}

static void format_time(char *buf, size_t len, double time)
{
    snprintf(buf, len, "t = %.3f s", time);
}

static void format_tick(char *buf, size_t len, double v) { snprintf(buf, len, "%.3g", v); }

enum { TEXT_BUF = 64 }; /* "t = %.3f s" of a huge time is cut here, harmlessly */

/* ---------------------------------------------------------------------------------------- */
/* Layout                                                                                    */

static int check_frame(const image_frame *f, int pixels_wide, char *err, size_t err_len)
{
    if (pixels_wide < 1 || pixels_wide > IMAGE_MAX_SIDE) {
        io_error(err, err_len, "image: pixels_wide = %d is not in 1..%d", pixels_wide,
                 IMAGE_MAX_SIDE);
        return -1;
    }
    if (!(isfinite(f->width) && isfinite(f->height) && f->width > 0 && f->height > 0)) {
        io_error(err, err_len, "image: bad tank size %g x %g m", f->width, f->height);
        return -1;
    }
    if (!(isfinite(f->vmin) && isfinite(f->vmax) && f->vmin < f->vmax)) {
        io_error(err, err_len, "image: bad colour range [%g, %g] (needs vmin < vmax)", f->vmin,
                 f->vmax);
        return -1;
    }
    if (!(0.5 * f->vmax - 0.5 * f->vmin > 0)) {
        io_error(err, err_len, "image: colour range [%g, %g] too narrow", f->vmin, f->vmax);
        return -1;
    }
    return 0;
}

/* The widest of the three tick labels */
static long tick_width(const image_frame *f)
{
    double ticks[3] = {f->vmin, 0.5 * f->vmin + 0.5 * f->vmax, f->vmax};
    long w = 0;
    for (int k = 0; k < 3; k++) {
        char buf[TEXT_BUF];
        format_tick(buf, sizeof buf, ticks[k]);
        if (text_width(buf) > w) w = text_width(buf);
    }
    return w;
}

/* The title line: "title  t = ... s" */
static long title_line_width(const image_frame *f)
{
    char time[TEXT_BUF];
    format_time(time, sizeof time, f->time);
    long w = text_width(time);
    if (f->title && *f->title) w += text_width(f->title) + TIME_GAP;
    return w;
}

int image_layout_of(const image_frame *f, int pixels_wide, image_layout *l, char *err,
                    size_t err_len)
{
    if (!f || !l) {
        io_error(err, err_len, "image: no frame");
        return -1;
    }
    if (check_frame(f, pixels_wide, err, err_len) != 0) return -1;
    double tank_h = pixels_wide * (f->height / f->width);
    if (!(tank_h <= IMAGE_MAX_SIDE)) {
        io_error(err, err_len, "image: a tank %g x %g m drawn %d px wide is too tall", f->width,
                 f->height, pixels_wide);
        return -1;
    }
    l->tank_width = pixels_wide;
    l->tank_height = tank_h < 1 ? 1 : (int)lround(tank_h);
    l->scale = pixels_wide / f->width;
    l->tank_left = MARGIN;
    l->bar_left = l->tank_left + l->tank_width + BAR_GAP;
    /* The bar label sits above the bar, on the title's line unless the two would meet; then
     * it gets a line of its own below. */
    long label_w = text_width(f->label);
    int lines = label_w > 0 && l->tank_left + title_line_width(f) + ADVANCE > l->bar_left ? 2 : 1;
    l->tank_top = TEXT_TOP + (lines - 1) * LINE + GLYPH_H + TEXT_BELOW;
    l->bar_top = l->tank_top;
    l->bar_width = BAR_WIDTH;
    l->bar_height = l->tank_height > BAR_MIN_HEIGHT ? l->tank_height : BAR_MIN_HEIGHT;
    long ticks_right = l->bar_left + BAR_WIDTH + TICK_LEN + TICK_GAP + tick_width(f);
    long label_right = l->bar_left + label_w;
    long right = (ticks_right > label_right ? ticks_right : label_right) + MARGIN;
    long title_right = l->tank_left + title_line_width(f) + MARGIN;
    long width = right > title_right ? right : title_right;
    /* the lowest tick label hangs half a glyph below the bar */
    long height = (long)l->bar_top + l->bar_height + GLYPH_H / 2 + MARGIN;
    if (width > IMAGE_MAX_SIDE || height > IMAGE_MAX_SIDE) {
        io_error(err, err_len, "image: %ld x %ld px is over the limit of %d", width, height,
                 IMAGE_MAX_SIDE);
        return -1;
    }
    l->width = (int)width;
    l->height = (int)height;
    return 0;
}

/* ---------------------------------------------------------------------------------------- */
/* Drawing                                                                                   */

/* The pixels whose centre is within r of (u, v); all in doubles until clipped, since a stray
 * particle may sit far beyond the range of int. */
static void draw_disc(canvas *c, double u, double v, double r, rgb8 col)
{
    double i0 = fmax(ceil(u - r - 0.5), 0), i1 = fmin(floor(u + r - 0.5), c->w - 1);
    double j0 = fmax(ceil(v - r - 0.5), 0), j1 = fmin(floor(v + r - 0.5), c->h - 1);
    if (!(i0 <= i1 && j0 <= j1)) return; /* off the image (or NaN) */
    double r2 = r * r;
    for (int j = (int)j0; j <= (int)j1; j++) {
        double dy = j + 0.5 - v;
        for (int i = (int)i0; i <= (int)i1; i++) {
            double dx = i + 0.5 - u;
            if (dx * dx + dy * dy <= r2) put_pixel(c, i, j, col);
        }
    }
}

static void draw_particles(canvas *c, const image_frame *f, const image_layout *l)
{
    double r = f->radius * l->scale;
    if (r < 1) r = 1;
    for (size_t k = 0; k < f->n; k++) {
        double u = l->tank_left + f->x[k] * l->scale;
        double v = l->tank_top + (f->height - f->y[k]) * l->scale;
        if (!isfinite(u) || !isfinite(v)) continue;
        draw_disc(c, u, v, r, colour_at(normalise(f->value[k], f->vmin, f->vmax)));
    }
}

/* A tick mark right of the bar at `row`, with its value centred on it */
static void draw_tick(canvas *c, const image_layout *l, int row, double value)
{
    int x = l->bar_left + l->bar_width;
    fill_rect(c, x, row, TICK_LEN, 1, black);
    char buf[TEXT_BUF];
    format_tick(buf, sizeof buf, value);
    draw_text(c, x + TICK_LEN + TICK_GAP, row - GLYPH_H / 2, buf, black);
}

/* Row k of the bar shows the value at its centre, vmax at the top and vmin at the bottom. */
static void draw_bar(canvas *c, const image_frame *f, const image_layout *l)
{
    int h = l->bar_height;
    for (int k = 0; k < h; k++) {
        rgb8 col = colour_at(1 - (k + 0.5) / h);
        fill_rect(c, l->bar_left, l->bar_top + k, l->bar_width, 1, col);
    }
    frame_rect(c, l->bar_left, l->bar_top, l->bar_width, h, 1, outline_colour);
    draw_tick(c, l, l->bar_top, f->vmax);
    draw_tick(c, l, l->bar_top + h / 2, 0.5 * f->vmin + 0.5 * f->vmax);
    draw_tick(c, l, l->bar_top + h - 1, f->vmin);
    if (f->label) draw_text(c, l->bar_left, l->tank_top - TEXT_BELOW - GLYPH_H, f->label, black);
}

static void draw_title(canvas *c, const image_frame *f, const image_layout *l)
{
    int x = l->tank_left;
    if (f->title && *f->title) {
        draw_text(c, x, TEXT_TOP, f->title, black);
        x += (int)text_width(f->title) + TIME_GAP;
    }
    char time[TEXT_BUF];
    format_time(time, sizeof time, f->time);
    draw_text(c, x, TEXT_TOP, time, black);
}

/* The outline goes on last, over any disc that overhangs a wall, so the walls stay crisp. */
static void draw_frame(canvas *c, const image_frame *f, const image_layout *l)
{
    draw_particles(c, f, l);
    draw_bar(c, f, l);
    draw_title(c, f, l);
    frame_rect(c, l->tank_left, l->tank_top, l->tank_width, l->tank_height, OUTLINE,
               outline_colour);
}

/* ---------------------------------------------------------------------------------------- */
/* PNG file                                                                                  */

static int check_particles(const image_frame *f, char *err, size_t err_len)
{
    if (f->n > 0 && (!f->x || !f->y || !f->value)) {
        io_error(err, err_len, "image: %zu particles without positions or values", f->n);
        return -1;
    }
    if (!(isfinite(f->radius) && f->radius >= 0)) {
        io_error(err, err_len, "image: bad disc radius %g m", f->radius);
        return -1;
    }
    return 0;
}

static int encode_png(const char *file, const canvas *c, char *err, size_t err_len)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)c->w;
    img.height = (png_uint_32)c->h;
    img.format = PNG_FORMAT_RGB;
    /* libpng closes the file and checks that close; on failure it removes the file */
    if (!png_image_write_to_file(&img, file, 0, c->rgb, 0, NULL)) {
        io_error(err, err_len, "image: cannot write '%s': %s", file, img.message);
        png_image_free(&img);
        return -1;
    }
    png_image_free(&img);
    return 0;
}

/* Encodes to path.tmp and renames it over path (atomic_file.h). */
static int write_atomically(const char *path, const canvas *c, char *err, size_t err_len)
{
    char *tmp = atomic_temp_path(path);
    if (!tmp) {
        io_error(err, err_len, "image: out of memory");
        return -1;
    }
    int rc = encode_png(tmp, c, err, err_len);
    if (rc == 0)
        rc = atomic_commit("image", tmp, path, err, err_len);
    else
        remove(tmp);
    free(tmp);
    return rc;
}

int image_write_particles(const char *path, const image_frame *f, int pixels_wide, char *err,
                          size_t err_len)
{
    if (!path || !f) {
        io_error(err, err_len, "image: no path or frame");
        return -1;
    }
    image_layout l;
    if (image_layout_of(f, pixels_wide, &l, err, err_len) != 0) return -1;
    if (check_particles(f, err, err_len) != 0) return -1;
    canvas c = {malloc((size_t)l.width * (size_t)l.height * 3), l.width, l.height};
    if (!c.rgb) {
        io_error(err, err_len, "image: out of memory for %d x %d px", l.width, l.height);
        return -1;
    }
    memset(c.rgb, 0xff, (size_t)l.width * (size_t)l.height * 3); /* a white background */
    draw_frame(&c, f, &l);
    int rc = write_atomically(path, &c, err, err_len);
    free(c.rgb);
    return rc;
}
