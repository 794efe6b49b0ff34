/* Tests of the prescribed tank motion (theory §6): the acceleration is the second derivative of
 * the displacement (sway and heave, with decay and phase), the signs of theory §6, `duration`,
 * a tabulated motion read through its cubic spline, and the g_max of the sound-speed rule. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "boundary/motion.h"
#include "core/config.h"

#include "check.h"

#define PI 3.14159265358979323846
#define G  9.81

/* A valid case; the motion section is appended. */
#define CASE_HEAD                                                                                  \
    "[case]\nt_end = 10.0\n[tank]\nlength = 1.0\nheight = 0.5\n[liquid]\nheight = 0.2\n"           \
    "[numerics]\nresolution = 20\n"

/* Loads CASE_HEAD + `motion_section` and initialises the motion from it. */
static void motion_from(motion *mo, const char *motion_section)
{
    char text[2048], err[1024];
    snprintf(text, sizeof text, "%s%s", CASE_HEAD, motion_section);
    config cfg;
    int rc = config_load_string(&cfg, text, "motion-test", NULL, 0, err, sizeof err);
    if (rc) fail_msg("config: %s", err);
    rc = motion_init(mo, &cfg, err, sizeof err);
    if (rc) fail_msg("motion_init: %s", err);
}

static double axis_position(const motion *mo, double t, int axis)
{
    double x[3];
    motion_position(mo, t, x);
    return x[axis];
}

static double axis_acceleration(const motion *mo, double t, int axis)
{
    double a[3];
    motion_acceleration(mo, t, a);
    return a[axis];
}

/* ---- acceleration = second derivative of the position ------------------------------------- */

/* Central second difference D(t) = (x(t+d) - 2 x(t) + x(t-d)) / d^2 = x''(t) + d^2/12 x''''(s)
 * for some s in [t-d, t+d] (Taylor with the mean-value remainder). For x = A e^{-lt} f(wt + p),
 * f = sin or -cos, x'''' = A e^{-lt} Re/Im[(-l + iw)^4 ...], so |x''''| <= A (l^2 + w^2)^2
 * e^{-l(t-d)}. Rounding: each x is within about (8 + |wt + p|) eps A (exp, sin/cos, products,
 * and the rounding of the argument wt + p, amplified by |x'| ~ A); the difference adds four
 * of them and divides by d^2. Tolerance = truncation bound + rounding bound. */
static void check_second_derivative(const char *motion_section, int axis, double A, double T,
                                    double decay, double phase)
{
    motion mo;
    motion_from(&mo, motion_section);
    const double w = 2.0 * PI / T, d = 1e-3;
    const double x4 = A * pow(decay * decay + w * w, 2);
    for (int k = 0; k <= 400; k++) {
        double t = d + 3.0 * T * k / 400.0;
        double fd = (axis_position(&mo, t + d, axis) - 2.0 * axis_position(&mo, t, axis) +
                     axis_position(&mo, t - d, axis)) /
                    (d * d);
        double a = axis_acceleration(&mo, t, axis);
        double theta = fabs(w * (t + d) + phase);
        double tol = d * d / 12.0 * x4 * exp(-decay * (t - d)) +
                     4.0 * (8.0 + theta) * DBL_EPSILON * A / (d * d);
        assert_close(a, fd, tol);
        /* the other axes do not move */
        for (int other = 0; other < 3; other++)
            if (other != axis) assert_true(axis_acceleration(&mo, t, other) == 0.0);
    }
    /* Guards of the test's own constants, so that the comparison has teeth: the truncation
     * bound is below 1e-3 of A w^2, and far below the 2 l w A term of the product rule (the
     * l^2 A term is larger still), so an acceleration missing either would fail above. */
    assert_true(x4 * d * d / 12.0 < 1e-3 * A * w * w);
    assert_true(2.0 * decay * w * A > 100.0 * (x4 * d * d / 12.0));
    motion_free(&mo);
}

static void test_sway_second_derivative(void **state)
{
    (void)state;
    check_second_derivative("[motion]\ntype = sway\namplitude = 0.02\nperiod = 1.1\n"
                            "decay = 0.4\nphase = 0.7\n",
                            0, 0.02, 1.1, 0.4, 0.7);
}

