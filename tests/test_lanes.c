/* The passes' lane forms (core/lanes.h), 4 and 8 wide, give the scalar forms' bits, on a
 * disordered block of liquid in a tank (wall ghosts, random velocities, shifting): the
 * right-hand side's rates in every variant of its loop (LES on and off, shifting on and off,
 * constant and variable masses), and every field of a few whole steps with surface tension. A
 * particle count that is not a multiple of four or eight takes the scalar tail too. A width the
 * processor does not have (AVX2 for 4, AVX-512 for 8) is skipped: only narrower forms run there. */
#include "core/lanes_switch.h"
#include "scheme/rhs.h"
#include "scheme/solver.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "disordered_block.h"
#include "test_filter.h"

/* rates of n particles, one array per integrated component */
typedef struct {
    double *data;
    rates r;
} rate_arrays;

static void rate_arrays_alloc(rate_arrays *a, size_t n)
{
    a->data = calloc(n * PARTICLE_N_RATED, sizeof(double));
    assert_non_null(a->data);
    double *next = a->data;
#define RATE_ARRAY_SCALAR(name) a->r.d##name = next, next += n;
#define RATE_ARRAY_VECTOR(name)                                                                    \
    for (int d = 0; d < DIM; d++) a->r.d##name[d] = next, next += n;
    PARTICLE_RATED(RATE_ARRAY_SCALAR, RATE_ARRAY_VECTOR)
}

/* ALE_BLOCK_CASE with water's surface tension: its passes' row sums too */
#define ALE_TENSION_CASE ALE_BLOCK_CASE "[fluid]\nsurface_tension = 0.0727\n"

/* The block of case_text (ALE_BLOCK_CASE or ALE_TENSION_CASE), disordered
 * (disordered_block.h): a particle count that is not a multiple of four, so that the scalar
 * tail runs too. */
static void lanes_block(const char *case_text, config *cfg, solver *s)
{
    disordered_block(case_text, 0.2, 7, cfg, s);
    assert_true(s->p.n_fluid % 4 != 0);
}

/* At most `width` lanes; false (the test is skipped) where the processor has fewer. */
static bool lanes_of_width(int width)
{
    lanes_limit(width);
    return lanes_width() == width;
}

/* n_values doubles at a and b: how many differ in their bits */
/* The values of a and b (n_values of `size` bytes each) whose bits differ. */
static size_t differing_values(const void *a, const void *b, size_t n_values, size_t size)
{
    size_t differ = 0;
    for (size_t v = 0; v < n_values; v++)
        differ += memcmp((const char *)a + v * size, (const char *)b + v * size, size) != 0;
    return differ;
}
#define differing(a, b, n_values) differing_values(a, b, n_values, sizeof *(a))

static void rhs_lanes_give_the_scalar_bits(int width)
{
    if (!lanes_of_width(width)) skip();
    config cfg;
    solver s;
    lanes_block(ALE_BLOCK_CASE, &cfg, &s);
    particles *p = &s.p;
    tank_frame frame = solver_frame(&s, 0.0);
    size_t n = p->n_fluid, n_values = n * PARTICLE_N_RATED;
    rate_arrays scalar, lanes;
    rate_arrays_alloc(&scalar, n);
    rate_arrays_alloc(&lanes, n);
    for (int les = 0; les <= 1; les++)
        for (int shifting = 0; shifting <= 1; shifting++)
            for (int variable_mass = 0; variable_mass <= shifting; variable_mass++) {
                s.pp.les = les;
                s.pp.shifting = shifting;
                double eta = variable_mass ? 1.0 : 0.0;
                lanes_limit(0);
                rhs_compute(&s.pp, p, &s.nl, &frame, eta, &scalar.r);
                lanes_limit(width);
                rhs_compute(&s.pp, p, &s.nl, &frame, eta, &lanes.r);
                size_t differ = differing(scalar.data, lanes.data, n_values);
                if (differ)
                    fail_msg("%d lanes, les %d, shifting %d, variable masses %d: %zu of %zu rates "
                             "differ",
                             width, les, shifting, variable_mass, differ, n_values);
            }
    /* the comparison compared something: forces and density rates are not all zero */
    double largest = 0.0;
    for (size_t v = 0; v < n_values; v++) largest = fmax(largest, fabs(lanes.data[v]));
    assert_true(largest > 0.0);
    free(scalar.data);
    free(lanes.data);
    solver_free(&s);
}

/* The fields of the fluid that every pass writes, compared after a few whole steps */
// clang-format off
#define FLUID_FIELDS(SCALAR, VECTOR)                                                               \
    VECTOR(x) VECTOR(u) SCALAR(rho) SCALAR(m) SCALAR(p)                                            \
    SCALAR(lambda) SCALAR(kernel_sum) SCALAR(gamma) VECTOR(normal) VECTOR(grad_rho)                \
    SCALAR(nu_t) SCALAR(nu_delta) VECTOR(shift) VECTOR(correction) SCALAR(diff_rho) SCALAR(diff_m) \
    SCALAR(interface) SCALAR(curvature) VECTOR(st_force)
// clang-format on

static void steps_with_lanes_give_the_scalar_bits(int width)
{
    if (!lanes_of_width(width)) skip();
    config cfg;
    solver scalar, lanes;
    lanes_limit(0);
    lanes_block(ALE_TENSION_CASE, &cfg, &scalar);
    for (int step = 0; step < 5; step++) assert_int_equal(solver_step(&scalar, cfg.t_end), 0);
    lanes_limit(width);
    lanes_block(ALE_TENSION_CASE, &cfg, &lanes);
    for (int step = 0; step < 5; step++) assert_int_equal(solver_step(&lanes, cfg.t_end), 0);
    size_t n = scalar.p.n_fluid;
    assert_int_equal(lanes.p.n_fluid, n);
    assert_true(lanes.t > 0.0 && memcmp(&lanes.t, &scalar.t, sizeof(double)) == 0);
#define COMPARE_SCALAR(name)                                                                       \
    if (differing(scalar.p.name, lanes.p.name, n))                                                 \
        fail_msg("%d lanes, " #name ": %zu of %zu values differ", width,                           \
                 differing(scalar.p.name, lanes.p.name, n), n);
#define COMPARE_VECTOR(name)                                                                       \
    for (int d = 0; d < DIM; d++) COMPARE_SCALAR(name[d])
    FLUID_FIELDS(COMPARE_SCALAR, COMPARE_VECTOR)
    solver_free(&scalar);
    solver_free(&lanes);
}

/* The tests below take their width from cmocka's initial state. */
static void test_rhs_lanes(void **state) { rhs_lanes_give_the_scalar_bits(*(const int *)*state); }

static void test_steps_with_lanes(void **state)
{
    steps_with_lanes_give_the_scalar_bits(*(const int *)*state);
}

int main(int argc, char **argv)
{
    test_filter_args(argc, argv);
    static int four = 4, eight = 8;
    const struct CMUnitTest tests[] = {
        {"test_rhs_in_4_lanes", test_rhs_lanes, NULL, NULL, &four},
        {"test_rhs_in_8_lanes", test_rhs_lanes, NULL, NULL, &eight},
        {"test_steps_in_4_lanes", test_steps_with_lanes, NULL, NULL, &four},
        {"test_steps_in_8_lanes", test_steps_with_lanes, NULL, NULL, &eight},
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
