/* lanes: LANES particles' pair sums side by side in SIMD lanes (GCC vector extensions), LANES = 4
 * (AVX2, x86-64-v3) or 8 (AVX-512, x86-64-v4), set by the file that includes this header (one
 * file per width, scheme/rhs_lanes4.c and rhs_lanes8.c). Each lane is one particle i walking its
 * own neighbour row in its own order, and every operation on a lane is the operation the scalar
 * code does on that particle, in the same order, so each particle's sums are the scalar code's
 * to the bit, whatever the width and the instruction set. */
#ifndef VCSPH_LANES_H
#define VCSPH_LANES_H

#include "core/dim.h"
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Lane values are passed between inline functions only, never across a call, so the ABI note
 * GCC makes about 256-bit vectors in code built without AVX does not apply. */
#pragma GCC diagnostic ignored "-Wpsabi"
#define LANE_INLINE __attribute__((always_inline)) static inline

#if LANES == 8
#define LANES_TARGET __attribute__((target("arch=x86-64-v4")))
#elif LANES == 4
#define LANES_TARGET __attribute__((target("arch=x86-64-v3")))
#else
#error "LANES must be 4 or 8 before core/lanes.h is included"
#endif

typedef double lane_real __attribute__((vector_size(LANES * sizeof(double))));
typedef int64_t lane_mask __attribute__((vector_size(LANES * sizeof(double)))); /* -1 or 0 */

typedef struct {
    lane_real c[DIM];
} lane_vec;

LANE_INLINE lane_real lane_broadcast(double a) { return (lane_real){0} + a; }

/* m ? a : b, lane by lane */
LANE_INLINE lane_real lane_select(lane_mask m, lane_real a, lane_real b)
{
    return (lane_real)((m & (lane_mask)a) | (~m & (lane_mask)b));
}

/* The readers of a field, for the store's double and single-precision fields alike
 * (core/particles.h: frozen_real), each element widened to double: lane_gather(a, j) is
 * a[j[0]], ..., a[j[LANES - 1]], lane_load(a, i) a[i], ..., a[i + LANES - 1], and
 * lane_vec_gather and lane_vec_load the same for the DIM component arrays of a vector. */
#define LANE_READERS(type)                                                                         \
    LANE_INLINE lane_real lane_gather_##type(const type *a, const int32_t j[LANES])                \
    {                                                                                              \
        lane_real r;                                                                               \
        for (int l = 0; l < LANES; l++) r[l] = a[j[l]];                                            \
        return r;                                                                                  \
    }                                                                                              \
    LANE_INLINE lane_real lane_load_##type(const type *a, size_t i)                                \
    {                                                                                              \
        lane_real r;                                                                               \
        for (int l = 0; l < LANES; l++) r[l] = a[i + (size_t)l];                                   \
        return r;                                                                                  \
    }                                                                                              \
    LANE_INLINE lane_vec lane_vec_gather_##type(type *const x[DIM], const int32_t j[LANES])        \
    {                                                                                              \
        lane_vec v;                                                                                \
        for (int d = 0; d < DIM; d++) v.c[d] = lane_gather_##type(x[d], j);                        \
        return v;                                                                                  \
    }                                                                                              \
    LANE_INLINE lane_vec lane_vec_load_##type(type *const x[DIM], size_t i)                        \
    {                                                                                              \
        lane_vec v;                                                                                \
        for (int d = 0; d < DIM; d++) v.c[d] = lane_load_##type(x[d], i);                          \
        return v;                                                                                  \
    }
LANE_READERS(double)
LANE_READERS(float)
#define LANE_READER(a, name) _Generic((a)[0], float : name##_float, default : name##_double)
#define lane_gather(a, j)    LANE_READER(a, lane_gather)(a, j)
#define lane_load(a, i)      LANE_READER(a, lane_load)(a, i)
#define lane_vec_gather(x, j)                                                                      \
    _Generic((x)[0], float * : lane_vec_gather_float, default : lane_vec_gather_double)(x, j)
#define lane_vec_load(x, i)                                                                        \
    _Generic((x)[0], float * : lane_vec_load_float, default : lane_vec_load_double)(x, i)

/* whether any lane of m is set */
LANE_INLINE bool lane_any(lane_mask m)
{
    int64_t any = 0;
    for (int l = 0; l < LANES; l++) any |= m[l];
    return any != 0;
}

/* The correctly rounded square root of each lane (sqrtpd), as sqrt() of each. */
LANE_INLINE lane_real lane_sqrt(lane_real a)
{
    lane_real r = a;
    for (int l = 0; l < LANES; l++) r[l] = __builtin_sqrt(a[l]);
    return r;
}

LANE_INLINE lane_vec lane_vec_zero(void)
{
    lane_vec v;
    for (int d = 0; d < DIM; d++) v.c[d] = lane_broadcast(0.0);
    return v;
}

LANE_INLINE lane_vec lane_vec_sub(lane_vec a, lane_vec b)
{
    for (int d = 0; d < DIM; d++) a.c[d] -= b.c[d];
    return a;
}

LANE_INLINE lane_vec lane_vec_add(lane_vec a, lane_vec b)
{
    for (int d = 0; d < DIM; d++) a.c[d] += b.c[d];
    return a;
}

LANE_INLINE lane_vec lane_vec_scale(lane_vec a, lane_real s)
{
    for (int d = 0; d < DIM; d++) a.c[d] *= s;
    return a;
}

/* a + s b */
LANE_INLINE lane_vec lane_vec_axpy(lane_vec a, lane_real s, lane_vec b)
{
    for (int d = 0; d < DIM; d++) a.c[d] += s * b.c[d];
    return a;
}

/* 0 + a_0 b_0 + a_1 b_1 (+ a_2 b_2): vec_dot's order */
LANE_INLINE lane_real lane_vec_dot(lane_vec a, lane_vec b)
{
    lane_real s = lane_broadcast(0.0);
    for (int d = 0; d < DIM; d++) s += a.c[d] * b.c[d];
    return s;
}

/* m ? a + b : a, lane by lane: a sum that takes the pair only where it counts */
LANE_INLINE lane_vec lane_vec_add_where(lane_mask m, lane_vec a, lane_vec b)
{
    for (int d = 0; d < DIM; d++) a.c[d] = lane_select(m, a.c[d] + b.c[d], a.c[d]);
    return a;
}

#endif