static void test_heave_second_derivative(void **state)
{
    (void)state;
    check_second_derivative("[motion]\ntype = heave\namplitude = 0.015\nperiod = 0.9\n"
                            "decay = 0.3\nphase = -1.2\n",
                            1, 0.015, 0.9, 0.3, -1.2);
}

/* ---- the formulas and signs of theory §6 --------------------------------------------------- */

/* Positions against theory §6 written out here: sway x = A e^{-lt} sin(wt + p), heave
 * y = -A e^{-lt} cos(wt + p). Tolerance: a few roundings of values of size A, plus the
 * rounding of the argument (|wt + p| eps, times |x'|/w ~ A). */
static void test_positions_follow_theory(void **state)
{
    (void)state;
    const double A = 0.02, T = 1.1, l = 0.4, p = 0.7, w = 2.0 * PI / T;
    motion sway, heave;
    motion_from(&sway, "[motion]\ntype = sway\namplitude = 0.02\nperiod = 1.1\ndecay = 0.4\n"
                       "phase = 0.7\n");
    motion_from(&heave, "[motion]\ntype = heave\namplitude = 0.02\nperiod = 1.1\ndecay = 0.4\n"
                        "phase = 0.7\n");
    for (int k = 0; k <= 50; k++) {
        double t = 0.1 * k;
        double tol = (8.0 + fabs(w * t + p)) * DBL_EPSILON * A;
        assert_close(axis_position(&sway, t, 0), A * exp(-l * t) * sin(w * t + p), tol);
        assert_close(axis_position(&heave, t, 1), -A * exp(-l * t) * cos(w * t + p), tol);
        assert_true(axis_position(&sway, t, 1) == 0.0 && axis_position(&heave, t, 0) == 0.0);
    }
    motion_free(&sway);
    motion_free(&heave);
}

/* Theory §6 with phase 0 and no decay: sway x = A sin wt peaks at T/4, where
 * a_x = -A w^2 (the tank is pulled back); heave y = -A cos wt is lowest at t = 0, where
 * a_y = +A w^2 (pushed up). Tolerance: rounding only, a few eps of A w^2. */
static void test_signs_of_theory(void **state)
{
    (void)state;
    const double A = 0.05, T = 1.6, w = 2.0 * PI / T, aw2 = A * w * w;
    const double tol = 16.0 * DBL_EPSILON * aw2;
    motion sway, heave;
    motion_from(&sway, "[motion]\ntype = sway\namplitude = 0.05\nperiod = 1.6\n");
    motion_from(&heave, "[motion]\ntype = heave\namplitude = 0.05\nperiod = 1.6\n");
    assert_close(axis_position(&sway, T / 4.0, 0), A, 16.0 * DBL_EPSILON * A);
    assert_close(axis_acceleration(&sway, T / 4.0, 0), -aw2, tol);
    assert_close(axis_acceleration(&sway, 3.0 * T / 4.0, 0), aw2, tol);
    assert_close(axis_acceleration(&sway, 0.0, 0), 0.0, tol);
    assert_close(axis_position(&heave, 0.0, 1), -A, 16.0 * DBL_EPSILON * A);
    assert_close(axis_acceleration(&heave, 0.0, 1), aw2, tol);
    assert_close(axis_acceleration(&heave, T / 2.0, 1), -aw2, tol);
    assert_close(axis_acceleration(&heave, T / 4.0, 1), 0.0, tol);
    motion_free(&sway);
    motion_free(&heave);
}

/* ---- duration ------------------------------------------------------------------------------- */

/* docs/case-file.md: after `duration` the tank acceleration is zero (exactly: no force at all), and
 * before it the motion is the periodic one (rounding tolerance as above). */
