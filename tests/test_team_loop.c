/* The team loop (core/team_loop.h): every item is taken exactly once, whatever the thread
 * count and however the threads' speeds differ, and a thread that is held up has its share
 * taken by the others. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>
#include <cmocka.h>

#include "core/team_loop.h"

#include <omp.h>

/* n items over `threads` threads, thread `late` (-1: none) held up 20 ms before it starts;
 * taker[i] the thread that took item i, each item's count of takings in taken[i]. */
static void run(int threads, size_t n, size_t chunk, int late, int *taken, int *taker)
{
    omp_set_num_threads(threads);
    for (size_t i = 0; i < n; i++) taken[i] = 0, taker[i] = -1;
    TEAM_LOOP_SHARES(q, n, chunk);
#pragma omp parallel
    {
        if (omp_get_thread_num() == late) nanosleep(&(struct timespec){0, 20000000}, NULL);
        TEAM_LOOP_FOR (&q, begin, end) {
            for (size_t i = begin; i < end; i++) {
                __atomic_add_fetch(&taken[i], 1, __ATOMIC_RELAXED);
                taker[i] = omp_get_thread_num();
            }
        }
    }
}

static void test_every_item_once(void **state)
{
    (void)state;
    enum { N = 10007 }; /* not a multiple of the chunk: a short last chunk */
    int *taken = malloc(N * sizeof *taken), *taker = malloc(N * sizeof *taker);
    for (int threads = 1; threads <= 4; threads++)
        for (int late = -1; late < threads; late++) {
            run(threads, N, 64, late, taken, taker);
            for (size_t i = 0; i < N; i++) assert_int_equal(taken[i], 1);
        }
    run(3, 0, 64, -1, taken, taker); /* no items: nothing taken, no chunk past the end */
    free(taken);
    free(taker);
}

/* Two threads, the first held up until the second has left the loop: the second takes its own
 * share, then the whole of the first's from the back, and the first finds nothing left. */
static void test_idle_thread_share_is_taken(void **state)
{
    (void)state;
    enum { N = 64 * 1000 + 5 };
    int *taken = malloc(N * sizeof *taken), *taker = malloc(N * sizeof *taker);
    for (size_t i = 0; i < N; i++) taken[i] = 0, taker[i] = -1;
    omp_set_num_threads(2);
    int second_done = 0, first_took = 0;
    TEAM_LOOP_SHARES(q, N, 64);
#pragma omp parallel
    {
        int me = omp_get_thread_num();
        if (omp_get_num_threads() == 2 && me == 0)
            while (!__atomic_load_n(&second_done, __ATOMIC_ACQUIRE)) continue;
        TEAM_LOOP_FOR (&q, begin, end) {
            if (me == 0) first_took = 1;
            for (size_t i = begin; i < end; i++) taken[i]++, taker[i] = me;
        }
        if (me == 1) __atomic_store_n(&second_done, 1, __ATOMIC_RELEASE);
    }
    if (omp_get_max_threads() < 2) skip(); /* no second thread to be had */
    assert_false(first_took);
    for (size_t i = 0; i < N; i++) {
        assert_int_equal(taken[i], 1);
        assert_int_equal(taker[i], 1);
    }
    free(taken);
    free(taker);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_item_once),
        cmocka_unit_test(test_idle_thread_share_is_taken),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
