/* cells_scan: the candidates of a run of cells against the search radius (core/cells_scan.h).
 * The candidates of a run are consecutive in the grid's item order, and so are their
 * positions in cell_grid.xs: a block of them is one load per axis, not a gather. */
#include "core/cells_scan.h"
#include "core/lanes_switch.h"

#include <immintrin.h>

static inline int32_t part_append(int32_t *part, int32_t found, int32_t cap, uint32_t j)
{
    if (found < cap) part[found] = (int32_t)j;
    return found + 1;
}

/* Candidate j at squared distance r2 into its part of the row, if within the search radius */
static inline void row_append(scan_row *row, uint32_t j, double r2)
{
    if (r2 < row->near2)
        row->n_near = part_append(row->near, row->n_near, row->cap, j);
    else if (r2 < row->r2max)
        row->n_skin = part_append(row->skin, row->n_skin, row->cap, j);
}

/* The candidates item[m + b] for the set bits b of `kept`, in order, into one part. */
static inline int32_t append_bits(const cell_grid *g, size_t m, unsigned kept, int32_t *part,
                                  int32_t found, int32_t cap)
{
    while (kept) {
        uint32_t j = g->item[m + (size_t)__builtin_ctz(kept)];
        kept &= kept - 1;
        found = part_append(part, found, cap, j);
    }
    return found;
}

/* Each form works on a copy of the row's state: the counts in registers, not reloaded after
 * every store of an entry (which, as far as the compiler knows, could have changed them). */
static void scan_scalar(const cell_grid *g, size_t m, size_t last, vec xi, uint32_t self,
                        scan_row *into)
{
    scan_row r = *into, *row = &r;
    for (; m < last; m++) {
        uint32_t j = g->item[m];
        if (j == self) continue;
        double r2 = 0.0; /* vec_norm2's order */
        for (int d = 0; d < DIM; d++) {
            double dx = g->xs[d][m] - xi.c[d];
            r2 += dx * dx;
        }
        row_append(row, j, r2);
    }
    *into = r;
}

/* The kept candidates of a block of eight (self already dropped) into one part: packed in
 * order (a compress) and stored at once where the part has room for the whole block. */
__attribute__((target("arch=x86-64-v4"))) static inline int32_t
part_store8(const cell_grid *g, size_t m, __m256i items, __mmask8 kept, int32_t *part,
            int32_t found, int32_t cap)
{
    if (found + 8 > cap) return append_bits(g, m, kept, part, found, cap);
    _mm256_storeu_si256((__m256i *)(part + found), _mm256_maskz_compress_epi32(kept, items));
    return found + __builtin_popcount(kept);
}

/* Eight candidates at a time */
__attribute__((target("arch=x86-64-v4"))) static void
scan_avx512(const cell_grid *g, size_t first, size_t last, vec xi, uint32_t self, scan_row *into)
{
    scan_row r = *into, *row = &r;
    size_t m = first;
    const __m512d near = _mm512_set1_pd(row->near2), limit = _mm512_set1_pd(row->r2max);
    const __m256i me = _mm256_set1_epi32((int)self);
    for (; m + 8 <= last; m += 8) {
        __m512d r2 = _mm512_setzero_pd();
        for (int d = 0; d < DIM; d++) {
            __m512d dx = _mm512_sub_pd(_mm512_loadu_pd(g->xs[d] + m), _mm512_set1_pd(xi.c[d]));
            r2 = _mm512_add_pd(r2, _mm512_mul_pd(dx, dx));
        }
        __m256i items = _mm256_loadu_si256((const __m256i *)(g->item + m));
        __mmask8 other = _mm256_cmpneq_epi32_mask(items, me);
        __mmask8 in_near = _mm512_cmp_pd_mask(r2, near, _CMP_LT_OQ) & other;
        __mmask8 in_skin = _mm512_cmp_pd_mask(r2, limit, _CMP_LT_OQ) & other & ~in_near;
        if (in_near)
            row->n_near = part_store8(g, m, items, in_near, row->near, row->n_near, row->cap);
        if (in_skin)
            row->n_skin = part_store8(g, m, items, in_skin, row->skin, row->n_skin, row->cap);
    }
    *into = r;
    scan_scalar(g, m, last, xi, self, into);
}

/* Four candidates at a time, the kept ones appended one by one. */
__attribute__((target("arch=x86-64-v3"))) static void
scan_avx2(const cell_grid *g, size_t first, size_t last, vec xi, uint32_t self, scan_row *into)
{
    scan_row r = *into, *row = &r;
    size_t m = first;
    const __m256d near = _mm256_set1_pd(row->near2), limit = _mm256_set1_pd(row->r2max);
    for (; m + 4 <= last; m += 4) {
        __m256d r2 = _mm256_setzero_pd();
        for (int d = 0; d < DIM; d++) {
            __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(g->xs[d] + m), _mm256_set1_pd(xi.c[d]));
            r2 = _mm256_add_pd(r2, _mm256_mul_pd(dx, dx));
        }
        unsigned in_near = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(r2, near, _CMP_LT_OQ));
        unsigned kept = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(r2, limit, _CMP_LT_OQ));
        while (kept) {
            unsigned b = (unsigned)__builtin_ctz(kept);
            uint32_t j = g->item[m + b];
            kept &= kept - 1;
            if (j == self) continue;
            if (in_near >> b & 1u)
                row->n_near = part_append(row->near, row->n_near, row->cap, j);
            else
                row->n_skin = part_append(row->skin, row->n_skin, row->cap, j);
        }
    }
    *into = r;
    scan_scalar(g, m, last, xi, self, into);
}

cells_scan_fn cells_scan_form(void)
{
    switch (lanes_width()) {
    case 8: return scan_avx512;
    case 4: return scan_avx2;
    default: return scan_scalar;
    }
}
