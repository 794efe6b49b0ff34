/* Integration: the viscous decay of a standing wave, whole runs against linear theory.
 *
 * The first sloshing mode of a 2D tank (L = 1 m, H = 0.35 m, k = pi / L, omega^2 = g k tanh(kH),
 * delta-SPH, N = 24) is excited by one period of sway at its own period (A = 1 cm) and then rings
 * down. Its amplitude is read from the extremes of com_x - L/2, one per half cycle, and the decay
 * rate gamma (amplitude ~ exp(-gamma t)) is the least-squares slope of their logarithm from 2 s
 * (0.7 s after the forcing ends) to 7.5 s. The wave is linear: the surface amplitude is at most
 * 3 cm, k a < 0.1; Re = a omega L / nu is 11 at nu = 1e-2 m^2/s.
 *
 * - Free-slip walls, LES off. The potential mode meets free-slip walls exactly (no normal flow,
 *   no shear stress on the bottom and the end walls), so the tank is one wavelength of a periodic
 *   wave over a free-slip bottom, whose exact linear dispersion relation is solved here
 *   (free_slip_rate). For small nu it gives Lamb's gamma = 2 nu k^2 (Hydrodynamics, sec. 348),
 *   whatever the depth; at nu = 1e-2 the exact rate is 8 % below it (the free surface's
 *   vortical layer), at 2.5e-3 4 % below. The scheme's own dissipation, measured by the same
 *   run at nu = 1e-6, bounds the runs' departure from the exact rates.
 * - No-slip walls, LES off. The Stokes layers on the bottom and the end walls, thickness
 *   delta = sqrt(2 nu / omega), dissipate (1/2) rho sqrt(nu omega / 2) |U|^2 per unit wall area,
 *   U the inviscid slip velocity there (Keulegan 1959, J. Fluid Mech. 6; Mei and Liu 1973, J.
 *   Fluid Mech. 59). Over the energy of the mode this adds, to leading order in sqrt(nu),
 *       gamma_wall = sqrt(nu omega / 2) (k L + sinh 2kH - 2kH) / (L sinh 2kH)
 *   (the bottom gives the k L term, the end walls the rest). The next term of the series is
 *   O(nu) (the layers' displacement of the outer flow, the frequency shift): the runs exceed
 *   gamma_wall by 40 % at nu = 1e-2, 28 % at 5e-3 and 19 % at 2.5e-3, the excess proportional
 *   to nu. So the test measures gamma_ns - gamma_fs at nu and nu / 4 and takes the sqrt(nu)
 *   coefficient a of a sqrt(nu) + b nu, which it compares with gamma_wall / sqrt(nu). delta
 *   spans 4.4 dr at 1e-2 and 2.2 dr at 2.5e-3.
 * - LES. The Smagorinsky viscosity nu_T = (C_S l)^2 |S|, l = 2h = 4 dr, |S| = sqrt(2 S:S), of
 *   the laminar wave adds the mean dissipation 2 rho nu_T S:S over the potential flow, an
 *   amplitude decay les_rate() proportional to the amplitude, 1.3e-3 1/s here: at nu = 2.5e-3
 *   the wave decays 2.5 % faster with LES than without. The runs with and without must differ
 *   by that estimate (it is 0 with LES off, a quarter with l = h). At nu = 1e-6, where LES is a
 *   fifth of the whole decay, the runs gave 1.54e-3 1/s against the estimate's 1.54e-3 (+-7 %,
 *   the fit's error); that pair of runs is left out for time. */
#include <complex.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "check.h"
#include "table.h"
#include "run_case.h"
#include "sloshing.h"
#include "slope.h"

#define LENGTH     1.0  /* m */
#define DEPTH      0.35 /* m */
#define GRAVITY    9.81 /* m/s^2 */
#define RESOLUTION 24
#define FIT_FROM   2.0  /* s */
#define NU_HIGH    1e-2 /* m^2/s */
#define NU_LOW     2.5e-3
#define NU_NONE    1e-6
#define MAX_PEAKS  64

static double wavenumber(void) { return M_PI / LENGTH; }

static double frequency(void)
{
    double k = wavenumber();
    return sqrt(GRAVITY * k * tanh(k * DEPTH));
}

