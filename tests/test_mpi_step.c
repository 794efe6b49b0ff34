/* A run split among processes (parallel/mpi_domain.h) gives the one-process result to the bit,
 * run by ctest on 1 to 4 processes in 2D and 3D: a long shallow tank under sway, whose cells
 * make at least five strips (docs/mpi.md), goes through a few steps, once on rank 0 alone and
 * once split among all processes. After every step the fluid particles of the processes, in
 * rank order, are the one-process particles in their order (ids), with the same position,
 * velocity, density and mass to the bit, the same per-step fields (record below), the same
 * global figures of the time series (energies, moments, extremes, volume errors), and the
 * step sizes agree. Checked for delta-SPH (geometry, free surface, diffusion, the walls'
 * images of halo particles), delta-plus-SPH (the shifting), delta-ALE-SPH (variable masses)
 * and delta-plus-ALE-SPH (the eta control and EdBC; then with the geometric volume
 * correction, whose bodies of liquid span the processes; with surface tension; in a tank that
 * rolls as it sways). The global figures include the loads on the tank. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "diag/volume.h"
#include "scheme/loads.h"
#include "noise.h"
#include <stdbool.h>
#include "parallel/mpi_domain.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { STEPS = 4 };
static int n_ranks, rank;

#if DIM == 2
#define TANK       "[tank]\nlength = 4.0\nheight = 0.2\n[liquid]\nheight = 0.05\n"
#define RESOLUTION "8"
#else
#define TANK       "[tank]\nlength = 2.0\nheight = 0.15\nwidth = 0.1\n[liquid]\nheight = 0.05\n"
#define RESOLUTION "5"
#endif

#define SWAY "type = sway\namplitude = 0.05\nperiod = 0.5"

static void setup(solver *s, config *cfg, const char *motion, const char *model)
{
    char text[1024], err[1024];
    snprintf(text, sizeof text,
             "[case]\nname = split\ndim = %d\nt_end = 10\n" TANK
             "[motion]\n%s\n[model]\n%s\n[numerics]\nresolution = " RESOLUTION "\n",
             DIM, motion, model);
    if (config_load_string(cfg, text, "split", NULL, 0, err, sizeof err)) fail_msg("%s", err);
    if (solver_init(s, cfg, err, sizeof err)) fail_msg("%s", err);
    /* off the lattice by up to 0.25 dr, the same on every process: irregular neighbourhoods
       across the slabs' boundaries (on a lattice a free surface's nearest neighbours never
       lie in another column) */
    uint64_t seed = 11;
    for (size_t i = 0; i < s->p.n_fluid; i++)
        for (int d = 0; d < DIM; d++) s->p.x[d][i] += 0.25 * s->dv.dr * noise(&seed);
    /* and a few drops in the air, lambda near 0: EdBC's particles (Eq. 9) */
    for (size_t i = 0; i < s->p.n_fluid; i += 499) s->p.x[1][i] += 0.08;
    /* and a sheet lifted off the top layer's middle, away from every wall: a free body that
       spans the processes, whose surface-tension force and moment are balanced as a whole */
    for (size_t i = 0; i < s->p.n_fluid; i++) {
        bool middle =
            s->p.x[0][i] > 0.2 * cfg->tank_length && s->p.x[0][i] < 0.8 * cfg->tank_length;
        if (DIM == 3)
            middle &= s->p.x[DIM - 1][i] > 0.35 * cfg->tank_width &&
                      s->p.x[DIM - 1][i] < 0.65 * cfg->tank_width;
        if (middle && s->p.x[1][i] > cfg->liquid_height - s->dv.dr) s->p.x[1][i] += 0.08;
    }
}

/* A particle's record: its id, the integrated variables after the step, and the per-step
 * fields of the step's start that read neighbours' per-step fields (the free surface's two
 * passes, the shifting, the diffusion): a stale halo shows in these first. */
