/* Ghost particles of the tank walls (theory §5): how many near each wall, edge and corner,
 * and their mirrored state. */
#include "boundary/tank.h"
#include "physics/eos.h"

#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "check.h"

static const double rho0 = 1000.0, c0 = 20.0, reach = 0.1;

static tank make_tank(void)
{
    double size[3] = {1.0, 0.8, 0.6};
    return tank_box(size, WALL_NO_SLIP);
}

static void add(particles *p, const double x[3])
{
    size_t i = p->n_fluid++;
    for (int d = 0; d < DIM; d++) {
        p->x[d][i] = x[d];
        p->u[d][i] = 1.0 + d;
    }
    p->rho[i] = 1002.0 + (double)i;
    p->p[i] = eos_pressure(p->rho[i], rho0, c0);
    p->m[i] = 0.5 + (double)i;
    p->id[i] = 100 + (int64_t)i;
    p->n_total = p->n_fluid;
}

static size_t ghosts_of(const particles *p, size_t i)
{
    size_t k = 0;
    for (size_t g = p->n_fluid; g < p->n_total; g++)
        k += (size_t)p->ghost_source[g - p->n_fluid] == i;
    return k;
}

static void test_counts(void **state)
{
    (void)state;
    particles p;
    particles_init(&p, 8);
    tank t = make_tank();
    add(&p, (double[3]){0.5, 0.4, 0.3});    /* interior */
    add(&p, (double[3]){0.05, 0.4, 0.3});   /* near the wall x = 0 */
    add(&p, (double[3]){0.96, 0.75, 0.3});  /* 2D: corner x = L, y = D; 3D: that edge */
    add(&p, (double[3]){0.05, 0.03, 0.58}); /* 2D: corner; 3D: corner of three walls */
    assert_int_equal(tank_make_ghosts(&t, &p, reach), 0);
    assert_int_equal(ghosts_of(&p, 0), 0);
    assert_int_equal(ghosts_of(&p, 1), 1);
    assert_int_equal(ghosts_of(&p, 2), 3);
    assert_int_equal(ghosts_of(&p, 3), DIM == 2 ? 3 : 7);
    assert_int_equal(p.n_total - p.n_fluid, DIM == 2 ? 7 : 11);
    particles_free(&p);
}

/* Every ghost's state is the mirror of its source's (theory §5). */
static void test_mirrored_state(void **state)
{
    (void)state;
    particles p;
    particles_init(&p, 8);
    tank t = make_tank();
    add(&p, (double[3]){0.05, 0.03, 0.58});
    add(&p, (double[3]){0.96, 0.75, 0.02});
    assert_int_equal(tank_make_ghosts(&t, &p, reach), 0);
    /* a tank accelerating at -0.5 m/s^2 along x: the body force g - a0 = (0.5, -9.81) */
    tank_frame frame = {.gravity = {0.0, -9.81, 0.0}, .origin_acc = {-0.5, 0.0, 0.0}};
    vec g_eff = frame_body_force(&frame, vec_zero(), vec_zero());
    assert_true(g_eff.c[0] == 0.5 && g_eff.c[1] == -9.81);
    tank_refresh_ghosts(&p, &frame, rho0, c0);
    for (size_t i = 0; i < p.n_fluid; i++) {
        vec grad = vec_zero();
        grad.c[1] = 3.0 + (double)i;
        vec_store(p.grad_rho, i, grad);
        p.nu_t[i] = 1e-5 * (double)(i + 1);
        p.nu_delta[i] = 2e-5 * (double)(i + 1);
        for (int d = 0; d < DIM; d++) p.shift[d][i] = 0.01 * (double)(d + 1) - 0.003 * (double)i;
    }
    tank_mirror_step_fields(&p, &frame, c0);
    for (size_t g = p.n_fluid; g < p.n_total; g++) {
        size_t i = (size_t)p.ghost_source[g - p.n_fluid];
        /* the box's map table is indexed by the walls: bit 2d the low wall of axis d, 2d + 1
           the high one; the mirror formulas below check its reflections */
        unsigned walls = p.ghost_map[g - p.n_fluid];
        for (int d = 0; d < DIM; d++) {
            int low = (walls >> (2 * d)) & 1, high = (walls >> (2 * d + 1)) & 1;
            double x = p.x[d][i];
            double expected_x = low ? -x : (high ? 2.0 * t.size[d] - x : x);
            assert_close(p.x[d][g], expected_x, 1e-15);
            /* free slip: normal component reversed, tangential kept; no slip: all reversed */
            assert_true(p.u[d][g] == ((low || high) ? -p.u[d][i] : p.u[d][i]));
            assert_true(particle_viscous_velocity(&p, g).c[d] == -p.u[d][i]);
            /* ghost lies across the wall: its distance to the wall equals the source's */
            if (low) assert_true(p.x[d][g] < 0.0);
            if (high) assert_true(p.x[d][g] > t.size[d]);
        }
        double dp = p.rho[i] * vec_dot(g_eff, vec_sub(vec_load(p.x, g), vec_load(p.x, i)));
        assert_close(p.p[g], p.p[i] + dp, 1e-9);
        assert_close(p.rho[g], eos_density(p.p[g], rho0, c0), 1e-12);
        /* an image holds no mass or id of its own (FIELD_SOURCES_ONLY): its volume is its
           source's mass over its own density */
        assert_close(p.vol[g], p.m[i] / p.rho[g], 1e-18);
        assert_true(p.nu_t[g] == p.nu_t[i] && p.nu_delta[g] == p.nu_delta[i]);
        /* a field the images do not hold, read through one (particle_source_scalar and
           _vector), is to the bit its source's entry, or what a mirror into the image holds
           (the velocity, which the images hold mirrored) */
        assert_true(particle_source_scalar(&p, p.kernel_sum, g) == p.kernel_sum[i]);
        vec read = particle_source_vector(&p, p.u, g);
        for (int d = 0; d < DIM; d++) assert_true(read.c[d] == p.u[d][g]);
        /* the hydrostatic part of the density gradient is continued, the rest mirrored */
        vec hydro = vec_scale(g_eff, p.rho[i] / (c0 * c0));
        for (int d = 0; d < DIM; d++) {
            int mirrored = (walls >> (2 * d)) & 3;
            double dyn = p.grad_rho[d][i] - hydro.c[d], want = (mirrored ? -dyn : dyn) + hydro.c[d];
            /* held in single precision (frozen_real): rounded once, by half an ulp at most */
            assert_close(p.grad_rho[d][g], want, 1e-12 + 0.5 * FLT_EPSILON * fabs(want));
        }
    }
    particles_free(&p);
}

