/* progress: run-time feedback. */
#include "app/progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

double progress_wall_time(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void progress_start(progress *pr, double t, double t_end, size_t n_particles, long step, bool quiet)
{
    pr->t_start = t;
    pr->tty = isatty(STDOUT_FILENO);
    pr->quiet = quiet;
    pr->t_end = t_end;
    pr->n_particles = n_particles;
    pr->wall_start = pr->wall_last = progress_wall_time();
    pr->step_start = step;
    pr->line_width = 0;
}

static void format_duration(char *buf, size_t len, double seconds)
{
    long s = seconds > 0 ? (long)(seconds + 0.5) : 0;
    snprintf(buf, len, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
}

void progress_update(progress *pr, double t, long step, bool force)
{
    if (pr->quiet) return;
    double now = progress_wall_time();
    if (!force && now - pr->wall_last < (pr->tty ? 1.0 : 30.0)) return;
    pr->wall_last = now;
    double elapsed = now - pr->wall_start;
    long steps = step - pr->step_start;
    double rate = elapsed > 0 ? (double)pr->n_particles * (double)steps / elapsed : 0.0;
    char eta[32], spent[32];
    double done = t - pr->t_start;
    format_duration(eta, sizeof eta, done > 0 ? elapsed * (pr->t_end - t) / done : 0.0);
    format_duration(spent, sizeof spent, elapsed);
    char line[200];
    snprintf(line, sizeof line,
             "t = %.4f / %.4g s (%3.0f%%)  step %ld  %.3g PS/s  elapsed %s  ETA %s", t, pr->t_end,
             100.0 * t / pr->t_end, step, rate, spent, eta);
    if (pr->tty) {
        int width = printf("\r%s", line) - 1;
        for (int k = width; k < pr->line_width; k++) putchar(' ');
        pr->line_width = width;
        fflush(stdout);
    } else {
        printf("%s\n", line);
        fflush(stdout);
    }
}

void progress_clear(progress *pr)
{
    if (!pr->tty || pr->quiet || pr->line_width == 0) return;
    printf("\r%*s\r", pr->line_width, "");
    fflush(stdout);
    pr->line_width = 0;
}
