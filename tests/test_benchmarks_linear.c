/* The benchmark cases cases/roll.ini, cases/inm1.ini and cases/upm.ini, loaded from the source
 * tree and shortened with --set overrides, against linear references at N = 16 (one thread).
 * Tolerances are measured error x margin; each check states both. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "check.h"
#include "table.h"
#include "run_case.h"
#include "linear_sloshing.h"
#include "slope.h"

#define PI 3.14159265358979323846

/* ---- the runs ------------------------------------------------------------------------------ */

/* cases/NAME.ini with the overrides, plus N = 16 and no snapshots, images or checkpoints; the
 * time series of the probes into probes */
enum { MAX_SET = 8 };
static void run_benchmark(const char *name, const char *const *set, int n_set, config *cfg,
                          table *probes)
{
    const char *all[MAX_SET + 4] = {"numerics.resolution=16", "output.snapshot_every=0",
                                    "output.image_every=0", "output.checkpoint_every=0"};
    assert_true(n_set <= MAX_SET);
    for (int k = 0; k < n_set; k++) all[4 + k] = set[k];
    run_case_load_file(name, all, 4 + n_set, cfg);
    char dir[64], path[128];
    table series;
    run_case_config(cfg, dir, &series);
    table_free(&series);
    snprintf(path, sizeof path, "%s/probes.csv", dir);
    assert_int_equal(table_read(probes, path), 0);
}

/* the linear reference of a sway or roll case (docs/roll.md): motion.center's y is the axis's
 * height above the bottom */
static linear_tank linear_of(const config *cfg)
{
    linear_tank m = {.L = cfg->tank_length,
                     .h = cfg->liquid_height,
                     .g = cfg->gravity,
                     .omega = 2.0 * PI / cfg->period,
                     .phase = cfg->phase};
    if (cfg->motion == MOTION_SWAY) m.sway = cfg->amplitude;
    if (cfg->motion == MOTION_ROLL) {
        m.angle = cfg->angle;
        m.phase += cfg->angle_phase;
        m.z_r = cfg->motion_center[1] - cfg->liquid_height;
    }
    return m;
}

/* The first time the linear elevation at x reaches `level` in magnitude (sampled every ms). */
static double linear_reaches(const linear_tank *m, double x, double level)
{
    for (double t = 0.0; t < 100.0; t += 1e-3)
        if (fabs(linear_tank_elevation(m, x, t)) >= level) return t;
    fail_msg("the linear elevation never reaches %g m", level);
    return 0.0;
}

/* ---- comparing a gauge with the linear elevation ------------------------------------------ */

typedef struct {
    double rms;                      /* RMS of (gauge - linear) / the largest |linear| */
    double amplitude;                /* the largest |linear| (m) */
    double t_first[2], eta_first[2]; /* the first extremum: the gauge's, the linear one's */
} gauge_comparison;

/* The first local extremum of v[0..n) whose size is at least `floor`, its time and value from
 * the parabola through it and its neighbours; NAN if there is none. */
static double first_extremum(const double *t, const double *v, size_t n, double floor,
                             double *value)
{
    for (size_t k = 1; k + 1 < n; k++) {
        double a = v[k - 1], b = v[k], c = v[k + 1];
        if ((b - a) * (c - b) > 0.0 || fabs(b) < floor || a - 2.0 * b + c == 0.0) continue;
        double s = parabola_vertex(a, b, c, value);
        return t[k] + s * (t[k + 1] - t[k]);
    }
    *value = NAN;
    return NAN;
}

/* The elevation of gauge `g` (column gauge_<g + 1>, less its value at t = 0) over the rows with
 * t <= t_hi against the linear elevation at x; with `extremum`, their first extrema too. */
