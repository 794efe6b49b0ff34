/* solver: set-up and the neighbour structures of a step. */
#include "scheme/solver.h"
#include "boundary/lattice.h"
#include "core/arrays.h"
#include "diag/freesurface.h"
#include "diag/health.h"
#include "physics/eos.h"
#include "physics/shifting.h"
#include "physics/viscosity.h"
#include "scheme/case_numbers.h"
#include "scheme/models.h"
#include "scheme/volume_correction.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void physics_setup(solver *s)
{
    const config *cfg = s->cfg;
    physics_params *pp = &s->pp;
    model_params mp = models_params(cfg->scheme);
    pp->k = kernel_make(s->dv.h);
    pp->dr = s->dv.dr;
    pp->rho0 = cfg->density;
    pp->c0 = s->dv.c0;
    pp->nu = cfg->viscosity;
    pp->filter_length = 2.0 * s->dv.h;
    pp->c_delta = mp.c_delta;
    pp->delta_cap = 0.1 * pp->filter_length * pp->c0;                    /* sec. 2.2 */
    pp->nu_t_cap = 0.1 * pp->filter_length * pp->c0 / (2.0 * (DIM + 2)); /* sec. 2.2 */
    pp->lambda_renormalize = 0.2; /* theory §2 (guessed there; kept) */
    pp->normal_reference = freesurface_reference_normal(&pp->k, pp->dr);
    pp->shifting = mp.xi > 0.0;
    pp->shift_u_max = 0.1 * pp->c0; /* theory §4 (inferred from Sun et al. 2019) */
    pp->volume_correction = cfg->volume_correction == VOLUME_CORRECTION_GEOMETRIC;
    pp->lattice_kernel_sum = kernel_lattice_sum(&pp->k, pp->dr, 0);
    pp->surface_kernel_sum = kernel_lattice_sum(&pp->k, pp->dr, 1);
    pp->w_dr = kernel_w(&pp->k, pp->dr);
    pp->unpack_speed = cfg->surface_unpacking ? SURFACE_UNPACK_RATE * pp->shift_u_max : 0.0;
    pp->surface_sum_scale = s->dv.cell_volume / pp->surface_kernel_sum;
    pp->delta_c0_h = mp.delta * pp->c0 * pp->k.h;
    pp->les = cfg->les;
    pp->van_driest = cfg->les && cfg->wall == WALL_NO_SLIP;
    pp->surface_tension = cfg->surface_tension > 0.0;
    s->st = surface_tension_setup(&pp->k, pp->dr, cfg->surface_tension, pp->lambda_renormalize);
}

/* The work arrays' numbers (core/arrays.h: each at its own offset in its pages), after the
 * particle store's fields'. */
enum {
    ARRAY_RATE_U = FIELD_BITS * DIM,
    ARRAY_RATE_RHO = ARRAY_RATE_U + DIM,
    ARRAY_RATE_M,
    ARRAY_Y0_M,
    ARRAY_SUM_M,
    ARRAY_SCRATCH,
    ARRAY_RK_BLOCK
};

/* Room for n elements of `size` bytes in work array number k, *a, which held `old` of them:
 * nothing it held is kept (a work array holds nothing between the steps that grow it). */
static int grow(void **a, size_t old, size_t n, size_t size, int k)
{
    return array_grow(a, old * size, 0, n * size, k);
}

/* The distance between the RK4 block's arrays, in doubles: at least n, and one cache line more
 * than whole pages, so that each array starts its own line past a page boundary. */
static size_t rk_stride(size_t n)
{
    size_t page = ARRAY_PAGE / sizeof(double), line = ARRAY_LINE / sizeof(double);
    return (n + page - 1) / page * page + line;
}

/* The RK4 block's doubles for n particles (none before the first solver_reserve). */
static size_t rk_block_doubles(size_t n) { return n ? 2 * RK_MASS * rk_stride(n) : 0; }

_Static_assert(PARTICLE_N_RATED == DIM + 2, "solver_reserve grows the rates du, drho and dm");

/* The RK4 arrays of the masses, at the work arrays' capacity. */
static int grow_mass_arrays(solver *s, size_t n)
{
    size_t old = s->k.dm ? s->work_capacity : 0;
    if (grow((void **)&s->y0[RK_MASS], old, n, sizeof(double), ARRAY_Y0_M) ||
        grow((void **)&s->sum[RK_MASS], old, n, sizeof(double), ARRAY_SUM_M) ||
        grow((void **)&s->k.dm, old, n, sizeof(double), ARRAY_RATE_M))
        return -1;
    return 0;
}

/* The stage's rates du and drho, room for n particles at least (solver_surface_tension_room
 * lends them over the fluid and the halo). */
static int grow_rates(solver *s, size_t n)
{
    if (n <= s->rate_capacity) return 0;
    for (int d = 0; d < DIM; d++)
        if (grow((void **)&s->k.du[d], s->rate_capacity, n, sizeof(double), ARRAY_RATE_U + d))
            return -1;
    if (grow((void **)&s->k.drho, s->rate_capacity, n, sizeof(double), ARRAY_RATE_RHO)) return -1;
    s->rate_capacity = n;
    return 0;
}

