/* bench_rhs: the right-hand side of Eq. (3) alone (rhs_compute: the lanes of
 * scheme/rhs_lanes.h where the processor has them), timed CALLS times on one state, for a
 * change to the pair loop whose effect a whole run's noise would hide. The state is issue
 * 22's case (cases/inm1.ini, delta-plus-ALE with every term; built with DIM = 3,
 * cases/inm2-3d.ini) at resolution N after three steps, with the whole rows of RK4's later
 * stages. Prints the fastest call, the tenth and the median in ms and per fluid particle: on
 * a shared machine the fastest of many calls moves least between sittings. A benchmark: it
 * never fails on timing.
 * Usage: bench_rhs_2d [CALLS [N]] (from the repository root: it reads cases/) */
#include "app/progress.h"
#include "scheme/rhs.h"
#include "scheme/solver.h"

#include <stdio.h>
#include <stdlib.h>

#if DIM == 2
static const char case_file[] = "cases/inm1.ini", default_resolution[] = "100";
#else
static const char case_file[] = "cases/inm2-3d.ini", default_resolution[] = "28";
#endif

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    int calls = argc > 1 ? atoi(argv[1]) : 200;
    const char *resolution = argc > 2 ? argv[2] : default_resolution;
    if (calls < 1) {
        fprintf(stderr, "bench_rhs: CALLS must be at least 1\n");
        return 2;
    }
    char set[64], err[1024];
    snprintf(set, sizeof set, "numerics.resolution=%s", resolution);
    const char *overrides[] = {set};
    config cfg;
    solver s;
    if (config_load(&cfg, case_file, overrides, 1, err, sizeof err) ||
        solver_init(&s, &cfg, err, sizeof err)) {
        fprintf(stderr, "bench_rhs: %s\n", err);
        return 1;
    }
    for (int k = 0; k < 3; k++) solver_step(&s, cfg.t_end);
    tank_frame frame = solver_frame(&s, s.t);
    double *ms = malloc((size_t)calls * sizeof *ms);
    if (!ms) return 1;
    for (int c = 0; c < calls; c++) {
        double t0 = progress_wall_time();
        rhs_compute(&s.pp, &s.p, &s.nl, &frame, s.eta_control.eta, &s.k);
        ms[c] = 1e3 * (progress_wall_time() - t0);
    }
    qsort(ms, (size_t)calls, sizeof *ms, by_value);
    double n = (double)s.p.n_fluid;
    printf("bench_rhs: %s at N = %s, %zu fluid particles and %zu ghosts, %d calls\n", case_file,
           resolution, s.p.n_fluid, s.p.n_total - s.p.n_fluid, calls);
    printf("fastest %.3f ms (%.3f us a particle), tenth %.3f ms, median %.3f ms\n", ms[0],
           1e3 * ms[0] / n, ms[calls / 10], ms[calls / 2]);
    free(ms);
    solver_free(&s);
    return 0;
}
