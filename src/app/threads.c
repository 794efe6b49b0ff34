/* threads: the thread count of a run, chosen by measurement (threads.h). */
#include "app/threads.h"

#include <omp.h>
#include <stdio.h>

enum { THREADS_TRY_MAX, THREADS_TRY_ONE, THREADS_KEEP };

static void use(thread_tuner *tt, int n)
{
    tt->current = n;
    omp_set_num_threads(n);
}

double threads_run_delay(void)
{
    FILE *f = fopen("/proc/self/schedstat", "r");
    unsigned long long running, waiting;
    int n = f ? fscanf(f, "%llu %llu", &running, &waiting) : 0;
    if (f) fclose(f);
    return n == 2 ? 1e-9 * (double)waiting : -1.0;
}

void thread_tuner_start(thread_tuner *tt, double wall, double delay, long step)
{
    tt->max = omp_get_max_threads();
    tt->current = tt->max;
    tt->phase = THREADS_TRY_MAX;
    tt->windows_left = 0;
    tt->window_start = wall;
    tt->delay_start = delay;
    tt->step_start = step;
    tt->rate_max = 0.0;
    tt->reduced_told = false;
}

void thread_tuner_stop(thread_tuner *tt)
{
    if (tt->max > 0) use(tt, tt->max);
}

bool thread_tuner_step(thread_tuner *tt, double wall, double delay, long step)
{
    double elapsed = wall - tt->window_start;
    if (tt->max <= 1 || elapsed < THREADS_WINDOW_S) return false;
    double rate = (double)(step - tt->step_start) / elapsed;
    /* an unknown delay (< 0) counts as busy, so that one thread is tried */
    bool busy = delay < 0.0 || delay - tt->delay_start > THREADS_BUSY_DELAY * elapsed;
    bool tell = false;
    switch (tt->phase) {
    case THREADS_TRY_MAX:
        tt->rate_max = rate;
        if (busy) {
            tt->phase = THREADS_TRY_ONE;
            use(tt, 1);
        } else { /* nothing competes: all threads, without trying one */
            tt->phase = THREADS_KEEP;
            tt->windows_left = THREADS_KEEP_WINDOWS;
        }
        break;
    case THREADS_TRY_ONE:
        tt->phase = THREADS_KEEP;
        tt->windows_left = THREADS_KEEP_WINDOWS;
        use(tt, rate > tt->rate_max ? 1 : tt->max);
        tell = tt->current == 1 && !tt->reduced_told;
        tt->reduced_told |= tell;
        break;
    default:
        if (--tt->windows_left > 0) break;
        tt->phase = THREADS_TRY_MAX;
        use(tt, tt->max);
    }
    tt->window_start = wall;
    tt->delay_start = delay;
    tt->step_start = step;
    return tell;
}
