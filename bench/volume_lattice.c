/* volume_lattice: the check of the paper's Fig. 2 (sec. 3.1, Eqs. 11-12; theory §1, §9).
 *
 * A periodic square (DIM = 2) or cube (DIM = 3) of side L = M dr holds N = M^n particles, one
 * per site of a square/cubic lattice of spacing dr, each moved off its site by a random
 * displacement drawn uniformly in a disc (2D) or ball (3D) of radius frac * dr. For every h/dr
 * of a range, the geometric volumes of Eq. (11)
 *
 *     V_i = 1 / sum_j W_ij      (self term j = i included, every periodic image within 2h)
 *
 * give eps_V^(1) = sum_i V_i / L^n - 1 (Eq. 12 with S_F empty: no free surface here).
 *
 * Periodic images: particle i on site I sees the particle of site (I + o) mod M at
 * (I + o) dr + d_{(I+o) mod M} for every integer offset o with |o| dr < 2h + 2 frac dr. Each
 * (particle, image) pair of the infinite periodic system within 2h is met exactly once this
 * way, whatever M is (for 2h < L/2 this is the minimum-image convention; for 2h >= L/2 it
 * also counts the further images, and the particle's own images). A brute-force sum over
 * every particle and every image shift checks this on a small box at start-up.
 *
 * The displacements come from splitmix64 (fixed seeds, the same numbers on every machine and
 * compiler); for one seed the same unit-ball samples u_i are used for every fraction
 * (d_i = frac dr u_i), so the columns differ only in amplitude. Each particle's sum runs over
 * the offsets in a fixed order and the sum over particles is serial in index order, so the
 * output does not depend on the number of OpenMP threads.
 *
 * The paper's particles come from a packing algorithm (Colagrossi et al. 2012, ref. [53]),
 * not from random displacements: the random columns are a proxy for that disorder.
 *
 * A benchmark: it prints figures. It exits 1 only if a correctness check fails (lattice sums
 * against theory §1, offsets against brute force). */
#include "core/kernel.h"

#include <errno.h>
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FRACTIONS 16

/* ---------------------------------------------------------------- random numbers */

/* splitmix64 (Steele, Lea & Flood 2014; public-domain reference by S. Vigna). */
static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* uniform in [-1, 1): 53 random bits, exact in double */
static double uniform_pm1(uint64_t *state)
{
    return 2.0 * ((double)(splitmix64(state) >> 11) * 0x1.0p-53) - 1.0;
}

/* n * DIM samples uniform in the unit disc/ball, by rejection from the square/cube. */
static void unit_ball_samples(double *u, size_t n, uint64_t seed)
{
    uint64_t state = seed;
    for (size_t i = 0; i < n; i++) {
        double v[DIM], r2;
        do {
            r2 = 0.0;
            for (int d = 0; d < DIM; d++) {
                v[d] = uniform_pm1(&state);
                r2 += v[d] * v[d];
            }
        } while (r2 >= 1.0);
        for (int d = 0; d < DIM; d++) u[i * DIM + d] = v[d];
    }
}

/* ---------------------------------------------------------------- the box */

typedef struct {
    int m;          /* sites per side */
    size_t n;       /* M^DIM particles */
    double dr;      /* lattice spacing */
    double *disp;   /* n * DIM displacements (absolute, already times frac dr) */
    double *volume; /* n geometric volumes V_i */
} box;

static size_t site_index(const int *site, int m)
{
    size_t idx = 0;
    for (int d = DIM - 1; d >= 0; d--) idx = idx * (size_t)m + (size_t)site[d];
    return idx;
}

static void site_of(size_t idx, int m, int *site)
{
    for (int d = 0; d < DIM; d++) {
        site[d] = (int)(idx % (size_t)m);
        idx /= (size_t)m;
    }
}

/* Integer offsets o with |o| dr < 2h + 2 max|d| (plus a margin), in lexicographic order. */
typedef struct {
    int count;
    int *o; /* count * DIM */
} offsets;

static offsets offsets_make(double reach_over_dr)
{
    int r = (int)ceil(reach_over_dr) + 1;
    int side = 2 * r + 1;
    int total = side * side * (DIM == 3 ? side : 1);
    offsets off = {0, malloc((size_t)total * DIM * sizeof(int))};
    if (!off.o) {
        fprintf(stderr, "volume_lattice: out of memory\n");
        exit(2);
    }
    double lim2 = (reach_over_dr + 1e-9) * (reach_over_dr + 1e-9);
    for (int a = -r; a <= r; a++)
        for (int b = -r; b <= r; b++)
#if DIM == 3
            for (int c = -r; c <= r; c++)
#else
            for (int c = 0; c <= 0; c++)
#endif
            {
                if ((double)(a * a + b * b + c * c) > lim2) continue;
                int *o = off.o + (size_t)off.count * DIM;
                o[0] = a;
                o[1] = b;
#if DIM == 3
                o[2] = c;
#else
                (void)c;
#endif
                off.count++;
            }
    return off;
}