static void test_duration_stops_acceleration(void **state)
{
    (void)state;
    const double A = 0.02, T = 1.0, w = 2.0 * PI / T, D = 1.7, aw2 = A * w * w;
    motion sway, heave;
    motion_from(&sway, "[motion]\ntype = sway\namplitude = 0.02\nperiod = 1.0\nduration = 1.7\n");
    motion_from(&heave, "[motion]\ntype = heave\namplitude = 0.02\nperiod = 1.0\n"
                        "duration = 1.0\n");
    for (int k = 0; k < 100; k++) {
        double before = D * k / 100.0, after = D + 1e-9 + 0.05 * k;
        double tol = (16.0 + w * before) * DBL_EPSILON * aw2;
        assert_close(axis_acceleration(&sway, before, 0), -aw2 * sin(w * before), tol);
        double a[3];
        motion_acceleration(&sway, after, a);
        assert_true(a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0);
        motion_acceleration(&heave, 1.0 + 1e-9 + 0.05 * k, a);
        assert_true(a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0);
    }
    /* just before the end, still moving: |a| = A w^2 |sin(w 1.7)| = 0.95 A w^2 */
    assert_true(fabs(axis_acceleration(&sway, D - 1e-6, 0)) > 0.9 * aw2);
    /* Heave stopped at t = T, where its velocity A w sin(wT) is zero: the tank rests at
     * y(T) = -A from then on (a position consistent with zero acceleration). */
    for (int k = 1; k < 20; k++)
        assert_close(axis_position(&heave, 1.0 + 0.1 * k, 1), -A, 16.0 * DBL_EPSILON * A);
    motion_free(&sway);
    motion_free(&heave);
}

/* ---- tabulated motion ----------------------------------------------------------------------- */

/* The table: x = A sin(wt), y = -B cos(wt) at K knots per period over P periods. */
enum { KNOTS_PER_PERIOD = 200, PERIODS = 3, MARGIN = 20 };

/* The table's folder, made and removed around the test (removed even when it fails). */
static char table_dir[] = "/tmp/vcsph-motion-XXXXXX";
static char table_path[sizeof table_dir + 16];

static int table_setup(void **state)
{
    (void)state;
    memcpy(table_dir + sizeof table_dir - 7, "XXXXXX", 6); /* a fresh name for each test */
    if (!mkdtemp(table_dir)) return -1;
    snprintf(table_path, sizeof table_path, "%s/table.csv", table_dir);
    return 0;
}

static int table_teardown(void **state)
{
    (void)state;
    remove(table_path);
    return rmdir(table_dir);
}

static void test_table_reproduces_acceleration(void **state)
{
    (void)state;
    const double A = 0.03, B = 0.01, T = 1.2, w = 2.0 * PI / T;
    const double hk = T / KNOTS_PER_PERIOD, theta = w * hk;
    const char *path = table_path;
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("t,x,y\n", f);
    const int n = KNOTS_PER_PERIOD * PERIODS;
    for (int k = 0; k <= n; k++) {
        double t = hk * k;
        fprintf(f, "%.17g,%.17g,%.17g\n", t, A * sin(w * t), -B * cos(w * t));
    }
    assert_int_equal(fclose(f), 0);
    char section[512];
    snprintf(section, sizeof section, "[motion]\ntype = table\nfile = %s\n", path);
    motion mo;
    motion_from(&mo, section);
    assert_int_equal(mo.n_knots, n + 1);

    /* Spline error for f = sin(wt) on knots hk apart (theta = w hk): the spline's knot values
     * M_k of f'' solve (M_{k-1} + 4 M_k + M_{k+1})/6 = (f_{k+1} - 2 f_k + f_{k-1})/hk^2, which
     * for a sinusoid gives M_k = f''_k (1 + theta^2/12 + O(theta^4)); between knots M is
     * linear, off by at most |f''''| hk^2/8 = w^4 A hk^2/8, of the opposite sign at the peaks.
     * So |S'' - f''| <= (theta^2/12) A w^2 to leading order; 10% for the O(theta^4) terms.
     * The natural end conditions (S'' = 0 at the ends; wrong for -cos, whose y'' is B w^2
     * there) cause an error that decays by 2 - sqrt(3) = 0.27 per knot: after MARGIN = 20
     * knots it is 0.27^20 = 4e-12 of B w^2, far below. Positions: the spline's error is
     * O(hk^4): (5/384) hk^4 |f''''| = (5/384) theta^4 A. */
    const double tol_ax = 1.1 * theta * theta / 12.0 * A * w * w;
    const double tol_ay = 1.1 * theta * theta / 12.0 * B * w * w;
    const double tol_x = 5.0 / 384.0 * pow(theta, 4) * A + 1e-15;
    const double tol_y = 5.0 / 384.0 * pow(theta, 4) * B + 1e-15;
    double worst = 0.0;
    for (int k = MARGIN * 4; k <= (n - MARGIN) * 4; k++) {
        double t = hk * k / 4.0; /* at knots and at quarters between them */
        double a[3], x[3];
        motion_acceleration(&mo, t, a);
        motion_position(&mo, t, x);
        assert_close(a[0], -A * w * w * sin(w * t), tol_ax);
        assert_close(a[1], B * w * w * cos(w * t), tol_ay);
        assert_true(a[2] == 0.0);
        assert_close(x[0], A * sin(w * t), tol_x);
        assert_close(x[1], -B * cos(w * t), tol_y);
        double e = fabs(a[0] + A * w * w * sin(w * t)) / (A * w * w);
        if (e > worst) worst = e;
    }
    /* The estimate is sharp: the error reaches most of theta^2/12 (a spline of lower order,
     * or a first-order difference, would be far off; a tighter bound would be wrong). */
    assert_true(worst > 0.8 * theta * theta / 12.0);
    /* Outside the table the tank does not accelerate */
    double a[3];
    motion_acceleration(&mo, hk * n + 0.01, a);
    assert_true(a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0);
    motion_free(&mo);
}

