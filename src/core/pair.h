/* pair: the geometry of one neighbour pair (i, j), shared by every pair loop: r_ji = r_j - r_i,
 * |r_ji|^2, W_ij and F_ij of grad_i W_ij = r_ji F_ij (theory §1). */
#ifndef VCSPH_PAIR_H
#define VCSPH_PAIR_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/vec.h"
#include <stdbool.h>

typedef struct {
    size_t j;
    vec r_ji;
    double r2, r, w, f; /* |r_ji|^2, |r_ji|, W_ij, F_ij */
} pair;

/* Entry n of particle i's row; false for a pair beyond 2h (the list's skin), which would add
 * exactly zero. */
static inline bool pair_of(const kernel *k, double *const x[DIM], vec xi, const int32_t *row,
                           int32_t n, pair *pr)
{
    pr->j = (size_t)row[n];
    pr->r_ji = vec_sub(vec_load(x, pr->j), xi);
    pr->r2 = vec_norm2(pr->r_ji);
    if (pr->r2 >= k->support2) return false;
    pr->r = sqrt(pr->r2);
    pr->w = kernel_w(k, pr->r);
    pr->f = kernel_f(k, pr->r);
    return true;
}

/* The geometry of a whole row (pair_row_of, below), a column per quantity (r_ji's components,
 * r^2, r, W, F), `stride` doubles apart; entry n is row[n]'s. Each entry is computed by pair_of's
 * operations in pair_of's order, so the values are pair_of's to the bit; an entry beyond 2h (the
 * list's skin) holds its r_ji, r^2, r and the kernel there (0 unless r / h rounds below 2), and
 * pair_at skips it; the columns run on to a whole number of PAIR_BLOCKs, the row's last entry
 * repeated with W = F = 0 (core/pair_block.h sums them). Where the processor has AVX2
 * or AVX-512 (core/lanes_switch.h), eight entries at a time in SIMD registers (core/pair.c). */
enum { PAIR_R2 = DIM, PAIR_R, PAIR_W, PAIR_F, PAIR_COLUMNS };
#define PAIR_BLOCK 8 /* entries computed at once; the columns' stride is a multiple of it */

/* The columns' stride for a row of `count`: room for whole blocks, and at least one entry. */
static inline size_t pair_columns_stride(int32_t count)
{
    return ((size_t)count / PAIR_BLOCK + 1) * PAIR_BLOCK;
}

/* Entry n of the row's geometry (pair_row_of) into `pr`; false for a pair beyond 2h. */
static inline bool pair_at(const int32_t *row, const double *columns, size_t stride, int32_t n,
                           double support2, pair *pr)
{
    pr->r2 = columns[PAIR_R2 * stride + (size_t)n];
    if (pr->r2 >= support2) return false;
    pr->j = (size_t)row[n];
    for (int d = 0; d < DIM; d++) pr->r_ji.c[d] = columns[(size_t)d * stride + (size_t)n];
    pr->r = columns[PAIR_R * stride + (size_t)n];
    pr->w = columns[PAIR_W * stride + (size_t)n];
    pr->f = columns[PAIR_F * stride + (size_t)n];
    return true;
}

/* One row's geometry kept for several pair loops over it: a pass that needs two sums of the
 * same neighbours (the shifting and the correction velocity) computes the row once.
 * FOR_EACH_PAIR below is the two in one statement.
 *
 *     PAIR_ROW (k, p->x, nl, i, xi, row);          declares `row`, its columns on the stack
 *     pair pr;
 *     FOR_EACH_PAIR_OF_ROW (&row, pr) { ... }       the pairs within 2h, as FOR_EACH_PAIR's */
typedef struct {
    const int32_t *row;
    int32_t count;
    size_t stride;
    const double *columns;
    double support2;
} pair_row;

/* Particle i's row (neighbour_row, into `entries`, room for its count) and its geometry
 * (into `columns`, PAIR_COLUMNS x stride doubles, stride = pair_columns_stride of its count). */
