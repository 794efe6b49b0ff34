/* estimate: the memory and wall time a case will take, printed by `vcsph check` and at the
 * start of `vcsph run` (docs/checks.md). Dimension-free declarations of the 2D and 3D builds
 * (scheme/estimate.c is compiled for each); estimate_run dispatches on case.dim. */
#ifndef VCSPH_ESTIMATE_H
#define VCSPH_ESTIMATE_H

#include "core/config.h"
#include "core/derived.h"

#include <stdio.h>

typedef struct {
    double n_fluid, n_ghost;     /* particles; the ghosts of the lattice at t = 0 */
    double bytes;                /* the solver's arrays: particle store, RK4 work, neighbour
                                    lists, cells, surface-tension work */
    double bytes_per_particle;   /* bytes / n_fluid */
    double neighbours_per_row;   /* the neighbour list's row width, entries */
    double steps;                /* t_end / dt (dt the estimate of Eq. (8)), and the steps
                                    split by landing on the outputs' times */
    double us_per_particle_step; /* on one thread, at this particle count (estimate.c) */
    int threads;                 /* omp_get_max_threads() */
    double speedup;              /* of the threads over one, 1 where one is faster */
    double output_seconds;       /* the start, the rows, snapshots and images */
    double seconds;              /* steps x n_fluid x us_per_particle_step / speedup, plus
                                    output_seconds */
} run_estimate;

void estimate_run_2d(const config *cfg, const derived *dv, int threads, run_estimate *out);
void estimate_run_3d(const config *cfg, const derived *dv, int threads, run_estimate *out);

static inline void estimate_run(const config *cfg, const derived *dv, int threads,
                                run_estimate *out)
{
    (cfg->dim == 3 ? estimate_run_3d : estimate_run_2d)(cfg, dv, threads, out);
}

/* "12.3 MB" / "4.5 GB": bytes in decimal units, three digits. */
static inline void estimate_format_bytes(double bytes, char *buf, size_t len)
{
    static const char *const unit[] = {"B", "kB", "MB", "GB", "TB", "PB"};
    int k = 0;
    while (bytes >= 1000.0 && k < 5) {
        bytes /= 1000.0;
        k++;
    }
    snprintf(buf, len, "%.3g %s", bytes, unit[k]);
}

/* "45 s" / "3.2 min" / "5.1 h" / "12 days" / "3.4 years". */
static inline void estimate_format_seconds(double s, char *buf, size_t len)
{
    if (s < 10.0)
        snprintf(buf, len, "%.2g s", s);
    else if (s < 120.0)
        snprintf(buf, len, "%.0f s", s);
    else if (s < 7200.0)
        snprintf(buf, len, "%.2g min", s / 60.0);
    else if (s < 2.0 * 86400.0)
        snprintf(buf, len, "%.2g h", s / 3600.0);
    else if (s < 730.0 * 86400.0)
        snprintf(buf, len, "%.3g days", s / 86400.0);
    else
        snprintf(buf, len, "%.3g years", s / (365.25 * 86400.0));
}

/* The two lines of the estimate, "memory ...: ..." and "wall time ...: ...", without newline. */
static inline void estimate_describe(const run_estimate *e, char *memory, size_t memory_len,
                                     char *wall, size_t wall_len)
{
    char b[32], t[32];
    estimate_format_bytes(e->bytes, b, sizeof b);
    estimate_format_seconds(e->seconds, t, sizeof t);
    snprintf(memory, memory_len,
             "%s (%.0f bytes per particle: %.3g fluid + %.3g ghosts at t = 0, neighbour rows "
             "of %.0f)",
             b, e->bytes_per_particle, e->n_fluid, e->n_ghost, e->neighbours_per_row);
    snprintf(wall, wall_len,
             "%s (%.3g steps x %.3g particles x %.3g us per particle-step / %.2g on %d "
             "thread(s), and %.2g s of start and outputs)",
             t, e->steps, e->n_fluid, e->us_per_particle_step, e->speedup, e->threads,
             e->output_seconds);
}

#define ESTIMATE_DAY_S 86400.0

/* The warning of a run estimated at more than a day, without prefix; empty when there is none. */
static inline void estimate_cost_warning(const run_estimate *e, char *msg, size_t msg_len)
{
    msg[0] = '\0';
    if (!(e->seconds > ESTIMATE_DAY_S)) return;
    char wall[32];
    estimate_format_seconds(e->seconds, wall, sizeof wall);
    snprintf(msg, msg_len,
             "this run is estimated at %s of wall time (%.3g steps of %.3g particles); it writes "
             "a checkpoint every output.checkpoint_every s, and `run --restart` continues it",
             wall, e->steps, e->n_fluid);
}

#endif
