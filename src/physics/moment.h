/* moment: moments about a point and the rigid-rotation field that carries a given moment, in
 * 2D (the z axis alone) and 3D alike. Used to keep the angular momentum of a free body
 * (scheme/surface_tension.c) and to measure it (diag). */
#ifndef VCSPH_PHYSICS_MOMENT_H
#define VCSPH_PHYSICS_MOMENT_H

#include "core/vec.h"

/* m += s r x f: in 2D only m[2], the z component, is touched. */
static inline void moment_add(double m[3], double s, vec r, vec f)
{
#if DIM == 2
    m[2] += s * (r.c[0] * f.c[1] - r.c[1] * f.c[0]);
#else
    m[0] += s * (r.c[1] * f.c[2] - r.c[2] * f.c[1]);
    m[1] += s * (r.c[2] * f.c[0] - r.c[0] * f.c[2]);
    m[2] += s * (r.c[0] * f.c[1] - r.c[1] * f.c[0]);
#endif
}

/* inertia += w (|r|^2 I - r r), the inertia tensor of a weight w at r (2D: its zz entry). */
static inline void inertia_add(double inertia[3][3], double w, vec r)
{
    double r2 = vec_norm2(r);
#if DIM == 2
    inertia[2][2] += w * r2;
#else
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) inertia[a][b] += w * ((a == b ? r2 : 0.0) - r.c[a] * r.c[b]);
#endif
}

/* Omega x r with inertia Omega = moment: the field w_i (Omega x r_i) over the weights w_i
 * summed in `inertia` has exactly that moment, sum r x w (Omega x r) = inertia Omega, and,
 * about their weighted centre, no resultant. Zero where the inertia is singular (every
 * weight on one point, or on a line in 3D). */
static inline vec rotation_field(double inertia[3][3], const double moment[3], vec r)
{
    vec v = vec_zero();
#if DIM == 2
    if (!(inertia[2][2] > 0.0)) return v;
    double omega = moment[2] / inertia[2][2];
    v.c[0] = -omega * r.c[1];
    v.c[1] = omega * r.c[0];
#else
    mat m, m_inv;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) m.a[a][b] = inertia[a][b];
    if (mat_inverse(&m, &m_inv) == 0.0) return v;
    vec omega = mat_mul_vec(&m_inv, (vec){{moment[0], moment[1], moment[2]}});
    v.c[0] = omega.c[1] * r.c[2] - omega.c[2] * r.c[1];
    v.c[1] = omega.c[2] * r.c[0] - omega.c[0] * r.c[2];
    v.c[2] = omega.c[0] * r.c[1] - omega.c[1] * r.c[0];
#endif
    return v;
}

#endif
