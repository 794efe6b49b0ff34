/* eta_control: the paper's eta switch and vcsph's adaptive control (eta_control.h). */
#include "scheme/eta_control.h"
#include "scheme/models.h"

#include <math.h>
#include <stdio.h>

void eta_control_init(eta_controller *c, const config *cfg, double response_period)
{
    *c = (eta_controller){0};
    c->switching = cfg->scheme == SCHEME_DELTA_PLUS_ALE;
    c->kind = cfg->eta_control;
    c->threshold = cfg->eta_threshold;
    c->period = response_period;
    /* Table 1: delta-ALE has variable masses; delta-plus-ALE starts as delta-plus (5.1.1) */
    c->eta = models_params(cfg->scheme).eta == 1 ? 1.0 : 0.0;
    c->eta0_regime = c->eta == 0.0;
    c->eps_mean = c->eps_expected = NAN;
}

/* The paper's rule (theory §8): eta = 1 above +threshold, eta = 0 below -threshold. */
static int threshold_update(eta_controller *c, double eps_v1, char *detail, size_t detail_len)
{
    double eta = c->eta;
    if (eps_v1 > c->threshold)
        eta = 1.0;
    else if (eps_v1 < -c->threshold)
        eta = 0.0;
    if (eta == c->eta) return 0;
    snprintf(detail, detail_len, "eta %g -> %g at eps_v1 = %.4g (threshold %g)", c->eta, eta,
             eps_v1, c->threshold);
    c->eta = eta;
    c->eta0_regime = eta == 0.0;
    return 1;
}

static double sample_spacing(const eta_controller *c) { return c->period / ETA_SAMPLES_PER_PERIOD; }

/* Adds eps_V1 at time t to the running integral (trapezoids) and stores the integral at every
 * sample time passed since the last call, interpolating eps_V1 linearly in between. */
static void integrate(eta_controller *c, double t, double eps_v1)
{
    if (c->n_samples == 0) { /* the integral starts at the first call, t = 0 */
        c->t_last = t;
        c->eps_last = eps_v1;
        c->samples[0] = 0.0;
        c->n_samples = 1;
        return;
    }
    double span = t - c->t_last;
    if (span <= 0.0) return;
    double spacing = sample_spacing(c);
    for (double tk; (tk = (double)c->n_samples * spacing) <= t; c->n_samples++) {
        double ek = c->eps_last + (eps_v1 - c->eps_last) * (tk - c->t_last) / span;
        c->samples[c->n_samples % ETA_HISTORY] =
            c->integral + 0.5 * (c->eps_last + ek) * (tk - c->t_last);
    }
    c->integral += 0.5 * (c->eps_last + eps_v1) * span;
    c->t_last = t;
    c->eps_last = eps_v1;
}

/* The integral at a past time tq within the last 2 T_f, linear between samples (the
 * integral is smooth: its curvature is d eps/dt, an error of spacing^2/8 |d eps/dt|). */
static double integral_at(const eta_controller *c, double tq)
{
    double position = tq / sample_spacing(c);
    long k = (long)floor(position);
    if (k < c->n_samples - ETA_HISTORY) k = c->n_samples - ETA_HISTORY; /* rounding guard */
    if (k > c->n_samples - 2) k = c->n_samples - 2;
    double a = c->samples[k % ETA_HISTORY], b = c->samples[(k + 1) % ETA_HISTORY];
    return a + (b - a) * (position - (double)k);
}

static double clamp01(double x) { return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x; }

static int adaptive_update(eta_controller *c, double t, double eps_v1, char *detail,
                           size_t detail_len)
{
    integrate(c, t, eps_v1);
    double T = c->period;
    if (t < 2.0 * T) return 0; /* keep the initial regime until the average has its history */
    /* averages over [t - T, t] and [t - 2T, t - T]; a drift eps = a + r t averages to
     * a + r (t - T/2), so adding half the change over one period gives back a + r t */
    double i1 = integral_at(c, t - T), i2 = integral_at(c, t - 2.0 * T);
    double mean = (c->integral - i1) / T, mean_before = (i1 - i2) / T;
    double expected = mean + 0.5 * (mean - mean_before);
    c->eps_mean = mean;
    c->eps_expected = expected;

    double band = 0.5 * c->threshold;
    bool eta0_regime = c->eta0_regime ? expected < 0.0 : expected < -band;
    c->eta = eta0_regime ? 0.0 : clamp01(expected / band);
    if (eta0_regime == c->eta0_regime) return 0;
    snprintf(detail, detail_len,
             "eta = 0 regime %s: eps_v1 = %.4g, mean over %.4g s %.4g, expected %.4g "
             "(threshold %g)",
             eta0_regime ? "begins" : "ends", eps_v1, T, mean, expected, c->threshold);
    c->eta0_regime = eta0_regime;
    return 1;
}

int eta_control_update(eta_controller *c, double t, double eps_v1, char *detail, size_t detail_len)
{
    if (!c->switching) return 0;
    int switched = c->kind == ETA_CONTROL_ADAPTIVE
                       ? adaptive_update(c, t, eps_v1, detail, detail_len)
                       : threshold_update(c, eps_v1, detail, detail_len);
    c->switches += switched;
    return switched;
}
