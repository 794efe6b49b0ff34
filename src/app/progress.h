/* progress: the run's progress on the terminal (a line rewritten in place) or, when stdout is
 * not a terminal, a plain line now and then on stdout (never in log.txt, which keeps the
 * run's record). */
#ifndef VCSPH_PROGRESS_H
#define VCSPH_PROGRESS_H

#include <stdbool.h>
#include <stddef.h>

typedef struct {
    bool tty, quiet;
    double t_start, t_end; /* t_start: where this invocation began (a restart's checkpoint) */
    size_t n_particles;
    double wall_start, wall_last;
    long step_start;
    int line_width;
} progress;

/* Wall-clock seconds (monotonic). */
double progress_wall_time(void);
void progress_start(progress *pr, double t, double t_end, size_t n_particles, long step,
                    bool quiet);
/* Shows simulated time, steps, particle-steps per second and the ETA (from the rate of this
 * invocation: the simulated time since t_start over the wall time since), at most once a second
 * on a terminal (every 30 s otherwise) unless `force`. */
void progress_update(progress *pr, double t, long step, bool force);
/* Clears the terminal line before other messages. */
void progress_clear(progress *pr);

#endif
