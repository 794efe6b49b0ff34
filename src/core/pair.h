/* pair: the geometry of one neighbour pair (i, j), shared by every pair loop: r_ji = r_j - r_i,
 * |r_ji|^2 and F_ij of grad_i W_ij = r_ji F_ij (theory §1). */
#ifndef VCSPH_PAIR_H
#define VCSPH_PAIR_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/vec.h"
#include <stdbool.h>

typedef struct {
    size_t j;
    vec r_ji;
    double r2, r, f; /* |r_ji|^2, |r_ji|, F_ij */
} pair;

static inline const int32_t *neighbour_row(const neighbour_list *nl, size_t i)
{
    return nl->index + i * nl->row_capacity;
}

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
    pr->f = kernel_f(k, pr->r);
    return true;
}

/* The pairs of particle i within 2h, in the list's order, into `out` (room for count[i]);
 * returns how many. A short loop of its own, so that the square roots and kernels of many
 * pairs are in flight at once before the physics reads them. */
static inline int32_t pairs_gather(const kernel *k, double *const x[DIM], const neighbour_list *nl,
                                   size_t i, vec xi, pair *out)
{
    const int32_t *row = neighbour_row(nl, i);
    int32_t n_in = 0;
    for (int32_t n = 0; n < nl->count[i]; n++)
        if (pair_of(k, x, xi, row, n, &out[n_in])) n_in++;
    return n_in;
}

/* The one neighbour loop of every pass: the pairs (i, j) of particle i at xi whose distance
 * is within 2h, one by one in `pr` (declared by the caller), in the list's order:
 *
 *     pair pr;
 *     FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) { ... pr.j, pr.r_ji, pr.f ... }
 *
 * Each pass supplies only its pair functions (src/physics). `continue` goes to the next pair,
 * `break` ends the loop. The geometry of the row is gathered first (pairs_gather, into a
 * buffer on the stack), then the body runs over it: the same pairs in the same order, so the
 * same sums, but the square roots of many pairs in flight at once instead of one pair's
 * chain of dependent operations after the other's. */
#define FOR_EACH_PAIR(k, x, nl, i, xi, pr)                                                         \
    for (pair pr##_all[(nl)->count[i] + 1],                                                        \
         *pr##_end = pr##_all + pairs_gather(k, x, nl, i, xi, pr##_all), *pr##_at = pr##_all;      \
         pr##_at < pr##_end && ((pr) = *pr##_at, true); pr##_at++)

/* FOR_EACH_PAIR over the neighbours for which `keep` holds, an expression of `pr.j` tested
 * before any geometry: for a pass that reads only a few of the neighbours (the free surface's)
 * of many particles. The same pairs as FOR_EACH_PAIR with `if (!keep) continue;` in its body, in
 * the same order, without the square root and kernel of the others. */
#define FOR_EACH_PAIR_WHERE(k, x, nl, i, xi, pr, keep)                                             \
    for (int32_t pr##_at = 0; pr##_at < (nl)->count[i]; pr##_at++)                                 \
        if (((pr).j = (size_t)neighbour_row(nl, i)[pr##_at], !(keep)) ||                           \
            !pair_of(k, x, xi, neighbour_row(nl, i), pr##_at, &(pr))) {                            \
        } else

/* A parallel loop over the fluid whose work lies in S_F: S_F is a few layers of a fluid sorted
 * by cell, so static chunks would give one thread most of it. Each particle must write only
 * its own entries, so that the result does not depend on the schedule. */
#define PARALLEL_FOR_OVER_S_F _Pragma("omp parallel for schedule(dynamic, 256)")

#endif
