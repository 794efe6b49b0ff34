/* estimate: memory and wall time of a case before it runs (docs/checks.md). Compiled for
 * DIM = 2 and 3: the particle store's bytes per slot and the RK4 work arrays depend on DIM. */
#include "scheme/estimate.h"
#include "core/cells.h"
#include "core/particles.h"
#include "scheme/models.h"
#include "scheme/solver.h"

#include <math.h>
#include <stdint.h>

/* The wall time's model (docs/checks.md), its figures measured on the 2-core development machine
   on whole runs of the shipped cases (delta-plus-ALE with its correction, surface tension in
   2D) with every output off, then with each output alone (2026-12-07):
   - one thread, a particle-step: 2D 3.9 / 2.87 / 2.24 / 2.21 us at 290 / 1775 / 7150 / 28600
     particles (cases/default.ini at N = 10, 25, 50, 100), the surface's share falling as
     1/sqrt(n): US_2D + US_2D_EDGE / sqrt(n); 3D 6.9 / 6.7 / 6.9 us at 1224 / 6840 / 23220
     (cases/inm2-3d.ini at N = 12, 20, 30);
   - more threads: two ran 1.6 to 2.1 times as fast from 1775 particles on in 2D, 1.8 to 1.95 in
     3D, and no faster at 290 (the thread tuner then keeps one): a step on p threads takes its
     one-thread time / (THREAD_EFFICIENCY p) + STEP_SYNC_US, or the one-thread time if less;
   - outputs: a row of timeseries.csv (with loads.csv and probes.csv) ROW_US + ROW_US_PARTICLE n,
     a snapshot SNAPSHOT_US + SNAPSHOT_US_PARTICLE n, a particle image IMAGE_US; and every
     multiple of output.timeseries_every, output.snapshot_every, probes.every and the motion's
     period on which a step lands splits a step in two, half a step more on average each, and
     an interval shorter than the step makes a step of each;
   - the start (lattice, first neighbour lists, files) START_US + START_US_PARTICLE n.
   The machine's speed varied by some 20 % from one minute to the next: the one-thread figures
   are those fits scaled by 0.9, which centres tools/check-estimates' whole runs on 1. */
#define US_2D                1.8
#define US_2D_EDGE           29.0
#define US_3D                6.2
#define THREAD_EFFICIENCY    0.9
#define STEP_SYNC_US         300.0
#define ROW_US               100.0
#define ROW_US_PARTICLE      0.3
#define SNAPSHOT_US          3000.0
#define SNAPSHOT_US_PARTICLE 0.2
#define IMAGE_US             25000.0
#define START_US             3e4
#define START_US_PARTICLE    1.0

static double us_per_particle_step(double n)
{
    return DIM == 2 ? US_2D + US_2D_EDGE / sqrt(fmax(n, 1.0)) : US_3D;
}

/* How many times an interval `every` (s) fits in t_end; 0 for an output that is off. */
static double count_of(double t_end, double every)
{
    return every > 0.0 ? floor(t_end / every + 1e-9) : 0.0;
}

/* The run's wall time: its steps, each on the threads that pay, its outputs and its start. */
static void estimate_seconds(const config *cfg, const derived *dv, run_estimate *e)
{
    double n = e->n_fluid;
    double step_1 = n * e->us_per_particle_step;
    double step_p = step_1 / (THREAD_EFFICIENCY * e->threads) + STEP_SYNC_US;
    e->speedup = e->threads > 1 && step_p < step_1 ? step_1 / step_p : 1.0;
    /* the finest interval a step lands on sets the extra steps; one finer than the step cuts
       every step to it */
    double finest = cfg->t_end, landing[CONFIG_LANDINGS];
    config_landing_intervals(cfg, dv->omega, landing);
    for (int k = 0; k < CONFIG_LANDINGS; k++)
        if (landing[k] > 0.0) finest = fmin(finest, landing[k]);
    e->steps = fmax(cfg->t_end / dv->dt + 0.5 * count_of(cfg->t_end, finest),
                    count_of(cfg->t_end, finest));
    double rows =
        cfg->timeseries_every > 0.0 ? count_of(cfg->t_end, cfg->timeseries_every) : e->steps;
    double output_us =
        rows * (ROW_US + ROW_US_PARTICLE * n) +
        count_of(cfg->t_end, cfg->snapshot_every) * (SNAPSHOT_US + SNAPSHOT_US_PARTICLE * n) +
        count_of(cfg->t_end, cfg->image_every) * IMAGE_US;
    e->output_seconds = 1e-6 * (output_us + START_US + START_US_PARTICLE * n);
    e->seconds = 1e-6 * e->steps * step_1 / e->speedup + e->output_seconds;
}

/* Lattice points of an axis of n points, spaced s, whose first point is dist0 + s/2 from a
   wall, that lie within `reach` of it: the layers that get a ghost on that side. */
