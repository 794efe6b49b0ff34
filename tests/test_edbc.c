/* EdBC, Eq. (9) (src/scheme/edbc.c): on a tank's lattice with three particles set by hand,
 * a particle of S_F with lambda < 0.1 (a drop or a thin jet) gets p = 0 and rho = rho0, its
 * volume m / rho0, exactly; a particle of S_F at lambda = 0.1 and an interior particle at a
 * small lambda keep their values. model.edbc = true acts always, false never, with-eta0 only in
 * the eta control's eta = 0 regime; n_edbc counts the particles it reset. Through a step's
 * preparation (solver_prepare's passes), a drop beside a wall is reset and the wall's image of
 * it carries the reset state: the pass driver refreshes the images after the passes that change
 * their sources. */
#include "diag/freesurface.h"
#include "scheme/edbc.h"
#include "boundary/tank.h"
#include "scheme/solver.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <cmocka.h>

#include "check.h"

static const char tank_case[] = "[case]\nname = edbc\nt_end = 1\n"
                                "[tank]\nlength = 0.4\nheight = 0.3\nwidth = 0.1\n"
                                "[liquid]\nheight = 0.1\n"
                                "[model]\nscheme = delta-plus-ale\n"
                                "[numerics]\nresolution = 8\n";

/* The state of particle i that EdBC may change. */
typedef struct {
    double rho, p, vol;
} state_of;

static state_of read_state(const particles *p, size_t i)
{
    return (state_of){p->rho[i], p->p[i], p->vol[i]};
}

/* Particle i set off rho0 (2 % compressed, its pressure and volume to match) in S_F or the
 * interior, at lambda. */
static void set_particle(particles *p, size_t i, uint8_t surface, double lambda, double rho0)
{
    p->surface[i] = surface;
    p->lambda[i] = lambda;
    p->rho[i] = 1.02 * rho0;
    p->p[i] = 1234.5;
    p->vol[i] = p->m[i] / p->rho[i];
}

/* The tank of tank_case in this build's DIM, with EdBC in mode `edbc`. */
static void start_tank(config *cfg, solver *s, edbc_mode edbc)
{
    char err[1024], dim[32];
    snprintf(dim, sizeof dim, "case.dim=%d", DIM);
    const char *overrides[] = {dim};
    if (config_load_string(cfg, tank_case, "test", overrides, 1, err, sizeof err))
        fail_msg("%s", err);
    cfg->edbc = edbc;
    if (solver_init(s, cfg, err, sizeof err)) fail_msg("%s", err);
}

/* EdBC in mode `edbc` (the eta = 0 regime or not) on the three particles: how many it reset,
 * asserting that exactly the drop's particle was reset when it acts and none otherwise. */
static long edbc_on_three(edbc_mode edbc, bool eta0_regime)
{
    config cfg;
    solver s;
    start_tank(&cfg, &s, edbc);
    s.eta_control.eta0_regime = eta0_regime;
    particles *p = &s.p;
    double rho0 = s.pp.rho0;
    for (size_t i = 0; i < p->n_fluid; i++) { /* nothing else qualifies */
        p->surface[i] = SURFACE_INTERIOR;
        p->lambda[i] = 1.0;
    }
    set_particle(p, 0, SURFACE_FREE, 0.05, rho0);          /* a drop's particle */
    set_particle(p, 1, SURFACE_REGION, EDBC_LAMBDA, rho0); /* at the threshold: kept */
    set_particle(p, 2, SURFACE_INTERIOR, 0.05, rho0);      /* interior: kept */
    state_of before[3];
    for (size_t i = 0; i < 3; i++) before[i] = read_state(p, i);
    edbc_correct(&s);
    bool acts = edbc_acts(&s);
    state_of drop = read_state(p, 0);
    if (acts) {
        assert_true(drop.rho == rho0);
        assert_true(drop.p == 0.0);
        assert_true(drop.vol == p->m[0] / rho0);
    } else {
        assert_memory_equal(&drop, &before[0], sizeof drop);
    }
    for (size_t i = 1; i < 3; i++) {
        state_of now = read_state(p, i);
        assert_memory_equal(&now, &before[i], sizeof now);
    }
    long n = s.n_edbc;
    assert_int_equal(n, acts ? 1 : 0);
    solver_free(&s);
    return n;
}

static void test_edbc_modes(void **state)
{
    (void)state;
    assert_int_equal(edbc_on_three(EDBC_ON, false), 1);
    assert_int_equal(edbc_on_three(EDBC_ON, true), 1);
    assert_int_equal(edbc_on_three(EDBC_OFF, true), 0);
    assert_int_equal(edbc_on_three(EDBC_WITH_ETA0, true), 1);
    assert_int_equal(edbc_on_three(EDBC_WITH_ETA0, false), 0);
}

/* One particle of the lattice moved up beside the left wall, far from the liquid (a drop), 2 %
 * compressed: solver_prepare's passes reset it (p = 0, rho = rho0) and its wall images hold its
 * state as tank_refresh_ghosts makes it, bit for bit. */
static void test_edbc_reaches_the_wall_images(void **state)
{
    (void)state;
    config cfg;
    solver s;
    start_tank(&cfg, &s, EDBC_ON);
    particles *p = &s.p;
    double rho0 = s.pp.rho0, dr = s.dv.dr;
    p->x[0][0] = 0.4 * dr; /* its image across x = 0 is 0.8 dr away */
    p->x[1][0] = 0.2;      /* 0.1 m above the liquid: no neighbour within 2h = 0.025 m */
    p->rho[0] = 1.02 * rho0;
    assert_int_equal(solver_prepare(&s, cfg.t_end), 0);
    assert_int_equal(s.n_edbc, 1);
    size_t drop = p->n_fluid;
    for (size_t i = 0; i < p->n_fluid; i++)
        if (p->x[1][i] > 0.15) drop = i;
    assert_true(drop < p->n_fluid);
    assert_true(p->rho[drop] == rho0 && p->p[drop] == 0.0);
    enum { MAX_IMAGES = 64 };
    size_t images[MAX_IMAGES], n_images = 0;
    state_of held[MAX_IMAGES];
    for (size_t g = particles_images_begin(p); g < p->n_total && n_images < MAX_IMAGES; g++)
        if (particle_source_of(p, g) == drop) {
            held[n_images] = read_state(p, g);
            images[n_images++] = g;
        }
    assert_true(n_images >= 1);
    tank_frame frame = solver_frame(&s, s.t);
    tank_refresh_ghosts(p, &frame, rho0, s.pp.c0);
    for (size_t k = 0; k < n_images; k++) {
        state_of refreshed = read_state(p, images[k]);
        assert_memory_equal(&refreshed, &held[k], sizeof refreshed);
    }
    assert_true(p->p[images[0]] == 0.0); /* beside a vertical wall: no hydrostatic step */
    solver_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_edbc_modes),
                                       cmocka_unit_test(test_edbc_reaches_the_wall_images)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
