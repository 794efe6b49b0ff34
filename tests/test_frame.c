/* The body force of the tank frame (boundary/frame.h, theory §6): for a translating tank it is
 * g - a0 at every position and velocity, the g_eff of the translating motions; for a rotating
 * one each of the Euler, centrifugal and Coriolis terms against its closed form about z, for
 * Omega = (0, 0, W):
 *   -dOmega/dt x r = dW (y, -x),
 *   -Omega x (Omega x r) = W^2 (x, y),
 *   -2 Omega x u = 2 W (u_y, -u_x).
 * The motions of today feed the translating case through motion_frame. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "boundary/frame.h"
#include "boundary/motion.h"
#include "check.h"

static vec vec_of(double x, double y, double z)
{
    vec v;
    double c[3] = {x, y, z};
    for (int d = 0; d < DIM; d++) v.c[d] = c[d];
    return v;
}

static void test_translation_is_uniform(void **state)
{
    (void)state;
    tank_frame f = {.gravity = {0.0, -9.81, 0.0}, .origin_acc = {1.5, -2.0, 0.25}};
    vec at_rest = frame_body_force(&f, vec_zero(), vec_zero());
    vec moving = frame_body_force(&f, vec_of(0.3, 0.7, 0.2), vec_of(-4.0, 2.0, 1.0));
    for (int d = 0; d < DIM; d++) {
        double expected = f.gravity[d] - f.origin_acc[d];
        assert_true(at_rest.c[d] == expected && moving.c[d] == expected);
    }
}

static void test_rotation_terms(void **state)
{
    (void)state;
    const double w = 0.8, w_dot = -0.3, x = 0.4, y = -0.25, ux = 1.1, uy = 0.6;
    tank_frame spin = {.omega = {0.0, 0.0, w}, .rotating = true};
    tank_frame accel = {.omega_dot = {0.0, 0.0, w_dot}, .rotating = true};
    vec r = vec_of(x, y, 0.0), still = vec_zero(), u = vec_of(ux, uy, 0.0);
    /* Euler alone */
    vec f = frame_body_force(&accel, r, u);
    assert_close(f.c[0], w_dot * y, 1e-15);
    assert_close(f.c[1], -w_dot * x, 1e-15);
    /* centrifugal alone (at rest in the frame) */
    f = frame_body_force(&spin, r, still);
    assert_close(f.c[0], w * w * x, 1e-15);
    assert_close(f.c[1], w * w * y, 1e-15);
    /* centrifugal and Coriolis */
    f = frame_body_force(&spin, r, u);
    assert_close(f.c[0], w * w * x + 2.0 * w * uy, 1e-15);
    assert_close(f.c[1], w * w * y - 2.0 * w * ux, 1e-15);
    if (DIM == 3) assert_close(f.c[DIM - 1], 0.0, 0.0);
}

/* Sway: the frame of motion_frame does not rotate and its force is g - a_tank. */
static void test_motion_frame_of_sway(void **state)
{
    (void)state;
    config cfg = {.motion = MOTION_SWAY, .amplitude = 0.1, .period = 1.0, .gravity = 9.81};
    motion mo;
    char err[256];
    assert_int_equal(motion_init(&mo, &cfg, err, sizeof err), 0);
    double t = 0.3, a[3];
    motion_acceleration(&mo, t, a);
    tank_frame f = motion_frame(&mo, cfg.gravity, t);
    assert_false(f.rotating);
    vec force = frame_body_force(&f, vec_of(0.5, 0.1, 0.0), vec_of(1.0, 1.0, 1.0));
    assert_true(force.c[0] == -a[0]);
    assert_true(force.c[1] == -a[1] - 9.81);
    motion_free(&mo);
}

/* motion.settling: no damping while the tank moves; after motion.duration the force on a
 * particle moving at u gains exactly -settling u (and the tank's acceleration is 0 then). */
static void test_settling_after_the_motion(void **state)
{
    (void)state;
    config cfg = {.motion = MOTION_SWAY,
                  .amplitude = 0.1,
                  .period = 1.0,
                  .duration = 2.0,
                  .settling = 1.5,
                  .gravity = 9.81};
    motion mo;
    char err[256];
    assert_int_equal(motion_init(&mo, &cfg, err, sizeof err), 0);
    vec r = vec_of(0.5, 0.1, 0.0), u = vec_of(0.4, -0.2, 0.1);
    tank_frame during = motion_frame(&mo, cfg.gravity, 1.9), after = motion_frame(&mo, 9.81, 2.1);
    assert_true(during.damping == 0.0 && after.damping == 1.5);
    vec force = frame_body_force(&after, r, u);
    for (int d = 0; d < DIM; d++)
        assert_close(force.c[d], (d == 1 ? -9.81 : 0.0) - 1.5 * u.c[d], 1e-15);
    motion_free(&mo);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_translation_is_uniform),
        cmocka_unit_test(test_rotation_terms),
        cmocka_unit_test(test_motion_frame_of_sway),
        cmocka_unit_test(test_settling_after_the_motion),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
