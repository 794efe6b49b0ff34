/* eta_control: the eta of Eq. (3) over a run of delta-plus-ALE-SPH, driven by the measured
 * volume error eps_V1 (theory §8). Two controls (model.eta_control):
 *
 * threshold (the paper's switch, sec. 5.1.1): eta = 1 when eps_V1 > +threshold, eta = 0 when
 *   eps_V1 < -threshold. The two regimes drift with opposite signs (docs/validation.md).
 *
 * adaptive (vcsph's own, docs/choices.md): acts on eps_V1 averaged over the response period
 *   T_f of the flow, which removes the oscillation within a period that forces the paper to
 *   use a wide threshold, and extrapolated by half a period along its own slope, which undoes
 *   the lag of that average. With e the extrapolated value and b = threshold / 2:
 *     - the eta = 0 regime (constant masses; EdBC acts there with edbc = with-eta0) begins
 *       when e < -b and ends when e >= 0;
 *     - outside it, eta = clamp(e / b, 0, 1): the variable-mass correction of delta-ALE
 *       in proportion to the excess volume, so it fades out as the error returns to 0
 *       instead of carrying it across to -threshold.
 *   Until the average has 2 T_f of history the control keeps its initial regime.
 *
 * The control only sees the time series of eps_V1: no particles, no dimension. */
#ifndef VCSPH_ETA_CONTROL_H
#define VCSPH_ETA_CONTROL_H

#include "core/config.h"

#include <stdbool.h>
#include <stddef.h>

#define ETA_SAMPLES_PER_PERIOD 64 /* samples of the running integral of eps_V1 per T_f */
#define ETA_HISTORY            (2 * ETA_SAMPLES_PER_PERIOD + 2)

typedef struct {
    bool switching;        /* false: eta fixed by the scheme (Table 1) */
    eta_control_kind kind; /* model.eta_control */
    double threshold;      /* model.eta_threshold */
    double period;         /* T_f, the averaging period of the adaptive control (s) */
    double eta;            /* eta of Eq. (3), in [0, 1] */
    bool eta0_regime;      /* the regime of constant masses, where with-eta0 applies EdBC */
    long switches;         /* changes of regime so far */
    /* adaptive: the integral of eps_V1 since t = 0 (trapezoids), sampled every T_f / 64 */
    double t_last, eps_last, integral;
    long n_samples;                /* sample k is the integral at t = k T_f / 64 */
    double samples[ETA_HISTORY];   /* sample k at [k % ETA_HISTORY] */
    double eps_mean, eps_expected; /* the last average and extrapolation (NAN before 2 T_f) */
} eta_controller;

/* A control for `scheme`: switching for delta-plus-ALE, which starts at eta = 0 (sec. 5.1.1);
 * otherwise eta is Table 1's, fixed. response_period is T_f (derived_response_period). */
void eta_control_init(eta_controller *c, const config *cfg, double response_period);

/* Takes eps_V1 of the state at time t (called once per step, from t = 0, t increasing) and
 * sets eta for the step from t. Returns 1 when the regime changed, with a description in
 * `detail`. */
int eta_control_update(eta_controller *c, double t, double eps_v1, char *detail, size_t detail_len);

#endif