/* One run's extremes of com_x - L/2 (one per half cycle after FIT_FROM) and their decay. */
typedef struct {
    double nu;
    const char *wall, *les;
    int n;
    double t[MAX_PEAKS], amplitude[MAX_PEAKS];
    double rate, rate_error; /* 1/s */
} wave;

/* The extreme of |com_x - L/2| in each half cycle that lies wholly after FIT_FROM (between two
 * crossings of L/2), refined by the parabola through it and its neighbours. */
static void find_peaks(const table *t, wave *w)
{
    const double *time = table_column(t, "t"), *com_x = table_column(t, "com_x");
    w->n = 0;
    int sign = 0;
    size_t best = 0;
    for (size_t r = 1; r + 1 < t->n_rows; r++) {
        if (time[r] < FIT_FROM) continue;
        double d = com_x[r] - 0.5 * LENGTH;
        int s = d > 0.0 ? 1 : -1;
        if (s != sign) {
            if (sign != 0 && best != 0 && w->n < MAX_PEAKS) {
                double a = fabs(com_x[best - 1] - 0.5 * LENGTH);
                double b = fabs(com_x[best] - 0.5 * LENGTH);
                double c = fabs(com_x[best + 1] - 0.5 * LENGTH), peak = b, shift = 0.0;
                if (a - 2.0 * b + c != 0.0) shift = parabola_vertex(a, b, c, &peak);
                w->t[w->n] = time[best] + shift * (time[best + 1] - time[best]);
                w->amplitude[w->n++] = peak;
            }
            best = sign != 0 ? r : 0; /* the half cycle cut by FIT_FROM does not count */
            sign = s;
        } else if (best != 0 && fabs(d) > fabs(com_x[best] - 0.5 * LENGTH)) {
            best = r;
        }
    }
    double ln_a[MAX_PEAKS];
    for (int j = 0; j < w->n; j++) ln_a[j] = log(w->amplitude[j]);
    assert_true(w->n >= 8);
    w->rate = -least_squares_slope(w->t, ln_a, w->n, &w->rate_error);
}

/* The run of the wave with this viscosity, wall condition and LES, made once per test program
 * (the tests share runs). */
static const wave *run_wave(double nu, const char *wall, const char *les)
{
    static wave runs[8];
    static int n_runs;
    for (int j = 0; j < n_runs; j++)
        if (runs[j].nu == nu && !strcmp(runs[j].wall, wall) && !strcmp(runs[j].les, les))
            return &runs[j];
    assert_true(n_runs < 8);
    wave *w = &runs[n_runs++];
    w->nu = nu, w->wall = wall, w->les = les;
    char set_n[64], set_nu[64], set_wall[64], set_les[64];
    snprintf(set_n, sizeof set_n, "numerics.resolution=%d", RESOLUTION);
    snprintf(set_nu, sizeof set_nu, "fluid.viscosity=%.17g", nu);
    snprintf(set_wall, sizeof set_wall, "model.wall=%s", wall);
    snprintf(set_les, sizeof set_les, "model.les=%s", les);
    /* sloshing.h's free sloshing (the tank of LENGTH x DEPTH, one period of sway at the linear
       period 2 pi / frequency()), at RESOLUTION and longer */
    const char *sets[] = {set_n, "case.t_end=7.5", set_nu, set_wall, set_les};
    char dir[64];
    table t;
    run_case_text(free_sloshing_case, sets, 5, dir, &t);
    find_peaks(&t, w);
    table_free(&t);
    printf("nu = %g m^2/s, %s, LES %s: gamma = %.5f +- %.5f 1/s over %d half cycles, "
           "com_x amplitude %.2f to %.2f mm\n",
           nu, wall, les, w->rate, w->rate_error, w->n, 1e3 * w->amplitude[0],
           1e3 * w->amplitude[w->n - 1]);
    return w;
}

/* The exact linear dispersion relation of a wave k over depth H with a free-slip bottom, zero
 * when s = -gamma + i omega: phi = cosh(kz), psi = S sinh(mz) / sinh(mH), m^2 = k^2 + s / nu,
 * (u, w) = (phi_x + psi_z, phi_z - psi_x); the free surface z = H is free of shear stress (which
 * gives S) and of normal stress, with eta from the kinematic condition. */
