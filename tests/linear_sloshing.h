/* linear_sloshing: the linear free-surface elevation of a 2D rectangular tank under harmonic
 * sway and roll from rest (docs/roll.md; tools/roll-reference evaluates the same sum), for the
 * tests that compare runs with it. */
#ifndef VCSPH_TEST_LINEAR_SLOSHING_H
#define VCSPH_TEST_LINEAR_SLOSHING_H

#include <math.h>

/* A tank of length L holding liquid of depth h under gravity g, moved by the sway
 * x = sway sin(omega t + phase) and the roll theta = angle sin(omega t + phase) (rad,
 * counter-clockwise) about an axis z_r above the mean free surface (-h: the bottom). */
typedef struct {
    double L, h, g;
    double sway, angle, omega, phase, z_r;
} linear_tank;

/* The elevation at x (m from the left wall) at time t, from rest: the odd modes n = 1..81,
 *   beta_n'' + sigma_n^2 beta_n = -k_n tanh(k_n h) X_n (x'' + g theta + theta'' Z_n),
 * k_n = n pi / L, sigma_n^2 = g k_n tanh(k_n h), X_n = -4 / (L k_n^2),
 * Z_n = z_r + (2 / k_n) tanh(k_n h / 2), beta_n(0) = beta_n'(0) = 0: the forced response
 * p_n sin(w t + phase) and the free modes the start excites. eta = sum beta_n cos(k_n x). */
static inline double linear_tank_elevation(const linear_tank *m, double x, double t)
{
    const double pi = 3.14159265358979323846, w = m->omega;
    double eta = 0.0;
    for (int n = 1; n < 82; n += 2) {
        double k = n * pi / m->L, th = tanh(k * m->h), sigma2 = m->g * k * th;
        double sigma = sqrt(sigma2), x_n = -4.0 / (m->L * k * k);
        double z_n = m->z_r + 2.0 / k * tanh(0.5 * k * m->h);
        /* x'' + g theta + theta'' Z_n = [angle (g - w^2 Z_n) - sway w^2] sin(w t + phase) */
        double force = -k * th * x_n * (m->angle * (m->g - w * w * z_n) - m->sway * w * w);
        double p = force / (sigma2 - w * w);
        double beta = p * sin(w * t + m->phase) - p * sin(m->phase) * cos(sigma * t) -
                      p * w * cos(m->phase) / sigma * sin(sigma * t);
        eta += beta * cos(k * x);
    }
    return eta;
}

#endif
