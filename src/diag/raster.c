/* raster: the graphical method, Eq. (15), in 2D and 3D.
 *
 * A pixel (voxel) is liquid when its centre x has
 *   C(x) = sum_j W(|x - x_j|, h_c) V_p >= 1/2   or lies within r_d of a particle.
 * C is the SPH interpolation of the liquid's indicator function (1 inside, 0 outside); the
 * level 1/2 is where that indicator steps, the usual definition of an interface in SPH. It
 * closes the gaps between lattice neighbours and between disordered particles, and it smooths
 * the valleys between the particles of a free surface and the staircase of a lattice cut by a
 * curve, keeping their area on average. Its one bias is curvature: the 1/2 level of a smoothed
 * convex shape lies sigma^2 kappa / 2 inside it (sigma^2: the kernel's variance per axis,
 * 0.278 h_c^2 in 2D, 0.267 h_c^2 in 3D for Wendland C2), a loss of pi sigma^2 per closed curve
 * in 2D, 3 sigma^2 / R^2 of a ball of radius R. The discs of radius r_d = dr/2 (a lattice
 * cell's own extent) keep what C alone loses: a lone particle (C peaks at 0.42 in 3D) and the
 * outermost particles of a convex shape, whose discs reach past the shrunken level.
 * docs/graphical-method.md compares the rules and gives the figures.
 *
 * The walls are mirrors, as with the ghost particles (theory §5): the particles within 2 h_c
 * of a wall add their images beyond it, so that C reads 1 along a wall as in the interior; in
 * a tank narrower than 4 h_c, about both walls.
 *
 * Scatter parallel over layers of the outermost axis (rows in 2D, planes in 3D): every pixel
 * is written by one thread, summing its sources in one fixed order, and the count is an
 * integer, so the result does not depend on the number of threads.
 *
 * A part of the raster (raster_count_part) is a range of pixel columns along x: its grid holds
 * only those columns, and only the sources within reach of them are kept. The sources keep
 * their order (by bin, then by index), so each of its pixels sums what the whole raster's
 * pixel sums, in the same order, when the particles are given in their global order. */
#include "diag/raster.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

raster_params raster_params_default(int dim)
{
    raster_params rp = {.k = dim == 3 ? 4 : 8, .radius = 0.5, .smoothing = 1.0};
    return rp;
}

typedef struct {
    int dim;
    int nn[3];      /* pixels per axis (1 past dim); along x, those of the part drawn */
    int x_first;    /* the first pixel column of the part drawn ... */
    int nx_all;     /* ... of all the box's columns along x */
    double h[3];    /* pixel side per axis, m */
    double size[3]; /* the walls: at 0 and size (nn h, or less when the last layer is cut) */
    double last[3]; /* the part of the last layer inside the box, in (0, 1] */
    size_t stride[3];
    size_t total;
} grid;

/* What a particle adds to a pixel at squared distance r2: the Wendland C2 kernel of the solver
 * (theory §1) with smoothing length h_c, times the particle volume V_p (`norm` = a_n V_p),
 * and a mark of 1 when the pixel is within the disc (C >= 1 then, whatever the rest). */
typedef struct {
    double inv_hc2; /* 1 / h_c^2; 0 without the colour function */
    double norm;    /* a_n(h_c) V_p; with V_p = dr^n, 7/(4 pi) (dr/h_c)^2 in 2D, 21/(16 pi)
                       (dr/h_c)^3 in 3D */
    double disc2;   /* r_d^2 */
} source_weight;

static inline float pixel_weight(const source_weight *sw, double r2)
{
    double w = r2 <= sw->disc2 ? 1.0 : 0.0;
    double q2 = r2 * sw->inv_hc2;
    if (q2 < 4.0) {
        double q = sqrt(q2), s = 1.0 - 0.5 * q, s2 = s * s;
        w += sw->norm * s2 * s2 * (1.0 + 2.0 * q);
    }
    return (float)w;
}

/* Pixels i of an axis whose centres (i + 1/2) h lie in [lo, hi], clipped to [from, to). */
static inline void pixel_range(double lo, double hi, double h, int from, int to, int *first,
                               int *last)
{
    double a = ceil(lo / h - 0.5), b = floor(hi / h - 0.5);
    *first = a < from ? from : (a > to ? to : (int)a);
    *last = b >= to ? to - 1 : (b < from - 1.0 ? from - 1 : (int)b);
}