/* ---- rotation (docs/case-file.md [motion]) ------------------------------------------------- */

/* Writes `text` as the table file of this test and loads a motion with it (dim 2 or 3). */
static int motion_from_table(motion *mo, const char *text, int dim, char *err, size_t err_len)
{
    FILE *f = fopen(table_path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
    char case_text[2048];
    snprintf(case_text, sizeof case_text,
             "%s[case]\ndim = %d\n[tank]\nwidth = 0.3\n[motion]\ntype = table\nfile = %s\n",
             CASE_HEAD, dim, table_path);
    config cfg;
    if (config_load_string(&cfg, case_text, "motion-test", NULL, 0, err, err_len)) return 2;
    return motion_init(mo, &cfg, err, err_len);
}

/* A harmonic roll: Theta sin(wt + phi) about z through the bottom centre (0.5, 0): the frame's
 * Omega = (0, 0, theta'), dOmega/dt = (0, 0, theta''), gravity R_z(theta)^T (0, -g) =
 * (-g sin theta, -g cos theta): a positive roll turns the tank counter-clockwise, so the
 * gravity of the tank frame points to its left wall (x < 0). No translation. The formulas are
 * those of the sway with Theta for A; rounding only (a few eps of each term). */
static void test_roll_frame(void **state)
{
    (void)state;
    const double th = 0.1, T = 0.9, w = 2.0 * PI / T, l = 0.2, phi = 0.3, dphi = 0.4;
    motion mo;
    motion_from(&mo, "[motion]\ntype = roll\nangle = 0.1\nperiod = 0.9\ndecay = 0.2\n"
                     "phase = 0.3\nangle_phase = 0.4\n");
    assert_true(mo.rotates && mo.center[0] == 0.5 && mo.center[1] == 0.0);
    for (int k = 0; k <= 100; k++) {
        double t = 0.031 * k, e = th * exp(-l * t), a = w * t + phi + dphi;
        double q = e * sin(a), q1 = e * (w * cos(a) - l * sin(a));
        double q2 = e * ((l * l - w * w) * sin(a) - 2.0 * l * w * cos(a));
        tank_frame f = motion_frame(&mo, G, t);
        double tol = 64.0 * DBL_EPSILON * (1.0 + fabs(a));
        assert_close(f.omega[2], q1, tol * th * (w + l));
        assert_close(f.omega_dot[2], q2, tol * th * (w + l) * (w + l));
        assert_true(f.omega[0] == 0.0 && f.omega[1] == 0.0);
        assert_close(f.gravity[0], -G * sin(q), tol * G);
        assert_close(f.gravity[1], -G * cos(q), tol * G);
        assert_true(f.origin_acc[0] == 0.0 && f.origin_acc[1] == 0.0);
        assert_true(f.rotating);
    }
    motion_free(&mo);
}

/* sway+roll: the sway moves the centre along the inertial x, so the frame sees its
 * acceleration turned into the tank's axes, R^T (a, 0) = (a cos q, -a sin q). */
static void test_sway_roll_frame(void **state)
{
    (void)state;
    motion both, sway;
    motion_from(&both, "[motion]\ntype = sway+roll\namplitude = 0.05\nangle = 0.2\nperiod = 1.1\n"
                       "center = 0.2 0.3\n");
    motion_from(&sway, "[motion]\ntype = sway\namplitude = 0.05\nperiod = 1.1\n");
    assert_true(both.center[0] == 0.2 && both.center[1] == 0.3);
    for (int k = 0; k <= 50; k++) {
        double t = 0.047 * k, a[3], q[3], q1[3], q2[3];
        motion_acceleration(&sway, t, a);
        motion_angles(&both, t, q, q1, q2);
        tank_frame f = motion_frame(&both, G, t);
        assert_close(f.origin_acc[0], a[0] * cos(q[0]), 1e-14 * (1.0 + fabs(a[0])));
        assert_close(f.origin_acc[1], -a[0] * sin(q[0]), 1e-14 * (1.0 + fabs(a[0])));
        assert_true(f.center[0] == 0.2 && f.center[1] == 0.3);
    }
    motion_free(&both);
    motion_free(&sway);
}

/* Three angles at once (a 3D table): Omega and dOmega/dt come from the chain rule of
 * R = R_y(yaw) R_x(pitch) R_z(roll). Checked against R itself by central differences:
 * [Omega]x = R^T R' and dOmega/dt = d(Omega)/dt (the body-axes rate of the body-axes vector
 * equals R^T w' because Omega x Omega = 0). With step d the truncation is d^2/6 of the third
 * derivatives, at most (sum of Theta_k w^k)^3-like terms ~ 1e-3 here, so 1e-9 at d = 1e-4;
 * rounding eps/d = 2e-12. Tolerance 1e-7. And gravity is R^T (0, -g, 0). */
static void test_orientation_rates(void **state)
{
    (void)state;
    char text[65536];
    size_t used = (size_t)snprintf(text, sizeof text, "t,roll,pitch,yaw\n");
    for (int k = 0; k <= 400; k++) {
        double t = 0.01 * k;
        used += (size_t)snprintf(text + used, sizeof text - used, "%.17g,%.17g,%.17g,%.17g\n", t,
                                 0.3 * sin(2.0 * t), 0.2 * sin(1.3 * t + 0.5), 0.4 * sin(0.7 * t));
    }
    motion mo;
    char err[512];
    assert_int_equal(motion_from_table(&mo, text, 3, err, sizeof err), 0);
    const double d = 1e-4;
    for (int k = 1; k < 30; k++) {
        /* mid-way between knots: the spline is one cubic over [t - d, t + d] (its third
           derivative jumps at the knots, which a difference across one would see as O(d)) */
        double t = 0.1 * k + 0.005, rp[3][3], rm[3][3], r[3][3];
        motion_rotation(&mo, t + d, rp);
        motion_rotation(&mo, t - d, rm);
        motion_rotation(&mo, t, r);
        double spin[3][3]; /* R^T R' */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                spin[i][j] = 0.0;
                for (int m = 0; m < 3; m++) spin[i][j] += r[m][i] * (rp[m][j] - rm[m][j]) / (2 * d);
            }
        tank_frame f = motion_frame(&mo, G, t), fp = motion_frame(&mo, G, t + d),
                   fm = motion_frame(&mo, G, t - d);
        assert_close(f.omega[0], spin[2][1], 1e-7);
        assert_close(f.omega[1], spin[0][2], 1e-7);
        assert_close(f.omega[2], spin[1][0], 1e-7);
        for (int i = 0; i < 3; i++) {
            assert_close(f.omega_dot[i], (fp.omega[i] - fm.omega[i]) / (2 * d), 1e-7);
            assert_close(f.gravity[i], -G * r[1][i], 1e-14 * G);
        }
    }
    motion_free(&mo);
}

