/* raster: the graphical method, Eq. (15), in 2D and 3D.
 *
 * The particles are drawn as discs (balls) of radius r_d on a grid that fits the tank box, and
 * the drawing is then closed (dilated, then eroded) with a disc of radius c, which fills the
 * gaps a lattice of discs leaves between diagonal neighbours and most of the valleys between
 * the particles of a free surface, while two pieces of liquid farther apart than 2c stay
 * apart. Dilation and erosion are thresholds of exact Euclidean distance transforms
 * (Felzenszwalb & Huttenlocher 2012, "Distance transforms of sampled functions"): squared
 * distances, one 1-D lower envelope of parabolas per grid line and axis, O(pixels) for any c.
 *
 * Distances are measured between pixel centres, and both transforms use c + h/2 (h = dr/k):
 * a pixel is a square that reaches h/2 past its centre. Without it, the top row of pixels of a
 * lattice's free surface, a row of short runs (the caps of the discs), could never be filled:
 * a disc rolling on runs of pixel centres at one height dips between them. With it, the flat
 * free surface of a lattice aligned with the grid reads exactly, and two pieces of liquid are
 * bridged when their drawings are 2c apart or closer, as in the continuum.
 *
 * One float per pixel holds everything: 0 on the sources of a transform and `cap` elsewhere.
 * Only whether a squared distance is <= (c + h/2)^2 matters, so the transforms are clamped at
 * cap = floor((c + h/2)^2) + 1 (in nominal pixels, dr / k): a parabola whose apex is at cap
 * or above cannot bring a value under (c + h/2)^2 and is skipped. On a box that is a whole number
 * of pixels wide, every value is an integer below 2^24 and the float arithmetic is exact.
 *
 * The walls are mirrors. Beyond a wall lies the mirror image of what is inside, as with the
 * ghost particles (theory §5); each 1-D transform reads its line reflected about both ends.
 * Then liquid along a wall is closed exactly as in the interior: the discs against a wall
 * and their images form one lattice, whose cusps at the wall are filled, and nothing of the
 * liquid is eroded. The alternatives do worse: empty space beyond the walls leaves the cusps
 * along every wall open, as on a free surface (each wall would read like one more free
 * surface, low); fluid beyond the walls fills them but glues to a wall any liquid closer to
 * it than 2c. With mirrors a drop is glued to a wall when closer than c: the wall stands
 * midway between the drop and its image, which join at 2c.
 *
 * Parallel over lines (layers for the drawing); every pixel is written by one thread, the
 * count is an integer, so the result does not depend on the number of threads. */
#include "diag/raster.h"

#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* Lines gathered together for a transform across the memory order, so that each read of the
 * grid fetches this many neighbouring floats rather than one. */
#define RASTER_BATCH 16

raster_params raster_params_default(int dim)
{
    raster_params rp = {.k = dim == 3 ? 4 : 8, .radius = 0.5, .closing = 2.0};
    return rp;
}

typedef struct {
    int dim;
    int nn[3];    /* pixels per axis (1 past dim) */
    double h[3];  /* pixel side per axis, m */
    double w2[3]; /* (h[d] / (dr / k))^2: squared distances are in nominal pixels */
    size_t stride[3];
    size_t total;
} grid;

/* Index of the position j of a line of n pixels reflected about both of its ends. */
static inline int reflect(long j, int n)
{
    long period = 2L * n;
    long t = j % period;
    if (t < 0) t += period;
    return (int)(t < n ? t : period - 1 - t);
}

/* 1-D squared distance transform of f[0..ne) with spacing^2 w2, clamped at cap; only the
 * outputs at lo..lo+n-1 are written, to out[0..n). Felzenszwalb & Huttenlocher's lower
 * envelope; v holds the apexes of the envelope's parabolas, z their left ends (ne + 1). */
static void edt_line(const float *f, int ne, int lo, int n, double w2, double cap, float *out,
                     int *v, double *z)
{
    int k = -1;
    for (int q = 0; q < ne; q++) {
        double fq = f[q];
        if (fq >= cap) continue;
        double s = -INFINITY;
        while (k >= 0) {
            int p = v[k];
            s = ((fq + w2 * (double)q * q) - ((double)f[p] + w2 * (double)p * p)) /
                (2.0 * w2 * (double)(q - p));
            if (s <= z[k])
                k--;
            else
                break;
        }
        if (k < 0) s = -INFINITY;
        k++;
        v[k] = q;
        z[k] = s;
    }
    if (k < 0) {
        for (int i = 0; i < n; i++) out[i] = (float)cap;
        return;
    }
    z[k + 1] = INFINITY;
    int j = 0;
    for (int i = 0; i < n; i++) {
        double q = lo + i;
        while (z[j + 1] < q) j++;
        double dq = q - v[j];
        double d = w2 * dq * dq + f[v[j]];
        out[i] = (float)(d < cap ? d : cap);
    }
}