#define pair_row_of DIM_NAME(pair_row_of)
pair_row pair_row_of(const kernel *k, double *const x[DIM], const neighbour_list *nl, size_t i,
                     vec xi, int32_t *entries, double *columns, size_t stride);

#define PAIR_ROW(k, x, nl, i, xi, name)                                                            \
    size_t name##_stride = pair_columns_stride((nl)->count[i]);                                    \
    int32_t name##_entries[name##_stride];                                                         \
    double name##_columns[PAIR_COLUMNS * name##_stride];                                           \
    const pair_row name =                                                                          \
        pair_row_of(k, x, nl, i, xi, name##_entries, name##_columns, name##_stride)

#define FOR_EACH_PAIR_OF_ROW(rw, pr)                                                               \
    for (int32_t pr##_n = 0; pr##_n < (rw)->count; pr##_n++)                                       \
        if (!pair_at((rw)->row, (rw)->columns, (rw)->stride, pr##_n, (rw)->support2, &(pr))) {     \
        } else

/* The one neighbour loop of every pass: the pairs (i, j) of particle i at xi whose distance
 * is within 2h, one by one in `pr` (declared by the caller), in the list's order:
 *
 *     pair pr;
 *     FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) { ... pr.j, pr.r_ji, pr.w, pr.f ... }
 *
 * Each pass supplies only its pair functions (src/physics). `continue` goes to the next pair,
 * `break` ends the loop. The geometry of the whole row is computed first (pair_row_of, into
 * columns on the stack), then the body runs over the entries within 2h: the same pairs in the
 * same order with the same values, so the same sums, but the square roots and kernels of the
 * row computed side by side, not one pair's chain of dependent operations after the other's. */
#define FOR_EACH_PAIR(k, x, nl, i, xi, pr)                                                         \
    for (size_t pr##_stride = pair_columns_stride((nl)->count[i]), pr##_once = 1; pr##_once;       \
         pr##_once = 0)                                                                            \
        for (int32_t pr##_entries[pr##_stride], *pr##_go = pr##_entries; pr##_go; pr##_go = NULL)  \
            for (double pr##_columns[PAIR_COLUMNS * pr##_stride], *pr##_on = pr##_columns;         \
                 pr##_on; pr##_on = NULL)                                                          \
                for (pair_row pr##_row =                                                           \
                         pair_row_of(k, x, nl, i, xi, pr##_entries, pr##_columns, pr##_stride);    \
                     pr##_row.row; pr##_row.row = NULL)                                            \
                    FOR_EACH_PAIR_OF_ROW (&pr##_row, pr)

/* FOR_EACH_PAIR over the neighbours for which `keep` holds, an expression of `pr.j` tested
 * before any geometry: for a pass that reads only a few of the neighbours (the free surface's)
 * of many particles. The same pairs as FOR_EACH_PAIR with `if (!keep) continue;` in its body, in
 * the same order, without the square root and kernel of the others. */
#define FOR_EACH_PAIR_WHERE(k, x, nl, i, xi, pr, keep)                                             \
    for (size_t pr##_room = (size_t)(nl)->count[i] + 1, pr##_once = 1; pr##_once; pr##_once = 0)   \
        for (int32_t pr##_entries[pr##_room], *pr##_go = pr##_entries; pr##_go; pr##_go = NULL)    \
            for (const int32_t *pr##_row = neighbour_row(nl, i, pr##_entries); pr##_row;           \
                 pr##_row = NULL)                                                                  \
                for (int32_t pr##_at = 0; pr##_at < (nl)->count[i]; pr##_at++)                     \
                    if (((pr).j = (size_t)pr##_row[pr##_at], !(keep)) ||                           \
                        !pair_of(k, x, xi, pr##_row, pr##_at, &(pr))) {                            \
                    } else

#endif
