/* decomposition: slabs of strips balanced by particle count (a linear partition). */
#include "parallel/decomposition.h"

#include <stdbool.h>

/* Greedy from the left: each slab takes strips while it stays within `bound`, but leaves at
 * least one strip for every slab after it. Fills first[] and returns whether the strips fit
 * in n_ranks such slabs. Taking as much as fits uses the fewest slabs for that bound, so the
 * strips fit whenever any split within it exists. */
static bool fits(const size_t *count, size_t n_strips, int n_ranks, size_t bound, size_t *first)
{
    size_t s = 0;
    first[0] = 0;
    for (int r = 0; r < n_ranks; r++) {
        size_t strips_after = (size_t)(n_ranks - 1 - r); /* one for each later slab */
        size_t load = 0;
        if (s >= n_strips - strips_after) return false; /* no strip left for this slab */
        do {
            if (count[s] > bound) return false;
            load += count[s++];
        } while (s < n_strips - strips_after && load + count[s] <= bound);
        first[r + 1] = s;
    }
    return s == n_strips;
}

int decomposition_balance(const size_t *count, size_t n_strips, int n_ranks, size_t *first)
{
    if (n_ranks < 1 || n_strips < (size_t)n_ranks) return -1;
    size_t lo = 0, hi = 0; /* the best bound lies in [largest strip, all particles] */
    for (size_t s = 0; s < n_strips; s++) {
        if (count[s] > lo) lo = count[s];
        hi += count[s];
    }
    while (lo < hi) { /* the smallest bound that fits: fits() is monotonic in it */
        size_t mid = lo + (hi - lo) / 2;
        if (fits(count, n_strips, n_ranks, mid, first))
            hi = mid;
        else
            lo = mid + 1;
    }
    fits(count, n_strips, n_ranks, lo, first);
    return 0;
}

size_t decomposition_largest(const size_t *count, int n_ranks, const size_t *first)
{
    size_t largest = 0;
    for (int r = 0; r < n_ranks; r++) {
        size_t load = 0;
        for (size_t s = first[r]; s < first[r + 1]; s++) load += count[s];
        if (load > largest) largest = load;
    }
    return largest;
}
