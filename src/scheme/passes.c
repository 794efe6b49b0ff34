/* passes: the preparation of a step as a list of passes (docs/architecture.md). Each pass
 * names the particle fields it reads and writes (core/particles.h's registry); the driver
 * runs them in order and brings the wall ghosts up to date, in this one place, before a pass
 * that reads a field an earlier pass changed. */
#include "scheme/passes.h"
#include "core/invariant.h"
#include "diag/freesurface.h"
#include "diag/volume.h"
#include "scheme/edbc.h"
#include "scheme/step_fields.h"
#include "scheme/volume_correction.h"

#include <stdint.h>
#include <stdio.h>

#define F(name) FIELD_MASK(name)

/* The fields a wall ghost takes from its source at every refresh (tank_refresh_ghosts): a pass
 * that changes one of them leaves the ghosts stale until the next refresh. */
#define GHOST_STATE (F(x) | F(u) | F(rho) | F(p) | F(m) | F(vol))

typedef struct {
    const char *name;
    uint64_t reads, writes; /* fields, the ghosts' copies included */
    /* NULL: always; otherwise whether the pass runs for this case and state */
    bool (*active)(const solver *s);
    /* Returns the particles whose state it changed (0: none, the ghosts stay as they are), or
       -1 when out of memory. `rows`: the neighbour rows for the particles' positions now. */
    long (*run)(solver *s, const tank_frame *frame, const neighbour_list *rows);
} step_pass;

static long geometry(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame;
    step_fields_geometry(&s->pp, &s->tank, &s->p, rows);
    return 0;
}

static long free_surface_test(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame;
    freesurface_test(&s->pp.k, s->pp.dr, s->pp.normal_reference, &s->p, rows);
    return 0;
}

static long free_surface_region(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame;
    freesurface_region(&s->pp.k, &s->p, rows, &s->grid);
    return 0;
}

static bool has_eta_control(const solver *s) { return s->cfg->scheme == SCHEME_DELTA_PLUS_ALE; }

/* eps_V1 of this state decides eta for the step (theory §8) */
static long eta_control(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame, (void)rows;
    volume_errors ve;
    volume_compute(&s->p, s->dv.cell_volume, s->scratch, solver_reducer(s), &ve);
    s->eta_switched = eta_control_update(&s->eta_control, s->t, ve.eps_v1, s->eta_switch_detail,
                                         sizeof s->eta_switch_detail);
    return 0;
}

static long edbc(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame, (void)rows;
    edbc_correct(s);
    return s->n_edbc;
}

static bool has_surface_tension(const solver *s) { return s->pp.surface_tension; }

static bool needs_bodies(const solver *s)
{
    return s->pp.surface_tension || s->pp.volume_correction;
}

static long find_bodies(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame;
    if (bodies_reserve(&s->bodies, particles_images_begin(&s->p))) return -1;
    return bodies_find(&s->pp.k, &s->p, rows, solver_bodies_domain(s), &s->bodies);
}

static bool corrects(const solver *s) { return s->pp.volume_correction; }

static bool shifts_or_corrects(const solver *s) { return s->pp.shifting || corrects(s); }

/* The step's density (and mass) diffusion, or NULL (step_fields.h) */
static const step_diffusion *diffusion_of(const solver *s, step_diffusion *d)
{
    if (s->pp.c_delta <= 0.0) return NULL;
    *d = (step_diffusion){.mass = s->eta_control.eta > 0.0, .dt = s->dt};
    return d;
}

/* The rows whose diffusion the shifting pass sums: in a frame that does not rotate, all of
 * them, the walls' images taking their diffusion fields first (their density gradient follows
 * the body force, which depends on the velocity only through the Coriolis force); in a
 * rotating one, those that reach no image, and the frozen terms the others after bounce-back.
 * The same operations either way (tests/test_block_sums.c), one row geometry less a row at a
 * wall. */
static diffusion_rows diffused_beside_shifting(const tank_frame *frame)
{
    return frame->rotating ? DIFFUSION_ROWS_OFF_WALLS : DIFFUSION_ROWS_ALL;
}

