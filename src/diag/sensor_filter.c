/* sensor_filter: first-order and second-order Butterworth low-passes, solved exactly over a
 * piecewise-linear input. */
#include "diag/sensor_filter.h"

#include <math.h>

sensor_filter sensor_filter_make(probes_filter_kind kind, double cutoff_hz)
{
    sensor_filter f = {kind, 2.0 * M_PI * cutoff_hz};
    return f;
}

/* 1 - (1 - exp(-a)) / a, the part of an input's rise over a step that a first-order filter
 * of a = w dt has not yet followed at the step's end; its series where the difference would
 * cancel. */
static double ramp_lag_fraction(double a)
{
    if (a < 1e-3) return a * (0.5 - a * (1.0 / 6.0 - a / 24.0));
    return 1.0 + expm1(-a) / a;
}

/* y' = w (u - y) over dt with u rising linearly from u0 to u1:
 * y1 = E y0 + (1 - E) u0 + (u1 - u0) (1 - (1 - E) / a), E = exp(-a), a = w dt. */
static void first_order_step(double omega, sensor_state *s, double dt, double u1)
{
    double a = omega * dt, decay = exp(-a);
    s->y = decay * s->y - expm1(-a) * s->u + (u1 - s->u) * ramp_lag_fraction(a);
}

/* y'' + sqrt(2) w y' + w^2 y = w^2 u over dt with u = u0 + k t. A ramp is followed at a lag
 * sqrt(2) / w, y_p = u - k sqrt(2) / w and y_p' = k; the rest, e = (y - y_p, y' - y_p'), is
 * the free response exp(A dt) e of the poles w (-1 +- i) / sqrt(2):
 * exp(A t) = exp(-w_d t) [cos(w_d t) I + sin(w_d t) / w_d (A + w_d I)], w_d = w / sqrt(2). */
static void butterworth2_step(double omega, sensor_state *s, double dt, double u1)
{
    double wd = omega * M_SQRT1_2, lag = M_SQRT2 / omega;
    double slope = (u1 - s->u) / dt;
    double ey = s->y - (s->u - slope * lag), ev = s->rate - slope;
    double decay = exp(-wd * dt), c = cos(wd * dt), sn = sin(wd * dt);
    double ey1 = decay * ((c + sn) * ey + sn * ev / wd);
    double ev1 = decay * ((c - sn) * ev - M_SQRT2 * omega * sn * ey);
    s->y = u1 - slope * lag + ey1;
    s->rate = slope + ev1;
}

double sensor_filter_sample(const sensor_filter *f, sensor_state *s, double t, double u)
{
    if (f->kind == PROBES_RAW) return u;
    if (!s->started) {
        *s = (sensor_state){.y = u, .rate = 0.0, .u = u, .t = t, .started = true};
        return u;
    }
    double dt = t - s->t;
    if (dt > 0.0) {
        if (f->kind == PROBES_FIRST_ORDER)
            first_order_step(f->omega, s, dt, u);
        else
            butterworth2_step(f->omega, s, dt, u);
    }
    s->u = u;
    s->t = t;
    return s->y;
}

void sensor_state_pack(const sensor_state *s, double out[SENSOR_STATE_VALUES])
{
    out[0] = s->y;
    out[1] = s->rate;
    out[2] = s->u;
    out[3] = s->t;
    out[4] = s->started ? 1.0 : 0.0;
}

void sensor_state_unpack(sensor_state *s, const double in[SENSOR_STATE_VALUES])
{
    *s = (sensor_state){in[0], in[1], in[2], in[3], in[4] != 0.0};
}
