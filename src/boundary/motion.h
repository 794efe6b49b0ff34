/* motion: the prescribed tank motion (theory §6) and the fictitious body force it causes in
 * the tank frame. */
#ifndef VCSPH_MOTION_H
#define VCSPH_MOTION_H

#include "boundary/frame.h"
#include "core/config.h"

#include <stddef.h>

typedef struct {
    motion_kind kind;
    double amplitude, omega, decay, phase, duration; /* duration 0: whole run */
    /* type = table: knots and the natural cubic spline's second derivatives per axis */
    size_t n_knots;
    double *t, *pos[3], *acc[3];
} motion;

/* Reads the table file when there is one. Returns 0, or 2 with a message in err. */
int motion_init(motion *mo, const config *cfg, char *err, size_t err_len);
void motion_free(motion *mo);
/* Tank acceleration (m/s^2) at time t along x, y, z of the tank frame. */
void motion_acceleration(const motion *mo, double t, double a[3]);
/* The tank frame at time t (frame.h): gravity (0, -gravity, 0) in the tank's axes, the
 * acceleration of motion_acceleration, no rotation (sway, heave and tables translate). */
tank_frame motion_frame(const motion *mo, double gravity, double t);
/* Tank displacement (m) at time t; after `duration`, uniform motion at the velocity reached
 * then. A table's natural spline has zero acceleration at its first and last rows. */
void motion_position(const motion *mo, double t, double x[3]);
/* Largest |g - a_tank| over [0, t_end] (sampled), the g_max of the sound-speed rule. */
double motion_max_effective_gravity(const motion *mo, double gravity, double t_end);
/* Largest tank speed |v_tank| over [0, t_end] (after `duration` the speed stays that of its
 * end): A sqrt(w^2 + l^2) for sway and heave (A w without decay, an upper bound with it), the
 * spline's largest speed for a table (sampled, 16 points per row interval). */
double motion_max_speed(const motion *mo, double t_end);
/* Half the range of the tank's displacement along x, y, z over [0, t_end] while it is driven
 * (before `duration`; what follows is uniform motion, which the liquid does not feel): A
 * along the axis of sway or heave, the sampled spline's for a table. */
void motion_max_excursion(const motion *mo, double t_end, double out[3]);

#endif