static long shifting_and_correction(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    /* the walls' images read e here, after the driver has brought the halo's e up to date */
    if (corrects(s)) volume_correction_ghost_mismatch(&s->p);
    step_diffusion d;
    const step_diffusion *diffusion = diffusion_of(s, &d);
    diffusion_rows beside = diffused_beside_shifting(frame);
    if (diffusion && beside == DIFFUSION_ROWS_ALL)
        tank_mirror_diffusion_fields(&s->p, frame, s->pp.c0);
    step_fields_shifting_and_correction(&s->pp, &s->p, rows, s->pp.shifting, corrects(s), diffusion,
                                        beside);
    return 0;
}

static long correction_mismatch(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame, (void)rows;
    volume_correction_mismatch(&s->pp, &s->p);
    return 0;
}

static long correction_band(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame;
    volume_correction_band(&s->pp, &s->p, rows);
    return 0;
}

static long correction_per_body(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame, (void)rows;
    return volume_correction_per_body(&s->p, &s->bodies, solver_bodies_domain(s), &s->vc_work) ? -1
                                                                                               : 0;
}

static long bounce_back(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame, (void)rows;
    return (long)tank_bounce_back(&s->tank, &s->p, s->dv.dr, s->dt);
}

static long frozen_terms(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    step_diffusion d;
    diffusion_rows rest = diffused_beside_shifting(frame) == DIFFUSION_ROWS_ALL
                              ? DIFFUSION_ROWS_NONE
                              : DIFFUSION_ROWS_AT_WALLS;
    step_fields_frozen_terms(&s->pp, &s->p, rows, frame, diffusion_of(s, &d),
                             shifts_or_corrects(s) ? rest : DIFFUSION_ROWS_ALL);
    return 0;
}

/* the force of stage 0, and room for the other stages' */
static long surface_tension(solver *s, const tank_frame *frame, const neighbour_list *rows)
{
    (void)frame;
    if (solver_reserve_surface_tension(s)) return -1;
    surface_tension_compute(&s->st, &s->pp.k, &s->p, rows, &s->bodies, solver_bodies_domain(s),
                            &s->st_work, solver_surface_tension_room(s));
    return 0;
}

/* In order. EdBC, the shifting and the correction need the step's geometry; the shifting is
 * weighed by the volumes EdBC corrects; bounce-back needs the transport velocity u + du + dv
 * whole; the frozen terms and surface tension see the bounced velocities. */
static const step_pass prepare_passes[] = {
    {"geometry", F(x) | F(u) | F(rho) | F(vol),
     F(lambda) | F(normal) | F(kernel_sum) | F(gamma) | F(grad_rho) | F(nu_t) | F(nu_delta), NULL,
     geometry},
    {"free-surface test", F(x) | F(lambda) | F(normal), F(is_free) | F(normal), NULL,
     free_surface_test},
    {"S_F", F(x) | F(is_free) | F(normal), F(surface) | F(normal), NULL, free_surface_region},
    {"eta control", F(kernel_sum) | F(surface), 0, has_eta_control, eta_control},
    {"bodies", F(x) | F(surface), 0, needs_bodies, find_bodies},
    {"EdBC (Eq. 9)", F(surface) | F(lambda), F(rho) | F(p) | F(vol), NULL, edbc},
    /* the geometric volume correction's mismatch e (volume_correction.h) */
    {"volume mismatch", F(vol) | F(kernel_sum) | F(surface), F(volume_mismatch), corrects,
     correction_mismatch},
    {"volume mismatch in S_F", F(x) | F(vol) | F(surface) | F(volume_mismatch), F(volume_mismatch),
     corrects, correction_band},
    /* Eq. (7), the correction velocity and the diffusion (Eq. 5) of every row, or in a
       rotating frame of the rows away from the walls, over one geometry of each row */
    {"shifting (Eq. 7), correction velocity, diffusion",
     F(x) | F(u) | F(rho) | F(m) | F(vol) | F(grad_rho) | F(nu_delta) | F(lambda) | F(normal) |
         F(surface) | F(volume_mismatch),
     F(shift) | F(correction) | F(diff_rho) | F(diff_m), shifts_or_corrects,
     shifting_and_correction},
    {"one normal speed per body", F(vol) | F(lambda) | F(normal) | F(correction), F(correction),
     corrects, correction_per_body},
    {"bounce-back", F(x) | F(u) | F(shift) | F(correction), F(u) | F(shift) | F(correction), NULL,
     bounce_back},
    /* the walls' images take the per-step fields of their sources (tank_mirror_step_fields) */
    {"frozen terms",
     F(x) | F(u) | F(rho) | F(m) | F(vol) | F(grad_rho) | F(nu_delta) | F(nu_t) | F(surface) |
         F(shift) | F(correction),
     F(diff_rho) | F(diff_m), NULL, frozen_terms},
    {"surface tension", F(x) | F(vol) | F(surface) | F(normal),
     F(interface) | F(curvature) | F(st_force), has_surface_tension, surface_tension},
};

