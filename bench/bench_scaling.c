/* bench_scaling: the cost of a particle-step against the number of particles, from 1e4 up to
 * MAX (default 1e6), on one thread, for the 2D INM1 tank (cases/inm1.ini: delta-plus-ALE with
 * every term) or, built with DIM = 3, the INM2 3D tank (cases/inm2-3d.ini). Each size is the
 * case at the resolution that gives about that many fluid particles on a lattice of the
 * same spacing along every axis (resolution_for), set up (all sizes at once) and
 * stepped twice to warm up, then timed in ROUNDS rounds of about 2e5 particle-steps each, the
 * sizes taking turns within a round. Prints microseconds per particle-step (the median round
 * and the range of the rounds), the heap per particle each size holds, each size's cost
 * against the smallest size's in the same round (the median over the rounds, and their range),
 * its neighbours within 2h a particle, and the walls' images per fluid particle (each a slot
 * of the store that the heap per particle and the step's ghost passes count; the narrow 3D
 * tank has 1.08 at 17,920 particles, 0.26 at 945,000): a flat curve means the cache and the
 * neighbour search scale (issue 22 asks for 20 %). A benchmark: it never fails on timing.
 * Usage: bench_scaling_2d [MAX] */
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

/* The fluid particles of the lattice at resolution N (H_L / dr), its spacing the same along
 * every axis (N a multiple of 7, below). */
static double fluid_particles(int n) { return liquid_volume * pow(n / liquid_height, DIM); }

/* The resolution H_L / dr nearest to the one that gives about `particles` fluid particles
 * among those that give the lattice the spacing dr along every axis. The lattice fits a whole
 * number of particles into each side of the liquid box (core/derived.c), spaced within
 * dr / (2 n) of dr. The kernel's support, 2h = 3 dr in 3D and 4 dr in 2D, passes exactly
 * through lattice points (30 of the 122 within 3 dr in 3D, 4 of the 48 within 4 dr in 2D), so
 * a spacing a few per cent under dr across one side brings them inside: the 3D tank's 0.1 m width
 * at 1e4 particles (6.57 dr, seven particles across) gave 125 neighbours within 2h where 1e5 (14.29
 * dr, fourteen) gave 93, and cost a third more per particle-step for it. Sides of 1, 0.1 and 0.35 m
 * hold 20 N / 7, 2 N / 7 and N spacings: N a multiple of 7 makes all of them dr. The sizes
 * stay within the range the curve is asked over ([lo, hi]: 1e4 and MAX): the nearest to a
 * target, unless it falls outside, then the nearest inside (1e4 gave 7,560 particles in 3D and
 * 8,960 in 2D, below the range). */
static int resolution_for(double particles, double lo, double hi)
{
    double dr = pow(liquid_volume / particles, 1.0 / DIM);
    int sevens = (int)lround(liquid_height / dr / 7.0);
    if (sevens < 1) sevens = 1;
    while (fluid_particles(7 * sevens) < lo) sevens++;
    while (sevens > 1 && fluid_particles(7 * sevens) > hi) sevens--;
    return 7 * sevens;
}

/* The mean number of neighbours within 2h of a fluid particle in the rows of the step last
 * built: the pairs a particle-step evaluates, which the cost per particle-step follows. */
static double mean_near(const solver *s)
{
    double sum = 0.0;
    for (size_t i = 0; i < s->p.n_fluid; i++) sum += s->nl.near[i];
    return sum / (double)s->p.n_fluid;
}

/* Rounds: every size is timed once a round, the sizes one after the other, and its cost is
 * the median of its rounds. The shared machine's speed drifts by a fifth within minutes; timed
 * one size after the other, a size would carry the speed of its own minutes into the curve. */
#define ROUNDS 5
/* The particle-steps of a size in one round: 1e6 over the rounds, as a whole timing was. */
#define ROUND_PARTICLE_STEPS (1e6 / ROUNDS)
/* 1e4 to 1e6 in steps of sqrt(10) */
#define MAX_SIZES 5