/* V_i = 1 / sum_j W_ij for every particle, then eps_V1 = sum_i V_i / L^n - 1.
 * max_disp: the largest |d_i| (frac dr), which sets how far the offsets must reach. */
static double eps_v1(box *bx, double h_over_dr, double max_disp)
{
    const double dr = bx->dr;
    const int m = bx->m;
    kernel k = kernel_make(h_over_dr * dr);
    offsets off = offsets_make((2.0 * k.h + 2.0 * max_disp) / dr);

#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < bx->n; i++) {
        int si[DIM];
        site_of(i, m, si);
        const double *di = bx->disp + i * DIM;
        double sum = 0.0;
        for (int q = 0; q < off.count; q++) {
            const int *o = off.o + (size_t)q * DIM;
            int sj[DIM];
            for (int d = 0; d < DIM; d++) {
                int s = (si[d] + o[d]) % m;
                sj[d] = s < 0 ? s + m : s;
            }
            const double *dj = bx->disp + site_index(sj, m) * DIM;
            double r2 = 0.0;
            for (int d = 0; d < DIM; d++) {
                double x = (double)o[d] * dr + (dj[d] - di[d]);
                r2 += x * x;
            }
            if (r2 < k.support2) sum += kernel_w(&k, sqrt(r2));
        }
        bx->volume[i] = 1.0 / sum;
    }
    free(off.o);

    double total = 0.0; /* serial, in index order: the same bits for any thread count */
    for (size_t i = 0; i < bx->n; i++) total += bx->volume[i];
    double ln = pow((double)m * dr, DIM);
    return total / ln - 1.0;
}

/* Brute force over every particle j and every image shift s (|s_d| <= K boxes): the same
 * volumes as eps_v1 up to the order of the sums. Returns max_i |V_i^brute / V_i - 1|. */
static double brute_check(box *bx, double h_over_dr, double max_disp)
{
    const double dr = bx->dr, len = (double)bx->m * dr;
    kernel k = kernel_make(h_over_dr * dr);
    eps_v1(bx, h_over_dr, max_disp);
    int kk = (int)ceil((2.0 * k.h + 2.0 * max_disp + dr) / len) + 1;
    double worst = 0.0;
    for (size_t i = 0; i < bx->n; i++) {
        int si[DIM];
        site_of(i, bx->m, si);
        double sum = 0.0;
        for (size_t j = 0; j < bx->n; j++) {
            int sj[DIM];
            site_of(j, bx->m, sj);
            for (int a = -kk; a <= kk; a++)
                for (int b = -kk; b <= kk; b++)
#if DIM == 3
                    for (int c = -kk; c <= kk; c++)
#else
                    for (int c = 0; c <= 0; c++)
#endif
                    {
                        int shift[3] = {a, b, c};
                        double r2 = 0.0;
                        for (int d = 0; d < DIM; d++) {
                            double xi = si[d] * dr + bx->disp[i * DIM + d];
                            double xj = sj[d] * dr + bx->disp[j * DIM + d] + shift[d] * len;
                            r2 += (xj - xi) * (xj - xi);
                        }
                        if (r2 < k.support2) sum += kernel_w(&k, sqrt(r2));
                    }
        }
        double rel = fabs((1.0 / sum) / bx->volume[i] - 1.0);
        if (rel > worst) worst = rel;
    }
    return worst;
}

static box box_make(int m, double dr)
{
    box bx;
    bx.m = m;
    bx.dr = dr;
    bx.n = 1;
    for (int d = 0; d < DIM; d++) bx.n *= (size_t)m;
    bx.disp = calloc(bx.n * DIM, sizeof(double));
    bx.volume = calloc(bx.n, sizeof(double));
    if (!bx.disp || !bx.volume) {
        fprintf(stderr, "volume_lattice: out of memory\n");
        exit(2);
    }
    return bx;
}

static void box_free(box *bx)
{
    free(bx->disp);
    free(bx->volume);
}

static void box_displace(box *bx, const double *unit, double amplitude)
{
    for (size_t i = 0; i < bx->n * DIM; i++) bx->disp[i] = amplitude * unit[i];
}

/* ---------------------------------------------------------------- checks */

/* theory §1: sum_j W_ij dr^n - 1 on the infinite lattice, to the digits given there */
typedef struct {
    double h_over_dr, offset, half_digit;
} lattice_ref;

