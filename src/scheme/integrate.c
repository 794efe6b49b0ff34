/* integrate: one time step, Eq. (8) and RK4 with frozen per-step terms (sec. 2.4); the
 * surface-tension force is taken again at every stage (scheme/surface_tension.h). */
#include "boundary/tank.h"
#include "core/reduce.h"
#include "core/team_loop.h"
#include "scheme/passes.h"
#include "scheme/solver.h"
#include "scheme/invariants.h"

/* Eq. (8); dt_a from the largest acceleration of the previous step */
static double time_step(const solver *s)
{
    double dt = s->dv.dt_c;
    if (s->dv.dt_v < dt) dt = s->dv.dt_v;
    if (s->dv.dt_st < dt) dt = s->dv.dt_st;
    if (s->max_acc > 0.0) {
        double dt_a = 0.25 * sqrt(s->dv.h / s->max_acc);
        if (dt_a < dt) dt = dt_a;
    }
    return dt;
}

/* The thinnest skin, in dr: a particle at rest still gets one. */
#define SKIN_MIN 0.05

/* The cell grid of the neighbour search within `cutoff`: the tank and a cutoff around it. */
static int neighbour_grid(const solver *s, cell_grid *g, double cutoff)
{
    double lo[DIM], hi[DIM];
    for (int d = 0; d < DIM; d++) {
        lo[d] = -cutoff;
        hi[d] = s->tank.size[d] + cutoff;
    }
    return cells_setup(g, lo, hi, cutoff, s->dv.dr);
}

size_t solver_strips_at_most(const solver *s)
{
    cell_grid g = {0};
    size_t strips =
        neighbour_grid(s, &g, 2.0 * s->dv.h + SKIN_MIN * s->dv.dr) ? 0 : cells_n_strips(&g);
    cells_free(&g);
    return strips;
}

/* Sorts the fluid by cell, makes the ghosts and lists the neighbours within 2h + skin, where
 * the skin covers the relative motion of two particles during the step: pairs beyond 2h add
 * exactly zero, so the results do not depend on the skin as long as it is wide enough. */
static int build_neighbours(solver *s, double dt, const tank_frame *frame)
{
    particles *p = &s->p;
    double max_speed = fluid_max_speed(&s->p, s->scratch);
    double bound = dt * (solver_max(s, &max_speed, 1) + dt * s->max_acc);
    s->skin = 3.0 * bound > SKIN_MIN * s->dv.dr ? 3.0 * bound : SKIN_MIN * s->dv.dr;
    double cutoff = 2.0 * s->dv.h + s->skin;
    if (neighbour_grid(s, &s->grid, cutoff)) return -1;
    /* fluid sorted by cell: neighbours are close in memory */
    p->n_total = p->n_fluid;
    p->n_halo = 0;
    if (cells_bin(&s->grid, p->x, p->n_fluid)) return -1;
    cells_sort_order(&s->grid, p->n_fluid, s->order);
    particles_permute_fluid(p, s->order, s->scratch);
    if (s->domain && s->domain->distribute(s->domain, s)) return -1;
    if (tank_make_ghosts(&s->tank, p, cutoff)) return -1;
    solver_update_eos(s);
    tank_refresh_ghosts(p, frame, s->pp.rho0, s->pp.c0);
    if (cells_bin(&s->grid, p->x, p->n_total)) return -1;
    cells_room idle = {s->rk_block, 2 * RK_MASS * s->work_capacity}; /* solver.h */
    return neighbours_build(&s->nl, &s->grid, p->x, p->n_fluid, cutoff, s->pp.k.support2, idle);
}

/* The integrated variables as a set of fields (FIELD_MASK). */
#define INTEGRATED_MASK_SCALAR(name) | FIELD_MASK(name)
#define INTEGRATED_MASK_VECTOR(name) | FIELD_MASK(name)
#define INTEGRATED_FIELDS            (0 PARTICLE_INTEGRATED(INTEGRATED_MASK_SCALAR, INTEGRATED_MASK_VECTOR))

/* The integrated variables y[v] and, for v >= DIM, their stored rates rate[v] (the first DIM
 * are the position's components, whose rate is the transport velocity, rhs.h). */
