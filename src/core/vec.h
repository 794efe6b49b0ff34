/* vec: DIM-generic small vectors by value; loops over DIM unroll at compile time. */
#ifndef VCSPH_VEC_H
#define VCSPH_VEC_H

#include "core/dim.h"
#include <math.h>
#include <stdbool.h>
#include <stddef.h>

typedef struct {
    double c[DIM];
} vec;

/* symmetric DIM x DIM matrix stored full (small, and the closed forms read better) */
typedef struct {
    double a[DIM][DIM];
} mat;

static inline vec vec_zero(void)
{
    vec v = {{0}};
    return v;
}

static inline vec vec_add(vec a, vec b)
{
    for (int d = 0; d < DIM; d++) a.c[d] += b.c[d];
    return a;
}

static inline vec vec_sub(vec a, vec b)
{
    for (int d = 0; d < DIM; d++) a.c[d] -= b.c[d];
    return a;
}

static inline vec vec_scale(vec a, double s)
{
    for (int d = 0; d < DIM; d++) a.c[d] *= s;
    return a;
}

/* a + s b */
static inline vec vec_axpy(vec a, double s, vec b)
{
    for (int d = 0; d < DIM; d++) a.c[d] += s * b.c[d];
    return a;
}

static inline double vec_dot(vec a, vec b)
{
    double s = 0.0;
    for (int d = 0; d < DIM; d++) s += a.c[d] * b.c[d];
    return s;
}

static inline double vec_norm2(vec a) { return vec_dot(a, a); }
static inline double vec_norm(vec a) { return sqrt(vec_dot(a, a)); }

/* vec_load(x, i) reads component arrays x[0..DIM) at index i (SoA -> value), vec_store(x, i, v)
 * writes them, for the store's double and single-precision fields alike (core/particles.h:
 * frozen_real; a float component is v's rounded to the nearest float). */
#define VEC_ACCESSORS(type)                                                                        \
    static inline vec vec_load_##type(type *const x[DIM], size_t i)                                \
    {                                                                                              \
        vec v;                                                                                     \
        for (int d = 0; d < DIM; d++) v.c[d] = x[d][i];                                            \
        return v;                                                                                  \
    }                                                                                              \
    static inline void vec_store_##type(type *const x[DIM], size_t i, vec v)                       \
    {                                                                                              \
        for (int d = 0; d < DIM; d++) x[d][i] = (type)v.c[d];                                      \
    }
VEC_ACCESSORS(double)
VEC_ACCESSORS(float)
#define vec_load(x, i) _Generic((x)[0], float * : vec_load_float, default : vec_load_double)(x, i)
#define vec_store(x, i, v)                                                                         \
    _Generic((x)[0], float * : vec_store_float, default : vec_store_double)(x, i, v)

static inline mat mat_zero(void)
{
    mat m = {{{0}}};
    return m;
}

static inline mat mat_identity(void)
{
    mat m = mat_zero();
    for (int d = 0; d < DIM; d++) m.a[d][d] = 1.0;
    return m;
}

static inline vec mat_mul_vec(const mat *m, vec v)
{
    vec r = vec_zero();
    for (int a = 0; a < DIM; a++)
        for (int b = 0; b < DIM; b++) r.c[a] += m->a[a][b] * v.c[b];
    return r;
}

/* m += s (v ⊗ w) */
static inline void mat_add_outer(mat *m, double s, vec v, vec w)
{
    for (int a = 0; a < DIM; a++)
        for (int b = 0; b < DIM; b++) m->a[a][b] += s * v.c[a] * w.c[b];
}

/* det m, by cofactors along the first row */
static inline double mat_determinant(const mat *m)
{
    const double(*a)[DIM] = m->a;
#if DIM == 2
    return a[0][0] * a[1][1] - a[0][1] * a[1][0];
#else
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) +
           a[0][1] * (a[1][2] * a[2][0] - a[1][0] * a[2][2]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
#endif
}

/* Inverse of a symmetric matrix by cofactors; returns the determinant (0: singular, m_inv
 * untouched). */
static inline double mat_inverse(const mat *m, mat *m_inv)
{
    double det = mat_determinant(m);
    if (det == 0.0) return 0.0;
#if DIM == 2
    m_inv->a[0][0] = m->a[1][1] / det;
    m_inv->a[1][1] = m->a[0][0] / det;
    m_inv->a[0][1] = -m->a[0][1] / det;
    m_inv->a[1][0] = -m->a[1][0] / det;
    return det;
#else
    const double(*a)[3] = m->a;
    double inv = 1.0 / det;
    m_inv->a[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) * inv;
    m_inv->a[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) * inv;
    m_inv->a[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) * inv;
    m_inv->a[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * inv;
    m_inv->a[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * inv;
    m_inv->a[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * inv;
    m_inv->a[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * inv;
    m_inv->a[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * inv;
    m_inv->a[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * inv;
    return det;
#endif
}

/* Smallest eigenvalue of a symmetric matrix, closed form (2x2: quadratic; 3x3: the
 * trigonometric solution of the characteristic cubic). Used for lambda of Eq. (10). */
static inline double mat_min_eigenvalue(const mat *m)
{
#if DIM == 2
    double mean = 0.5 * (m->a[0][0] + m->a[1][1]);
    double half_diff = 0.5 * (m->a[0][0] - m->a[1][1]);
    return mean - sqrt(half_diff * half_diff + m->a[0][1] * m->a[0][1]);
#else
    const double(*a)[3] = m->a;
    double p1 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    double d0 = a[0][0] - q, d1 = a[1][1] - q, d2 = a[2][2] - q;
    double p2 = d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * p1;
    if (p2 <= 1e-300) return q; /* a multiple of the identity */
    double p = sqrt(p2 / 6.0);
    /* B = (A - q I) / p; r = det(B) / 2 */
    double b00 = d0 / p, b11 = d1 / p, b22 = d2 / p;
    double b01 = a[0][1] / p, b02 = a[0][2] / p, b12 = a[1][2] / p;
    double r = 0.5 * (b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) +
                      b02 * (b01 * b12 - b11 * b02));
    double phi = r <= -1.0 ? M_PI / 3.0 : (r >= 1.0 ? 0.0 : acos(r) / 3.0);
    /* eigenvalues q + 2p cos(phi + 2 pi k / 3); the smallest is k = 1 */
    return q + 2.0 * p * cos(phi + 2.0 * M_PI / 3.0);
#endif
}

/* Whether every eigenvalue of a symmetric matrix exceeds `floor`, that is whether m - floor I
 * is positive definite: by Sylvester's criterion, all its leading principal minors are
 * positive. The answer of mat_min_eigenvalue(m) > floor (the two may differ by round-off only
 * where the smallest eigenvalue is the floor itself) without the cubic's arc cosine and
 * cosine, for a pass that needs the answer and not the eigenvalue. */
static inline bool mat_eigenvalues_above(const mat *m, double floor)
{
    mat shifted = *m; /* m - floor I */
    for (int d = 0; d < DIM; d++) shifted.a[d][d] -= floor;
    double(*a)[DIM] = shifted.a;
    double minor2 = a[0][0] * a[1][1] - a[0][1] * a[1][0]; /* in 2D, the determinant */
    return a[0][0] > 0.0 && minor2 > 0.0 && (DIM == 2 || mat_determinant(&shifted) > 0.0);
}

#endif