#if DIM == 2
static const lattice_ref refs[] = {
    {2.0, 1.206e-3, 0.5e-6},
    {1.5, 5.14e-3, 0.5e-5},
    {3.0, 1.62e-4, 0.5e-6},
};
#else
static const lattice_ref refs[] = {
    {1.5, 3.14e-3, 0.5e-5},
    {2.0, 5.49e-4, 0.5e-6},
};
#endif

static int run_checks(int m)
{
    int failed = 0;
    printf("# checks: perfect lattice against the lattice sums of theory §1 "
           "(eps_V1 = 1/(1 + s) - 1, s = sum_j W_ij dr^n - 1)\n");
    printf("#   %-5s %-12s %-12s %-13s %-13s %s\n", "h/dr", "s measured", "s theory",
           "eps_V1 meas.", "eps_V1 theory", "");
    box bx = box_make(m, 1.0);
    for (size_t r = 0; r < sizeof refs / sizeof refs[0]; r++) {
        double e = eps_v1(&bx, refs[r].h_over_dr, 0.0);
        double s = 1.0 / (1.0 + e) - 1.0;
        double e_ref = 1.0 / (1.0 + refs[r].offset) - 1.0;
        int ok = fabs(s - refs[r].offset) <= refs[r].half_digit;
        failed |= !ok;
        printf("#   %-5.1f %+.5e  %+.3e   %+.5e  %+.5e  %s\n", refs[r].h_over_dr, s, refs[r].offset,
               e, e_ref, ok ? "ok" : "FAIL");
    }
    box_free(&bx);

    /* offsets against brute force over all images, on a box so small that 2h > L/2 */
    const int mb = DIM == 2 ? 7 : 5;
    box small = box_make(mb, 1.0);
    double *unit = malloc(small.n * DIM * sizeof(double));
    if (!unit) exit(2);
    unit_ball_samples(unit, small.n, UINT64_C(12345));
    const double hs[] = {1.0, 1.5, 2.3, 3.0};
    const double fs[] = {0.0, 0.2, 0.45};
    double worst = 0.0;
    for (size_t a = 0; a < sizeof hs / sizeof hs[0]; a++)
        for (size_t b = 0; b < sizeof fs / sizeof fs[0]; b++) {
            box_displace(&small, unit, fs[b] * small.dr);
            double w = brute_check(&small, hs[a], fs[b] * small.dr);
            if (w > worst) worst = w;
        }
    int ok = worst < 1e-12;
    failed |= !ok;
    printf("# checks: image offsets against brute force over all images, M = %d, h/dr up to 3 "
           "(2h > L/2), frac up to 0.45: max |dV_i/V_i| = %.1e  %s\n",
           mb, worst, ok ? "ok" : "FAIL");
    free(unit);
    box_free(&small);
    return failed;
}

/* ---------------------------------------------------------------- small-disorder theory */

/* Second order in the displacements, for i.i.d. displacements of per-component variance
 * sigma^2 (uniform in a disc of radius R: R^2/4; in a ball: R^2/5). With S_i = sum_j W_ij dr^n
 * and S0 its lattice value, the relative displacements d_j - d_i have per-component variance
 * 2 sigma^2, so
 *     E[S_i] - S0  = sigma^2 dr^n sum_{j != i} lap W(r_ij)              (the kernel is smoothed)
 *     Var[S_i]     = sigma^2 dr^2n sum_{j != i} |grad W(r_ij)|^2        (sum_j grad W_ij = 0)
 *     E[1/S_i]     = 1/S0 - (E[S_i] - S0)/S0^2 + Var[S_i]/S0^3 + ...
 * and eps_V1 - eps_V1(lattice) = c2 frac^2 + O(frac^4) with c2 returned here (dr = 1).
 * grad W = -r F, lap W = -n F - r dF/dr, F = 5 a_n (1 - q/2)^3 / h^2 (theory §1). */
static double second_order_c2(double h_over_dr)
{
    kernel k = kernel_make(h_over_dr);
    int r = (int)ceil(2.0 * h_over_dr) + 1;
    double s0 = 0.0, lap = 0.0, grad2 = 0.0;
    for (int a = -r; a <= r; a++)
        for (int b = -r; b <= r; b++)
#if DIM == 3
            for (int c = -r; c <= r; c++)
#else
            for (int c = 0; c <= 0; c++)
#endif
            {
                double rr = sqrt((double)(a * a + b * b + c * c));
                s0 += kernel_w(&k, rr);
                if (rr == 0.0 || rr >= 2.0 * k.h) continue;
                double sq = 1.0 - 0.5 * rr * k.inv_h;
                double f = kernel_f(&k, rr);
                double dfdr = -1.5 * k.f_norm * sq * sq * k.inv_h;
                lap += -DIM * f - rr * dfdr;
                grad2 += rr * rr * f * f;
            }
    double var_per_frac2 = DIM == 2 ? 0.25 : 0.2; /* sigma^2 / (frac dr)^2 */
    return var_per_frac2 * (-lap / (s0 * s0) + grad2 / (s0 * s0 * s0));
}

