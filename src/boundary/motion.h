/* motion: the prescribed tank motion (theory §6) and the fictitious body force it causes in
 * the tank frame. */
#ifndef VCSPH_MOTION_H
#define VCSPH_MOTION_H

#include "boundary/frame.h"
#include "core/config.h"

#include <stdbool.h>
#include <stddef.h>

/* The six channels of a motion: the displacement of motion.center along x, y, z (m, in the
 * inertial axes, which coincide with the tank's at rest) and the angles roll (about z), pitch
 * (about x) and yaw (about y) in rad. */
enum { MOTION_X, MOTION_Y, MOTION_Z, MOTION_ROLL_ANGLE, MOTION_PITCH_ANGLE, MOTION_YAW_ANGLE };
#define MOTION_CHANNELS 6

typedef struct {
    motion_kind kind;
    int translation, rotation; /* the harmonic motion's channels, -1 when none */
    double amplitude, angle, omega, decay, phase, angle_phase, duration; /* duration 0: whole run */
    double settling;  /* the frame's damping after `duration` (1/s) */
    double center[3]; /* the rotation axis's point, tank coordinates (m) */
    double reach;     /* largest distance from center to a corner of the tank (m) */
    bool rotates;     /* a rotation channel is driven */
    /* type = table: knots and the natural cubic spline's second derivatives per channel */
    size_t n_knots;
    bool table_by_position; /* no header: t,x,y[,z] by position */
    double *t, *pos[MOTION_CHANNELS], *acc[MOTION_CHANNELS];
} motion;

/* Reads the table file when there is one. Returns 0, or 2 with a message in err. */
int motion_init(motion *mo, const config *cfg, char *err, size_t err_len);
void motion_free(motion *mo);
/* A table's columns as its rows hold them, e.g. "t,x,y,roll". */
void motion_table_columns(const motion *mo, char *buf, size_t size);
/* Acceleration (m/s^2) of motion.center at time t along the inertial x, y, z. */
void motion_acceleration(const motion *mo, double t, double a[3]);
/* The angles roll, pitch, yaw (rad) at time t, their rates and second derivatives. */
void motion_angles(const motion *mo, double t, double q[3], double q_dot[3], double q_ddot[3]);
/* The tank's orientation R at time t (below): a vector of the tank's axes is R v in the
 * inertial axes. */
void motion_rotation(const motion *mo, double t, double r[3][3]);
/* The tank frame at time t (frame.h). The tank's orientation is R = R_y(yaw) R_x(pitch)
 * R_z(roll) (yaw about the vertical first, then pitch, then roll, each about the axis turned by
 * the ones before); the frame's gravity is R^T (0, -gravity, 0), its origin_acc R^T times the
 * centre's acceleration, its Omega and dOmega/dt R^T times the angular velocity and
 * acceleration in the inertial axes. Without rotation: gravity (0, -gravity, 0) and the
 * acceleration of motion_acceleration, exactly. */
tank_frame motion_frame(const motion *mo, double gravity, double t);
/* Tank displacement (m) at time t; after `duration`, uniform motion at the velocity reached
 * then. A table's natural spline has zero acceleration at its first and last rows. */
void motion_position(const motion *mo, double t, double x[3]);
/* Largest |g - a_tank| over [0, t_end] (sampled), the g_max of the sound-speed rule. A
 * rotating tank adds the Euler and centrifugal terms at the reach: |dOmega/dt| + |Omega|^2
 * times the largest distance from the axis to a tank corner (the Coriolis term depends on the
 * flow and is left out). */
double motion_max_effective_gravity(const motion *mo, double gravity, double t_end);
/* Largest tank speed |v_tank| over [0, t_end] (after `duration` the speed stays that of its
 * end): A sqrt(w^2 + l^2) for sway and heave (A w without decay, an upper bound with it), the
 * spline's largest speed for a table (sampled, 16 points per row interval); a rotation adds
 * its largest angular rate times the reach. */
double motion_max_speed(const motion *mo, double t_end);
/* Half the range of the tank's displacement along x, y, z over [0, t_end] while it is driven
 * (before `duration`; what follows is uniform motion, which the liquid does not feel): A
 * along the axis of sway or heave, the sampled spline's for a table. */
void motion_max_excursion(const motion *mo, double t_end, double out[3]);

#endif
