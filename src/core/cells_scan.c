/* cells_scan: the candidates of a run of cells against the search radius (core/cells_scan.h).
 * The candidates of a run are consecutive in the grid's item order, and so are their
 * positions in cell_grid.xs: a block of them is one load per axis, not a gather. */
#include "core/cells_scan.h"
#include "core/lanes_switch.h"

#include <immintrin.h>

static inline int32_t row_append(int32_t *row, int32_t found, int32_t cap, uint32_t j)
{
    if (found < cap) row[found] = (int32_t)j;
    return found + 1;
}

/* The candidates item[m + b] for the set bits b of `within`, in order. */
static inline int32_t append_bits(const cell_grid *g, size_t m, unsigned within, uint32_t self,
                                  int32_t *row, int32_t found, int32_t cap)
{
    while (within) {
        uint32_t j = g->item[m + (size_t)__builtin_ctz(within)];
        within &= within - 1;
        if (j != self) found = row_append(row, found, cap, j);
    }
    return found;
}

static int32_t scan_scalar(const cell_grid *g, size_t m, size_t last, vec xi, uint32_t self,
                           double r2max, int32_t *row, int32_t found, int32_t cap)
{
    for (; m < last; m++) {
        uint32_t j = g->item[m];
        if (j == self) continue;
        double r2 = 0.0; /* vec_norm2's order */
        for (int d = 0; d < DIM; d++) {
            double dx = g->xs[d][m] - xi.c[d];
            r2 += dx * dx;
        }
        if (r2 < r2max) found = row_append(row, found, cap, j);
    }
    return found;
}

/* Eight candidates at a time; the kept ones of a block are packed in order (a compress) and
 * stored at once when the row has room for the whole block. */
__attribute__((target("arch=x86-64-v4"))) static int32_t
scan_avx512(const cell_grid *g, size_t first, size_t last, vec xi, uint32_t self, double r2max,
            int32_t *row, int32_t found, int32_t cap)
{
    size_t m = first;
    const __m512d limit = _mm512_set1_pd(r2max);
    const __m256i me = _mm256_set1_epi32((int)self);
    for (; m + 8 <= last; m += 8) {
        __m512d r2 = _mm512_setzero_pd();
        for (int d = 0; d < DIM; d++) {
            __m512d dx = _mm512_sub_pd(_mm512_loadu_pd(g->xs[d] + m), _mm512_set1_pd(xi.c[d]));
            r2 = _mm512_add_pd(r2, _mm512_mul_pd(dx, dx));
        }
        __m256i items = _mm256_loadu_si256((const __m256i *)(g->item + m));
        __mmask8 within =
            _mm512_cmp_pd_mask(r2, limit, _CMP_LT_OQ) & _mm256_cmpneq_epi32_mask(items, me);
        if (found + 8 <= cap) {
            _mm256_storeu_si256((__m256i *)(row + found),
                                _mm256_maskz_compress_epi32(within, items));
            found += __builtin_popcount(within);
        } else {
            found = append_bits(g, m, within, self, row, found, cap);
        }
    }
    return scan_scalar(g, m, last, xi, self, r2max, row, found, cap);
}

/* Four candidates at a time, the kept ones appended one by one. */
__attribute__((target("arch=x86-64-v3"))) static int32_t
scan_avx2(const cell_grid *g, size_t first, size_t last, vec xi, uint32_t self, double r2max,
          int32_t *row, int32_t found, int32_t cap)
{
    size_t m = first;
    const __m256d limit = _mm256_set1_pd(r2max);
    for (; m + 4 <= last; m += 4) {
        __m256d r2 = _mm256_setzero_pd();
        for (int d = 0; d < DIM; d++) {
            __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(g->xs[d] + m), _mm256_set1_pd(xi.c[d]));
            r2 = _mm256_add_pd(r2, _mm256_mul_pd(dx, dx));
        }
        unsigned within = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(r2, limit, _CMP_LT_OQ));
        found = append_bits(g, m, within, self, row, found, cap);
    }
    return scan_scalar(g, m, last, xi, self, r2max, row, found, cap);
}

cells_scan_fn cells_scan_form(void)
{
    switch (lanes_width()) {
    case 8: return scan_avx512;
    case 4: return scan_avx2;
    default: return scan_scalar;
    }
}