/* ---------------------------------------------------------------- command line */

static void usage(FILE *f)
{
    fprintf(f,
            "usage: volume_lattice_%dd [options]\n"
            "  -M, --sites M          sites per side, L = M dr (default %d)\n"
            "  -f, --fractions LIST   displacement radii / dr, comma separated (default "
            "0.05,0.1,0.2;\n"
            "                         the perfect lattice, 0, is always the first column)\n"
            "  -s, --seeds S          seeds per fraction (default 5)\n"
            "      --seed0 N          first seed (default 1; seeds are seed0 .. seed0+S-1)\n"
            "      --hmin X --hmax Y --hsteps K   h/dr from X to Y in K steps (default 1 3 20)\n"
            "      --per-seed         also print every seed's eps_V1\n"
            "      --no-checks        skip the checks against theory and brute force\n"
            "  -h, --help\n",
            DIM, DIM == 2 ? 40 : 20);
}

static int parse_int(const char *s, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || *end || end == s || v < 1 || v > 100000) return -1;
    *out = (int)v;
    return 0;
}

static int parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || *end || end == s || !isfinite(v)) return -1;
    *out = v;
    return 0;
}

static int parse_list(const char *s, double *out, int *count)
{
    char buf[512];
    if (strlen(s) >= sizeof buf) return -1;
    strcpy(buf, s);
    *count = 0;
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        if (*count >= MAX_FRACTIONS || parse_double(tok, &out[*count]) || out[*count] < 0.0)
            return -1;
        (*count)++;
    }
    return *count > 0 ? 0 : -1;
}

