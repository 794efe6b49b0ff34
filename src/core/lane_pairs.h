/* lane_pairs: FOR_EACH_PAIR for LANES particles side by side (core/lanes.h). Step n gives each
 * lane the n-th entry of its own particle's row, with the pair geometry of pair_of (r_ji, r^2,
 * F) computed by the same operations, and a mask of the lanes whose entry exists and lies
 * within 2h: a pass adds a lane's pair term only where the mask is set, so each particle's sums
 * see its pairs in its row's order, as in the scalar loop. */
#ifndef VCSPH_LANE_PAIRS_H
#define VCSPH_LANE_PAIRS_H

#include "core/lanes.h"
#include "core/pair.h"

#include <stdbool.h>

typedef struct {
    int32_t j[LANES]; /* the lane's neighbour; the particle itself past the end of its row */
    lane_mask within; /* the lane has a pair at this step: within 2h */
    lane_vec r_ji;
    lane_real r2, f;
} lane_pair;

/* The rows of particles i0 .. i0 + LANES - 1 and their positions. */
typedef struct {
    const int32_t *row[LANES];
    int32_t count[LANES], most;
    lane_vec xi;
} lane_rows;

/* The rows, unpacked into `entries` (room for LANES rows of the list's length, neighbour_row) */
LANE_INLINE lane_rows lane_rows_of(const neighbour_list *nl, double *const x[DIM], size_t i0,
                                   int32_t *entries)
{
    lane_rows rows;
    rows.most = 0;
    for (int l = 0; l < LANES; l++) {
        rows.row[l] = neighbour_row(nl, i0 + (size_t)l, entries + (size_t)l * nl->row_capacity);
        rows.count[l] = nl->count[i0 + (size_t)l];
        if (rows.count[l] > rows.most) rows.most = rows.count[l];
    }
    rows.xi = lane_vec_load(x, i0);
    return rows;
}

/* kernel_f of each lane */
LANE_INLINE lane_real lane_kernel_f(const kernel *k, lane_real r)
{
    lane_real q = r * k->inv_h;
    lane_real s = 1.0 - 0.5 * q;
    return lane_select(q >= 2.0, lane_broadcast(0.0), k->f_norm * s * s * s);
}

/* Step n of the rows from i0; false when no lane has a pair within 2h there. */
LANE_INLINE bool lane_pair_at(const kernel *k, double *const x[DIM], const lane_rows *rows,
                              size_t i0, int32_t n, lane_pair *pr)
{
    lane_mask active;
    for (int l = 0; l < LANES; l++) {
        bool has = n < rows->count[l];
        active[l] = has ? -1 : 0;
        pr->j[l] = has ? rows->row[l][n] : (int32_t)(i0 + (size_t)l);
    }
    pr->r_ji = lane_vec_sub(lane_vec_gather(x, pr->j), rows->xi);
    pr->r2 = lane_vec_dot(pr->r_ji, pr->r_ji);
    pr->within = active & (pr->r2 < lane_broadcast(k->support2));
    if (!lane_any(pr->within)) return false;
    pr->f = lane_kernel_f(k, lane_sqrt(pr->r2));
    return true;
}

/* The lanes' loop, as FOR_EACH_PAIR's:
 *
 *     lane_pair pr;
 *     FOR_EACH_LANE_PAIR (k, p->x, nl, i0, pr) { ... pr.j, pr.within, pr.r_ji, pr.f ... }
 */
#define FOR_EACH_LANE_PAIR(k, x, nl, i0, pr)                                                       \
    for (int32_t pr##_entries[LANES * (nl)->row_capacity], *pr##_go = pr##_entries; pr##_go;       \
         pr##_go = NULL)                                                                           \
        for (lane_rows pr##_rows = lane_rows_of(nl, x, i0, pr##_entries), *pr##_once = &pr##_rows; \
             pr##_once; pr##_once = NULL)                                                          \
            for (int32_t pr##_n = 0; pr##_n < pr##_rows.most; pr##_n++)                            \
                if (!lane_pair_at(k, x, &pr##_rows, i0, pr##_n, &(pr))) {                          \
                } else

#endif
