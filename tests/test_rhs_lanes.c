/* The right-hand side's four-lane sums (scheme/rhs_sums.h) give the scalar sums' bits: on a
 * disordered block of liquid in a tank (wall ghosts, random velocities, shifting), for every
 * variant of the loop (LES on and off, shifting on and off, constant and variable masses), every
 * rate of every particle is the same double. A particle count that is not a multiple of four
 * takes the scalar tail too. Skipped on a processor without AVX2, where only the scalar sums
 * run. */
#include "scheme/rhs.h"
#include "scheme/solver.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#if DIM == 2
static const char block_case[] = "[case]\nname = block\ndim = 2\nt_end = 1\n"
                                 "[tank]\nlength = 0.4\nheight = 0.3\n"
                                 "[liquid]\nheight = 0.2\n[model]\nscheme = delta-plus-ale\n"
                                 "les = true\n[numerics]\nresolution = 19\n";
#else
static const char block_case[] = "[case]\nname = block\ndim = 3\nt_end = 1\n"
                                 "[tank]\nlength = 0.24\nheight = 0.2\nwidth = 0.12\n"
                                 "[liquid]\nheight = 0.12\n[model]\nscheme = delta-plus-ale\n"
                                 "les = true\n[numerics]\nresolution = 11\n";
#endif

/* a small deterministic generator: the same numbers everywhere */
static double uniform(uint64_t *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) / 9007199254740992.0 * 2.0 - 1.0;
}

/* rates of n particles, one array per integrated component */
typedef struct {
    double *data;
    rates r;
} rate_arrays;

static void rate_arrays_alloc(rate_arrays *a, size_t n)
{
    a->data = calloc(n * PARTICLE_N_INTEGRATED, sizeof(double));
    assert_non_null(a->data);
    double *next = a->data;
#define RATE_ARRAY_SCALAR(name) a->r.d##name = next, next += n;
#define RATE_ARRAY_VECTOR(name) for (int d = 0; d < DIM; d++) a->r.d##name[d] = next, next += n;
    PARTICLE_INTEGRATED(RATE_ARRAY_SCALAR, RATE_ARRAY_VECTOR)
}

static void test_lanes_give_the_scalar_bits(void **state)
{
    (void)state;
    if (!rhs_lanes_available()) skip();
    config cfg;
    solver s;
    char err[1024];
    if (config_load_string(&cfg, block_case, "test", NULL, 0, err, sizeof err)) fail_msg("%s", err);
    if (solver_init(&s, &cfg, err, sizeof err)) fail_msg("%s", err);
    particles *p = &s.p;
    uint64_t st = 7;
    for (size_t i = 0; i < p->n_fluid; i++)
        for (int d = 0; d < DIM; d++) {
            p->x[d][i] += 0.2 * s.dv.dr * uniform(&st);
            p->u[d][i] = s.pp.shift_u_max * uniform(&st);
        }
    assert_int_equal(solver_prepare(&s, cfg.t_end), 0);
    assert_true(p->n_fluid % 4 != 0); /* the scalar tail runs too */
    tank_frame frame = solver_frame(&s, 0.0);
    size_t n = p->n_fluid, n_values = n * PARTICLE_N_INTEGRATED;
    rate_arrays scalar, lanes;
    rate_arrays_alloc(&scalar, n);
    rate_arrays_alloc(&lanes, n);
    for (int les = 0; les <= 1; les++)
        for (int shifting = 0; shifting <= 1; shifting++)
            for (int variable_mass = 0; variable_mass <= shifting; variable_mass++) {
                s.pp.les = les;
                s.pp.shifting = shifting;
                double eta = variable_mass ? 1.0 : 0.0;
                rhs_compute_with(&s.pp, p, &s.nl, &frame, eta, &scalar.r, false);
                rhs_compute_with(&s.pp, p, &s.nl, &frame, eta, &lanes.r, true);
                size_t differ = 0;
                for (size_t v = 0; v < n_values; v++)
                    differ += memcmp(&scalar.data[v], &lanes.data[v], sizeof(double)) != 0;
                if (differ)
                    fail_msg("les %d, shifting %d, variable masses %d: %zu of %zu rates differ",
                             les, shifting, variable_mass, differ, n_values);
            }
    /* the comparison compared something: forces and density rates are not all zero */
    double largest = 0.0;
    for (size_t v = 0; v < n_values; v++) largest = fmax(largest, fabs(lanes.data[v]));
    assert_true(largest > 0.0);
    free(scalar.data);
    free(lanes.data);
    solver_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lanes_give_the_scalar_bits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
