/* sensor_filter: the bandwidth of a pressure transducer (probes.filter, docs/case-file.md), a
 * low-pass of cut-off frequency f_c applied to the probe's samples as they are written:
 * - first order, H(s) = 1 / (1 + s / w_c): a time constant 1 / w_c;
 * - Butterworth of order 2, H(s) = w_c^2 / (s^2 + sqrt(2) w_c s + w_c^2): flat below f_c,
 *   -12 dB per octave above it;
 * with w_c = 2 pi f_c; both read |H| = 1 / sqrt(2) at f_c. Between two samples the input is
 * taken as the straight line joining them, and the filter's ODE is solved exactly over that
 * line, so the output depends on the samples only (not on the step that brought them) and any
 * spacing of the samples, every step's or a fixed rate's, is filtered alike. Not thread-safe
 * per state; one state per probe. */
#ifndef VCSPH_SENSOR_FILTER_H
#define VCSPH_SENSOR_FILTER_H

#include "core/config.h" /* probes_filter_kind: raw, first order, Butterworth */

#include <stdbool.h>

typedef struct {
    probes_filter_kind kind;
    double omega; /* w_c = 2 pi f_c, rad/s */
} sensor_filter;

/* What a filter carries from one sample to the next: its output y and the output's rate dy/dt
 * (Butterworth only), the last input u and its time t. Before the first sample `started` is
 * false: the first sample starts the sensor at rest at its value. */
typedef struct {
    double y, rate, u, t;
    bool started;
} sensor_state;

/* The states as numbers, for a checkpoint: y, rate, u, t, started (0 or 1). */
#define SENSOR_STATE_VALUES 5

sensor_filter sensor_filter_make(probes_filter_kind kind, double cutoff_hz);

/* Feeds the sample u taken at time t (t >= the last sample's) and returns the filtered
 * value; PROBES_RAW returns u. */
double sensor_filter_sample(const sensor_filter *f, sensor_state *s, double t, double u);

void sensor_state_pack(const sensor_state *s, double out[SENSOR_STATE_VALUES]);
void sensor_state_unpack(sensor_state *s, const double in[SENSOR_STATE_VALUES]);

#endif
