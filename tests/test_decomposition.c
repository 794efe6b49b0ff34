/* The split of the tank among MPI processes (parallel/decomposition.h): every split covers the
 * strips once, in order, one strip or more per process; its largest slab is the smallest any
 * split can have (checked against every split of small cases); the same counts give the same
 * split; and the boundaries follow the liquid when it moves to one end of the tank. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "noise.h"
#include "parallel/decomposition.h"

#include <string.h>

#define MAX_STRIPS 10
#define MAX_RANKS  5

static void assert_valid(const size_t *first, size_t n_strips, int n_ranks)
{
    assert_int_equal(first[0], 0);
    assert_int_equal(first[n_ranks], n_strips);
    for (int r = 0; r < n_ranks; r++) assert_true(first[r + 1] > first[r]);
}

/* The smallest largest slab over every split of n strips into k slabs, by enumeration. */
static size_t best_by_enumeration(const size_t *count, size_t n, int k)
{
    if (k == 1) {
        size_t load = 0;
        for (size_t s = 0; s < n; s++) load += count[s];
        return load;
    }
    size_t best = SIZE_MAX, head = 0;
    for (size_t cut = 1; cut + (size_t)(k - 1) <= n; cut++) { /* the first slab: strips < cut */
        head += count[cut - 1];
        size_t rest = best_by_enumeration(count + cut, n - cut, k - 1);
        size_t largest = head > rest ? head : rest;
        if (largest < best) best = largest;
    }
    return best;
}

static void test_optimal_against_enumeration(void **state)
{
    (void)state;
    uint64_t seed = 7;
    for (int trial = 0; trial < 400; trial++) {
        size_t n = 1 + (size_t)((noise(&seed) + 1.0) * 0.5 * MAX_STRIPS);
        if (n > MAX_STRIPS) n = MAX_STRIPS;
        size_t count[MAX_STRIPS], first[MAX_RANKS + 1];
        for (size_t s = 0; s < n; s++) /* empty strips too: the air above a tank's end */
            count[s] = trial % 3 == 0 && s % 2 ? 0 : (size_t)((noise(&seed) + 1.0) * 500.0);
        for (int k = 1; k <= MAX_RANKS; k++) {
            if ((size_t)k > n) {
                assert_int_equal(decomposition_balance(count, n, k, first), -1);
                continue;
            }
            assert_int_equal(decomposition_balance(count, n, k, first), 0);
            assert_valid(first, n, k);
            assert_int_equal(decomposition_largest(count, k, first),
                             best_by_enumeration(count, n, k));
            size_t again[MAX_RANKS + 1];
            decomposition_balance(count, n, k, again);
            assert_memory_equal(first, again, (size_t)(k + 1) * sizeof *first);
        }
    }
}

/* 40 strips; the liquid first level (100 a strip), then piled at the right end, as at the
 * crest of a sloshing period: four processes' boundaries move right, and the busiest process
 * holds no more than a quarter of the liquid plus one strip. */
static void test_boundaries_follow_the_liquid(void **state)
{
    (void)state;
    enum { N = 40, P = 4 };
    size_t count[N], level[P + 1], piled[P + 1], total = 0, largest_strip = 0;
    for (size_t s = 0; s < N; s++) count[s] = 100;
    assert_int_equal(decomposition_balance(count, N, P, level), 0);
    size_t expect[P + 1] = {0, 10, 20, 30, 40};
    assert_memory_equal(level, expect, sizeof expect);
    for (size_t s = 0; s < N; s++) {
        count[s] = 20 + 10 * s; /* 20 .. 410 */
        total += count[s];
        if (count[s] > largest_strip) largest_strip = count[s];
    }
    assert_int_equal(decomposition_balance(count, N, P, piled), 0);
    assert_valid(piled, N, P);
    for (int r = 1; r < P; r++) assert_true(piled[r] > level[r]);
    assert_true(decomposition_largest(count, P, piled) <= total / P + largest_strip);
}

static void test_too_many_ranks(void **state)
{
    (void)state;
    size_t count[3] = {5, 5, 5}, first[5];
    assert_int_equal(decomposition_balance(count, 3, 4, first), -1);
    assert_int_equal(decomposition_balance(count, 0, 1, first), -1);
    assert_int_equal(decomposition_balance(count, 3, 3, first), 0);
    size_t each[4] = {0, 1, 2, 3};
    assert_memory_equal(first, each, sizeof each);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_optimal_against_enumeration),
        cmocka_unit_test(test_boundaries_follow_the_liquid),
        cmocka_unit_test(test_too_many_ranks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
