/* pair: the geometry of a neighbour row (core/pair.h), in SIMD blocks where the processor has
 * them. */
#include "core/pair.h"
#include "core/lanes_switch.h"
#include "core/pair_block.h"

#include <string.h>

/* pair_of, entry by entry, and what the blocks below store where it returns early: an entry
 * with r^2 beyond the support has its r, W and F (which are 0 unless r / h rounds below 2), the
 * padding up to the last block repeats the row's last entry with W = F = 0. Every entry of the
 * whole blocks holds the same numbers in either form (pair_block.h reads them). */
static void geometry_scalar(const kernel *k, double *const x[DIM], const int32_t *row,
                            int32_t count, vec xi, double *columns, size_t stride)
{
    int32_t padded = (count + PAIR_BLOCK - 1) / PAIR_BLOCK * PAIR_BLOCK;
    for (int32_t n = 0; n < padded; n++) {
        pair pr;
        if (!pair_of(k, x, xi, row, n < count ? n : count - 1, &pr)) {
            pr.r = sqrt(pr.r2);
            pr.w = kernel_w(k, pr.r);
            pr.f = kernel_f(k, pr.r);
        }
        if (n >= count) pr.w = pr.f = 0.0;
        for (int d = 0; d < DIM; d++) columns[(size_t)d * stride + (size_t)n] = pr.r_ji.c[d];
        columns[PAIR_R2 * stride + (size_t)n] = pr.r2;
        columns[PAIR_R * stride + (size_t)n] = pr.r;
        columns[PAIR_W * stride + (size_t)n] = pr.w;
        columns[PAIR_F * stride + (size_t)n] = pr.f;
    }
}

/* From entry PAIR_BLOCK - m on: m ones, then zeros */
static const double ones_then_zeros[2 * PAIR_BLOCK] = {1, 1, 1, 1, 1, 1, 1, 1,
                                                       0, 0, 0, 0, 0, 0, 0, 0};

/* pair_of's operations on PAIR_BLOCK entries at once, without its branch: vec_sub, vec_norm2
 * (0 + a_0^2 + a_1^2 (+ a_2^2)), sqrt, kernel_w and kernel_f, lane by lane in the scalar order, so
 * the same bits. Entries past the row's end repeat its last one, with W = F = 0, and land in the
 * columns' padding (stride is a multiple of PAIR_BLOCK). */
__attribute__((always_inline)) static inline void
geometry_blocks(const kernel *k, double *const x[DIM], const int32_t *row, int32_t count, vec xi,
                double *columns, size_t stride)
{
    for (int32_t n0 = 0; n0 < count; n0 += PAIR_BLOCK) {
        int32_t last[PAIR_BLOCK];
        const int32_t *j = pair_block_neighbours(row, count, n0, last);
        pair_block sum = {0}, r;
        for (int d = 0; d < DIM; d++) {
            pair_block c = pair_block_gather(x[d], j) - xi.c[d];
            sum += c * c;
            memcpy(&columns[(size_t)d * stride + (size_t)n0], &c, sizeof c);
        }
        for (int l = 0; l < PAIR_BLOCK; l++) r[l] = __builtin_sqrt(sum[l]);
        /* kernel_w and kernel_f, 0 where q >= 2, and (both are >= 0, so a product with 0 is
           +0) past the row's end: a second mask made GCC 12 take the block apart element by
           element */
        pair_block q = r * k->inv_h, s = 1.0 - 0.5 * q, s2 = s * s;
        pair_block w = k->norm * s2 * s2 * (1.0 + 2.0 * q), f = k->f_norm * s * s * s;
        pair_block_mask beyond = q >= 2.0;
        w = (pair_block)(~beyond & (pair_block_mask)w);
        f = (pair_block)(~beyond & (pair_block_mask)f);
        int32_t in_row = count - n0 < PAIR_BLOCK ? count - n0 : PAIR_BLOCK;
        pair_block in_row_ones;
        memcpy(&in_row_ones, &ones_then_zeros[PAIR_BLOCK - in_row], sizeof in_row_ones);
        w *= in_row_ones;
        f *= in_row_ones;
        memcpy(&columns[PAIR_R2 * stride + (size_t)n0], &sum, sizeof sum);
        memcpy(&columns[PAIR_R * stride + (size_t)n0], &r, sizeof r);
        memcpy(&columns[PAIR_W * stride + (size_t)n0], &w, sizeof w);
        memcpy(&columns[PAIR_F * stride + (size_t)n0], &f, sizeof f);
    }
}

/* Row i unpacked (neighbour_row) and its geometry, in the form the caller names: in SIMD
 * blocks (`blocks`, inlined into a function built for AVX2 or AVX-512, which unpacks the row
 * with the same vectors) or entry by entry. */
__attribute__((always_inline)) static inline pair_row
row_geometry(const kernel *k, double *const x[DIM], const neighbour_list *nl, size_t i, vec xi,
             int32_t *entries, double *columns, size_t stride, const bool blocks)
{
    pair_row rw = {neighbour_row(nl, i, entries), nl->count[i], stride, columns, k->support2};
    if (blocks)
        geometry_blocks(k, x, rw.row, rw.count, xi, columns, stride);
    else
        geometry_scalar(k, x, rw.row, rw.count, xi, columns, stride);
    return rw;
}

__attribute__((target("arch=x86-64-v4"))) static pair_row
row_geometry_avx512(const kernel *k, double *const x[DIM], const neighbour_list *nl, size_t i,
                    vec xi, int32_t *entries, double *columns, size_t stride)
{
    return row_geometry(k, x, nl, i, xi, entries, columns, stride, true);
}

__attribute__((target("arch=x86-64-v3"))) static pair_row
row_geometry_avx2(const kernel *k, double *const x[DIM], const neighbour_list *nl, size_t i, vec xi,
                  int32_t *entries, double *columns, size_t stride)
{
    return row_geometry(k, x, nl, i, xi, entries, columns, stride, true);
}

pair_row pair_row_of(const kernel *k, double *const x[DIM], const neighbour_list *nl, size_t i,
                     vec xi, int32_t *entries, double *columns, size_t stride)
{
    switch (lanes_width()) {
    case 8: return row_geometry_avx512(k, x, nl, i, xi, entries, columns, stride);
    case 4: return row_geometry_avx2(k, x, nl, i, xi, entries, columns, stride);
    default: return row_geometry(k, x, nl, i, xi, entries, columns, stride, false);
    }
}