int main(int argc, char **argv)
{
    int m = DIM == 2 ? 40 : 20, seeds = 5, hsteps = 20, per_seed = 0, checks = 1;
    long long seed0 = 1;
    double hmin = 1.0, hmax = 3.0;
    double fr[MAX_FRACTIONS] = {0.05, 0.1, 0.2};
    int nfr = 3;

    for (int a = 1; a < argc; a++) {
        const char *o = argv[a];
        const char *v = a + 1 < argc ? argv[a + 1] : NULL;
        int bad = 0;
        if (!strcmp(o, "-h") || !strcmp(o, "--help")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(o, "--per-seed")) {
            per_seed = 1;
        } else if (!strcmp(o, "--no-checks")) {
            checks = 0;
        } else if (!v) {
            bad = 1;
        } else if (!strcmp(o, "-M") || !strcmp(o, "--sites")) {
            bad = parse_int(v, &m) || m < 2, a++;
        } else if (!strcmp(o, "-f") || !strcmp(o, "--fractions")) {
            bad = parse_list(v, fr, &nfr), a++;
        } else if (!strcmp(o, "-s") || !strcmp(o, "--seeds")) {
            bad = parse_int(v, &seeds), a++;
        } else if (!strcmp(o, "--seed0")) {
            double x;
            bad = parse_double(v, &x) || x < 0 || x != floor(x), a++;
            seed0 = (long long)x;
        } else if (!strcmp(o, "--hmin")) {
            bad = parse_double(v, &hmin) || hmin <= 0.0, a++;
        } else if (!strcmp(o, "--hmax")) {
            bad = parse_double(v, &hmax) || hmax <= 0.0, a++;
        } else if (!strcmp(o, "--hsteps")) {
            bad = parse_int(v, &hsteps), a++;
        } else {
            bad = 1;
        }
        if (bad) {
            fprintf(stderr, "volume_lattice: bad option or value: %s%s%s\n", o, v ? " " : "",
                    v ? v : "");
            usage(stderr);
            return 2;
        }
    }
    if (hmax < hmin) {
        fprintf(stderr, "volume_lattice: --hmax < --hmin\n");
        return 2;
    }

    double t0 = omp_get_wtime();
    int failed = checks ? run_checks(m) : 0;

    box bx = box_make(m, 1.0);
    double *unit = malloc(bx.n * DIM * (size_t)seeds * sizeof(double));
    if (!unit) {
        fprintf(stderr, "volume_lattice: out of memory\n");
        return 2;
    }
    for (int s = 0; s < seeds; s++)
        unit_ball_samples(unit + (size_t)s * bx.n * DIM, bx.n, (uint64_t)(seed0 + s));

    printf("# volume_lattice: %dD periodic %s, L = M dr, M = %d, N = %zu particles\n", DIM,
           DIM == 2 ? "square" : "cube", m, bx.n);
    printf("# disorder: displacement uniform in a %s of radius frac*dr (rms = %s frac*dr), "
           "splitmix64 seeds %lld..%lld, the same unit samples for every frac\n",
           DIM == 2 ? "disc" : "ball", DIM == 2 ? "0.707" : "0.775", seed0, seed0 + seeds - 1);
    printf("# eps_V1 = sum_i V_i / L^%d - 1, V_i = 1/sum_j W_ij (Wendland C2, self term and "
           "all periodic images within 2h)\n",
           DIM);
    printf("# columns: h/dr, eps_V1 of the perfect lattice, then per frac the mean and the "
           "sample standard deviation over the seeds\n");
    printf("%-6s %-12s", "h/dr", "frac=0");
    for (int f = 0; f < nfr; f++) {
        char name[32];
        snprintf(name, sizeof name, "frac=%g", fr[f]);
        printf(" %-12s %-9s", name, "sd");
    }
    printf("\n");

    double *vals = malloc((size_t)seeds * (size_t)nfr * sizeof(double));
    double *lat = malloc((size_t)(hsteps + 1) * sizeof(double));
    double *means = malloc((size_t)(hsteps + 1) * (size_t)nfr * sizeof(double));
    if (!vals || !lat || !means) return 2;
    for (int k = 0; k <= hsteps; k++) {
        /* (hmin (K-k) + hmax k) / K: 1.5, 2 and 3 come out exact */
        double hr = (hmin * (hsteps - k) + hmax * k) / hsteps;
        box_displace(&bx, unit, 0.0);
        lat[k] = eps_v1(&bx, hr, 0.0);
        printf("%-6.2f %+.4e", hr, lat[k]);
        for (int f = 0; f < nfr; f++) {
            double *v = vals + (size_t)f * (size_t)seeds;
            double mean = 0.0;
            for (int s = 0; s < seeds; s++) {
                box_displace(&bx, unit + (size_t)s * bx.n * DIM, fr[f] * bx.dr);
                v[s] = eps_v1(&bx, hr, fr[f] * bx.dr);
                mean += v[s];
            }
            mean /= seeds;
            means[(size_t)k * (size_t)nfr + (size_t)f] = mean;
            double var = 0.0;
            for (int s = 0; s < seeds; s++) var += (v[s] - mean) * (v[s] - mean);
            if (seeds > 1)
                printf(" %+.4e  %.2e ", mean, sqrt(var / (seeds - 1)));
            else
                printf(" %+.4e  %-9s", mean, "-");
        }
        printf("\n");
        if (per_seed)
            for (int f = 0; f < nfr; f++) {
                printf("#   h/dr %.2f frac %g seeds:", hr, fr[f]);
                for (int s = 0; s < seeds; s++)
                    printf(" %+.6e", vals[(size_t)f * (size_t)seeds + (size_t)s]);
                printf("\n");
            }
        fflush(stdout);
    }

    /* the disorder part (mean - lattice) / frac^2 against the second-order expansion */
    printf("# small-disorder check: (eps_V1 mean - eps_V1 lattice) / frac^2 against c2, the "
           "second-order expansion (informative, not a pass/fail)\n");
    printf("%-6s %-11s", "h/dr", "c2 theory");
    for (int f = 0; f < nfr; f++) {
        char name[32];
        snprintf(name, sizeof name, "frac=%g", fr[f]);
        printf(" %-11s", name);
    }
    printf("\n");
    for (int k = 0; k <= hsteps; k++) {
        double hr = (hmin * (hsteps - k) + hmax * k) / hsteps;
        printf("%-6.2f %+.4e", hr, second_order_c2(hr));
        for (int f = 0; f < nfr; f++) {
            double d = means[(size_t)k * (size_t)nfr + (size_t)f] - lat[k];
            if (fr[f] > 0.0)
                printf(" %+.4e", d / (fr[f] * fr[f]));
            else
                printf(" %-11s", "-");
        }
        printf("\n");
    }
    free(lat);
    free(means);

    printf("# wall time %.2f s on %d OpenMP threads\n", omp_get_wtime() - t0,
           omp_get_max_threads());
    free(vals);
    free(unit);
    box_free(&bx);
    if (failed) fprintf(stderr, "volume_lattice: a check FAILED\n");
    return failed ? 1 : 0;
}