static void rk_arrays(solver *s, double **y, double **rate)
{
    int v = 0;
    for (int d = 0; d < DIM; d++) y[v] = s->p.x[d], rate[v++] = NULL;
#define RK_SCALAR(name) y[v] = s->p.name, rate[v++] = s->k.d##name;
#define RK_VECTOR(name)                                                                            \
    for (int d = 0; d < DIM; d++) y[v] = s->p.name[d], rate[v++] = s->k.d##name[d];
    PARTICLE_RATED(RK_SCALAR, RK_VECTOR)
}

/* One variable of particle i after a stage's rate k: the weighted sum gains w k, and the state
 * moves on to the next stage's, y0 + c k, or after the last stage to the step's end, y0 + c sum
 * (c = dt). The first stage keeps the step's starting state in y0 first: within the loop that
 * reads it, by the thread that goes on to use it, rather than in a copy of its own. */
static inline void rk_variable(double *sum, double *y, double *y0, size_t i, double k, double w,
                               double c, bool first, bool last)
{
    if (first) y0[i] = y[i];
    sum[i] = (first ? 0.0 : sum[i]) + w * k;
    y[i] = y0[i] + c * (last ? sum[i] : k);
}

/* After the right-hand side of stage `stage` (0..3) with weight w, every fluid particle's
 * variables (rk_variable). One loop for the sum and the next state, so the state and the rates
 * are read once; each particle's own entries only, and the position's rate taken from the
 * stage's state before its velocity changes. */
static void rk_accumulate(solver *s, double *const *y, double *const *rate, int n_vars, int stage,
                          double w, double c)
{
    particles *p = &s->p;
    bool first = stage == 0, last = stage == 3;
    /* a team loop, as the right-hand side before it: whoever wrote a particle's rates */
    TEAM_FOR (i, p->n_fluid) {
        vec transport = rhs_transport_velocity(&s->pp, p, i);
        for (int v = 0; v < DIM; v++)
            rk_variable(s->sum[v], y[v], s->y0[v], i, transport.c[v], w, c, first, last);
        for (int v = DIM; v < n_vars; v++)
            rk_variable(s->sum[v], y[v], s->y0[v], i, rate[v][i], w, c, first, last);
    }
}

/* Input power of the tank's motion (theory §10): the power of the body force beyond the
 * level gravity (0, -g, 0) whose potential epot counts, sum m (f(r, u) - g_level) . u. For a
 * tank that translates that is -sum m a0 . u. A rotating one adds its turned gravity and the
 * Euler and centrifugal terms; the Coriolis term does no work and is left out. */
static double input_power(solver *s, const tank_frame *frame)
{
    if (s->mo.kind == MOTION_NONE) return 0.0;
    vec a;
    for (int d = 0; d < DIM; d++) a.c[d] = frame->origin_acc[d];
    particles *p = &s->p;
    if (!s->mo.rotates) {
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < p->n_fluid; i++)
            s->scratch[i] = -p->m[i] * vec_dot(a, vec_load(p->u, i));
        return solver_sum(s, s->scratch, p->n_fluid);
    }
    vec tilt; /* the frame's gravity less the level one */
    for (int d = 0; d < DIM; d++) tilt.c[d] = frame->gravity[d] - (d == 1 ? -s->cfg->gravity : 0.0);
    vec uniform = vec_sub(tilt, a);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        double r[3] = {0.0, 0.0, 0.0}, rotation[3];
        for (int d = 0; d < DIM; d++) r[d] = p->x[d][i] - frame->center[d];
        frame_rotation_force(frame, r, rotation);
        vec f = uniform;
        for (int d = 0; d < DIM; d++) f.c[d] += rotation[d];
        s->scratch[i] = p->m[i] * vec_dot(f, vec_load(p->u, i));
    }
    return solver_sum(s, s->scratch, p->n_fluid);
}

/* The rate at which the particles' moves beyond the flow change the potential energy
 * sum m g y: shifting and the volume correction move a particle by (dx/dt - u) dt, and with
 * variable masses (eta > 0) mass moves between particles. None is a force: the liquid's
 * mass is relocated, not lifted, so this energy is no work and no dissipation, and the budget
 * books it apart (work_moves; docs/energy.md). */
