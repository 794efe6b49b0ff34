/* threads: how many OpenMP threads a run uses, measured as it goes. On an idle machine all
 * of them (OMP_NUM_THREADS, or the cores); when another process shares the cores, a step's
 * dozens of short parallel loops each wait at their barrier for a thread the system has set
 * aside, and one thread runs up to twice as fast as two (measured on the default case: 8.9 s
 * against 17.6 s). So the run times a window of steps with all threads; if the system kept the
 * run waiting for a core in it (its run-queue delay, /proc/self/schedstat), it times one with
 * one thread, keeps the faster for THREADS_KEEP_WINDOWS windows, and measures again. On an idle
 * machine the delay is nil and one thread is never tried. Results do not depend on the thread
 * count (the reductions are in a fixed order), so the switches change nothing but the wall
 * time. */
#ifndef VCSPH_THREADS_H
#define VCSPH_THREADS_H

#include <stdbool.h>

typedef struct {
    int max;             /* the threads the user allows (omp_get_max_threads at the start) */
    int current;         /* the threads in use */
    int phase;           /* THREADS_TRY_MAX, THREADS_TRY_ONE or THREADS_KEEP */
    int windows_left;    /* of THREADS_KEEP */
    double window_start; /* wall-clock time, run-queue delay and step at the start of the window */
    double delay_start;
    long step_start;
    double rate_max;   /* steps per second with max threads in the last measurement */
    bool reduced_told; /* the first time one thread won was said in log.txt */
} thread_tuner;

/* Wall-clock seconds of one measuring window, the windows the faster count is kept, and the
 * share of a window spent waiting for a core above which one thread is tried (idle: below
 * 0.5 %; one competing process on 2 cores: tens of per cent). */
#define THREADS_WINDOW_S     2.0
#define THREADS_KEEP_WINDOWS 20
#define THREADS_BUSY_DELAY   0.05

/* Seconds this process's main thread has waited for a core since it started (Linux
 * /proc/self/schedstat), or -1 where that is not known (then one thread is always tried). */
double threads_run_delay(void);

void thread_tuner_start(thread_tuner *tt, double wall, double delay, long step);

/* Puts back the thread count the run started with (for a caller that runs again). */
void thread_tuner_stop(thread_tuner *tt);

/* Whether a window has ended at wall-clock time `wall` (then call thread_tuner_step). */
static inline bool thread_tuner_due(const thread_tuner *tt, double wall)
{
    return tt->max > 1 && wall - tt->window_start >= THREADS_WINDOW_S;
}

/* After each step, with the wall-clock time and threads_run_delay(): at the end of a window,
 * sets the thread count for the next one. Returns true when one thread has just won for the
 * first time (the caller says so). */
bool thread_tuner_step(thread_tuner *tt, double wall, double delay, long step);

#endif