/* A table that samples the harmonic roll, 200 rows a period over 3 periods: its frames follow
 * the harmonic roll's within the natural spline's error (test_table_reproduces_acceleration
 * derives the bounds): theta'' within 1.1 theta_k^2 / 12 Theta w^2 and theta within
 * (5/384) theta_k^4 Theta, with theta_k = w h_k; so Omega' and the gravity's components
 * (g sin theta, g cos theta) within those times their factors. Bits cannot agree: a spline
 * through samples of a sine is not the sine. With phase 0 the sine's second derivative is 0
 * at both ends, as the natural spline's is, so the whole table is compared. */
static void test_table_roll_follows_the_harmonic_roll(void **state)
{
    (void)state;
    const double th = 0.05, T = 1.2, w = 2.0 * PI / T, hk = T / KNOTS_PER_PERIOD, theta = w * hk;
    char text[65536], err[512];
    size_t used = (size_t)snprintf(text, sizeof text, "t,roll\n");
    for (int k = 0; k <= KNOTS_PER_PERIOD * PERIODS; k++)
        used += (size_t)snprintf(text + used, sizeof text - used, "%.17g,%.17g\n", hk * k,
                                 th * sin(w * hk * k));
    motion table, roll;
    assert_int_equal(motion_from_table(&table, text, 2, err, sizeof err), 0);
    motion_from(&roll, "[motion]\ntype = roll\nangle = 0.05\nperiod = 1.2\n");
    const double tol_acc = 1.1 * theta * theta / 12.0 * th * w * w;
    const double tol_angle = 5.0 / 384.0 * pow(theta, 4) * th + 1e-15;
    for (int k = 1; k < 4 * KNOTS_PER_PERIOD * PERIODS; k++) {
        double t = hk * k / 4.0;
        tank_frame a = motion_frame(&table, G, t), b = motion_frame(&roll, G, t);
        assert_close(a.omega_dot[2], b.omega_dot[2], tol_acc);
        assert_close(a.gravity[0], b.gravity[0], G * tol_angle + 1e-15);
        assert_close(a.gravity[1], b.gravity[1], G * tol_angle * th + 1e-15);
    }
    motion_free(&table);
    motion_free(&roll);
}