enum { MAX_IMAGES = 27 }; /* 3 per axis: the particle, its image about the low wall, the high */

/* Particle i and its mirror images about every wall within `reach` of it, and about every
 * pair and triple of such walls of different axes (an edge, a corner), into img[0..count);
 * returns count. In a tank narrower than 2 reach a particle is near both walls of an axis and
 * has an image about each, as the solver's ghosts do (tank_make_ghosts). */
static inline int particle_images(const grid *g, double *const x[3], size_t i, double reach,
                                  double img[MAX_IMAGES][3])
{
    double coord[3][3]; /* per axis: the coordinate itself, then its mirrors */
    int n_coord[3] = {1, 1, 1};
    for (int d = 0; d < 3; d++) {
        double c = d < g->dim ? x[d][i] : 0.0, size = g->size[d];
        coord[d][0] = c;
        if (d >= g->dim) continue;
        if (c < reach) coord[d][n_coord[d]++] = -c;
        if (c > size - reach) coord[d][n_coord[d]++] = 2.0 * size - c;
    }
    int count = 0;
    for (int a = 0; a < n_coord[0]; a++)
        for (int b = 0; b < n_coord[1]; b++)
            for (int c = 0; c < n_coord[2]; c++) {
                img[count][0] = coord[0][a];
                img[count][1] = coord[1][b];
                img[count][2] = coord[2][c];
                count++;
            }
    return count;
}

/* The sources of the colour function: every particle and its images, s[0..3)[0..count). */
typedef struct {
    double *x[3];
    size_t count;
} sources;

static void sources_free(sources *s)
{
    for (int d = 0; d < 3; d++) free(s->x[d]);
}

/* Whether a source at x along x reaches a pixel of the part [x_lo, x_hi) of the raster. */
static inline int reaches_part(double x, double x_lo, double x_hi, double reach)
{
    return x >= x_lo - reach && x <= x_hi + reach;
}

/* The particles' images within reach of the part [x_lo, x_hi), in the particles' order. */
static int sources_make(const grid *g, size_t n, double *const x[3], double reach, double x_lo,
                        double x_hi, sources *s)
{
    double img[MAX_IMAGES][3];
    s->count = 0;
    for (size_t i = 0; i < n; i++) {
        int k = particle_images(g, x, i, reach, img);
        for (int c = 0; c < k; c++) s->count += (size_t)reaches_part(img[c][0], x_lo, x_hi, reach);
    }
    for (int d = 0; d < 3; d++) s->x[d] = malloc((s->count ? s->count : 1) * sizeof(double));
    if (!s->x[0] || !s->x[1] || !s->x[2]) {
        sources_free(s);
        return -1;
    }
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        int k = particle_images(g, x, i, reach, img);
        for (int c = 0; c < k; c++) {
            if (!reaches_part(img[c][0], x_lo, x_hi, reach)) continue;
            for (int d = 0; d < 3; d++) s->x[d][m] = img[c][d];
            m++;
        }
    }
    return 0;
}

/* F[p] = what all the sources add to pixel p (pixel_weight), for every pixel. The sources go
 * into bins along the outermost axis, in index order within a bin, so that each layer reads
 * only those within reach, always in the same order. */
