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
    AXIS_GAP = 8,           /* between an axis' numbers and its label */
    MAX_TICKS = 8,          /* per axis */
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

/* The width of the dots of s: text_width less the blank column after the last character */
static inline long ink_width(const char *s)
{
    long w = text_width(s);
    return w > 0 ? w - TEXT_SCALE : 0;
}

/* s written upwards (turned a quarter left, as a y axis' label): (x, y) is the bottom-left
 * pixel of the first character, whose top is then on the left. */
static void draw_text_up(canvas *c, int x, int y, const char *s, rgb8 col)
{
    for (; *s && y >= 0; s++, y -= ADVANCE) {
        unsigned u = (unsigned char)*s;
        if (u < FONT5X7_FIRST || u > FONT5X7_LAST) u = '?';
        const uint8_t *rows = font5x7[u - FONT5X7_FIRST];
        for (int r = 0; r < FONT5X7_HEIGHT; r++)
            for (int k = 0; k < FONT5X7_WIDTH; k++)
                if (rows[r] & (1u << (FONT5X7_WIDTH - 1 - k)))
                    fill_rect(c, x + r * TEXT_SCALE, y - (k + 1) * TEXT_SCALE + 1, TEXT_SCALE,
                              TEXT_SCALE, col);
    }
}

static void format_time(char *buf, size_t len, double time)
{
    snprintf(buf, len, "t = %.3f s", time);
}

enum { TEXT_BUF = 64 }; /* "t = %.3f s" of a huge time is cut here, harmlessly */

static const char x_label[] = "x (m)", y_label[] = "y (m)";

/* ---------------------------------------------------------------------------------------- */
/* Ticks                                                                                     */

/* The multiples of step in [lo, hi], the ends to within 1e-9 of a step: k0 .. k1 */
static inline double first_multiple(double lo, double step) { return ceil(lo / step - 1e-9); }
static inline double last_multiple(double hi, double step) { return floor(hi / step + 1e-9); }

double image_nice_step(double lo, double hi, int max_ticks)
{
    if (!(isfinite(lo) && isfinite(hi) && lo < hi && isfinite(hi - lo)) || max_ticks < 2) return 0;
    static const double mantissa[3] = {1, 2, 5};
    /* a decade below the step of max_ticks - 1 intervals: the first candidates give too many */
    int e = (int)floor(log10((hi - lo) / max_ticks)) - 1;
    for (; e < 400; e++)
        for (int m = 0; m < 3; m++) {
            /* m / 10^-e rather than m * 10^e: 0.02 and not 0.020000000000000004 */
            double step = e < 0 ? mantissa[m] / pow(10, -e) : mantissa[m] * pow(10, e);
            if (!(step > 0)) continue; /* 10^-e overflowed: a range near the smallest double */
            if (!isfinite(step)) return 0;
            if (last_multiple(hi, step) - first_multiple(lo, step) + 1 <= max_ticks) return step;
        }
    return 0;
}

/* The ticks of one axis: where they are (in the axis' values) and what they say */
typedef struct {
    int n;
    double at[MAX_TICKS];
    char text[MAX_TICKS][TEXT_BUF];
    long widest; /* the widest text's ink_width (px) */
} tick_set;

/* Digits after the point that the multiples of a nice step need */
static int step_decimals(double step)
{
    int e = (int)floor(log10(step) + 1e-9);
    return e < 0 ? -e : 0;
}

static void tick_text(char *buf, size_t len, double shown, int decimals, const char *suffix)
{
    /* a plain number as long as it is short; else three digits and an exponent */
    int n = snprintf(buf, len, "%.*f%s", decimals, shown, suffix);
    if (n < 0 || n > 12) snprintf(buf, len, "%.3g%s", shown, suffix);
}

static void add_tick(tick_set *t, double at, const char *text)
{
    snprintf(t->text[t->n], sizeof t->text[0], "%s", text);
    t->at[t->n++] = at;
    if (ink_width(text) > t->widest) t->widest = ink_width(text);
}

/* The ticks over [lo, hi] drawn `length` pixels long, their numbers `mult` times the values
 * followed by `suffix`: the most (up to MAX_TICKS) that keep the numbers apart, which is their
 * width plus two characters' advance when they lie along the axis (`along`) and a text line
 * when they are stacked across it. A range with no nice step (see image_nice_step) gets its
 * ends and middle, as printed by "%.3g". */