static double complex dispersion(double complex s, double nu)
{
    double k = wavenumber(), h = DEPTH;
    double complex m = csqrt(k * k + s / nu);
    double complex shear = -2.0 * I * k * k * sinh(k * h) / (m * m + k * k); /* S */
    double complex eta = (k * sinh(k * h) - I * k * shear) / s;
    return s * cosh(k * h) + GRAVITY * eta +
           2.0 * nu * (k * k * cosh(k * h) - I * k * m * shear / ctanh(m * h));
}

/* gamma of the first mode in the free-slip tank, by Newton's method from Lamb's rate. */
static double free_slip_rate(double nu)
{
    double k = wavenumber();
    double complex s = -2.0 * nu * k * k + I * frequency();
    for (int it = 0; it < 40; it++) {
        double complex f = dispersion(s, nu), ds = 1e-7 * cabs(s);
        s -= f * ds / (dispersion(s + ds, nu) - f);
    }
    assert_true(cabs(dispersion(s, nu)) < 1e-9);
    return -creal(s);
}

/* gamma_wall / sqrt(nu) of the Stokes layers on the bottom and the two end walls. */
static double stokes_layer_coefficient(void)
{
    double k = wavenumber(), s2 = sinh(2.0 * k * DEPTH);
    return sqrt(frequency() / 2.0) * (k * LENGTH + s2 - 2.0 * k * DEPTH) / (LENGTH * s2);
}

/* The amplitude decay the Smagorinsky viscosity adds to the potential mode whose com_x swings
 * by com_amplitude about L/2. With phi = A cos(kx) cosh(kz) cos(omega t): S:S = 2 A^2 k^4 f
 * cos^2(omega t), f = cos^2(kx) cosh^2(kz) + sin^2(kx) sinh^2(kz); the mean dissipation
 * <2 rho nu_T S:S> = 8 rho (C_S l)^2 A^3 k^6 (4 / 3 pi) int f^3/2 over the energy
 * rho A^2 k L sinh(2kH) / 8, halved for the amplitude. The surface amplitude a = A omega
 * cosh(kH) / g gives com_x - L/2 = 2 a L / (pi^2 H). */
static double les_rate(double com_amplitude)
{
    const double c_s = 0.18, filter = 4.0 * DEPTH / RESOLUTION; /* paper sec. 2.2: l = 2h */
    double k = wavenumber(), omega = frequency();
    double a = com_amplitude * M_PI * M_PI * DEPTH / (2.0 * LENGTH);
    double phi = GRAVITY * a / (omega * cosh(k * DEPTH));
    enum { NX = 200, NZ = 100 };
    double integral = 0.0;
    for (int i = 0; i < NX; i++)
        for (int j = 0; j < NZ; j++) {
            double x = (i + 0.5) * LENGTH / NX, z = (j + 0.5) * DEPTH / NZ;
            double c = cos(k * x) * cosh(k * z), s = sin(k * x) * sinh(k * z);
            integral += pow(c * c + s * s, 1.5) * LENGTH * DEPTH / (NX * NZ);
        }
    double ls = c_s * filter;
    return 128.0 / (3.0 * M_PI) * ls * ls * phi * pow(k, 5) * integral /
           (LENGTH * sinh(2.0 * k * DEPTH));
}

/* gamma_on - gamma_off from the log ratio of the two runs' amplitudes, peak by peak (the
 * wiggles of the fit common to both cancel); its standard error in *error. */
static double rate_difference(const wave *on, const wave *off, double *error)
{
    assert_int_equal(on->n, off->n);
    double ln_ratio[MAX_PEAKS];
    for (int j = 0; j < on->n; j++) {
        assert_true(fabs(on->t[j] - off->t[j]) < 0.05);
        ln_ratio[j] = log(on->amplitude[j] / off->amplitude[j]);
    }
    return -least_squares_slope(off->t, ln_ratio, on->n, error);
}

/* The mean of a run's peak amplitudes. */
static double mean_amplitude(const wave *w)
{
    double sum = 0.0;
    for (int j = 0; j < w->n; j++) sum += w->amplitude[j];
    return sum / w->n;
}