static int scatter(const grid *g, float *F, const sources *s, double reach, const source_weight *sw)
{
    int ao = g->dim - 1, nl = g->nn[ao];
    double ho = g->h[ao];
    double bw = reach > ho ? reach : ho;
    long nbins = (long)ceil(nl * ho / bw);
    if (nbins < 1) nbins = 1;
    size_t *start = calloc((size_t)nbins + 1, sizeof *start);
    size_t *fill = malloc((size_t)nbins * sizeof *fill);
    size_t *order = malloc((s->count ? s->count : 1) * sizeof *order);
    if (!start || !fill || !order) {
        free(start);
        free(fill);
        free(order);
        return -1;
    }
    const double *xo = s->x[ao];
    /* sources beyond a wall go to the end bins, where the layers near that wall look */
#define BIN_OF(c) ((c) < 0.0 ? 0L : ((c) / bw >= (double)nbins ? nbins - 1 : (long)((c) / bw)))
    for (size_t i = 0; i < s->count; i++) start[BIN_OF(xo[i]) + 1]++;
    for (long b = 0; b < nbins; b++) {
        start[b + 1] += start[b];
        fill[b] = start[b];
    }
    for (size_t i = 0; i < s->count; i++) order[fill[BIN_OF(xo[i])]++] = i;
    free(fill);

    size_t layer_size = g->stride[ao];
    double reach2 = reach * reach;
#pragma omp parallel for schedule(dynamic, 1)
    for (int L = 0; L < nl; L++) {
        float *lay = F + (size_t)L * layer_size;
        for (size_t p = 0; p < layer_size; p++) lay[p] = 0.0f;
        double zc = (L + 0.5) * ho;
        long b0 = BIN_OF(zc - reach), b1 = BIN_OF(zc + reach);
        for (size_t o = start[b0]; o < start[b1 + 1]; o++) {
            size_t i = order[o];
            double dz = xo[i] - zc, left = reach2 - dz * dz;
            if (left < 0.0) continue;
            int row0 = 0, row1 = 0;
            if (g->dim == 3) {
                double half = sqrt(left);
                pixel_range(s->x[1][i] - half, s->x[1][i] + half, g->h[1], 0, g->nn[1], &row0,
                            &row1);
            }
            for (int row = row0; row <= row1; row++) {
                double dy = g->dim == 3 ? (row + 0.5) * g->h[1] - s->x[1][i] : 0.0;
                double r2_row = dz * dz + dy * dy, chord = reach2 - r2_row;
                if (chord < 0.0) continue;
                double half = sqrt(chord);
                int first, last;
                pixel_range(s->x[0][i] - half, s->x[0][i] + half, g->h[0], g->x_first,
                            g->x_first + g->nn[0], &first, &last);
                float *line = lay + (size_t)row * g->nn[0];
                for (int c = first; c <= last; c++) {
                    double dx = (c + 0.5) * g->h[0] - s->x[0][i];
                    line[c - g->x_first] += pixel_weight(sw, dx * dx + r2_row);
                }
            }
        }
    }
#undef BIN_OF
    free(start);
    free(order);
    return 0;
}

static int fail(char *err, size_t err_len, const char *msg)
{
    snprintf(err, err_len, "graphical method: %s", msg);
    return -1;
}

/* The pixels with F >= 1/2 into count[kind], kind's bit d set on the last layer of axis d. */
static void count_liquid(const grid *g, const float *F, unsigned long long count[8])
{
#pragma omp parallel for schedule(static) reduction(+ : count[:8])
    for (size_t p = 0; p < g->total; p++) {
        if (!(F[p] >= 0.5f)) continue;
        int kind = g->x_first + (int)(p % (size_t)g->nn[0]) == g->nx_all - 1 ? 1 : 0;
        for (int d = 1; d < g->dim; d++)
            if ((int)(p / g->stride[d] % (size_t)g->nn[d]) == g->nn[d] - 1) kind |= 1 << d;
        count[kind]++;
    }
}

double raster_reach(const raster_params *rp, double dr)
{
    return fmax(2.0 * rp->smoothing * dr, rp->radius * dr);
}

/* The pixel columns along x whose centres lie in [x_lo, x_hi): g->x_first and g->nn[0], out
 * of the g->nx_all of the box. The parts of processes that share a bound agree on it. */
static void part_columns(grid *g, double x_lo, double x_hi)
{
    double first = ceil(x_lo / g->h[0] - 0.5), end = ceil(x_hi / g->h[0] - 0.5);
    first = fmin(fmax(first, 0.0), g->nx_all);
    end = fmin(fmax(end, first), g->nx_all);
    g->x_first = (int)first;
    g->nn[0] = (int)end - g->x_first;
}