static void make_ticks(double lo, double hi, double mult, const char *suffix, double length,
                       bool along, tick_set *t)
{
    double shown_lo = mult * lo, shown_hi = mult * hi;
    for (int max = MAX_TICKS; max >= 2; max--) {
        double step = image_nice_step(shown_lo, shown_hi, max);
        if (step == 0) break;
        *t = (tick_set){0};
        int decimals = step_decimals(step);
        double k0 = first_multiple(shown_lo, step), k1 = last_multiple(shown_hi, step);
        for (double k = k0; k <= k1 && t->n < MAX_TICKS; k++) {
            char buf[TEXT_BUF];
            double shown = k * step + 0.0; /* + 0.0: no "-0.0" from k = -0 */
            tick_text(buf, sizeof buf, shown, decimals, suffix);
            double at = shown / mult;
            add_tick(t, at < lo ? lo : at > hi ? hi : at, buf);
        }
        double spacing = step / (shown_hi - shown_lo) * length;
        double needed = along ? (double)(t->widest + 2 * ADVANCE) : LINE;
        if (spacing >= needed || max == 2) return;
    }
    *t = (tick_set){0};
    const double at[3] = {lo, 0.5 * lo + 0.5 * hi, hi};
    for (int k = 0; k < 3; k++) {
        char buf[TEXT_BUF];
        snprintf(buf, sizeof buf, "%.3g%s", mult * at[k], suffix);
        add_tick(t, at[k], buf);
    }
}

/* The ticks of the three axes of frame f drawn with the tank `tank_width` x `tank_height` px
 * and the bar `bar_height` px tall */
typedef struct {
    tick_set x, y, bar;
} frame_ticks;

static void ticks_of(const image_frame *f, int tank_width, int tank_height, int bar_height,
                     frame_ticks *t)
{
    make_ticks(0, f->width, 1, "", tank_width, true, &t->x);
    make_ticks(0, f->height, 1, "", tank_height, false, &t->y);
    make_ticks(f->vmin, f->vmax, f->percent ? 100 : 1, f->percent ? " %" : "", bar_height, false,
               &t->bar);
}

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
    l->bar_width = BAR_WIDTH;
    l->bar_height = l->tank_height > BAR_MIN_HEIGHT ? l->tank_height : BAR_MIN_HEIGHT;
    frame_ticks t;
    ticks_of(f, l->tank_width, l->tank_height, l->bar_height, &t);
    /* Left of the tank: the y label (written upwards, a glyph's height wide), the y numbers
     * flush right, the tick marks and the outline; and room for half the first x number,
     * which is centred on the tank's left edge. */
    long half_x0 = t.x.n ? ink_width(t.x.text[0]) / 2 : 0;
    long half_x1 = t.x.n ? ink_width(t.x.text[t.x.n - 1]) / 2 : 0;
    long left = MARGIN + GLYPH_H + AXIS_GAP + t.y.widest + TICK_GAP + TICK_LEN + OUTLINE;
    if (MARGIN + half_x0 > left) left = MARGIN + half_x0;
    if (left > IMAGE_MAX_SIDE) {
        io_error(err, err_len, "image: tick labels %ld px wide are over the limit", t.y.widest);
        return -1;
    }
    l->tank_left = (int)left;
    /* the last x number, centred on the tank's right edge, stays clear of the bar */
    long bar_gap = half_x1 + ADVANCE > BAR_GAP ? half_x1 + ADVANCE : BAR_GAP;
    l->bar_left = (int)(l->tank_left + l->tank_width + bar_gap);
    /* The bar label sits above the bar, on the title's line unless the two would meet; then
     * it gets a line of its own below. */
    long label_w = text_width(f->label);
    int lines = label_w > 0 && l->tank_left + title_line_width(f) + ADVANCE > l->bar_left ? 2 : 1;
    l->tank_top = TEXT_TOP + (lines - 1) * LINE + GLYPH_H + TEXT_BELOW;
    l->bar_top = l->tank_top;
    long ticks_right = l->bar_left + BAR_WIDTH + TICK_LEN + TICK_GAP + t.bar.widest;
    long label_right = l->bar_left + label_w;
    long right = (ticks_right > label_right ? ticks_right : label_right) + MARGIN;
    long title_right = l->tank_left + title_line_width(f) + MARGIN;
    long width = right > title_right ? right : title_right;
    /* Below: the bar's lowest number hangs half a glyph below the bar; under the tank, the
     * outline, the tick marks, the x numbers and the x label; the y label, centred on the
     * tank, may reach below a flat tank. */
    long bar_bottom = (long)l->bar_top + l->bar_height + GLYPH_H / 2;
    long axis_bottom = (long)l->tank_top + l->tank_height + OUTLINE + TICK_LEN + TICK_GAP +
                       GLYPH_H + AXIS_GAP + GLYPH_H;
    long label_bottom = (long)l->tank_top + l->tank_height / 2 + ink_width(y_label) / 2 + 1;
    long bottom = bar_bottom > axis_bottom ? bar_bottom : axis_bottom;
    if (label_bottom > bottom) bottom = label_bottom;
    long height = bottom + MARGIN;
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