/* A header that names t,x,y and a table without a header (a first row of numbers, t,x,y by
 * position) read the same rows: the same accelerations bit for bit, the first row kept; a roll
 * column turns the tank; pitch in 2D is refused. */
static void test_named_columns(void **state)
{
    (void)state;
    const char rows[] = "0,0,0\n0.5,0.01,0.002\n1,0.03,-0.001\n1.5,0.02,0\n2,0,0.001\n";
    char named[256], err[512];
    snprintf(named, sizeof named, "t,x,y\n%s", rows);
    motion a, b;
    assert_int_equal(motion_from_table(&a, named, 2, err, sizeof err), 0);
    assert_int_equal(motion_from_table(&b, rows, 2, err, sizeof err), 0);
    assert_false(a.table_by_position);
    assert_true(b.table_by_position);
    assert_int_equal(b.n_knots, 5);
    assert_true(b.t[0] == 0.0);
    for (int k = 0; k <= 40; k++) {
        tank_frame fa = motion_frame(&a, G, 0.05 * k), fb = motion_frame(&b, G, 0.05 * k);
        assert_memory_equal(&fa, &fb, sizeof fa);
    }
    assert_false(a.rotates);
    char columns[64];
    motion_table_columns(&b, columns, sizeof columns);
    assert_string_equal(columns, "t,x,y");
    motion_free(&a);
    motion_free(&b);
    motion r;
    assert_int_equal(motion_from_table(&r, "# a comment\n\nt, roll\n0,0\n1,0.1\n2,0\n3,-0.1\n", 2,
                                       err, sizeof err),
                     0);
    assert_true(r.rotates && r.pos[MOTION_X] == NULL);
    motion_table_columns(&r, columns, sizeof columns);
    assert_string_equal(columns, "t,roll");
    motion_free(&r);
    assert_int_equal(motion_from_table(&r, "t,x,y,pitch\n0,0,0,0\n1,0,0,0\n2,0,0,0\n3,0,0,0\n", 2,
                                       err, sizeof err),
                     2);
    assert_non_null(strstr(err, "3D only"));
    assert_int_equal(motion_from_table(&r, "t,roll\n0,0\n1,0.1,2\n2,0\n3,0\n", 2, err, sizeof err),
                     2);
    assert_non_null(strstr(err, ":3: expected 2 decimal numbers t,roll"));
}

/* Every header word is a column, spelled as documented: a misspelt, capitalised or unknown
 * word, t not first, a column twice, a header of other words are refused with the file's
 * line, the word and, for a near miss, the column meant; so is a row with a hex number or a
 * first row of numbers that is neither t,x,y nor t,x,y,z. */
