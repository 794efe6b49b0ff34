/* estimate: memory and wall time of a case before it runs (docs/checks.md). Compiled for
 * DIM = 2 and 3: the particle store's bytes per slot and the RK4 work arrays depend on DIM. */
#include "scheme/estimate.h"
#include "core/cells.h"
#include "core/particles.h"
#include "scheme/models.h"
#include "scheme/solver.h"

#include <math.h>
#include <stdint.h>

/* Cost of one particle-step (one fluid particle through one RK4 step, its ghosts, neighbour
   lists, per-step fields and volume diagnostics included) on one thread of the 2-core
   development machine, measured on whole runs of the shipped cases as they are
   (delta-plus-ALE, surface tension, probes, snapshots and images): a run's wall time over
   the steps and particles this estimate counts (docs/checks.md). cases/inm1.ini at N = 25
   over 5 s, 3.4 us; cases/inm2-3d.ini at N = 20 over 0.5 s, 7.5 us. Finer resolutions cost
   less a particle-step (INM1 at N = 50: 2.2 us; INM2 3D at N = 40: 5.3 us): this errs long. */
#define US_PER_PARTICLE_STEP (DIM == 2 ? 3.4 : 7.5)

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
    e->steps = cfg->t_end / dv->dt;
    e->us_per_particle_step = US_PER_PARTICLE_STEP;
    e->threads = threads > 0 ? threads : 1;
    e->seconds = e->steps * n * US_PER_PARTICLE_STEP * 1e-6 / e->threads;
}
