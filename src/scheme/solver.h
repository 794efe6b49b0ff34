/* solver: the state of a run and one time step (docs/architecture.md): neighbours and ghosts, the
 * frozen per-step fields and bounce-back, four RK4 stages. */
#ifndef VCSPH_SOLVER_H
#define VCSPH_SOLVER_H

#include "boundary/motion.h"
#include "boundary/tank.h"
#include "core/cells.h"
#include "core/config.h"
#include "core/derived.h"
#include "core/particles.h"
#include "core/reduce.h"
#include "diag/energy.h"
#include "scheme/eta_control.h"
#include "scheme/physics_params.h"
#include "scheme/rhs.h"
#include "scheme/surface_tension.h"
#include "scheme/volume_correction.h"

/* integrated fluid variables (PARTICLE_INTEGRATED): x[DIM], u[DIM], rho, m */
#define RK_VARS PARTICLE_N_INTEGRATED
/* the mass, the last of them: a step with constant masses integrates the others only */
#define RK_MASS (RK_VARS - 1)

/* What the step asks of a run split among processes (the MPI build's parallel/mpi_domain.h,
 * docs/mpi.md); a solver without one (domain NULL) is the whole liquid on one process, where
 * each of these is the identity or the local reduction of core/reduce.h. */
struct solver;
typedef struct solver_domain {
    /* After the fluid's sort by cell: hands every particle to the process that owns its
       position, sorts the own ones by cell again and appends the halo (p->n_halo). Returns 0,
       or -1 when out of memory. */
    int (*distribute)(const struct solver_domain *d, struct solver *s);
    /* Copies the fields of `fields` (a set of FIELD_MASK) of the own particles into the
       halos of the other processes. */
    void (*refresh_halo)(const struct solver_domain *d, particles *p, uint64_t fields);
    /* This process's part of the box along x, [lo, hi) (m; -INFINITY and INFINITY at the
       ends): the positions whose cells it owns since the last distribute, every neighbour
       within a cell of them being its own or in its halo; and how many of the halo particles
       precede its own in the global order (the left neighbour's, at the head of the tail).
       Returns -1 before the first distribute. */
    int (*part_along_x)(const struct solver_domain *d, const struct solver *s, double *lo,
                        double *hi, size_t *n_halo_before);
    /* The global reductions (core/reduce.h), and the bodies of liquid across processes
       (bodies.h). */
    reducer reduce;
    bodies_domain bodies;
    void *context;
} solver_domain;

typedef struct solver {
    const config *cfg;
    derived dv;
    motion mo;
    tank tank;
    physics_params pp;
    particles p;
    cell_grid grid;
    neighbour_list nl;

    /* RK4 work arrays over the fluid; the masses' (y0[RK_MASS], sum[RK_MASS], k.dm) only from
       the first step with variable masses on (solver_masses_vary), NULL before */
    double *y0[RK_VARS];  /* state at the start of the step */
    double *sum[RK_VARS]; /* weighted sum of the stage rates */
    double *rk_block;     /* y0[v] and sum[v] for v < RK_MASS, in one block of 2 RK_MASS
                             work_capacity doubles: between steps it holds nothing, and the
                             neighbour build borrows it for its copy of the positions */
    rates k;              /* rates of the current stage */
    double *scratch;      /* n_fluid doubles */
    uint32_t *order;      /* n_fluid sort permutation (32-bit, as the cell grid's items), used
                             only between steps: it lies in rk_block */
    size_t work_capacity; /* the fluid particles these arrays hold room for */
    size_t rate_capacity; /* k.du and k.drho: work_capacity, or the fluid and the halo when
                             lent to surface tension (solver_surface_tension_room) */

    double t, dt;   /* time; size of the prepared step */
    double last_dt; /* size of the step that ended at t */
    long step;
    double max_acc;                 /* largest |du/dt| of the last step (dt_a of Eq. 8) */
    double skin;                    /* neighbour-list margin of this step */
    double max_displacement;        /* largest move of a particle during the last step */
    double work_in;                 /* integral of the input power -sum m a_tank . u */
    surface_tension_params st;      /* sigma and the calibration of the interface function */
    surface_tension_work st_work;   /* its work arrays, fluid and ghosts */
    bodies bodies;                  /* the step's bodies of liquid, for both of the above */
    volume_correction_work vc_work; /* the correction's sums per body */
    double work_st;                 /* integral of the surface-tension power sum F^st . u */
    double work_moves;              /* integral of the moves' potential power (integrate.c) */
    eta_controller eta_control;     /* eta of Eq. (3): 1 = variable masses (delta-ALE), varied in
                                       delta-plus-ALE by the switch (theory §8) */
    long n_edbc;                    /* particles corrected by EdBC at the last step start */
    int eta_switched;               /* the last solver_prepare switched eta ... */
    char eta_switch_detail[160];    /* ... and how */
    const solver_domain *domain;    /* the processes' split (MPI), or NULL: one process */
    double mass_reference;          /* the debug build's total mass at its first check */
} solver;

/* Whether the masses vary in this step (rhs_masses_vary at the step's eta). */
static inline bool solver_masses_vary(const solver *s)
{
    return rhs_masses_vary(&s->pp, s->eta_control.eta);
}

