/* The thread tuner (app/threads.h) on made-up clocks: after a window with all threads in which
 * the run waited for a core (busy), it times one with one thread, keeps the faster for
 * THREADS_KEEP_WINDOWS windows, then measures again, and says so once when one thread wins;
 * when the run never waits (idle) it never tries one thread; with one thread allowed it does
 * nothing. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "app/threads.h"

#include <omp.h>

typedef struct {
    double wall, delay;
    long step;
} clocks;

/* One window of `steps` steps over THREADS_WINDOW_S seconds, in which the run waits for a core
 * a share `waiting` of the time (-1: not known); returns what the last call returned. */
static bool window(thread_tuner *tt, clocks *c, long steps, double waiting)
{
    bool told = false;
    double start = c->wall, delay0 = c->delay;
    for (long k = 1; k <= steps; k++) {
        /* the last step a hair past the window, whatever the sum's rounding */
        double f = k < steps ? (double)k / (double)steps : 1.000001;
        c->wall = start + THREADS_WINDOW_S * f;
        c->delay = waiting < 0.0 ? -1.0 : delay0 + waiting * THREADS_WINDOW_S * f;
        c->step++;
        if (thread_tuner_due(tt, c->wall)) told = thread_tuner_step(tt, c->wall, c->delay, c->step);
    }
    return told;
}

/* A tuner started with `threads` allowed, on clocks at c. */
static void start(thread_tuner *tt, int threads, clocks c)
{
    omp_set_num_threads(threads);
    thread_tuner_start(tt, c.wall, c.delay, c.step);
}

static void test_one_thread_wins_on_a_busy_machine(void **state)
{
    (void)state;
    thread_tuner tt;
    clocks c = {100.0, 3.0, 0};
    start(&tt, 2, c);
    assert_int_equal(tt.current, 2);
    assert_false(window(&tt, &c, 50, 0.3)); /* 2 threads: 25 steps/s, waiting 30 % */
    assert_int_equal(tt.current, 1);
    assert_int_equal(omp_get_max_threads(), 1);
    assert_true(window(&tt, &c, 80, 0.3)); /* 1 thread: 40 steps/s, faster */
    assert_int_equal(tt.current, 1);
    for (int k = 0; k < THREADS_KEEP_WINDOWS - 1; k++) window(&tt, &c, 80, 0.3);
    assert_int_equal(tt.current, 1);
    window(&tt, &c, 80, 0.3); /* the kept windows are over: measure again */
    assert_int_equal(tt.current, 2);
    assert_false(window(&tt, &c, 90, 0.3)); /* said once only */
    assert_false(window(&tt, &c, 80, 0.3)); /* now 2 threads win */
    assert_int_equal(tt.current, 2);
    thread_tuner_stop(&tt);
    assert_int_equal(omp_get_max_threads(), 2);
}

static void test_one_thread_never_tried_on_an_idle_machine(void **state)
{
    (void)state;
    thread_tuner tt;
    clocks c = {0.0, 0.0, 0};
    start(&tt, 2, c);
    for (int k = 0; k < 3 * THREADS_KEEP_WINDOWS; k++) {
        window(&tt, &c, 90, 0.001);
        assert_int_equal(tt.current, 2);
    }
}

static void test_unknown_delay_tries_one_thread(void **state)
{
    (void)state;
    thread_tuner tt;
    clocks c = {0.0, -1.0, 0};
    start(&tt, 2, c);
    window(&tt, &c, 90, -1.0);
    assert_int_equal(tt.current, 1);
    assert_false(window(&tt, &c, 50, -1.0)); /* slower: back to 2 */
    assert_int_equal(tt.current, 2);
}

static void test_nothing_with_one_thread(void **state)
{
    (void)state;
    thread_tuner tt;
    clocks c = {0.0, 0.0, 0};
    start(&tt, 1, c);
    for (int k = 0; k < 5; k++) assert_false(window(&tt, &c, 10, 0.5));
    assert_int_equal(tt.current, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_one_thread_wins_on_a_busy_machine),
        cmocka_unit_test(test_one_thread_never_tried_on_an_idle_machine),
        cmocka_unit_test(test_unknown_delay_tries_one_thread),
        cmocka_unit_test(test_nothing_with_one_thread),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
