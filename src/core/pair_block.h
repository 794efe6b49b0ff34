/* pair_block: a row's pairs PAIR_BLOCK entries at a time (GCC vector extensions), for the sums
 * of a pass over a row's geometry (core/pair.h's columns). Lane l of a block sum adds the row's
 * entries n = l, l + PAIR_BLOCK, l + 2 PAIR_BLOCK, ... in order, and block_total adds the lanes
 * in order at the end: the same operations on every processor, whether a function that uses it
 * is built for AVX-512 (one register a block), AVX2 (two) or the baseline (four SSE halves), so
 * every form gives the same bits. */
#ifndef VCSPH_PAIR_BLOCK_H
#define VCSPH_PAIR_BLOCK_H

#include "core/lanes_switch.h"
#include "core/pair.h"
#include "core/particles.h"

/* Blocks are passed between inline functions only, never across a call, so GCC's note on the
 * ABI of wide vector arguments does not apply. */
#pragma GCC diagnostic ignored "-Wpsabi"
#define PAIR_BLOCK_INLINE __attribute__((always_inline)) static inline

typedef double pair_block __attribute__((vector_size(PAIR_BLOCK * sizeof(double))));
_Static_assert(PAIR_BLOCK == 8, "core/pair.c's ones_then_zeros holds two blocks of eight");
typedef int64_t pair_block_mask __attribute__((vector_size(PAIR_BLOCK * sizeof(double))));

/* Entries n0 .. n0 + PAIR_BLOCK - 1 of a row's geometry. An entry past the row's end has
 * W = F = 0, and so has one beyond 2h (pair_row_of: the kernel's own zero at q >= 2; where
 * r^2 >= (2h)^2 but r / h rounds just below 2, a value of order 1e-48 of the kernel's peak,
 * where the pair loops of core/pair.h skip the entry). So a term with a factor W or F adds an
 * exact zero there (every value in the columns is a number, and a sum that starts at +0 never
 * holds -0): the sums need no mask. */
typedef struct {
    const int32_t *j;         /* the block's neighbours: into the row, or `last` */
    int32_t last[PAIR_BLOCK]; /* the row's last block, its last entry repeated past the end */
    pair_block_mask inside;   /* -1 where the entry's r^2 is below (2h)^2 (past the row's end too,
                                 where the row's last entry repeats), else 0 */
    pair_block r_ji[DIM], w, f;
} pair_block_geometry;

PAIR_BLOCK_INLINE pair_block pair_block_column(const pair_row *rw, int column, int32_t n0)
{
    pair_block b;
    __builtin_memcpy(&b, &rw->columns[(size_t)column * rw->stride + (size_t)n0], sizeof b);
    return b;
}

/* The neighbours of a row's entries n0 .. n0 + PAIR_BLOCK - 1 (n0 < count): the row itself
 * where the block is whole, else `last`, the row's tail with its last entry repeated (the
 * columns' padding, pair_row_of). */
PAIR_BLOCK_INLINE const int32_t *pair_block_neighbours(const int32_t *row, int32_t count,
                                                       int32_t n0, int32_t last[PAIR_BLOCK])
{
    if (n0 + PAIR_BLOCK <= count) return row + n0;
    for (int l = 0; l < PAIR_BLOCK; l++) last[l] = row[n0 + l < count ? n0 + l : count - 1];
    return last;
}

/* The block of entries from n0 (a multiple of PAIR_BLOCK below the row's count). */
PAIR_BLOCK_INLINE void pair_block_at(const pair_row *rw, int32_t n0, pair_block_geometry *b)
{
    b->j = pair_block_neighbours(rw->row, rw->count, n0, b->last);
    b->inside = pair_block_column(rw, PAIR_R2, n0) < rw->support2;
    for (int d = 0; d < DIM; d++) b->r_ji[d] = pair_block_column(rw, d, n0);
    b->w = pair_block_column(rw, PAIR_W, n0);
    b->f = pair_block_column(rw, PAIR_F, n0);
}

