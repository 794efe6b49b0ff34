/* bench_step: a 2D sloshing tank of about 50,000 particles (the INM1 tank of the paper,
 * sway, LES on, no-slip walls), timed over whole steps on 1 and 2 threads, for each scheme
 * named on the command line (default delta-SPH): bench_step [STEPS [SCHEME[:CORRECTION]...]],
 * CORRECTION a model.volume_correction (default auto), e.g. delta-plus-ale:none. Prints
 * particle-steps per second (PS/s), neighbour-pair evaluations per second, bytes per
 * particle and each scheme's cost per step against the first and the one before. delta-plus-ALE
 * starts with eta = 0, so its steps are delta-plus-SPH steps; those with eta = 1 are delta-ALE
 * steps. A benchmark: it never fails on timing. */
#define DIM 2
#include "app/progress.h"
#include "bench_memory.h"
#include "scheme/solver.h"

#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char bench_case[] = "[case]\nname = bench\ndim = 2\nt_end = 100\n"
                                 "[tank]\nlength = 1.0\nheight = 1.0\n"
                                 "[liquid]\nheight = 0.35\n"
                                 "[motion]\ntype = sway\namplitude = 0.05\nperiod = 1.1\n"
                                 "[model]\nscheme = delta\nles = true\nwall = no-slip\n"
                                 "[numerics]\nresolution = 132\nsound_speed = 20\n";

/* Pairs within the kernel support 2h over the fluid rows (what every pair loop evaluates). */
static double support_pairs(const solver *s)
{
    double pairs = 0.0;
    const particles *p = &s->p;
    for (size_t i = 0; i < p->n_fluid; i++) {
        int32_t entries[s->nl.row_capacity];
        const int32_t *row = neighbour_row(&s->nl, i, entries);
        for (int32_t k = 0; k < s->nl.count[i]; k++) {
            vec r = vec_sub(vec_load(p->x, (size_t)row[k]), vec_load(p->x, i));
            pairs += vec_norm2(r) < s->pp.k.support2;
        }
    }
    return pairs;
}

/* Times `steps` steps of `scheme` on 1 and 2 threads; stores the PS/s in ps_out[0..1]. */
static int bench_scheme(const char *scheme, int steps, double ps_out[2])
{
    char set[64], correction[64] = "model.volume_correction=auto", err[1024];
    snprintf(set, sizeof set, "model.scheme=%s", scheme);
    char *colon = strchr(set, ':');
    if (colon) {
        snprintf(correction, sizeof correction, "model.volume_correction=%s", colon + 1);
        *colon = '\0';
    }
    const char *overrides[] = {set, correction};
    config cfg;
    if (config_load_string(&cfg, bench_case, "bench", overrides, 2, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    printf("bench_step: %s, 2D INM1 tank, sway, LES on, no-slip, double precision\n", scheme);
    for (int threads = 1; threads <= 2; threads++) {
        omp_set_num_threads(threads);
        solver s;
        if (solver_init(&s, &cfg, err, sizeof err)) {
            fprintf(stderr, "%s\n", err);
            return 1;
        }
        for (int k = 0; k < 5; k++) solver_step(&s, cfg.t_end); /* warm-up: caches, lists */
        double t0 = progress_wall_time();
        for (int k = 0; k < steps; k++) solver_step(&s, cfg.t_end);
        double wall = progress_wall_time() - t0;
        double n = (double)s.p.n_fluid, ps = n * steps / wall;
        ps_out[threads - 1] = ps;
        /* per step: one fields pass + one diffusion pass + four RK stages over the pairs */
        double pair_evals = support_pairs(&s) * 6.0 * steps / wall;
        printf("threads %d: %zu fluid + %zu ghost particles, %d steps in %.2f s: "
               "%.3g PS/s, %.3g pair evaluations/s, %.0f bytes/particle, %.1f neighbours "
               "(within 2h) per particle\n",
               threads, s.p.n_fluid, s.p.n_total - s.p.n_fluid, steps, wall, ps, pair_evals,
               bytes_per_particle(&s), support_pairs(&s) / n);
        solver_free(&s);
    }
    return 0;
}

int main(int argc, char **argv)
{
    int steps = argc > 1 ? atoi(argv[1]) : 30;
    const char *default_scheme[] = {"delta"};
    const char *const *schemes = argc > 2 ? (const char *const *)argv + 2 : default_scheme;
    int n_schemes = argc > 2 ? argc - 2 : 1;
    double first[2] = {0.0, 0.0}, previous[2] = {0.0, 0.0};
    for (int k = 0; k < n_schemes; k++) {
        double ps[2];
        if (bench_scheme(schemes[k], steps, ps)) return 1;
        if (k == 0) {
            first[0] = ps[0];
            first[1] = ps[1];
        } else {
            printf("bench_step: a %s step costs %.2f (1 thread) and %.2f (2 threads) %s steps\n",
                   schemes[k], first[0] / ps[0], first[1] / ps[1], schemes[0]);
            if (k > 1)
                printf("bench_step: a %s step costs %.2f (1 thread) and %.2f (2 threads) %s "
                       "steps\n",
                       schemes[k], previous[0] / ps[0], previous[1] / ps[1], schemes[k - 1]);
        }
        previous[0] = ps[0];
        previous[1] = ps[1];
    }
    return 0;
}