typedef struct {
    config cfg;
    solver s;
    double n, bytes, neighbours;
    double images; /* the walls' images per fluid particle: each holds the fields of a slot */
    int steps;     /* a round's */
    double us[ROUNDS];
    double ratio[ROUNDS]; /* us against the smallest size's in the same round */
} size_run;

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sets up the case at `target` particles and runs its two warm-up steps (the first allocates
 * and guesses the rows' length, the second sizes them by the first's longest row); its bytes
 * per particle are what the heap in use grew by (bench_memory.h: the sizes set up before it
 * stay alive). 0, or -1 on error. */
static int set_up_size(size_run *r, double target, double max)
{
    char set[64], err[1024];
    snprintf(set, sizeof set, "numerics.resolution=%d", resolution_for(target, 1e4, max));
    const char *overrides[] = {set};
    double heap0 = heap_in_use();
    if (config_load_string(&r->cfg, bench_case, "scaling", overrides, 1, err, sizeof err) ||
        solver_init(&r->s, &r->cfg, err, sizeof err)) {
        fprintf(stderr, "bench_scaling: %s\n", err);
        return -1;
    }
    for (int k = 0; k < 2; k++)
        if (solver_step(&r->s, r->cfg.t_end)) return -1;
    r->n = (double)r->s.p.n_fluid;
    r->bytes = (heap_in_use() - heap0) / r->n;
    r->steps = (int)ceil(ROUND_PARTICLE_STEPS / r->n);
    r->neighbours = mean_near(&r->s);
    r->images = (double)(r->s.p.n_total - particles_images_begin(&r->s.p)) / r->n;
    return 0;
}

/* One round of a size: microseconds per particle-step, or a negative on error. */
static double time_round(size_run *r)
{
    double t0 = progress_wall_time();
    for (int k = 0; k < r->steps; k++)
        if (solver_step(&r->s, r->cfg.t_end)) return -1.0;
    return 1e6 * (progress_wall_time() - t0) / (r->n * r->steps);
}

int main(int argc, char **argv)
{
    double max = argc > 1 ? atof(argv[1]) : 1e6;
    omp_set_num_threads(1);
    printf("bench_scaling: %s, delta-plus-ALE with every term, one thread, the median of %d "
           "rounds\n",
           tank_name, ROUNDS);
    size_run *runs = calloc(MAX_SIZES, sizeof *runs);
    int sizes = 0;
    for (double target = 1e4; target <= max * 1.01 && sizes < MAX_SIZES; target *= sqrt(10.0))
        if (!runs || set_up_size(&runs[sizes++], target, max)) return 1;
    for (int round = 0; round < ROUNDS; round++)
        for (int k = 0; k < sizes; k++)
            if ((runs[k].us[round] = time_round(&runs[k])) < 0.0) return 1;
    printf("%10s %8s %16s %8s %10s %14s %10s %7s\n", "particles", "us/PS", "rounds' range", "bytes",
           "cost/first", "rounds' range", "neighbours", "images");
    /* each size against the smallest in the same round, where both ran within a minute */
    for (int k = 0; k < sizes; k++)
        for (int round = 0; round < ROUNDS; round++)
            runs[k].ratio[round] = runs[k].us[round] / runs[0].us[round];
    for (int k = 0; k < sizes; k++) {
        size_run *r = &runs[k];
        qsort(r->ratio, ROUNDS, sizeof *r->ratio, by_value);
        qsort(r->us, ROUNDS, sizeof *r->us, by_value);
        printf("%10.0f %8.3f %7.3f - %6.3f %8.0f %10.2f %6.2f - %5.2f %10.1f %7.2f\n", r->n,
               r->us[ROUNDS / 2], r->us[0], r->us[ROUNDS - 1], r->bytes, r->ratio[ROUNDS / 2],
               r->ratio[0], r->ratio[ROUNDS - 1], r->neighbours, r->images);
    }
    for (int k = 0; k < sizes; k++) solver_free(&runs[k].s);
    free(runs);
    return 0;
}