static void test_table_header_refused(void **state)
{
    (void)state;
    static const struct {
        const char *table, *expected;
    } bad[] = {
        {"t,x,rol\n", ":1: motion table header: 'rol' is not a column (did you mean 'roll'?)"},
        {"t,x,Roll\n", "'Roll' is not a column (did you mean 'roll'?)"},
        {"t,x,foo\n", "'foo' is not a column; the columns are t, then any of x, y, z"},
        {"time (s),x (m),y (m)\n", "'time (s)' is not a column"},
        {"x,t,y\n", "'x' comes before t; t must be the first column"},
        {"t,x,x\n", "'x' comes twice"},
        {"t,x,t\n", "'t' comes twice"},
        {"t\n", "names t alone"},
        {"# notes\n\nT,x\n", ":3: motion table header: 'T' is not a column (did you mean 't'?)"},
        {"t,x\n0,0\n0x1p-2,0\n", ":3: expected 2 decimal numbers t,x"},
        {"0,1\n1,2\n2,3\n3,4\n", ":1: a motion table without a header has t,x,y or t,x,y,z"},
        {"0,0,0\n1,0,0,0\n", ":2: expected 3 decimal numbers t,x,y (s, m, rad), as the first row"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char table[256], err[512] = "";
        snprintf(table, sizeof table, "%s0,0,0\n1,0,0\n2,0,0\n3,0,0\n", bad[i].table);
        motion mo;
        int status = motion_from_table(&mo, table, 2, err, sizeof err);
        if (status == 0) motion_free(&mo);
        if (status != 2 || !strstr(err, bad[i].expected))
            fail_msg("table \"%s\": status %d, message \"%s\", expected \"%s\"", bad[i].table,
                     status, err, bad[i].expected);
    }
}

/* ---- g_max ---------------------------------------------------------------------------------- */

/* g_eff = g - a_tank with g = (0, -g) (theory §6). Heave: |g_eff| = |g + A w^2 cos(wt + p)|,
 * largest g + A w^2; sway: sqrt(g^2 + (A w^2 sin(wt + p))^2), largest sqrt(g^2 + (A w^2)^2).
 * A sampled maximum never exceeds the true one (1e-12 for rounding) and, with samples at most
 * T/2000 apart, misses the peak by at most half a spacing, dtheta = pi/2000, which lowers it by
 * A w^2 dtheta^2/2 (heave) or (A w^2)^2 dtheta^2 / (2 g_max) (sway). c0 ~ sqrt(g_max) needs no
 * more. A phase puts the peak between samples. */
static void test_max_effective_gravity(void **state)
{
    (void)state;
    const double A = 0.04, T = 0.7, w = 2.0 * PI / T, aw2 = A * w * w, dth = PI / 2000.0;
    motion heave, sway;
    motion_from(&heave, "[motion]\ntype = heave\namplitude = 0.04\nperiod = 0.7\nphase = 0.123\n");
    motion_from(&sway, "[motion]\ntype = sway\namplitude = 0.04\nperiod = 0.7\nphase = 0.123\n");
    double g_heave = motion_max_effective_gravity(&heave, G, 10.0);
    double g_sway = motion_max_effective_gravity(&sway, G, 10.0);
    double exact_heave = G + aw2, exact_sway = sqrt(G * G + aw2 * aw2);
    assert_close(g_heave, exact_heave - 0.5 * aw2 * dth * dth / 2.0,
                 0.5 * aw2 * dth * dth / 2.0 + 1e-12 * exact_heave);
    assert_close(g_sway, exact_sway - 0.5 * aw2 * aw2 * dth * dth / (2.0 * exact_sway),
                 0.5 * aw2 * aw2 * dth * dth / (2.0 * exact_sway) + 1e-12 * exact_sway);
    /* without motion, g itself */
    motion none;
    motion_from(&none, "");
    assert_true(motion_max_effective_gravity(&none, G, 10.0) == G);
    motion_free(&heave);
    motion_free(&sway);
    motion_free(&none);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sway_second_derivative),
        cmocka_unit_test(test_heave_second_derivative),
        cmocka_unit_test(test_positions_follow_theory),
        cmocka_unit_test(test_signs_of_theory),
        cmocka_unit_test(test_duration_stops_acceleration),
        cmocka_unit_test_setup_teardown(test_table_reproduces_acceleration, table_setup,
                                        table_teardown),
        cmocka_unit_test(test_max_effective_gravity),
        cmocka_unit_test(test_roll_frame),
        cmocka_unit_test(test_sway_roll_frame),
        cmocka_unit_test_setup_teardown(test_orientation_rates, table_setup, table_teardown),
        cmocka_unit_test_setup_teardown(test_named_columns, table_setup, table_teardown),
        cmocka_unit_test_setup_teardown(test_table_header_refused, table_setup, table_teardown),
        cmocka_unit_test_setup_teardown(test_table_roll_follows_the_harmonic_roll, table_setup,
                                        table_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
