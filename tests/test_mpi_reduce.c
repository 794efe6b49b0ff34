/* The MPI build's global reductions (parallel/mpi_reduce.h), run by ctest on 1 to 4 processes:
 * the sum of values of both signs over 8 decades, split among the processes in every way that
 * matters (evenly, all on one process, empty processes, ranges shorter than a block, random
 * cuts), is reduce_sum's of the whole array to the bit; maximum, minimum and count are exact.
 * The values make the order count: summed left to right without blocks, they give another
 * double (checked), so a sum that grouped them differently would fail here; one that adds each
 * process's own sum does, on 2 processes and more. Every process checks the same result, so a
 * failure stops all of them at the same assertion. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "core/reduce.h"
#include "noise.h"
#include "parallel/mpi_reduce.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int n_ranks, rank;

static double *values(size_t n, uint64_t seed)
{
    double *a = malloc((n ? n : 1) * sizeof *a);
    assert_non_null(a);
    for (size_t i = 0; i < n; i++) a[i] = noise(&seed) * pow(10.0, 4.0 * noise(&seed));
    return a;
}

/* The processes' ranges: cut[r] .. cut[r + 1], by way of splitting n. */
enum split { EVEN, ALL_ON_LAST, FIRST_EMPTY, RANDOM, N_SPLITS };

static void cuts(enum split how, size_t n, uint64_t seed, size_t *cut)
{
    cut[0] = 0;
    cut[n_ranks] = n;
    for (int r = 1; r < n_ranks; r++) {
        switch (how) {
        case EVEN: cut[r] = n * (size_t)r / (size_t)n_ranks; break;
        case ALL_ON_LAST: cut[r] = 0; break;
        case FIRST_EMPTY: cut[r] = r == 1 ? 0 : n * (size_t)r / (size_t)n_ranks; break;
        default: cut[r] = (size_t)((noise(&seed) + 1.0) * 0.5 * (double)n); break;
        }
    }
    for (int r = 1; r < n_ranks; r++) /* random cuts in order */
        for (int q = r + 1; q < n_ranks; q++)
            if (cut[q] < cut[r]) {
                size_t t = cut[q];
                cut[q] = cut[r];
                cut[r] = t;
            }
}

static void test_sum_is_reduce_sum(void **state)
{
    (void)state;
    const size_t sizes[] = {
        0, 1, 7, REDUCE_BLOCK - 1, REDUCE_BLOCK, REDUCE_BLOCK + 1, 3 * REDUCE_BLOCK + 5, 50000};
    size_t cut[8];
    for (size_t k = 0; k < sizeof sizes / sizeof *sizes; k++) {
        size_t n = sizes[k];
        double *a = values(n, 11 + k), expect = reduce_sum(a, n);
        for (int how = 0; how < N_SPLITS; how++) {
            for (uint64_t trial = 0; trial < (how == RANDOM ? 5u : 1u); trial++) {
                cuts(how, n, 100 * k + trial, cut);
                double got =
                    mpi_reduce_sum(a + cut[rank], cut[rank + 1] - cut[rank], MPI_COMM_WORLD);
                assert_memory_equal(&got, &expect, sizeof got);
            }
        }
        if (n > 2 * REDUCE_BLOCK) { /* from the third block on, the grouping changes the sum */
            double left_to_right = 0.0;
            for (size_t i = 0; i < n; i++) left_to_right += a[i];
            assert_true(left_to_right != expect);
        }
        free(a);
    }
}

static void test_max_min_total(void **state)
{
    (void)state;
    size_t n = 10000, cut[8];
    double *a = values(n, 5);
    for (int how = 0; how < N_SPLITS; how++) {
        cuts(how, n, 3, cut);
        size_t mine = cut[rank + 1] - cut[rank];
        assert_true(mpi_reduce_max(a + cut[rank], mine, MPI_COMM_WORLD) == reduce_max(a, n));
        assert_true(mpi_reduce_min(a + cut[rank], mine, MPI_COMM_WORLD) == reduce_min(a, n));
        assert_int_equal(mpi_reduce_total((long)mine, MPI_COMM_WORLD), (long)n);
    }
    assert_true(mpi_reduce_max(a, 0, MPI_COMM_WORLD) == -INFINITY);
    free(a);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (n_ranks > 7) MPI_Abort(MPI_COMM_WORLD, 2); /* cut[] holds 8 */
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sum_is_reduce_sum),
        cmocka_unit_test(test_max_min_total),
    };
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    MPI_Finalize();
    return failed;
}