int raster_count_part(int dim, size_t n, double *const x[3], double dr, const double size[3],
                      const raster_params *rp, double x_lo, double x_hi, raster_count *c, char *err,
                      size_t err_len)
{
    if (dim != 2 && dim != 3) return fail(err, err_len, "dim must be 2 or 3");
    if (!(dr > 0.0 && isfinite(dr))) return fail(err, err_len, "dr must be positive");
    if (rp->k < 1) return fail(err, err_len, "k (pixels per dr) must be at least 1");
    if (!(rp->radius >= 0.0 && isfinite(rp->radius)))
        return fail(err, err_len, "disc radius must be 0 or positive");
    if (!(rp->smoothing >= 0.0 && isfinite(rp->smoothing)))
        return fail(err, err_len, "smoothing length must be 0 or positive");
    if (rp->radius == 0.0 && rp->smoothing == 0.0)
        return fail(err, err_len, "a disc radius or a smoothing length is needed");
    if (isnan(x_lo) || isnan(x_hi) || x_lo > x_hi)
        return fail(err, err_len, "the part's range along x is not a range");
    for (size_t i = 0; i < n; i++)
        for (int d = 0; d < dim; d++)
            if (!isfinite(x[d][i])) return fail(err, err_len, "particle position not finite");

    grid g = {.dim = dim, .nn = {1, 1, 1}, .h = {1.0, 1.0, 1.0}, .last = {1.0, 1.0, 1.0}};
    double box_pixels = 1.0;
    for (int d = 0; d < dim; d++) {
        if (!(size[d] > 0.0 && isfinite(size[d])))
            return fail(err, err_len, "tank size must be positive");
        double spacing = rp->spacing[d] > 0.0 ? rp->spacing[d] : dr, h = spacing / rp->k;
        /* a box within 1e-9 of a whole number of pixels is taken as one */
        double cells = ceil(size[d] / h - 1e-9);
        if (cells < 1.0) cells = 1.0;
        box_pixels *= cells;
        if (cells > INT_MAX / 4 || box_pixels > (double)(SIZE_MAX / 8))
            return fail(err, err_len, "grid too large (lower k)");
        g.nn[d] = (int)cells;
        g.size[d] = size[d];
        if (rp->spacing[d] > 0.0) {
            g.h[d] = h;
            g.last[d] = fmin(1.0, size[d] / h - (cells - 1.0));
        } else {
            g.h[d] = size[d] / cells;
        }
    }
    /* the part: its columns along x only */
    g.nx_all = g.nn[0];
    part_columns(&g, x_lo, x_hi);
    g.total = 1;
    for (int d = 0; d < dim; d++) {
        g.stride[d] = g.total;
        g.total *= (size_t)g.nn[d];
    }

    *c = (raster_count){.dim = dim, .last = {g.last[0], g.last[1], g.last[2]}};
    c->pixel_volume = g.h[0] * g.h[1] * (dim == 3 ? g.h[2] : 1.0);

    double hc = rp->smoothing * dr, rd = rp->radius * dr;
    double reach = raster_reach(rp, dr);
    double ratio = hc > 0.0 ? dr / hc : 0.0;
    double volume_ratio = rp->particle_volume > 0.0 ? rp->particle_volume / pow(dr, dim) : 1.0;
    source_weight sw = {
        .inv_hc2 = hc > 0.0 ? 1.0 / (hc * hc) : 0.0,
        .norm = volume_ratio * (dim == 2 ? 7.0 / (4.0 * M_PI) * ratio * ratio
                                         : 21.0 / (16.0 * M_PI) * ratio * ratio * ratio),
        .disc2 = rd * rd,
    };
    if (g.total == 0) return 0; /* no pixel centre in the part */
    float *F = malloc(g.total * sizeof *F);
    sources s;
    int status = F ? sources_make(&g, n, x, reach, x_lo, x_hi, &s) : -1;
    if (!status) {
        status = scatter(&g, F, &s, reach, &sw);
        sources_free(&s);
    }
    /* liquid pixels counted per kind: integers, the same for any thread count */
    if (!status) count_liquid(&g, F, c->count);
    free(F);
    if (status) {
        snprintf(err, err_len, "graphical method: out of memory (%zu pixels)", g.total);
        return -1;
    }
    return 0;
}

double raster_count_volume(const raster_count *c)
{
    double pixels = 0.0;
    for (int kind = 0; kind < 1 << c->dim; kind++) {
        double weight = 1.0;
        for (int d = 0; d < c->dim; d++)
            if (kind >> d & 1) weight *= c->last[d];
        pixels += (double)c->count[kind] * weight;
    }
    return pixels * c->pixel_volume;
}

int raster_volume(int dim, size_t n, double *const x[3], double dr, const double size[3],
                  const raster_params *rp, double *volume, char *err, size_t err_len)
{
    raster_count c;
    if (raster_count_part(dim, n, x, dr, size, rp, -INFINITY, INFINITY, &c, err, err_len))
        return -1;
    *volume = raster_count_volume(&c);
    return 0;
}
