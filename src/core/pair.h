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

/* The one neighbour loop of every pass: the pairs (i, j) of particle i at xi whose distance
 * is within 2h, one by one in `pr` (declared by the caller), in the list's order:
 *
 *     pair pr;
 *     FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) { ... pr.j, pr.r_ji, pr.f ... }
 *
 * Each pass supplies only its pair functions (src/physics). `continue` goes to the next pair,
 * `break` ends the loop. */
#define FOR_EACH_PAIR(k, x, nl, i, xi, pr)                                                         \
    for (int32_t pr##_at = 0; pr##_at < (nl)->count[i]; pr##_at++)                                 \
        if (!pair_of(k, x, xi, neighbour_row(nl, i), pr##_at, &(pr))) {                            \
        } else

/* A parallel loop over the fluid whose work lies in S_F: S_F is a few layers of a fluid sorted
 * by cell, so static chunks would give one thread most of it. Each particle must write only
 * its own entries, so that the result does not depend on the schedule. */
#define PARALLEL_FOR_OVER_S_F _Pragma("omp parallel for schedule(dynamic, 256)")

#endif