/* The transform along axis a, in place, every line reflected about the walls. */
static int edt_axis(const grid *g, float *F, int a, double cap)
{
    int na = g->nn[a];
    size_t stride = g->stride[a];
    size_t inner = stride, outer = g->total / (stride * (size_t)na);
    int batch = inner < RASTER_BATCH ? (int)inner : RASTER_BATCH;
    size_t blocks = (inner + (size_t)batch - 1) / (size_t)batch;
    /* values beyond a reach of sqrt(cap) do not matter */
    int m = (int)ceil(sqrt(cap / g->w2[a])) + 1;
    int ne = na + 2 * m;
    int nt = omp_get_max_threads();
    float *tile = malloc((size_t)nt * (size_t)batch * (size_t)na * sizeof *tile);
    float *ext = malloc((size_t)nt * (size_t)ne * sizeof *ext);
    int *v = malloc((size_t)nt * (size_t)ne * sizeof *v);
    double *z = malloc((size_t)nt * (size_t)(ne + 1) * sizeof *z);
    int status = 0;
    if (!tile || !ext || !v || !z) {
        status = -1;
        goto done;
    }
    long tasks = (long)(outer * blocks);
#pragma omp parallel for schedule(dynamic, 4)
    for (long t = 0; t < tasks; t++) {
        int id = omp_get_thread_num();
        float *my_tile = tile + (size_t)id * (size_t)batch * (size_t)na;
        float *my_ext = ext + (size_t)id * (size_t)ne;
        int *my_v = v + (size_t)id * (size_t)ne;
        double *my_z = z + (size_t)id * (size_t)(ne + 1);
        size_t o = (size_t)t / blocks, i0 = ((size_t)t % blocks) * (size_t)batch;
        int nb = (int)(inner - i0 < (size_t)batch ? inner - i0 : (size_t)batch);
        float *base = F + o * stride * (size_t)na + i0;
        for (int j = 0; j < na; j++)
            for (int b = 0; b < nb; b++) my_tile[(size_t)b * na + j] = base[(size_t)j * stride + b];
        for (int b = 0; b < nb; b++) {
            float *line = my_tile + (size_t)b * na;
            for (int e = 0; e < ne; e++) my_ext[e] = line[reflect(e - m, na)];
            edt_line(my_ext, ne, m, na, g->w2[a], cap, line, my_v, my_z);
        }
        for (int j = 0; j < na; j++)
            for (int b = 0; b < nb; b++) base[(size_t)j * stride + b] = my_tile[(size_t)b * na + j];
    }
done:
    free(tile);
    free(ext);
    free(v);
    free(z);
    return status;
}

static int edt(const grid *g, float *F, double cap)
{
    for (int a = 0; a < g->dim; a++)
        if (edt_axis(g, F, a, cap)) return -1;
    return 0;
}

/* Pixels i of an axis whose centres (i + 1/2) h lie in [lo, hi], clipped to [0, n). */
static inline void pixel_range(double lo, double hi, double h, int n, int *first, int *last)
{
    double a = ceil(lo / h - 0.5), b = floor(hi / h - 0.5);
    *first = a < 0.0 ? 0 : (a > n ? n : (int)a);
    *last = b >= n ? n - 1 : (b < -1.0 ? -1 : (int)b);
}

/* Draws the discs: F = 0 on every pixel whose centre lies within r of a particle, `empty`
 * elsewhere. Parallel over layers of the outermost axis (rows in 2D, planes in 3D), the
 * particles of a layer found through bins along that axis. */