static gauge_comparison compare_gauge(const table *probes, int g, double x, const linear_tank *m,
                                      double t_hi, bool extremum)
{
    char name[16];
    snprintf(name, sizeof name, "gauge_%d", g + 1);
    const double *t = table_column(probes, "t"), *gauge = table_column(probes, name);
    assert_non_null(gauge);
    static double eta[2][8192];
    size_t n = 0;
    while (n < probes->n_rows && t[n] <= t_hi + 1e-9) n++;
    assert_true(n > 10 && n <= 8192 && t[n - 1] >= t_hi - 0.02);
    gauge_comparison c = {0.0, 0.0, {NAN, NAN}, {NAN, NAN}};
    for (size_t k = 0; k < n; k++) {
        eta[0][k] = gauge[k] - gauge[0];
        eta[1][k] = linear_tank_elevation(m, x, t[k]);
        c.rms += (eta[0][k] - eta[1][k]) * (eta[0][k] - eta[1][k]);
        c.amplitude = fmax(c.amplitude, fabs(eta[1][k]));
    }
    c.rms = sqrt(c.rms / (double)n) / c.amplitude;
    print_message("gauge at x = %.3g m, t <= %.3g s: RMS difference %.2f %% of the linear "
                  "amplitude %.4g m\n",
                  x, t[n - 1], 100.0 * c.rms, c.amplitude);
    if (!extremum) return c;
    for (int s = 0; s < 2; s++)
        c.t_first[s] = first_extremum(t, eta[s], n, 0.2 * c.amplitude, &c.eta_first[s]);
    print_message("first extremum %.4g m at %.4g s, linear %.4g m at %.4g s\n", c.eta_first[0],
                  c.t_first[0], c.eta_first[1], c.t_first[1]);
    return c;
}

/* The shipped case `name` until the linear elevation at its gauge 1 reaches H/8: the RMS
 * difference from linear theory at most `allowed` (of the linear amplitude). */
static void first_rise_within(const char *name, double allowed)
{
    config cfg;
    run_case_load_file(name, NULL, 0, &cfg); /* as shipped */
    linear_tank m = linear_of(&cfg);
    const double x = cfg.gauges[0], t_hi = linear_reaches(&m, x, cfg.liquid_height / 8.0);
    char t_end[64];
    snprintf(t_end, sizeof t_end, "case.t_end=%.17g", t_hi);
    const char *set[] = {t_end};
    table probes;
    run_benchmark(name, set, 1, &cfg, &probes);
    gauge_comparison c = compare_gauge(&probes, 0, x, &m, t_hi, false);
    assert_true(c.rms <= allowed);
    table_free(&probes);
}

/* The shipped case `name` with `scaled` (a motion key) set to the case's value over `divisor`,
 * over `periods` forcing periods: the RMS difference from linear theory at gauge 1 at most
 * `rms_allowed`, its first extremum within `time_allowed` (s) of linear theory's. */
static void linear_regime_within(const char *name, const char *scaled, double divisor,
                                 double periods, double rms_allowed, double time_allowed)
{
    config cfg;
    run_case_load_file(name, NULL, 0, &cfg); /* as shipped */
    double value = !strcmp(scaled, "angle") ? cfg.angle : cfg.amplitude;
    char motion[64], t_end[64];
    snprintf(motion, sizeof motion, "motion.%s=%.17g", scaled, value / divisor);
    snprintf(t_end, sizeof t_end, "case.t_end=%.17g", periods * cfg.period);
    const char *set[] = {motion, t_end};
    table probes;
    run_benchmark(name, set, 2, &cfg, &probes);
    linear_tank m = linear_of(&cfg);
    gauge_comparison c = compare_gauge(&probes, 0, cfg.gauges[0], &m, periods * cfg.period, true);
    assert_true(c.rms <= rms_allowed);
    assert_close(c.t_first[0], c.t_first[1], time_allowed);
    table_free(&probes);
}

/* ---- roll.ini ------------------------------------------------------------------------------ */

