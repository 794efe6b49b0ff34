/* The eta controls of delta-plus-ALE-SPH (eta_control.h) on synthetic eps_V1 signals: the
 * paper's threshold switch, and the adaptive control's average, its lag correction, its two
 * regimes and its immunity to the oscillation within a period. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "check.h"
#include "scheme/eta_control.h"

#include <math.h>
#include <stdbool.h>

#define T         0.5  /* response period of these tests (s) */
#define THRESHOLD 0.01 /* model.eta_threshold */

static eta_controller make(scheme_kind scheme, eta_control_kind kind)
{
    config cfg = {0};
    cfg.scheme = scheme;
    cfg.eta_control = kind;
    cfg.eta_threshold = THRESHOLD;
    eta_controller c;
    eta_control_init(&c, &cfg, T);
    return c;
}

/* Steps of uneven size, like a run's: T/200 to T/100. */
static double next_step(long k) { return T / 200.0 * (1.0 + 0.5 * (1.0 + sin(0.7 * k))); }

/* Feeds eps(t) from t0 to t1 in uneven steps; returns the number of regime changes. */
static long feed(eta_controller *c, double *t, double t1, double (*eps)(double))
{
    char detail[200];
    long switches = 0, k = 0;
    for (; *t < t1; *t += next_step(k++))
        switches += eta_control_update(c, *t, eps(*t), detail, sizeof detail);
    return switches;
}

static double eps_level;
static double constant(double t)
{
    (void)t;
    return eps_level;
}

/* A drift a + r t under an oscillation of amplitude 5e-3 at the response period. */
#define DRIFT_A     2.0e-3
#define DRIFT_R     4.0e-3
#define OSCILLATION 5.0e-3
static double drifting(double t)
{
    return DRIFT_A + DRIFT_R * t + OSCILLATION * sin(2.0 * M_PI * t / T + 0.3);
}

/* The average over one period removes the oscillation, and half its change over the period
 * before puts back the lag T/2 of the drift: eps_mean = a + r (t - T/2), eps_expected = a + r t.
 * Error bound: trapezoids on steps <= T/100 leave (w dt)^2 / 12 of the amplitude, 3.3e-4 of
 * it, and the linear interpolation of the integral between its samples T/64 apart leaves at
 * most 2 (T/64)^2 / 8 w A / T = 2 pi / 16384 of it, 3.8e-4; 1e-3 of the amplitude covers both.
 * eps_expected = 1.5 mean - 0.5 mean_before: twice that. */
#define MEAN_ERROR 1e-3 /* of the oscillation's amplitude */
static void test_average_removes_oscillation_and_lag(void **state)
{
    (void)state;
    eta_controller c = make(SCHEME_DELTA_PLUS_ALE, ETA_CONTROL_ADAPTIVE);
    double t = 0.0;
    feed(&c, &t, 7.3 * T, drifting);
    double t_last = c.t_last;
    assert_close(c.eps_mean, DRIFT_A + DRIFT_R * (t_last - 0.5 * T), MEAN_ERROR * OSCILLATION);
    assert_close(c.eps_expected, DRIFT_A + DRIFT_R * t_last, 2.0 * MEAN_ERROR * OSCILLATION);
}

/* The initial eta = 0 regime holds for 2 T whatever eps_V1, then a constant excess of a
 * quarter threshold (whose average is exact) ends it with eta = eps / (threshold / 2) = 1/2. */
static void test_initial_regime(void **state)
{
    (void)state;
    eta_controller c = make(SCHEME_DELTA_PLUS_ALE, ETA_CONTROL_ADAPTIVE);
    assert_true(c.eta0_regime);
    double t = 0.0;
    eps_level = 0.25 * THRESHOLD;
    assert_int_equal(feed(&c, &t, 1.99 * T, constant), 0); /* no history yet */
    assert_true(c.eta0_regime);
    assert_true(c.eta == 0.0);
    assert_int_equal(feed(&c, &t, 4.0 * T, constant), 1);
    assert_false(c.eta0_regime);
    assert_close(c.eta, 0.5, 1e-12);
}

/* A slow wave of 0.9 threshold (period 16 T) under an oscillation at the response period:
 * at every update the regime follows the rule on eps_expected (the eta = 0 regime begins
 * below -threshold / 2 and ends at 0: hysteresis), and eta = clamp(eps_expected / b, 0, 1)
 * outside it. Over 3 slow periods: the initial end, then one beginning and one end each. */
static double slow_wave(double t)
{
    return 0.9 * THRESHOLD * sin(2.0 * M_PI * t / (16.0 * T)) +
           0.5 * THRESHOLD * sin(2.0 * M_PI * t / T + 0.3);
}

