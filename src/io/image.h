/* image: particle images as PNG files (README.md: the PNG files under images/): discs coloured by a
 * field with a colour bar, the tank outline with axes in metres, and the time.
 *
 * Our own rasteriser; libpng only encodes. Dimension-free: a 3D caller passes the projection it
 * wants drawn (e.g. x and z of a slice).
 *
 * Layout, from the top left: a text line (title and time, and the colour-bar label above the
 * bar), then the tank drawn `pixels_wide` pixels wide with a dark 2-px outline just outside it,
 * and right of it a vertical colour bar (vmax at the top, vmin at the bottom). The tank has
 * axes in metres of the tank frame: x from 0 to width along the bottom and y from 0 to height
 * up the left side, with tick marks outside the outline at "nice" values (image_nice_step),
 * their numbers beside them and the axis labels "x (m)" below and "y (m)" (written upwards)
 * left of them. The colour bar has tick marks and numbers at nice values of its range too, in
 * per cent when the frame says so. Text is black on white, in a 5x7 bitmap font scaled 2x.
 * Ticks are as many as fit (at most 8 per axis): their numbers never touch.
 *
 * Mapping: with the numbers of image_layout_of, a point (x, y) of the tank frame (m, y up) lies
 * at image coordinates
 *     u = tank_left + x * scale,   v = tank_top + (height - y) * scale
 * (pixels; pixel (i, j), column i and row j from the top left, covers [i, i+1) x [j, j+1)).
 * A particle's disc covers the pixels whose centre (i + 1/2, j + 1/2) is within
 * max(radius * scale, 1) of (u, v), so it always covers at least the pixel holding its centre.
 * A tick at x marks the column holding u, one at y the row holding v, kept inside the tank's
 * columns and rows (x = width marks the tank's last column, y = 0 its last row). */
#ifndef VCSPH_IMAGE_H
#define VCSPH_IMAGE_H

#include <stdbool.h>
#include <stddef.h>

typedef struct {
    const double *x, *y;  /* particle centres in the tank frame (m), n of them */
    const double *value;  /* the colour field, one per particle */
    size_t n;             /* 0 draws only the outline, bar and text (x, y, value may be NULL) */
    double radius;        /* disc radius (m), e.g. dr/2; 0 draws 1-px discs */
    double width, height; /* the tank: the drawn domain is [0,width] x [0,height] (m), outlined */
    double vmin, vmax;    /* colour range; values outside are clamped; vmin < vmax */
    const char *label;    /* colour-bar label, e.g. "eps_Vi" (ASCII; may be NULL) */
    const char *title;    /* text at the top left, e.g. "inm1" (may be NULL) */
    double time;          /* s, printed as "t = 12.345 s" */
    bool percent;         /* the colour bar's numbers are 100 v followed by " %" (e.g. "-2 %"
                             for v = -0.02); the values, vmin and vmax stay fractions */
} image_frame;

/* Where things are in the image of a frame (pixels). */
typedef struct {
    int width, height;           /* the whole image */
    int tank_left, tank_top;     /* the pixel column and row where the tank's corner (0, height)
                                    lies: the tank occupies columns tank_left .. tank_left +
                                    tank_width - 1 and rows tank_top .. tank_top + tank_height - 1 */
    int tank_width, tank_height; /* pixels_wide, and round(pixels_wide * height / width) (>= 1) */
    double scale;                /* pixels per metre, pixels_wide / width */
    int bar_left, bar_top;       /* the colour bar's top-left pixel */
    int bar_width, bar_height;   /* its size; it is at least as tall as the tank */
} image_layout;

/* The sides of an image are at most this many pixels, and the tank at least 1 pixel wide. */
enum { IMAGE_MAX_SIDE = 16384 };

/* Computes the layout of the image of f drawn `pixels_wide` wide. Needs only f's tank size,
 * colour range and texts. Returns 0, or -1 with a message in err (bad tank size, range or
 * pixels_wide; an image over IMAGE_MAX_SIDE). */
int image_layout_of(const image_frame *f, int pixels_wide, image_layout *layout, char *err,
                    size_t err_len);

/* The step between the ticks of an axis over [lo, hi]: the smallest "nice" step, 1, 2 or 5
 * times a power of ten, that puts at most max_ticks of its multiples in [lo, hi] (the ends
 * count, to within 1e-9 of a step). With max_ticks = 8 that gives 4 to 8 ticks, now and then
 * 3: image_nice_step(0, 0.1172, 8) = 0.02 (0, 0.02, .., 0.1), image_nice_step(0, 1, 8) = 0.2,
 * image_nice_step(-2, 2, 8) = 1. Returns 0 when there is no such step: lo or hi not finite,
 * lo >= hi, hi - lo not finite, or max_ticks < 2. */
double image_nice_step(double lo, double hi, int max_ticks);

/* The colour map: a diverging blue-white-red map (after Moreland's "cool to warm") at
 * t in [0, 1]: blue at 0, near-white at 1/2, red at 1; t outside is clamped and a non-finite
 * t gives grey. The middle is a light grey (236, 236, 236) rather than pure white, so that
 * particles at the middle value still show against the white background. The red minus blue
 * difference increases with t, so the map reads in one direction on a grey-scale print too. */
void image_colour(double t, unsigned char rgb[3]);

/* Writes the frame as an 8-bit RGB PNG `pixels_wide` wide (the tank part; the height follows the
 * tank's aspect ratio, plus margins for text and a colour bar on the right). Written to a
 * temporary name ("path.tmp") and renamed, so that a reader never sees half a file. Particles
 * are drawn in the given order (later over earlier), also outside the tank as far as the image
 * reaches; a particle with a non-finite position is skipped and one with a non-finite value is
 * grey. Returns 0, or -1 with a message in err (also for vmin >= vmax). */
int image_write_particles(const char *path, const image_frame *f, int pixels_wide, char *err,
                          size_t err_len);

#endif