/* roll.ini as shipped (4 degrees about the bottom centre at T = 1.919 s, from t = 0 with the
 * sine's phase 0) until the linear elevation at gauge 1 (5 cm from the left wall) reaches h/8:
 * beyond it the wave is not small on this shallow layer (h = 93 mm). Over the first half period
 * the linear elevation there grows to 0.42 h, and by one period to 0.84 h, while the run's
 * first crest comes 55 ms early and its first trough is 40 % shallower; the RMS difference
 * over the first half period, 3.0 % at N = 16, is 3.5 % at N = 20: the wave's nonlinearity,
 * not the resolution (and the bore of docs/roll.md forms in the second period). Linear theory
 * only holds in this first rise. The
 * run starts with the liquid at rest in the tank while the tank turns: the rigid rotation's
 * vorticity this adds is a steady flow tangent to every boundary, which moves no surface to
 * first order. Measured: RMS difference 1.41 % of the linear amplitude (1.76 % at N = 20);
 * allowed: 2 x 1.41 %. */
static void test_roll_first_rise(void **state)
{
    (void)state;
    first_rise_within("roll", 2.0 * 0.0141);
}

/* roll.ini with its angle divided by 8 (0.5 degree) over its first period: the forced response
 * near resonance and the free modes the start excites, with the linear elevation at gauge 1
 * below 0.105 h. On this shallow layer (k h = 0.32) the wave is not quite linear even so:
 * measured, the RMS difference is 2.81 % of the linear amplitude at N = 16, 2.75 % at N = 20
 * and 1.74 % at 0.25 degree, so most of it is the wave's amplitude, not the resolution (in
 * the next half period the crest steepens and comes 100 ms early). The first crest: 10.2 ms
 * before linear theory's. Allowed: 2 x 2.81 % and 2 x 10.2 ms. */
static void test_roll_linear_regime(void **state)
{
    (void)state;
    linear_regime_within("roll", "angle", 8.0, 1.0, 2.0 * 0.0281, 2.0 * 0.0102);
}

/* ---- inm1.ini ------------------------------------------------------------------------------ */

/* inm1.ini as shipped (sway A = 5 cm at T = 1.1 s = 0.87 T1, from rest) until the linear
 * elevation at gauge 1 (5 cm from the left wall) reaches H/8. Linear theory's wall elevation
 * grows to 0.28 H at the first trough (0.54 s), 0.48 H in the first period and H in the
 * second: there the run's first trough is 11 % shallower than linear theory, at N = 16 and 20
 * alike, and 10 times less sway gives 0.6 %: the nonlinearity of the wave, not the solver.
 * Before H/8 (0.30 s), measured: RMS difference 1.75 % of the linear amplitude (1.77 % at
 * N = 20); allowed: 2 x 1.75 %. */
static void test_inm1_first_rise(void **state)
{
    (void)state;
    first_rise_within("inm1", 2.0 * 0.0175);
}

/* inm1.ini with a tenth of its sway (A/L = 0.5 %), where linear theory holds (the linear
 * elevation at gauge 1 stays below 0.08 H), over its first two periods. Measured: RMS
 * difference 2.83 % of the linear amplitude (0.97 % over the first period: the free modes the
 * start excites decay in SPH, by delta-plus-ALE's numerical dissipation); the first trough
 * 3.7 ms before linear theory's. Allowed: 2 x 2.83 % and 2 x 3.7 ms. */
static void test_inm1_linear_regime(void **state)
{
    (void)state;
    linear_regime_within("inm1", "amplitude", 10.0, 2.0, 2.0 * 0.0283, 2.0 * 0.0037);
}

/* ---- upm.ini ------------------------------------------------------------------------------- */