/* The neighbour rows for a pair loop between the lists' build and the first stage's move (the
 * passes of solver_prepare, the outputs of a step, the first stage's right-hand side): no
 * pass moves a particle (passes_prepare_writes, checked by tests/test_near_rows.c), so the
 * particles are where the lists were built, and the rows' near parts hold every pair within
 * 2h (core/cells.h). */
static inline neighbour_list solver_prepared_rows(const solver *s)
{
    return neighbours_near(&s->nl);
}

/* The global reductions of the run: over every process with a domain, NULL without. */
static inline const reducer *solver_reducer(const solver *s)
{
    return s->domain ? &s->domain->reduce : NULL;
}
static inline const bodies_domain *solver_bodies_domain(const solver *s)
{
    return s->domain ? &s->domain->bodies : NULL;
}
static inline double solver_sum(const solver *s, const double *a, size_t n)
{
    return reducer_sum(solver_reducer(s), a, n);
}
static inline double solver_max(const solver *s, const double *a, size_t n)
{
    return reducer_max(solver_reducer(s), a, n);
}

#define solver_init                    DIM_NAME(solver_init)
#define solver_init_part               DIM_NAME(solver_init_part)
#define solver_strips_at_most          DIM_NAME(solver_strips_at_most)
#define solver_reserve                 DIM_NAME(solver_reserve)
#define solver_reserve_masses          DIM_NAME(solver_reserve_masses)
#define solver_reserve_surface_tension DIM_NAME(solver_reserve_surface_tension)
#define solver_free                    DIM_NAME(solver_free)
#define solver_step                    DIM_NAME(solver_step)
#define solver_prepare                 DIM_NAME(solver_prepare)
#define solver_advance                 DIM_NAME(solver_advance)
#define solver_frame                   DIM_NAME(solver_frame)
#define solver_update_eos              DIM_NAME(solver_update_eos)
#define solver_diagnostics             DIM_NAME(solver_diagnostics)
#define solver_health                  DIM_NAME(solver_health)

/* Particles on a lattice filling the liquid box with the hydrostatic state (sec. 2.1).
 * Returns 0, or 2 with a message. */
int solver_init(solver *s, const config *cfg, char *err, size_t err_len);
/* solver_init with only part `part` of `parts` of the lattice order (reduce_share): a
 * process's share of the liquid in an MPI run, which never holds the whole (docs/mpi.md). */
int solver_init_part(solver *s, const config *cfg, int part, int parts, char *err, size_t err_len);
void solver_free(solver *s);
/* The most strips of cells along x (core/cells.h) that a step's neighbour grid can have: the
 * one of the thinnest skin, a liquid at rest; a faster flow has a thicker skin, larger cells
 * and fewer strips. An MPI run gives each process whole strips (docs/mpi.md). 0 when out of
 * memory. */
size_t solver_strips_at_most(const solver *s);
/* Room in the work arrays for n_fluid fluid particles (an MPI process's share changes from
 * step to step). Returns 0, or -1 when out of memory. */
int solver_reserve(solver *s, size_t n_fluid);
/* Room for surface tension's work over the fluid and the halo, and for what the solver lends
 * it (solver_surface_tension_room). Returns 0, or -1 when out of memory. */
int solver_reserve_surface_tension(solver *s);
/* The room surface_tension_compute borrows: the stage's rates du and drho. The force is computed
 * only between one stage's rk_accumulate, which has added the rates to the weighted sum, and
 * the next right-hand side, which writes them again (passes.c at stage 0, integrate.c at the
 * others), when they hold nothing. */
static inline surface_tension_room solver_surface_tension_room(const solver *s)
{
    surface_tension_room room = {.kappa = s->k.drho};
    for (int d = 0; d < DIM; d++) room.normal[d] = s->k.du[d];
    return room;
}
/* Allocates the masses' RK4 arrays (a step with variable masses) if it has not yet. Returns
 * 0, or -1 when out of memory. */
int solver_reserve_masses(solver *s);
/* Sets up the step from the current state: its size min(Eq. (8), t_stop - t), the fluid
 * sorted by cell, ghosts, neighbour lists, the per-step fields (geometry, free surface,
 * shifting, diffusion, surface tension), which also serve the diagnostics of the state at
 * time t, and bounce-back (tank.h). Returns 0, or -1 when out of memory. */
int solver_prepare(solver *s, double t_stop);
/* The prepared step: four RK4 stages. */
void solver_advance(solver *s, double t_stop);
/* solver_prepare, then solver_advance. */
int solver_step(solver *s, double t_stop);
/* The tank frame at time t (boundary/frame.h; theory §6). */
tank_frame solver_frame(const solver *s, double t);
/* The global sums of the time series for the state at s->t (diag/energy.h; uses s->scratch). */
void solver_diagnostics(solver *s, diagnostics *out);
/* health_check of the state at s->t within the tank and numerics.density_bound. */
int solver_health(const solver *s, char *msg, size_t msg_len);
/* p and V = m/rho (the linear EOS) of the fluid and the halo. */
void solver_update_eos(solver *s);

#endif