static int draw(const grid *g, float *F, size_t n, double *const x[3], double r, float empty)
{
    int ao = g->dim - 1, nl = g->nn[ao];
    double ho = g->h[ao];
    double bw = r > ho ? r : ho;
    long nbins = (long)ceil(nl * ho / bw);
    if (nbins < 1) nbins = 1;
    size_t *start = calloc((size_t)nbins + 1, sizeof *start);
    size_t *fill = malloc((size_t)nbins * sizeof *fill);
    size_t *order = malloc((n ? n : 1) * sizeof *order);
    if (!start || !fill || !order) {
        free(start);
        free(fill);
        free(order);
        return -1;
    }
    const double *xo = x[ao];
    /* particles beyond a wall go to the end bins, where the layers near that wall look */
#define BIN_OF(c) ((c) < 0.0 ? 0L : ((c) / bw >= (double)nbins ? nbins - 1 : (long)((c) / bw)))
    for (size_t i = 0; i < n; i++) start[BIN_OF(xo[i]) + 1]++;
    for (long b = 0; b < nbins; b++) {
        start[b + 1] += start[b];
        fill[b] = start[b];
    }
    for (size_t i = 0; i < n; i++) order[fill[BIN_OF(xo[i])]++] = i;
    free(fill);

    size_t layer_size = g->stride[ao];
    double r2 = r * r;
#pragma omp parallel for schedule(dynamic, 1)
    for (int L = 0; L < nl; L++) {
        float *lay = F + (size_t)L * layer_size;
        for (size_t p = 0; p < layer_size; p++) lay[p] = empty;
        double zc = (L + 0.5) * ho;
        long b0 = BIN_OF(zc - r), b1 = BIN_OF(zc + r);
        for (size_t s = start[b0]; s < start[b1 + 1]; s++) {
            size_t i = order[s];
            double dz = xo[i] - zc, rr = r2 - dz * dz;
            if (rr < 0.0) continue;
            if (g->dim == 2) {
                double half = sqrt(rr);
                int first, last;
                pixel_range(x[0][i] - half, x[0][i] + half, g->h[0], g->nn[0], &first, &last);
                for (int c = first; c <= last; c++) lay[c] = 0.0f;
            } else {
                double half1 = sqrt(rr);
                int row0, row1;
                pixel_range(x[1][i] - half1, x[1][i] + half1, g->h[1], g->nn[1], &row0, &row1);
                for (int row = row0; row <= row1; row++) {
                    double dy = (row + 0.5) * g->h[1] - x[1][i], q = rr - dy * dy;
                    if (q < 0.0) continue;
                    double half = sqrt(q);
                    int first, last;
                    pixel_range(x[0][i] - half, x[0][i] + half, g->h[0], g->nn[0], &first, &last);
                    float *line = lay + (size_t)row * g->nn[0];
                    for (int c = first; c <= last; c++) line[c] = 0.0f;
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

int raster_volume(int dim, size_t n, double *const x[3], double dr, const double size[3],
                  const raster_params *rp, double *volume, char *err, size_t err_len)
{
    if (dim != 2 && dim != 3) return fail(err, err_len, "dim must be 2 or 3");
    if (!(dr > 0.0 && isfinite(dr))) return fail(err, err_len, "dr must be positive");
    if (rp->k < 1) return fail(err, err_len, "k (pixels per dr) must be at least 1");
    if (!(rp->radius > 0.0 && isfinite(rp->radius)))
        return fail(err, err_len, "disc radius must be positive");
    if (!(rp->closing >= 0.0 && isfinite(rp->closing)))
        return fail(err, err_len, "closing radius must be 0 or positive");
    for (size_t i = 0; i < n; i++)
        for (int d = 0; d < dim; d++)
            if (!isfinite(x[d][i])) return fail(err, err_len, "particle position not finite");

    grid g = {.dim = dim, .nn = {1, 1, 1}, .h = {1.0, 1.0, 1.0}, .w2 = {1.0, 1.0, 1.0}};
    double h = dr / rp->k;
    g.total = 1;
    for (int d = 0; d < dim; d++) {
        if (!(size[d] > 0.0 && isfinite(size[d])))
            return fail(err, err_len, "tank size must be positive");
        /* a box within 1e-9 of a whole number of nominal pixels is taken as one */
        double cells = ceil(size[d] / h - 1e-9);
        if (cells < 1.0) cells = 1.0;
        if (cells > INT_MAX / 4 || (double)g.total * cells > (double)(SIZE_MAX / 8))
            return fail(err, err_len, "grid too large (lower k)");
        g.nn[d] = (int)cells;
        g.h[d] = size[d] / cells;
        double w = g.h[d] / h;
        g.w2[d] = fabs(w - 1.0) < 1e-9 ? 1.0 : w * w;
        g.stride[d] = g.total;
        g.total *= (size_t)g.nn[d];
    }
    double pixel_volume = g.h[0] * g.h[1] * (dim == 3 ? g.h[2] : 1.0);

    float *F = malloc(g.total * sizeof *F);
    if (!F) {
        snprintf(err, err_len, "graphical method: out of memory (%zu pixels)", g.total);
        return -1;
    }
    /* squared distances between pixel centres, in nominal pixels; c + h/2: see the top */
    double c_px = rp->closing * rp->k + 0.5, c2 = c_px * c_px;
    double cap = floor(c2) + 1.0;
    if (cap > 16777216.0) {
        free(F);
        return fail(err, err_len, "closing radius too large for this k");
    }
    int status = draw(&g, F, n, x, rp->radius * dr, (float)cap);
    size_t count = 0;
    if (!status && rp->closing > 0.0) {
        status = edt(&g, F, cap); /* F: squared distance to the discs */
        if (!status) {
            /* dilated: within c of the discs; its complement is the erosion's source */
#pragma omp parallel for schedule(static)
            for (size_t p = 0; p < g.total; p++) F[p] = F[p] <= c2 ? (float)cap : 0.0f;
            status = edt(&g, F, cap); /* F: squared distance to what the dilation left out */
        }
        if (!status) {
#pragma omp parallel for schedule(static) reduction(+ : count)
            for (size_t p = 0; p < g.total; p++) count += F[p] > c2;
        }
    } else if (!status) {
#pragma omp parallel for schedule(static) reduction(+ : count)
        for (size_t p = 0; p < g.total; p++) count += F[p] == 0.0f;
    }
    free(F);
    if (status) {
        snprintf(err, err_len, "graphical method: out of memory (%zu pixels)", g.total);
        return -1;
    }
    *volume = (double)count * pixel_volume;
    return 0;
}