int solver_reserve_surface_tension(solver *s)
{
    size_t sources = particles_images_begin(&s->p);
    if (grow_rates(s, sources ? sources : 1) ||
        surface_tension_reserve(&s->st_work, sources, s->bodies.count))
        return -1;
    return 0;
}

int solver_reserve(solver *s, size_t n_fluid)
{
    size_t n = n_fluid ? n_fluid : 1;
    if (n <= s->work_capacity) return 0;
    /* nothing in the block outlives a step (solver_advance writes it before reading it) */
    size_t stride = rk_stride(n);
    if (grow((void **)&s->rk_block, rk_block_doubles(s->work_capacity), rk_block_doubles(n),
             sizeof(double), ARRAY_RK_BLOCK))
        return -1;
    for (int v = 0; v < RK_MASS; v++) {
        s->y0[v] = s->rk_block + (size_t)v * stride;
        s->sum[v] = s->rk_block + (size_t)(RK_MASS + v) * stride;
    }
    s->order = (uint32_t *)s->rk_block; /* the sort by cell, before a step */
    if (grow_rates(s, n)) return -1;
    if (s->k.dm && grow_mass_arrays(s, n)) return -1;
    if (grow((void **)&s->scratch, s->work_capacity, n, sizeof(double), ARRAY_SCRATCH)) return -1;
    s->work_capacity = n;
    return 0;
}

int solver_reserve_masses(solver *s) { return s->k.dm ? 0 : grow_mass_arrays(s, s->work_capacity); }

int solver_init(solver *s, const config *cfg, char *err, size_t err_len)
{
    return solver_init_part(s, cfg, 0, 1, err, err_len);
}

int solver_init_part(solver *s, const config *cfg, int part, int parts, char *err, size_t err_len)
{
    memset(s, 0, sizeof *s);
    s->cfg = cfg;
    int status = motion_init(&s->mo, cfg, err, err_len);
    if (status) return status;
    case_numbers(cfg, &s->mo, &s->dv);
    if ((status = derived_check(cfg, &s->dv, err, err_len))) {
        motion_free(&s->mo);
        return status;
    }
    double size[3] = {cfg->tank_length, cfg->tank_height, cfg->tank_width};
    s->tank = tank_box(size, cfg->wall);
    physics_setup(s);
    size_t first, end;
    reduce_share((size_t)s->dv.n_fluid, part, parts, &first, &end);
    if (particles_init(&s->p, 0) || lattice_fill(&s->p, cfg, &s->dv, first, end) ||
        solver_reserve(s, s->p.n_fluid)) {
        snprintf(err, err_len, "out of memory for %ld particles", s->dv.n_fluid);
        solver_free(s);
        return 2;
    }
    eta_control_init(&s->eta_control, cfg, s->dv.response_period);
    /* before any step, the only known acceleration is the largest effective gravity */
    s->max_acc = s->dv.g_max;
    return 0;
}

void solver_free(solver *s)
{
    size_t work = s->work_capacity * sizeof(double), rates = s->rate_capacity * sizeof(double);
    array_free(s->rk_block, rk_block_doubles(s->work_capacity) * sizeof(double), ARRAY_RK_BLOCK);
    array_free(s->y0[RK_MASS], work, ARRAY_Y0_M);
    array_free(s->sum[RK_MASS], work, ARRAY_SUM_M);
    for (int d = 0; d < DIM; d++) array_free(s->k.du[d], rates, ARRAY_RATE_U + d);
    array_free(s->k.drho, rates, ARRAY_RATE_RHO);
    array_free(s->k.dm, work, ARRAY_RATE_M);
    array_free(s->scratch, work, ARRAY_SCRATCH);
    surface_tension_free(&s->st_work);
    bodies_free(&s->bodies);
    volume_correction_free(&s->vc_work);
    particles_free(&s->p);
    cells_free(&s->grid);
    neighbours_free(&s->nl);
    motion_free(&s->mo);
    memset(s, 0, sizeof *s); /* freeing twice (a failed init, then its caller's close) is safe */
}

tank_frame solver_frame(const solver *s, double t)
{
    return motion_frame(&s->mo, s->cfg->gravity, t);
}

void solver_update_eos(solver *s)
{
    particles *p = &s->p;
    double rho0 = s->pp.rho0, c0 = s->pp.c0;
    /* the halo too: the same function of the same state as on its own process */
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < particles_images_begin(p); i++) {
        p->p[i] = eos_pressure(p->rho[i], rho0, c0);
        p->vol[i] = p->m[i] / p->rho[i];
    }
}

void solver_diagnostics(solver *s, diagnostics *out)
{
    energy_params ep = {s->cfg->gravity, s->pp.rho0, s->pp.c0};
    diagnostics_compute(&s->p, &ep, s->scratch, solver_reducer(s), out);
}

int solver_health(const solver *s, char *msg, size_t msg_len)
{
    health_limits lim = {&s->tank, s->pp.rho0, s->cfg->density_bound};
    return health_check(&s->p, &lim, s->t, s->step, msg, msg_len);
}