/* The row of value v on the bar: vmax on its first row, vmin on its last */
static int bar_row(const image_frame *f, const image_layout *l, double v)
{
    double t = normalise(v, f->vmin, f->vmax);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return l->bar_top + (int)lround((1 - t) * (l->bar_height - 1));
}

/* Row k of the bar shows the value at its centre, vmax at the top and vmin at the bottom. Its
 * ticks are marks right of it with their numbers centred on them. */
static void draw_bar(canvas *c, const image_frame *f, const image_layout *l, const tick_set *t)
{
    int h = l->bar_height;
    for (int k = 0; k < h; k++) {
        rgb8 col = colour_at(1 - (k + 0.5) / h);
        fill_rect(c, l->bar_left, l->bar_top + k, l->bar_width, 1, col);
    }
    frame_rect(c, l->bar_left, l->bar_top, l->bar_width, h, 1, outline_colour);
    int x = l->bar_left + l->bar_width;
    for (int k = 0; k < t->n; k++) {
        int row = bar_row(f, l, t->at[k]);
        fill_rect(c, x, row, TICK_LEN, 1, black);
        draw_text(c, x + TICK_LEN + TICK_GAP, row - GLYPH_H / 2, t->text[k], black);
    }
    if (f->label) draw_text(c, l->bar_left, l->tank_top - TEXT_BELOW - GLYPH_H, f->label, black);
}

static int clamp_int(double v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : (int)v; }

/* The x axis under the tank and the y axis left of it: marks outside the outline, the numbers
 * beyond them, then the axis labels. */
static void draw_axes(canvas *c, const image_frame *f, const image_layout *l, const frame_ticks *t)
{
    int right = l->tank_left + l->tank_width - 1, bottom = l->tank_top + l->tank_height - 1;
    int below = bottom + 1 + OUTLINE; /* the first row under the outline */
    for (int k = 0; k < t->x.n; k++) {
        int col = clamp_int(floor(l->tank_left + t->x.at[k] * l->scale), l->tank_left, right);
        fill_rect(c, col, below, 1, TICK_LEN, black);
        draw_text(c, col - (int)ink_width(t->x.text[k]) / 2, below + TICK_LEN + TICK_GAP,
                  t->x.text[k], black);
    }
    draw_text(c, l->tank_left + (l->tank_width - (int)ink_width(x_label)) / 2,
              below + TICK_LEN + TICK_GAP + GLYPH_H + AXIS_GAP, x_label, black);

    int mark = l->tank_left - OUTLINE - TICK_LEN; /* the marks' first column */
    for (int k = 0; k < t->y.n; k++) {
        int row = clamp_int(floor(l->tank_top + (f->height - t->y.at[k]) * l->scale), l->tank_top,
                            bottom);
        fill_rect(c, mark, row, TICK_LEN, 1, black);
        draw_text(c, mark - TICK_GAP - (int)ink_width(t->y.text[k]), row - GLYPH_H / 2,
                  t->y.text[k], black);
    }
    int label_x = mark - TICK_GAP - (int)t->y.widest - AXIS_GAP - GLYPH_H;
    draw_text_up(c, label_x, l->tank_top + (l->tank_height + (int)ink_width(y_label)) / 2, y_label,
                 black);
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

/* The text and marks go over any disc outside the tank, and the outline on last, over any
 * disc that overhangs a wall, so the walls stay crisp. */
static void draw_frame(canvas *c, const image_frame *f, const image_layout *l)
{
    frame_ticks t;
    ticks_of(f, l->tank_width, l->tank_height, l->bar_height, &t);
    draw_particles(c, f, l);
    draw_bar(c, f, l, &t.bar);
    draw_axes(c, f, l, &t);
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
