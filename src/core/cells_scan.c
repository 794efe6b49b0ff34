/* cells_scan: the candidates of a run of cells against the search radius, and the split of a
 * row into its near part and its skin (core/cells_scan.h). The candidates of a run are
 * consecutive in the grid's item order, and so are their positions in cell_grid.xs: a block
 * of them is one load per axis, not a gather. */
#include "core/cells_scan.h"
#include "core/lanes_switch.h"

#include <immintrin.h>
#include <stdbool.h>
#include <string.h>

static inline void row_append(scan_row *row, uint32_t j, double r2)
{
    if (row->found < row->cap) {
        row->entries[row->found] = (int32_t)j;
        row->r2[row->found] = r2;
    }
    row->found++;
}

/* The candidates item[m + b] other than `self` for the set bits b of `within`, in order, with
 * their squared distances r2[b]. */
static inline void append_bits(const cell_grid *g, size_t m, unsigned within, uint32_t self,
                               const double *r2, scan_row *row)
{
    while (within) {
        unsigned b = (unsigned)__builtin_ctz(within);
        uint32_t j = g->item[m + b];
        within &= within - 1;
        if (j != self) row_append(row, j, r2[b]);
    }
}

/* The candidates item[m .. last) one by one (a form's last few, or the scalar form's all). */
static inline void scan_tail(const cell_grid *g, size_t m, size_t last, vec xi, uint32_t self,
                             double r2max, scan_row *row)
{
    for (; m < last; m++) {
        uint32_t j = g->item[m];
        if (j == self) continue;
        double r2 = 0.0; /* vec_norm2's order */
        for (int d = 0; d < DIM; d++) {
            double dx = g->xs[d][m] - xi.c[d];
            r2 += dx * dx;
        }
        if (r2 < r2max) row_append(row, j, r2);
    }
}

/* Each form works on a copy of the row's state: the count in a register, not reloaded after
 * every store of an entry (which, as far as the compiler knows, could have changed it). */
static void scan_scalar(const cell_grid *g, size_t first, size_t last, vec xi, uint32_t self,
                        double r2max, scan_row *into)
{
    scan_row r = *into;
    scan_tail(g, first, last, xi, self, r2max, &r);
    *into = r;
}

/* Eight candidates at a time; the kept ones of a block and their squared distances are packed
 * in order (a compress) and stored at once when the row has room for the whole block. */
__attribute__((target("arch=x86-64-v4"))) static void scan_avx512(const cell_grid *g, size_t first,
                                                                  size_t last, vec xi,
                                                                  uint32_t self, double r2max,
                                                                  scan_row *into)
{
    scan_row r = *into;
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
        if (r.found + 8 <= r.cap) {
            _mm256_storeu_si256((__m256i *)(r.entries + r.found),
                                _mm256_maskz_compress_epi32(within, items));
            _mm512_storeu_pd(r.r2 + r.found, _mm512_maskz_compress_pd(within, r2));
            r.found += __builtin_popcount(within);
        } else {
            double lanes[8];
            _mm512_storeu_pd(lanes, r2);
            append_bits(g, m, within, self, lanes, &r);
        }
    }
    scan_tail(g, m, last, xi, self, r2max, &r);
    *into = r;
}

/* Four candidates at a time, the kept ones appended one by one. */
__attribute__((target("arch=x86-64-v3"))) static void scan_avx2(const cell_grid *g, size_t first,
                                                                size_t last, vec xi, uint32_t self,
                                                                double r2max, scan_row *into)
{
    scan_row r = *into;
    size_t m = first;
    const __m256d limit = _mm256_set1_pd(r2max);
    for (; m + 4 <= last; m += 4) {
        __m256d r2 = _mm256_setzero_pd();
        for (int d = 0; d < DIM; d++) {
            __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(g->xs[d] + m), _mm256_set1_pd(xi.c[d]));
            r2 = _mm256_add_pd(r2, _mm256_mul_pd(dx, dx));
        }
        unsigned within = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(r2, limit, _CMP_LT_OQ));
        if (!within) continue;
        double lanes[4];
        _mm256_storeu_pd(lanes, r2);
        append_bits(g, m, within, self, lanes, &r);
    }
    scan_tail(g, m, last, xi, self, r2max, &r);
    *into = r;
}

cells_scan_fn cells_scan_form(void)
{
    switch (lanes_width()) {
    case 8: return scan_avx512;
    case 4: return scan_avx2;
    default: return scan_scalar;
    }
}

/* cells_split_fn, entry by entry without a branch on the distance (which the pairs decide):
 * each entry is written to both parts, and only its own part's count moves on. */
static int32_t split_scalar(const int32_t *entries, const double *r2, int32_t count, double near2,
                            int32_t *row, int32_t *skin)
{
    int32_t n_near = 0, n_skin = 0;
    for (int32_t k = 0; k < count; k++) {
        bool in_near = r2[k] < near2;
        row[n_near] = skin[n_skin] = entries[k];
        n_near += in_near;
        n_skin += !in_near;
    }
    memcpy(row + n_near, skin, (size_t)n_skin * sizeof *row);
    return n_near;
}