/* upm.ini heaves as y = -A exp(-l t) cos(w t), with the acceleration amplitude
 * A (w^2 + l^2) exp(-l t), 9.7 g at t = 0. Once it is below g the liquid stays on the bottom,
 * flat and at rest in the tank, and the pressure at the bottom centre is the weight of the
 * column in the accelerating frame, rho H (g + y''(t)) (a force balance on the column: exact
 * for the weakly compressible liquid too, as long as the acoustic period 4 H / c0 = 3 ms is
 * short against T = 154 ms). The run starts from there: the shipped motion from the first
 * zero of y'' after the acceleration amplitude has fallen below 0.8 g (so that the bottom
 * pressure stays above 0.2 rho g H), t0 = 2.65 s (0.69 g), i.e. amplitude A exp(-l t0) and
 * phase w t0, with the liquid at rest and hydrostatic. (The shipped run reaches t0 with waves
 * left from its violent start; the reference is for the calm liquid.) Starting where y'' = 0,
 * the liquid's hydrostatic start is already the reference's state. Two periods. Measured: the
 * probe's RMS difference from rho H (g + y'') 2.29 Pa, at most 3.48 Pa, against its
 * oscillation of amplitude 202.5 Pa about rho g H = 294.3 Pa; allowed 2 x 2.29 Pa. The gauge
 * on the centre line moved by at most 1.84e-6 m, which is the column's elastic compression
 * H^2 A w^2 / (2 c0^2) = 1.9e-6 m; allowed 2 x 1.84e-6 m: the liquid stays on the bottom. */
static void test_upm_bottom_pressure(void **state)
{
    (void)state;
    config cfg;
    run_case_load_file("upm", NULL, 0, &cfg); /* as shipped */
    const double w = 2.0 * PI / cfg.period, l = cfg.decay, g = cfg.gravity;
    const double acc0 = cfg.amplitude * (w * w + l * l);
    assert_true(l > 0.0 && acc0 > g);
    const double t_g = log(acc0 / (0.8 * g)) / l, phase = atan2(w * w - l * l, 2.0 * l * w);
    const double t0 = (phase + 2.0 * PI * ceil((w * t_g - phase) / (2.0 * PI))) / w;
    const double a = cfg.amplitude * exp(-l * t0), rho_h = cfg.density * cfg.liquid_height;
    char amplitude[64], phase_set[64], t_end[64];
    snprintf(amplitude, sizeof amplitude, "motion.amplitude=%.17g", a);
    snprintf(phase_set, sizeof phase_set, "motion.phase=%.17g", phase);
    snprintf(t_end, sizeof t_end, "case.t_end=%.17g", 2.0 * cfg.period);
    const char *set[] = {amplitude, phase_set, t_end};
    table probes;
    run_benchmark("upm", set, 3, &cfg, &probes);
    /* pressure probe 1 at the bottom centre, gauge 1 on the centre line */
    assert_true(cfg.pressure_probes[0][1] == 0.0);
    const double *t = table_column(&probes, "t"), *p = table_column(&probes, "pressure_1");
    const double *gauge = table_column(&probes, "gauge_1");
    double rms = 0.0, most = 0.0, lift = 0.0;
    for (size_t k = 0; k < probes.n_rows; k++) {
        double e = a * exp(-l * t[k]), th = w * t[k] + phase;
        double y2 = e * ((w * w - l * l) * cos(th) - 2.0 * l * w * sin(th));
        double err = p[k] - rho_h * (g + y2);
        rms += err * err;
        most = fmax(most, fabs(err));
        lift = fmax(lift, fabs(gauge[k] - gauge[0]));
    }
    rms = sqrt(rms / (double)probes.n_rows);
    const double swing = rho_h * a * (w * w + l * l); /* the pressure's amplitude at t0 */
    print_message("t0 = %.4g s, acceleration %.3g g: bottom pressure - rho H (g + y'') RMS "
                  "%.3g Pa, at most %.3g Pa (amplitude %.4g Pa, rho g H %.4g Pa); the surface "
                  "moved by at most %.3g m\n",
                  t0, a * (w * w + l * l) / g, rms, most, swing, rho_h * g, lift);
    assert_true(rms <= 2.0 * 2.29);
    assert_true(lift <= 2.0 * 1.84e-6);
    table_free(&probes);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_roll_first_rise),     cmocka_unit_test(test_roll_linear_regime),
        cmocka_unit_test(test_inm1_first_rise),     cmocka_unit_test(test_inm1_linear_regime),
        cmocka_unit_test(test_upm_bottom_pressure),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