static double layers(double dist0, double s, long n, double reach)
{
    double q = (reach - dist0) / s - 0.5;
    if (!(q > 0.0)) return 0.0;
    q = ceil(q);
    return q < (double)n ? q : (double)n;
}

void DIM_NAME(estimate_run)(const config *cfg, const derived *dv, int threads, run_estimate *e)
{
    const double tank[3] = {cfg->tank_length, cfg->tank_height, cfg->tank_width};
    const double lo[3] = {cfg->liquid_x0, cfg->liquid_y0, 0.0};
    const double len[3] = {cfg->liquid_length, cfg->liquid_height, cfg->tank_width};
    /* the neighbour lists' and ghosts' radius 2h + skin, the skin at its floor 0.05 dr
       (the particles are at rest at t = 0: build_neighbours in integrate.c) */
    double reach = 2.0 * dv->h + 0.05 * dv->dr;
    double n = (double)dv->n_fluid, box = 1.0, padded = 1.0, cells = 1.0, cell_volume = 1.0;
    for (int d = 0; d < DIM; d++) {
        double nd = (double)dv->n_axis[d];
        double ghost_lo = layers(lo[d], dv->spacing[d], dv->n_axis[d], reach);
        double ghost_hi = layers(tank[d] - (lo[d] + len[d]), dv->spacing[d], dv->n_axis[d], reach);
        box *= nd;
        padded *= nd + ghost_lo + ghost_hi;
        cells *= fmax(1.0, ceil((tank[d] + 2.0 * reach) / reach)); /* cells_setup */
        cell_volume *= dv->spacing[d];
    }
    /* tank_make_ghosts mirrors each particle within reach of a wall once per wall, edge and
       corner: the padded lattice less the lattice; for the ellipse, in proportion to its
       share of the box's points */
    double ghosts = box > 0.0 ? (padded - box) * n / box : 0.0;
    double total = n + ghosts;

    /* the store: lattice_fill's room, grown as particles_reserve_images grows it for the
       ghosts; the fields no image holds (FIELD_SOURCES_ONLY) for the fluid alone, the
       ghosts' own (FIELD_GHOSTS_ONLY) for the store's tail */
    size_t capacity = particles_initial_room((size_t)n);
    while ((double)capacity < total) capacity = particles_grown(capacity);
    double sources_only = (double)particles_bytes_sources_only();
    double ghosts_only = (double)particles_bytes_ghosts_only();
    double store = ((double)particles_bytes_per_slot() - sources_only - ghosts_only) * capacity +
                   sources_only * n + ghosts_only * ((double)capacity - n);
    /* solver_reserve: y0 and sum (RK_VARS each) and the stored rates (PARTICLE_N_RATED),
       the masses' three only where they may vary (eta = 1 or the switch), and scratch (the
       sort's order lies in y0 and sum, idle between steps) */
    double rk = 2.0 * RK_VARS + PARTICLE_N_RATED - (models_params(cfg->scheme).eta ? 0.0 : 3.0);
    double work = (rk + 1.0) * sizeof(double) * n;
    /* neighbours_build: a row per fluid particle, sized by the longest row, of 16-bit entries,
       a count, the near part's count and two bases (core/cells.h; a tank whose rows do not
       fit the 16-bit windows takes 32 bits an entry and no bases); at rest a particle has
       about the lattice points of the ball of radius reach */
    double ball = DIM == 2 ? M_PI * reach * reach : 4.0 / 3.0 * M_PI * reach * reach * reach;
    double row = (double)neighbours_row_room((int32_t)ceil(ball / cell_volume));
    double lists = (row * sizeof(uint16_t) + 4.0 * sizeof(int32_t)) * n;
    /* the cell grid: start per cell, item and cell_of per particle; the neighbour build's copy
       of the positions goes into the RK4 arrays y0 and sum (cells_room), which are idle then,
       unless the images outnumber them (never in a tank: 2 RK_MASS / DIM particles a fluid
       particle) */
    double grid = (cells + 1.0) * sizeof(size_t) + 2.0 * sizeof(uint32_t) * total;
    if (DIM * total > 2.0 * RK_MASS * n) grid += DIM * sizeof(double) * total;
    /* surface tension's work over the fluid (a wall's image reads its source's; its normals
       and curvature in the stage's rates, solver_surface_tension_room) and its sums per body
       (at most one body a particle) */
    double st =
        cfg->surface_tension > 0.0
            ? ((DIM + 1.0 + BALANCE_FIRST + BALANCE_SECOND) * sizeof(double) + sizeof(int32_t)) * n
            : 0.0;

    e->n_fluid = n;
    e->n_ghost = ghosts;
    e->bytes = store + work + lists + grid + st;
    e->bytes_per_particle = n > 0.0 ? e->bytes / n : 0.0;
    e->neighbours_per_row = row;
    e->us_per_particle_step = us_per_particle_step(n);
    e->threads = threads > 0 ? threads : 1;
    estimate_seconds(cfg, dv, e);
}
