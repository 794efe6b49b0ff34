/* The thread tuner (app/threads.h) on made-up clocks: it times a window with all threads and
 * one with one, keeps the faster for THREADS_KEEP_WINDOWS windows, then measures again; it
 * says so once when one thread wins; with one thread allowed it does nothing. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "app/threads.h"

#include <omp.h>

/* One window of `steps` steps over THREADS_WINDOW_S seconds, step by step; returns what the
 * last call returned (a window ends only on its last step). */
static bool window(thread_tuner *tt, double *wall, long *step, long steps)
{
    bool told = false;
    double start = *wall;
    for (long k = 1; k <= steps; k++) {
        /* the last step a hair past the window, whatever the sum's rounding */
        *wall = start + THREADS_WINDOW_S * (k < steps ? (double)k / (double)steps : 1.000001);
        ++*step;
        told = thread_tuner_step(tt, *wall, *step);
    }
    return told;
}

static void test_one_thread_wins_on_a_busy_machine(void **state)
{
    (void)state;
    omp_set_num_threads(2);
    thread_tuner tt;
    double wall = 100.0;
    long step = 0;
    thread_tuner_start(&tt, wall, step);
    assert_int_equal(tt.current, 2);
    assert_false(window(&tt, &wall, &step, 50)); /* 2 threads: 25 steps/s */
    assert_int_equal(tt.current, 1);
    assert_int_equal(omp_get_max_threads(), 1);
    assert_true(window(&tt, &wall, &step, 80)); /* 1 thread: 40 steps/s, faster */
    assert_int_equal(tt.current, 1);
    for (int k = 0; k < THREADS_KEEP_WINDOWS - 1; k++) window(&tt, &wall, &step, 80);
    assert_int_equal(tt.current, 1);
    window(&tt, &wall, &step, 80); /* the kept windows are over: measure again */
    assert_int_equal(tt.current, 2);
    assert_false(window(&tt, &wall, &step, 90)); /* said once only */
    assert_false(window(&tt, &wall, &step, 80)); /* now 2 threads win */
    assert_int_equal(tt.current, 2);
    thread_tuner_stop(&tt);
    assert_int_equal(omp_get_max_threads(), 2);
}

static void test_all_threads_kept_on_an_idle_machine(void **state)
{
    (void)state;
    omp_set_num_threads(2);
    thread_tuner tt;
    double wall = 0.0;
    long step = 0;
    thread_tuner_start(&tt, wall, step);
    window(&tt, &wall, &step, 90);
    assert_false(window(&tt, &wall, &step, 50));
    assert_int_equal(tt.current, 2);
}

static void test_nothing_with_one_thread(void **state)
{
    (void)state;
    omp_set_num_threads(1);
    thread_tuner tt;
    double wall = 0.0;
    long step = 0;
    thread_tuner_start(&tt, wall, step);
    for (int k = 0; k < 5; k++) assert_false(window(&tt, &wall, &step, 10));
    assert_int_equal(tt.current, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_one_thread_wins_on_a_busy_machine),
        cmocka_unit_test(test_all_threads_kept_on_an_idle_machine),
        cmocka_unit_test(test_nothing_with_one_thread),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