/* The row's blocks, in order: `b` (declared by the caller) for n0 = 0, PAIR_BLOCK, ... */
#define FOR_EACH_PAIR_BLOCK_OF_ROW(rw, b)                                                          \
    for (int32_t b##_n0 = 0; b##_n0 < (rw)->count; b##_n0 += PAIR_BLOCK)                           \
        if (pair_block_at(rw, b##_n0, &(b)), 0) {                                                  \
        } else

/* pair_block_gather(a, j): a[j[0]], ..., a[j[PAIR_BLOCK - 1]], element by element into the
 * register (through memory, the block's load would wait for eight stores: no store
 * forwarding), for the store's double and single-precision fields alike (core/particles.h:
 * frozen_real), each element widened to double. */
#define PAIR_BLOCK_GATHER(type)                                                                    \
    PAIR_BLOCK_INLINE pair_block pair_block_gather_##type(const type *a, const int32_t *j)         \
    {                                                                                              \
        pair_block r;                                                                              \
        for (int l = 0; l < PAIR_BLOCK; l++) r[l] = a[j[l]];                                       \
        return r;                                                                                  \
    }
PAIR_BLOCK_GATHER(double)
PAIR_BLOCK_GATHER(float)
#define pair_block_gather(a, j)                                                                    \
    _Generic((a)[0], float : pair_block_gather_float, default : pair_block_gather_double)(a, j)

PAIR_BLOCK_INLINE pair_block pair_block_broadcast(double a) { return (pair_block){0} + a; }

/* m ? a : b, lane by lane */
PAIR_BLOCK_INLINE pair_block pair_block_select(pair_block_mask m, pair_block a, pair_block b)
{
    return (pair_block)((m & (pair_block_mask)a) | (~m & (pair_block_mask)b));
}

/* The lanes of a block sum added in order: the row's sum */
PAIR_BLOCK_INLINE double block_total(pair_block s)
{
    double total = s[0];
    for (int l = 1; l < PAIR_BLOCK; l++) total += s[l];
    return total;
}

/* The block sums of L = sum r_ji (x) r_ji F V_j (Eq. 10; its upper triangle, L being
 * symmetric) and of sum r_ji F V_j = sum grad_i W_ij V_j over a row: the geometry pass's
 * (scheme/step_fields.c) and surface tension's interface (scheme/surface_tension.c). */
typedef struct {
    pair_block l[DIM][DIM], grad_one[DIM];
} pair_block_moments;

/* A block's terms; fv = F V_j, zero where the entry does not count */
PAIR_BLOCK_INLINE void pair_block_moments_add(pair_block_moments *m, pair_block fv,
                                              const pair_block r_ji[DIM])
{
    for (int a = 0; a < DIM; a++) {
        pair_block fr = fv * r_ji[a];
        for (int c = a; c < DIM; c++) m->l[a][c] += fr * r_ji[c];
        m->grad_one[a] += fr;
    }
}

/* The row's L (the upper triangle mirrored) and sum grad W V, from the lanes' sums */
PAIR_BLOCK_INLINE void pair_block_moments_total(const pair_block_moments *m, mat *l, vec *grad_one)
{
    for (int a = 0; a < DIM; a++) {
        for (int c = a; c < DIM; c++) l->a[a][c] = l->a[c][a] = block_total(m->l[a][c]);
        grad_one->c[a] = block_total(m->grad_one[a]);
    }
}

/* The viscous term's velocity of the block's neighbours, component by component: their own
 * velocity, or, where the row reaches a ghost, particle_viscous_velocity's (a wall image's
 * no-slip or free-slip image). */
PAIR_BLOCK_INLINE void pair_block_viscous_velocity(const particles *p, const pair_block_geometry *b,
                                                   bool ghosts, pair_block u[DIM])
{
    for (int d = 0; d < DIM; d++) u[d] = pair_block_gather(p->u[d], b->j);
    if (ghosts)
        for (int l = 0; l < PAIR_BLOCK; l++) {
            vec v = particle_viscous_velocity(p, (size_t)b->j[l]);
            for (int d = 0; d < DIM; d++) u[d][l] = v.c[d];
        }
}

/* NAME built three times from the always_inline function NAME (which returns TYPE and takes
 * PARAMS, called with ARGS): for AVX-512 (x86-64-v4, one register a block), AVX2 (x86-64-v3)
 * and the baseline (x86-64-v2), and NAME_form(), the one lanes_width allows. The same
 * operations in each, so the same bits (tests/test_lanes.c runs them all). */
#define PAIR_BLOCK_FORMS(TYPE, NAME, PARAMS, ARGS)                                                 \
    __attribute__((target("arch=x86-64-v4"))) static TYPE NAME##_avx512 PARAMS                     \
    {                                                                                              \
        return NAME ARGS;                                                                          \
    }                                                                                              \
    __attribute__((target("arch=x86-64-v3"))) static TYPE NAME##_avx2 PARAMS { return NAME ARGS; } \
    static TYPE NAME##_baseline PARAMS { return NAME ARGS; }                                       \
    static TYPE(*NAME##_form(void)) PARAMS                                                         \
    {                                                                                              \
        switch (lanes_width()) {                                                                   \
        case 8: return NAME##_avx512;                                                              \
        case 4: return NAME##_avx2;                                                                \
        default: return NAME##_baseline;                                                           \
        }                                                                                          \
    }

#endif