enum { RECORD = 1 + PARTICLE_N_INTEGRATED + 3 + 3 * DIM };
static void record(const particles *p, size_t i, double *r)
{
    memcpy(r, &p->id[i], sizeof(double)); /* the bits of the int64 */
    int v = 1;
#define RECORD_SCALAR(name) r[v++] = p->name[i];
#define RECORD_VECTOR(name)                                                                        \
    for (int d = 0; d < DIM; d++) r[v++] = p->name[d][i];
    PARTICLE_INTEGRATED(RECORD_SCALAR, RECORD_VECTOR)
    r[v++] = p->surface[i];
    r[v++] = p->lambda[i];
    r[v++] = p->diff_rho[i];
    for (int d = 0; d < DIM; d++) r[v++] = p->normal[d][i];
    for (int d = 0; d < DIM; d++) r[v++] = p->shift[d][i];
    for (int d = 0; d < DIM; d++) r[v++] = p->correction[d][i];
}

/* Every process's records, gathered on rank 0 in rank order. */
static double *gather(const particles *p, size_t *n_all)
{
    double *mine = malloc((p->n_fluid + 1) * RECORD * sizeof *mine);
    assert_non_null(mine);
    for (size_t i = 0; i < p->n_fluid; i++) record(p, i, mine + i * RECORD);
    int count = (int)(p->n_fluid * RECORD);
    int *counts = calloc(2 * (size_t)n_ranks, sizeof *counts), *at = counts + n_ranks;
    assert_non_null(counts);
    MPI_Gather(&count, 1, MPI_INT, counts, 1, MPI_INT, 0, MPI_COMM_WORLD);
    size_t total = 0;
    for (int q = 0; q < n_ranks; q++) {
        at[q] = (int)total;
        total += (size_t)counts[q];
    }
    double *all = rank == 0 ? malloc((total + 1) * sizeof *all) : NULL;
    MPI_Gatherv(mine, count, MPI_DOUBLE, all, counts, at, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    free(mine);
    free(counts);
    *n_all = total / RECORD;
    return all;
}

/* Rank 0's comparison of the gathered state with its own one-process run after one step:
 * "" when they agree to the bit, else what differs. Never leaves early: the other processes
 * are in the same collective calls. */
/* The global figures of a state: the time series' energies, moments and extremes and
 * volume errors, and loads.csv's force and moment on the tank. Collective with a domain. */
typedef struct {
    diagnostics d;
    volume_errors v;
    tank_loads loads;
} figures;

/* The figures of the state after a step. The loads read the walls' images, which the step's
 * last update leaves as they were at its last stage (the next step makes them again); a run
 * writes its loads after solver_prepare, from images of the state itself, and so do these:
 * the halo and the images are brought up to the state first (a no-slip image's viscous
 * velocity, read through its source, would otherwise mix the fluid's new velocities with the
 * halo's of the last stage). */
static figures state_figures(solver *s)
{
    figures f;
    memset(&f, 0, sizeof f); /* the padding too: compared with memcmp */
    solver_diagnostics(s, &f.d);
    volume_compute(&s->p, s->dv.cell_volume, s->scratch, solver_reducer(s), &f.v);
    tank_frame frame = solver_frame(s, s->t);
    uint64_t state = FIELD_MASK(x) | FIELD_MASK(u) | FIELD_MASK(rho) | FIELD_MASK(m);
    if (s->domain) s->domain->refresh_halo(s->domain, &s->p, state);
    solver_update_eos(s);
    tank_refresh_ghosts(&s->p, &frame, s->pp.rho0, s->pp.c0);
    assert_int_equal(loads_compute(&s->pp, &s->p, &s->nl, &frame, solver_reducer(s), &f.loads), 0);
    return f;
}

static void compare(solver *alone, const double *all, size_t n_all, double split_dt,
                    const figures *split_figures, const char *model, int step, char *failure,
                    size_t len)
{
    if (failure[0]) return;
    if (solver_step(alone, alone->cfg->t_end)) {
        snprintf(failure, len, "the one-process step %d failed", step);
        return;
    }
    if (n_all != alone->p.n_fluid) {
        snprintf(failure, len, "%zu particles in all, one process has %zu", n_all,
                 alone->p.n_fluid);
        return;
    }
    size_t differ = 0;
    for (size_t i = 0; i < n_all; i++) {
        double expected[RECORD];
        record(&alone->p, i, expected);
        if (memcmp(all + i * RECORD, expected, sizeof expected)) differ++;
    }
    figures expected = state_figures(alone);
    if (memcmp(split_figures, &expected, sizeof expected))
        snprintf(failure, len,
                 "%s, step %d, %d processes: the global figures differ (eps_v1 %.17g vs %.17g, "
                 "ekin %.17g vs %.17g, force_x %.17g vs %.17g)",
                 model, step, n_ranks, split_figures->v.eps_v1, expected.v.eps_v1,
                 split_figures->d.ekin, expected.d.ekin, split_figures->loads.force[0],
                 expected.loads.force[0]);
    if (differ || memcmp(&split_dt, &alone->dt, sizeof split_dt))
        snprintf(failure, len,
                 "%s, step %d, %d processes: %zu of %zu particles differ, dt %.17g vs %.17g", model,
                 step, n_ranks, differ, n_all, split_dt, alone->dt);
}

static void same_bits_as_one_process_moving(const char *motion, const char *model)
{
    config cfg;
    solver alone, split;
    if (rank == 0) setup(&alone, &cfg, motion, model);
    setup(&split, &cfg, motion, model);
    mpi_domain domain;
    mpi_domain_attach(&domain, &split, MPI_COMM_WORLD);
    char failure[256] = "";
    for (int step = 1; step <= STEPS && !failure[0]; step++) {
        int failed = solver_step(&split, cfg.t_end) != 0;
        figures split_figures = state_figures(&split);
        size_t n_all;
        double *all = gather(&split.p, &n_all);
        if (failed) snprintf(failure, sizeof failure, "the split step %d failed", step);
        if (rank == 0)
            compare(&alone, all, n_all, split.dt, &split_figures, model, step, failure,
                    sizeof failure);
        MPI_Bcast(failure, sizeof failure, MPI_CHAR, 0, MPI_COMM_WORLD);
        free(all);
    }
    if (rank == 0) solver_free(&alone);
    solver_free(&split);
    mpi_domain_free(&domain);
    if (failure[0]) fail_msg("%s", failure);
}

static void same_bits_as_one_process(const char *model)
{
    same_bits_as_one_process_moving(SWAY, model);
}

static void test_delta(void **state)
{
    (void)state;
    same_bits_as_one_process("scheme = delta");
}

static void test_delta_plus(void **state)
{
    (void)state;
    same_bits_as_one_process("scheme = delta-plus");
}

/* variable masses: the mass diffusion and the ALE terms, which read the neighbours' shifting */
static void test_delta_ale(void **state)
{
    (void)state;
    same_bits_as_one_process("scheme = delta-ale");
}

/* the eta control, which reads the global eps_V1 at every step (eta stays 0 over these
   steps), and EdBC (with eta = 0, its default), which corrects the drops' densities */
static void test_delta_plus_ale(void **state)
{
    (void)state;
    same_bits_as_one_process("scheme = delta-plus-ale\nvolume_correction = none");
}

/* delta-plus-ALE's defaults: the geometric volume correction too, whose normal speed is a sum
   over each body of liquid: the layer's band spans every process, the drops are bodies of
   their own */
static void test_delta_plus_ale_corrected(void **state)
{
    (void)state;
    same_bits_as_one_process("scheme = delta-plus-ale");
}

/* and surface tension (water's), whose force reads the halo's work arrays (interface,
   normals, curvature) and balances each body's net force and moment, as the paper's cases
   run: INM1, INM2, SAP and UPM all have it */
static void test_surface_tension(void **state)
{
    (void)state;
    same_bits_as_one_process("scheme = delta-plus-ale\n[fluid]\nsurface_tension = 0.0727");
}

/* a tank that rolls as it sways (0.2 rad about the bottom's centre): the frame's rotation,
   its Euler and centrifugal forces and the walls' images in the turning frame, the same on
   every process */
static void test_roll(void **state)
{
    (void)state;
    same_bits_as_one_process_moving("type = sway+roll\namplitude = 0.05\nperiod = 0.5\nangle = 0.2",
                                    "scheme = delta-plus-ale");
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_delta),
        cmocka_unit_test(test_delta_plus),
        cmocka_unit_test(test_delta_ale),
        cmocka_unit_test(test_delta_plus_ale),
        cmocka_unit_test(test_delta_plus_ale_corrected),
        cmocka_unit_test(test_surface_tension),
        cmocka_unit_test(test_roll),
    };
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    MPI_Finalize();
    return failed;
}