/* Before a pass that reads what earlier passes wrote: an MPI run's halo first (each process
 * computes its own particles only), then the walls' images, whose sources include the halo. */
static void refresh_for(solver *s, const tank_frame *frame, uint64_t reads, uint64_t *halo_stale,
                        uint64_t *ghost_stale)
{
    if (s->domain && (*halo_stale & reads)) {
        s->domain->refresh_halo(s->domain, &s->p, *halo_stale);
        *ghost_stale |= *halo_stale & GHOST_STATE;
        *halo_stale = 0;
    }
    if (*ghost_stale & reads) {
        tank_refresh_ghosts(&s->p, frame, s->pp.rho0, s->pp.c0);
        *ghost_stale = 0;
    }
}

/* The steps whose passes the debug build checks against their write masks: every one of the
 * first 64, then one in 8 (hashing every field around every pass doubles a step's cost). */
#define WRITES_CHECK_EVERY 8

/* The debug build's check that a pass changed no field of the fluid it does not declare. */
static void check_writes(const step_pass *pass, const particles *p,
                         const uint64_t before[FIELD_BITS])
{
    uint64_t after[FIELD_BITS];
    particles_field_hashes(p, p->n_fluid, after);
    for (int f = 0; f < FIELD_BITS; f++)
        if (after[f] != before[f] && !(pass->writes & (UINT64_C(1) << f))) {
            char what[128];
            snprintf(what, sizeof what, "it changed the field %s, which it does not declare",
                     particles_field_name(f));
            invariant_broken(pass->name, what);
        }
}

int passes_prepare(solver *s, const tank_frame *frame)
{
    s->eta_switched = 0;
    /* fields changed since the halo (every field a pass wrote: the same on every process)
       and the walls' images (the state a pass changed here) were last refreshed */
    uint64_t halo_stale = 0, ghost_stale = 0;
    neighbour_list rows = solver_prepared_rows(s); /* no pass moves a particle */
    /* the debug build's write masks: the first steps, then every WRITES_CHECK_EVERY-th */
    bool check = INVARIANTS_ON && (s->step < WRITES_CHECK_EVERY * WRITES_CHECK_EVERY ||
                                   s->step % WRITES_CHECK_EVERY == 0);
    for (size_t k = 0; k < sizeof prepare_passes / sizeof prepare_passes[0]; k++) {
        const step_pass *pass = &prepare_passes[k];
        if (pass->active && !pass->active(s)) continue;
        refresh_for(s, frame, pass->reads, &halo_stale, &ghost_stale);
        uint64_t before[FIELD_BITS];
        if (check) particles_field_hashes(&s->p, s->p.n_fluid, before);
        long changed = pass->run(s, frame, &rows);
        if (check) check_writes(pass, &s->p, before);
        if (changed < 0) return -1;
        halo_stale |= pass->writes;
        if (changed > 0) ghost_stale |= pass->writes & GHOST_STATE;
    }
    /* the RK stages read every field at the neighbours */
    refresh_for(s, frame, ~UINT64_C(0), &halo_stale, &ghost_stale);
    return 0;
}

uint64_t passes_prepare_writes(void)
{
    uint64_t writes = 0;
    for (size_t k = 0; k < sizeof prepare_passes / sizeof prepare_passes[0]; k++)
        writes |= prepare_passes[k].writes;
    return writes;
}