static void test_regimes_and_hysteresis(void **state)
{
    (void)state;
    eta_controller c = make(SCHEME_DELTA_PLUS_ALE, ETA_CONTROL_ADAPTIVE);
    const double band = 0.5 * THRESHOLD;
    char detail[200];
    long k = 0, begins = 0, ends = 0;
    for (double t = 0.0; t < 50.0 * T; t += next_step(k++)) {
        bool before = c.eta0_regime;
        int changed = eta_control_update(&c, t, slow_wave(t), detail, sizeof detail);
        assert_int_equal(changed, before != c.eta0_regime);
        if (t < 2.0 * T) {
            assert_true(c.eta0_regime);
            continue;
        }
        double e = c.eps_expected;
        if (before)
            assert_true(c.eta0_regime == (e < 0.0));
        else
            assert_true(c.eta0_regime == (e < -band));
        double eta = c.eta0_regime ? 0.0 : fmin(1.0, fmax(0.0, e / band));
        assert_close(c.eta, eta, 0.0);
        begins += changed && c.eta0_regime;
        ends += changed && !c.eta0_regime;
    }
    assert_int_equal(ends, 4);
    assert_int_equal(begins, 3);
    assert_int_equal(c.switches, 7);
}

/* An oscillation of three thresholds around +threshold / 5: the paper's switch flips twice a
 * period; the adaptive control sees only the mean and changes regime once, when its history
 * is complete, whatever the amplitude. */
static double oscillating(double t)
{
    return 0.2 * THRESHOLD + 3.0 * THRESHOLD * sin(2.0 * M_PI * t / T);
}

static void test_oscillation_does_not_switch(void **state)
{
    (void)state;
    eta_controller paper = make(SCHEME_DELTA_PLUS_ALE, ETA_CONTROL_THRESHOLD);
    eta_controller adaptive = make(SCHEME_DELTA_PLUS_ALE, ETA_CONTROL_ADAPTIVE);
    double t = 0.0;
    long paper_switches = feed(&paper, &t, 20.0 * T, oscillating);
    t = 0.0;
    long adaptive_switches = feed(&adaptive, &t, 20.0 * T, oscillating);
    assert_in_range(paper_switches, 39, 40);
    assert_int_equal(adaptive_switches, 1);
    /* (threshold / 5) / (threshold / 2), within the error of eps_expected over b */
    assert_close(adaptive.eta, 0.4, 2.0 * MEAN_ERROR * 3.0 * THRESHOLD / (0.5 * THRESHOLD));
}

/* The paper's rule: eta = 1 above +threshold, 0 below -threshold, unchanged in between. */
static void test_threshold_rule(void **state)
{
    (void)state;
    eta_controller c = make(SCHEME_DELTA_PLUS_ALE, ETA_CONTROL_THRESHOLD);
    char d[200];
    assert_true(c.eta == 0.0 && c.eta0_regime);
    assert_int_equal(eta_control_update(&c, 0.0, 0.9 * THRESHOLD, d, sizeof d), 0);
    assert_int_equal(eta_control_update(&c, 0.1, 1.1 * THRESHOLD, d, sizeof d), 1);
    assert_true(c.eta == 1.0 && !c.eta0_regime);
    assert_int_equal(eta_control_update(&c, 0.2, -0.9 * THRESHOLD, d, sizeof d), 0);
    assert_int_equal(eta_control_update(&c, 0.3, -1.1 * THRESHOLD, d, sizeof d), 1);
    assert_true(c.eta == 0.0 && c.eta0_regime);
    assert_string_equal(d, "eta 1 -> 0 at eps_v1 = -0.011 (threshold 0.01)");
}

/* The other schemes keep Table 1's eta whatever the volume does. */
static void test_fixed_schemes(void **state)
{
    (void)state;
    eta_controller ale = make(SCHEME_DELTA_ALE, ETA_CONTROL_ADAPTIVE);
    eta_controller plus = make(SCHEME_DELTA_PLUS, ETA_CONTROL_THRESHOLD);
    double t = 0.0;
    eps_level = -5.0 * THRESHOLD;
    assert_int_equal(feed(&ale, &t, 5.0 * T, constant), 0);
    t = 0.0;
    eps_level = 5.0 * THRESHOLD;
    assert_int_equal(feed(&plus, &t, 5.0 * T, constant), 0);
    assert_true(ale.eta == 1.0 && !ale.eta0_regime);
    assert_true(plus.eta == 0.0 && plus.eta0_regime);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_average_removes_oscillation_and_lag),
        cmocka_unit_test(test_initial_regime),
        cmocka_unit_test(test_regimes_and_hysteresis),
        cmocka_unit_test(test_oscillation_does_not_switch),
        cmocka_unit_test(test_threshold_rule),
        cmocka_unit_test(test_fixed_schemes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
