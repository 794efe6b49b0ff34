/* frame: the tank frame, the non-inertial frame in which vcsph solves (theory §6). The motion
 * gives, at each time, the acceleration of the frame's origin, its angular velocity and
 * angular acceleration, and the gravity in the frame's axes; a particle at r with velocity u
 * (both in the frame) then feels, per unit mass,
 *
 *     f(r, u) = g - a0 - dOmega/dt x r - Omega x (Omega x r) - 2 Omega x u
 *
 * (translation, Euler, centrifugal and Coriolis terms), with r measured from the point
 * `center` on the rotation axis and a0 that point's acceleration. A tank that only translates
 * (sway, heave, a table of positions) has Omega = 0 and f = g - a0 everywhere, the g_eff of
 * theory §6; a rolling, pitching or yawing one fills in Omega, dOmega/dt and turns g. After
 * the motion stops (motion.duration), motion.settling > 0 adds the damping -settling u, a
 * numerical aid that brings the liquid to rest; it is no physics of the tank. */
#ifndef VCSPH_FRAME_H
#define VCSPH_FRAME_H

#include <math.h>
#include <stdbool.h>

typedef struct {
    double gravity[3];    /* g in the frame's axes (m/s^2): (0, -|g|, 0) for a level tank */
    double origin_acc[3]; /* a0: acceleration of the point `center` (m/s^2) */
    double center[3];     /* a point of the rotation axis, tank coordinates (m) */
    double omega[3];      /* angular velocity (rad/s); in 2D only omega[2] */
    double omega_dot[3];  /* angular acceleration (rad/s^2) */
    bool rotating;        /* Omega or dOmega/dt not zero */
    double damping;       /* 1/s: the body force -damping u (motion.settling), 0 mostly */
} tank_frame;

/* a x b of two 3-vectors */
static inline void frame_cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* R v: a vector of the tank's axes in the inertial ones, R the tank's orientation */
static inline void mat3_apply(double r[3][3], const double v[3], double out[3])
{
    for (int i = 0; i < 3; i++) out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
}

/* R^T v: a vector of the inertial axes in the tank's */
static inline void mat3_apply_transposed(double r[3][3], const double v[3], double out[3])
{
    for (int j = 0; j < 3; j++) out[j] = r[0][j] * v[0] + r[1][j] * v[1] + r[2][j] * v[2];
}

static inline double vec3_norm(const double a[3])
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

/* The part of the body force at r (relative to `center`, 3-vector) that rotation adds:
 * -(dOmega/dt x r) - Omega x (Omega x r), the Euler and centrifugal terms (per unit mass). */
static inline void frame_rotation_force(const tank_frame *f, const double r[3], double out[3])
{
    double euler[3], spin[3], centrifugal[3];
    frame_cross(f->omega_dot, r, euler);
    frame_cross(f->omega, r, spin);
    frame_cross(f->omega, spin, centrifugal);
    for (int d = 0; d < 3; d++) out[d] = -euler[d] - centrifugal[d];
}

#ifdef DIM /* the body force, for the particle code (compiled for DIM = 2 and 3) */
#include "core/vec.h"

/* The uniform part g - a0, the whole force when the frame does not rotate. */
static inline vec frame_translation_force(const tank_frame *f)
{
    vec g;
    for (int d = 0; d < DIM; d++) g.c[d] = -f->origin_acc[d] + f->gravity[d];
    return g;
}

/* f(r, u) per unit mass at position r, velocity u (the header's formula). */
static inline vec frame_body_force(const tank_frame *f, vec r, vec u)
{
    vec force = frame_translation_force(f);
    if (f->damping > 0.0) force = vec_axpy(force, -f->damping, u);
    if (!f->rotating) return force;
    double r3[3] = {0.0, 0.0, 0.0}, u3[3] = {0.0, 0.0, 0.0}, rotation[3], coriolis[3];
    for (int d = 0; d < DIM; d++) r3[d] = r.c[d] - f->center[d], u3[d] = u.c[d];
    frame_rotation_force(f, r3, rotation);
    frame_cross(f->omega, u3, coriolis);
    for (int d = 0; d < DIM; d++) force.c[d] += rotation[d] - 2.0 * coriolis[d];
    return force;
}
#endif

#endif
