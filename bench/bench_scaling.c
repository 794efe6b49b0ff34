/* bench_scaling: the cost of a particle-step against the number of particles, from 1e4 up to
 * MAX (default 1e6), on one thread, for the 2D INM1 tank (cases/inm1.ini: delta-plus-ALE with
 * every term) or, built with DIM = 3, the INM2 3D tank (cases/inm2-3d.ini). Each size is the
 * case at the resolution that gives that many fluid particles, timed step by step over enough
 * steps to make about 1e6 particle-steps (at least MIN_STEPS) after one warm-up step. Prints
 * microseconds per particle-step (the median step's), bytes per particle and each size's cost
 * against the smallest: a flat curve means the cache and the neighbour search scale (issue 22
 * asks for 20 %). A benchmark: it never fails on timing. Usage: bench_scaling_2d [MAX] */
#include "app/progress.h"
#include "bench_memory.h"
#include "scheme/solver.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#if DIM == 2
/* cases/inm1.ini without its probes and outputs; fluid particles = (L / dr) (H_L / dr) */
static const char bench_case[] = "[case]\nname = scaling\ndim = 2\nt_end = 100\n"
                                 "[tank]\nlength = 1.0\nheight = 1.0\n"
                                 "[liquid]\nheight = 0.35\n"
                                 "[fluid]\nviscosity = 1.0e-6\nsurface_tension = 0.0727\n"
                                 "[motion]\ntype = sway\namplitude = 0.05\nperiod = 1.1\n"
                                 "[model]\nscheme = delta-plus-ale\nedbc = with-eta0\n"
                                 "wall = no-slip\n"
                                 "[numerics]\nsound_speed = 20.0\n";
static const double liquid_volume = 1.0 * 0.35;
static const char tank_name[] = "2D INM1 tank";
#else
/* cases/inm2-3d.ini without its probes and outputs */
static const char bench_case[] = "[case]\nname = scaling\ndim = 3\nt_end = 100\n"
                                 "[tank]\nlength = 1.0\nheight = 1.0\nwidth = 0.1\n"
                                 "[liquid]\nheight = 0.35\n"
                                 "[fluid]\nviscosity = 1.0e-6\nsurface_tension = 0.0727\n"
                                 "[motion]\ntype = sway\namplitude = 0.10\nperiod = 1.0\n"
                                 "[model]\nscheme = delta-plus-ale\nedbc = with-eta0\n"
                                 "wall = no-slip\n"
                                 "[numerics]\nsound_speed = 20.0\n";
static const double liquid_volume = 1.0 * 0.1 * 0.35;
static const char tank_name[] = "3D INM2 tank";
#endif
static const double liquid_height = 0.35;

/* The resolution H_L / dr that gives about `particles` fluid particles. */
static int resolution_for(double particles)
{
    double dr = pow(liquid_volume / particles, 1.0 / DIM);
    return (int)lround(liquid_height / dr);
}

/* The fewest steps a size is timed over: the median of a few steps, not one step, so that a
 * step the shared machine slowed does not make the largest size look dearer. */
#define MIN_STEPS 5

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Times one size: the median over its steps of a step's wall time, in microseconds per
 * particle-step; a negative on error. */
static double time_size(double target, double *particles, double *bytes)
{
    char set[64], err[1024];
    snprintf(set, sizeof set, "numerics.resolution=%d", resolution_for(target));
    const char *overrides[] = {set};
    config cfg;
    solver s;
    if (config_load_string(&cfg, bench_case, "scaling", overrides, 1, err, sizeof err) ||
        solver_init(&s, &cfg, err, sizeof err)) {
        fprintf(stderr, "bench_scaling: %s\n", err);
        return -1.0;
    }
    double n = (double)s.p.n_fluid;
    int steps = n < 1e6 / MIN_STEPS ? (int)ceil(1e6 / n) : MIN_STEPS;
    double *wall = malloc((size_t)steps * sizeof *wall);
    if (!wall || solver_step(&s, cfg.t_end)) return -1.0; /* warm-up: allocation, first lists */
    for (int k = 0; k < steps; k++) {
        double t0 = progress_wall_time();
        if (solver_step(&s, cfg.t_end)) return -1.0;
        wall[k] = progress_wall_time() - t0;
    }
    qsort(wall, (size_t)steps, sizeof *wall, by_value);
    double median = steps % 2 ? wall[steps / 2] : 0.5 * (wall[steps / 2 - 1] + wall[steps / 2]);
    free(wall);
    *particles = n;
    *bytes = bytes_per_particle(&s);
    solver_free(&s);
    return 1e6 * median / n;
}

int main(int argc, char **argv)
{
    double max = argc > 1 ? atof(argv[1]) : 1e6;
    omp_set_num_threads(1);
    printf("bench_scaling: %s, delta-plus-ALE with every term, one thread\n", tank_name);
    printf("%12s %14s %14s %10s\n", "particles", "us/PS", "bytes/particle", "cost/first");
    double first = 0.0;
    for (double target = 1e4; target <= max * 1.01; target *= sqrt(10.0)) {
        double particles, bytes, us = time_size(target, &particles, &bytes);
        if (us < 0.0) return 1;
        if (first == 0.0) first = us;
        printf("%12.0f %14.3f %14.0f %10.2f\n", particles, us, bytes, us / first);
        fflush(stdout);
    }
    return 0;
}