/* cells_split_fn eight entries at a time: each part of a block packed in order (a compress)
 * and stored whole (the slack takes the lanes past the part's end). */
__attribute__((target("arch=x86-64-v4"))) static int32_t split_avx512(const int32_t *entries,
                                                                      const double *r2,
                                                                      int32_t count, double near2,
                                                                      int32_t *row, int32_t *skin)
{
    const __m512d limit = _mm512_set1_pd(near2);
    int32_t n_near = 0, n_skin = 0;
    for (int32_t k = 0; k < count; k += 8) {
        __mmask8 live = count - k >= 8 ? 0xff : (__mmask8)((1u << (count - k)) - 1u);
        __m512d d2 = _mm512_maskz_loadu_pd(live, r2 + k);
        __m256i e = _mm256_maskz_loadu_epi32(live, entries + k);
        __mmask8 in_near = _mm512_mask_cmp_pd_mask(live, d2, limit, _CMP_LT_OQ);
        __mmask8 in_skin = live & (__mmask8)~in_near;
        _mm256_storeu_si256((__m256i *)(row + n_near), _mm256_maskz_compress_epi32(in_near, e));
        _mm256_storeu_si256((__m256i *)(skin + n_skin), _mm256_maskz_compress_epi32(in_skin, e));
        n_near += __builtin_popcount(in_near);
        n_skin += __builtin_popcount(in_skin);
    }
    memcpy(row + n_near, skin, (size_t)n_skin * sizeof *row);
    return n_near;
}

/* For each mask of four lanes, the shuffle (_mm_shuffle_epi8) that packs the set lanes' 32-bit
 * values in order at the front (-1: a zero byte): AVX2 has no compress. */
static const int8_t pack4[16][16] = {
    {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1},
    {0, 1, 2, 3, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1},
    {4, 5, 6, 7, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1},
    {0, 1, 2, 3, 4, 5, 6, 7, -1, -1, -1, -1, -1, -1, -1, -1},
    {8, 9, 10, 11, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1},
    {0, 1, 2, 3, 8, 9, 10, 11, -1, -1, -1, -1, -1, -1, -1, -1},
    {4, 5, 6, 7, 8, 9, 10, 11, -1, -1, -1, -1, -1, -1, -1, -1},
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, -1, -1, -1, -1},
    {12, 13, 14, 15, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1},
    {0, 1, 2, 3, 12, 13, 14, 15, -1, -1, -1, -1, -1, -1, -1, -1},
    {4, 5, 6, 7, 12, 13, 14, 15, -1, -1, -1, -1, -1, -1, -1, -1},
    {0, 1, 2, 3, 4, 5, 6, 7, 12, 13, 14, 15, -1, -1, -1, -1},
    {8, 9, 10, 11, 12, 13, 14, 15, -1, -1, -1, -1, -1, -1, -1, -1},
    {0, 1, 2, 3, 8, 9, 10, 11, 12, 13, 14, 15, -1, -1, -1, -1},
    {4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, -1, -1, -1, -1},
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
};

/* cells_split_fn four entries at a time, each part of a block packed in order (pack4) and
 * stored whole (the slack takes the lanes past the part's end); a last block of fewer with
 * masked loads. */
__attribute__((target("arch=x86-64-v3"))) static int32_t split_avx2(const int32_t *entries,
                                                                    const double *r2, int32_t count,
                                                                    double near2, int32_t *row,
                                                                    int32_t *skin)
{
    const __m256d limit = _mm256_set1_pd(near2);
    const __m128i lane = _mm_setr_epi32(0, 1, 2, 3);
    int32_t n_near = 0, n_skin = 0;
    for (int32_t k = 0; k < count; k += 4) {
        __m128i live32 = _mm_cmpgt_epi32(_mm_set1_epi32(count - k), lane);
        __m256i live = _mm256_cvtepi32_epi64(live32);
        __m256d d2 = _mm256_maskload_pd(r2 + k, live);
        __m128i e = _mm_maskload_epi32(entries + k, live32);
        unsigned live_bits = (unsigned)_mm256_movemask_pd(_mm256_castsi256_pd(live));
        unsigned in_near =
            (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(d2, limit, _CMP_LT_OQ)) & live_bits;
        unsigned in_skin = live_bits & ~in_near;
        _mm_storeu_si128((__m128i *)(row + n_near),
                         _mm_shuffle_epi8(e, _mm_loadu_si128((const __m128i *)pack4[in_near])));
        _mm_storeu_si128((__m128i *)(skin + n_skin),
                         _mm_shuffle_epi8(e, _mm_loadu_si128((const __m128i *)pack4[in_skin])));
        n_near += __builtin_popcount(in_near);
        n_skin += __builtin_popcount(in_skin);
    }
    memcpy(row + n_near, skin, (size_t)n_skin * sizeof *row);
    return n_near;
}

cells_split_fn cells_split_form(void)
{
    switch (lanes_width()) {
    case 8: return split_avx512;
    case 4: return split_avx2;
    default: return split_scalar;
    }
}
