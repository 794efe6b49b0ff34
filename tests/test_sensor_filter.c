/* The sensor's low-pass (diag/sensor_filter.c) against the analytic responses of its ODEs:
 * - a unit step: first order 1 - exp(-w t); Butterworth of order 2
 *   1 - exp(-w_d t) (cos w_d t + sin w_d t), w_d = w / sqrt(2);
 * - a unit ramp from rest: first order t - (1 - exp(-w t)) / w; Butterworth
 *   t - 1 / w_d + exp(-w_d t) cos(w_d t) / w_d;
 * both exact for any spacing of the samples (the filter solves its ODE over the straight line
 * between samples, and these inputs are such lines), so they are checked at uneven times to
 * round-off (1e-12 of the signal);
 * - a sine of frequency f: the gain |H| = 1 / sqrt(1 + (f / f_c)^2) (first order) and
 *   1 / sqrt(1 + (f / f_c)^4) (Butterworth), 1 / sqrt(2) at f_c, sampled 200 times a period:
 *   the straight lines between samples then differ from the sine by at most
 *   (2 pi / 200)^2 / 8 = 1.2e-4 of its amplitude, and the gain is checked to 5e-4;
 * - a checkpoint: a filter packed, unpacked and fed on gives the same bits as one fed through. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "diag/sensor_filter.h"

#include <math.h>
#include <stdio.h>

#define CUTOFF 100.0 /* Hz */

/* uneven times: steps of 0.3 to 1.7 ms, in a fixed sequence */
static double next_time(double t, int k)
{
    return t + 1e-3 * (0.3 + 1.4 * fmod(k * 0.618034, 1.0));
}

static double step_response(probes_filter_kind kind, double omega, double t)
{
    if (kind == PROBES_FIRST_ORDER) return -expm1(-omega * t);
    double wd = omega * M_SQRT1_2;
    return 1.0 - exp(-wd * t) * (cos(wd * t) + sin(wd * t));
}

static double ramp_response(probes_filter_kind kind, double omega, double t)
{
    if (kind == PROBES_FIRST_ORDER) return t + expm1(-omega * t) / omega;
    double wd = omega * M_SQRT1_2;
    return t - 1.0 / wd + exp(-wd * t) * cos(wd * t) / wd;
}

static void check_step_and_ramp(probes_filter_kind kind)
{
    sensor_filter f = sensor_filter_make(kind, CUTOFF);
    /* a step: the input 1 from t = 0 on, the sensor at rest at 0 */
    sensor_state s = {.y = 0.0, .rate = 0.0, .u = 1.0, .t = 0.0, .started = true};
    double t = 0.0, worst = 0.0;
    for (int k = 1; k <= 60; k++) {
        t = next_time(t, k);
        double y = sensor_filter_sample(&f, &s, t, 1.0);
        worst = fmax(worst, fabs(y - step_response(kind, f.omega, t)));
    }
    printf("%s step: largest error %.3e over %.1f ms\n",
           kind == PROBES_FIRST_ORDER ? "first order" : "Butterworth", worst, 1e3 * t);
    assert_true(worst < 1e-12);
    /* a ramp u = t from rest: the first sample starts the sensor at rest at 0 */
    sensor_state r = {0};
    assert_true(sensor_filter_sample(&f, &r, 0.0, 0.0) == 0.0);
    t = 0.0;
    worst = 0.0;
    for (int k = 1; k <= 60; k++) {
        t = next_time(t, k);
        double y = sensor_filter_sample(&f, &r, t, t);
        worst = fmax(worst, fabs(y - ramp_response(kind, f.omega, t)) / t);
    }
    printf("  ramp: largest error %.3e of the input\n", worst);
    assert_true(worst < 1e-12);
}

static void test_first_order_exact(void **state)
{
    (void)state;
    check_step_and_ramp(PROBES_FIRST_ORDER);
}

static void test_butterworth_exact(void **state)
{
    (void)state;
    check_step_and_ramp(PROBES_BUTTERWORTH);
}

/* The amplitude of the filtered sine of frequency f over its last two of 40 periods. */
static double gain(probes_filter_kind kind, double f)
{
    sensor_filter filter = sensor_filter_make(kind, CUTOFF);
    sensor_state s = {0};
    const int per_period = 200, periods = 40;
    double amplitude = 0.0;
    for (int k = 0; k <= per_period * periods; k++) {
        double t = k / (f * per_period);
        double y = sensor_filter_sample(&filter, &s, t, sin(2.0 * M_PI * f * t));
        if (k >= per_period * (periods - 2)) amplitude = fmax(amplitude, fabs(y));
    }
    return amplitude;
}

static void test_gain(void **state)
{
    (void)state;
    const double ratios[] = {0.5, 1.0, 2.0, 4.0};
    for (size_t k = 0; k < sizeof ratios / sizeof ratios[0]; k++) {
        double x = ratios[k];
        double first = gain(PROBES_FIRST_ORDER, x * CUTOFF),
               butter = gain(PROBES_BUTTERWORTH, x * CUTOFF);
        double first_exact = 1.0 / sqrt(1.0 + x * x),
               butter_exact = 1.0 / sqrt(1.0 + x * x * x * x);
        printf("f / f_c = %.1f: first order %.5f (|H| %.5f), Butterworth %.5f (|H| %.5f)\n", x,
               first, first_exact, butter, butter_exact);
        assert_true(fabs(first - first_exact) < 5e-4);
        assert_true(fabs(butter - butter_exact) < 5e-4);
    }
}

static void test_raw_and_checkpoint(void **state)
{
    (void)state;
    sensor_filter raw = sensor_filter_make(PROBES_RAW, CUTOFF);
    sensor_state s = {0};
    assert_true(sensor_filter_sample(&raw, &s, 0.1, 1234.5) == 1234.5);
    sensor_filter f = sensor_filter_make(PROBES_BUTTERWORTH, CUTOFF);
    sensor_state through = {0}, resumed = {0};
    double t = 0.0, y_through = 0.0, y_resumed = 0.0;
    for (int k = 0; k < 50; k++) {
        t = next_time(t, k);
        double u = sin(300.0 * t) + (k == 20 ? 5.0 : 0.0);
        y_through = sensor_filter_sample(&f, &through, t, u);
        y_resumed = sensor_filter_sample(&f, &resumed, t, u);
        if (k == 25) { /* a checkpoint and a restart */
            double saved[SENSOR_STATE_VALUES];
            sensor_state_pack(&resumed, saved);
            resumed = (sensor_state){0};
            sensor_state_unpack(&resumed, saved);
        }
    }
    assert_true(y_through == y_resumed);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_order_exact),
        cmocka_unit_test(test_butterworth_exact),
        cmocka_unit_test(test_gain),
        cmocka_unit_test(test_raw_and_checkpoint),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