static double moves_power(solver *s)
{
    particles *p = &s->p;
    const rates *k = &s->k;
    double g = s->cfg->gravity;
    bool masses_vary = solver_masses_vary(s);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        double dx = rhs_transport_velocity(&s->pp, p, i).c[1], dm = masses_vary ? k->dm[i] : 0.0;
        s->scratch[i] = g * (p->m[i] * (dx - p->u[1][i]) + dm * p->x[1][i]);
    }
    return solver_sum(s, s->scratch, p->n_fluid);
}

static double max_acceleration(solver *s)
{
    particles *p = &s->p;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) s->scratch[i] = vec_norm(vec_load(s->k.du, i));
    return solver_max(s, s->scratch, p->n_fluid);
}

static double max_displacement(solver *s)
{
    particles *p = &s->p;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        double r2 = 0.0;
        for (int d = 0; d < DIM; d++) {
            double dx = p->x[d][i] - s->y0[d][i];
            r2 += dx * dx;
        }
        s->scratch[i] = sqrt(r2);
    }
    return solver_max(s, s->scratch, p->n_fluid);
}

int solver_prepare(solver *s, double t_stop)
{
    double dt = time_step(s);
    if (s->t + dt > t_stop) dt = t_stop - s->t;
    s->dt = dt;
    tank_frame frame = solver_frame(s, s->t);
    if (build_neighbours(s, dt, &frame) || passes_prepare(s, &frame)) return -1;
    /* eta is decided now (passes.c): the masses' RK4 arrays when they first vary */
    return solver_masses_vary(s) ? solver_reserve_masses(s) : 0;
}

void solver_advance(solver *s, double t_stop)
{
    static const double stage_c[4] = {0.0, 0.5, 0.5, 1.0};
    static const double stage_w[4] = {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0};
    particles *p = &s->p;
    double dt = s->dt;
    double *y[RK_VARS], *rate[RK_VARS];
    rk_arrays(s, y, rate);
    /* constant masses stay as they are: m + c * 0 = m (the mass is the last variable) */
    int n_vars = solver_masses_vary(s) ? RK_VARS : RK_MASS;
    double work = 0.0, work_st = 0.0, work_moves = 0.0;
    bool moves = s->pp.shifting || s->pp.volume_correction;
    for (int stage = 0; stage < 4; stage++) {
        double ts = s->t + stage_c[stage] * dt;
        tank_frame frame = solver_frame(s, ts);
        if (stage > 0) { /* stage 0 is the state solver_prepare has set up; the others' state
                            was set by the previous stage's rk_accumulate */
            if (s->domain) s->domain->refresh_halo(s->domain, p, INTEGRATED_FIELDS);
            solver_update_eos(s);
            tank_refresh_ghosts(p, &frame, s->pp.rho0, s->pp.c0);
            if (s->pp.surface_tension) /* from the stage's positions (surface_tension.h) */
                surface_tension_compute(&s->st, &s->pp.k, p, &s->nl, &s->bodies,
                                        solver_bodies_domain(s), &s->st_work,
                                        solver_surface_tension_room(s));
        }
        /* stage 0 at the positions of the build (solver_prepared_rows) */
        neighbour_list prepared = solver_prepared_rows(s);
        rhs_compute(&s->pp, p, stage == 0 ? &prepared : &s->nl, &frame, s->eta_control.eta, &s->k);
        if (stage == 0) s->max_acc = max_acceleration(s);
        work += stage_w[stage] * input_power(s, &frame);
        if (s->pp.surface_tension)
            work_st += stage_w[stage] * surface_tension_power(p, s->scratch, solver_reducer(s));
        if (moves) work_moves += stage_w[stage] * moves_power(s);
        rk_accumulate(s, y, rate, n_vars, stage, stage_w[stage],
                      stage < 3 ? stage_c[stage + 1] * dt : dt);
    }
    s->work_in += dt * work;
    s->work_st += dt * work_st;
    s->work_moves += dt * work_moves;
    s->max_displacement = max_displacement(s);
    /* land exactly on t_stop when the step was cut to reach it */
    s->t = s->t + dt >= t_stop ? t_stop : s->t + dt;
    s->step++;
    s->last_dt = dt;
    solver_update_eos(s);
}

int solver_step(solver *s, double t_stop)
{
    if (solver_prepare(s, t_stop)) return -1;
    solver_check_invariants(s);
    solver_advance(s, t_stop);
    return 0;
}