static void test_free_slip_decay(void **state)
{
    (void)state;
    double k = wavenumber(), numerical = run_wave(NU_NONE, "free-slip", "false")->rate;
    /* measured 6.8e-3 1/s, 14 % of the exact rate at nu = 2.5e-3: the tolerance below is twice
       it, so it must stay that small (2.2 times the measured figure) */
    assert_true(numerical < 0.015);
    const double nus[] = {NU_HIGH, NU_LOW};
    for (int j = 0; j < 2; j++) {
        const wave *w = run_wave(nus[j], "free-slip", "false");
        double exact = free_slip_rate(nus[j]), lamb = 2.0 * nus[j] * k * k;
        printf("free slip, nu = %g: gamma = %.5f 1/s, exact linear %.5f (%+.1f %%), Lamb's "
               "2 nu k^2 %.5f; the scheme's own at nu = %g: %.5f\n",
               nus[j], w->rate, exact, 100.0 * (w->rate / exact - 1.0), lamb, NU_NONE, numerical);
        /* measured: the runs exceed the exact rate by 0.96 (nu = 1e-2) and 0.49 (2.5e-3) times
           the scheme's own dissipation; tolerance twice it */
        assert_close(w->rate, exact, 2.0 * numerical);
    }
}

static void test_no_slip_boundary_layers(void **state)
{
    (void)state;
    const wave *fs_high = run_wave(NU_HIGH, "free-slip", "false");
    const wave *ns_high = run_wave(NU_HIGH, "no-slip", "false");
    const wave *fs_low = run_wave(NU_LOW, "free-slip", "false");
    const wave *ns_low = run_wave(NU_LOW, "no-slip", "false");
    double coefficient = stokes_layer_coefficient(), dr = DEPTH / RESOLUTION;
    assert_true(sqrt(2.0 * NU_LOW / frequency()) > 2.0 * dr); /* the layers are resolved */
    double d_high = ns_high->rate - fs_high->rate, d_low = ns_low->rate - fs_low->rate;
    double e_high = hypot(ns_high->rate_error, fs_high->rate_error);
    double e_low = hypot(ns_low->rate_error, fs_low->rate_error);
    /* d = a sqrt(nu) + b nu at nu and nu / 4 */
    double a = (4.0 * d_low - d_high) / sqrt(NU_HIGH), b = (d_high - a * sqrt(NU_HIGH)) / NU_HIGH;
    double a_error = hypot(4.0 * e_low, e_high) / sqrt(NU_HIGH);
    printf("no slip - free slip: %.5f 1/s at nu = %g (gamma_wall %.5f), %.5f at %g (%.5f)\n",
           d_high, NU_HIGH, coefficient * sqrt(NU_HIGH), d_low, NU_LOW, coefficient * sqrt(NU_LOW));
    printf("sqrt(nu) coefficient %.4f +- %.4f, Stokes layers %.4f (%+.1f %%); O(nu) term %.2f "
           "1/m^2\n",
           a, a_error, coefficient, 100.0 * (a / coefficient - 1.0), b);
    /* measured -0.7 % (+-0.9 %, the fits' error); from the pairs 1e-2, 5e-3 and 5e-3, 2.5e-3
       instead (runs to 10 s), -2.3 % and -0.9 %: the O(nu^3/2) terms left out. 5 % is 2.2
       times the largest */
    assert_close(a, coefficient, 0.05 * coefficient);
}

static void test_les(void **state)
{
    (void)state;
    const wave *off = run_wave(NU_LOW, "free-slip", "false");
    const wave *on = run_wave(NU_LOW, "free-slip", "true");
    double error, extra = rate_difference(on, off, &error);
    double estimate = les_rate(mean_amplitude(off));
    printf("LES at nu = %g: gamma %.5f against %.5f without (%+.2f %%); it adds %.6f +- %.6f "
           "1/s, the Smagorinsky estimate %.6f (%+.1f %%)\n",
           NU_LOW, on->rate, off->rate, 100.0 * (on->rate / off->rate - 1.0), extra, error,
           estimate, 100.0 * (extra / estimate - 1.0));
    /* measured -2.6 % (+-1.4 %, the fit's error): the SPH strain rate and the pairs' harmonic
       mean of nu_T against the exact flow's. Tolerance 7.5 %, 2.9 times it */
    assert_close(extra, estimate, 0.075 * estimate);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_free_slip_decay),
        cmocka_unit_test(test_no_slip_boundary_layers),
        cmocka_unit_test(test_les),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