/* Bounce-back reverses only the normal velocity of particles within dr/4 of a wall moving
 * towards it (sec. 2.5), the distance taken one step ahead at the transport velocity u + du. */
static void test_bounce_back(void **state)
{
    (void)state;
    particles p;
    particles_init(&p, 8);
    tank t = make_tank();
    double dr = 0.04;
    add(&p, (double[3]){0.005, 0.4, 0.3}); /* within dr/4 of x = 0 */
    add(&p, (double[3]){0.02, 0.4, 0.3});  /* beyond dr/4 */
    p.u[0][0] = -1.0;
    p.u[0][1] = -1.0;
    assert_int_equal(tank_bounce_back(&t, &p, dr, 0.0), 1);
    assert_true(p.u[0][0] == 1.0);
    assert_true(p.u[1][0] == 2.0);
    assert_true(p.u[0][1] == -1.0);
    assert_int_equal(tank_bounce_back(&t, &p, dr, 0.0), 0); /* moving away now: unchanged */
    assert_true(p.u[0][0] == 1.0);
    /* 0.02 from the wall at 1 m/s: within dr/4 = 0.01 after a step of 0.015 s, not of 0.005 s */
    tank_bounce_back(&t, &p, dr, 0.005);
    assert_true(p.u[0][1] == -1.0);
    tank_bounce_back(&t, &p, dr, 0.015);
    assert_true(p.u[0][1] == 1.0);
    particles_free(&p);
}

/* With ALE the particle moves with u + du: a shifting velocity that carries it into the wall
 * is reversed even when u takes it away, and u, already pointing away, is kept. */
static void test_bounce_back_shifting(void **state)
{
    (void)state;
    particles p;
    particles_init(&p, 8);
    tank t = make_tank();
    double dr = 0.04;
    add(&p, (double[3]){0.3, 0.795, 0.3}); /* within dr/4 of the roof y = 0.8 */
    p.u[1][0] = -0.1;
    p.shift[1][0] = 0.3;
    p.shift[0][0] = 0.2;
    assert_int_equal(tank_bounce_back(&t, &p, dr, 0.0), 1);
    assert_true(p.u[1][0] == -0.1);
    assert_true(p.shift[1][0] == -(frozen_real)0.3); /* the stored value's sign reversed */
    assert_true(p.shift[0][0] == (frozen_real)0.2);  /* tangential: kept */
    assert_int_equal(tank_bounce_back(&t, &p, dr, 0.0), 0);
    particles_free(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_counts),
        cmocka_unit_test(test_mirrored_state),
        cmocka_unit_test(test_bounce_back),
        cmocka_unit_test(test_bounce_back_shifting),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
