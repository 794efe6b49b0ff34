/* The rows' near parts (core/cells.h) give a pass at the positions of the build the bits of
 * the whole rows: the step's geometry, shifting and correction, frozen terms, the volume rate
 * and the right-hand side of RK4's first stage (in each lane form the processor has), on a
 * disordered block of liquid with random velocities, whose skin holds pairs beyond 2h; and
 * no pass of the step's preparation moves a particle, which is what makes the near parts
 * valid for them (solver_prepared_rows). */
#include "core/lanes_switch.h"
#include "diag/freesurface.h"
#include "diag/volume.h"
#include "scheme/step_fields.h"
#include "scheme/passes.h"
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

/* The fluid's fields the passes below write */
// clang-format off
#define PASS_FIELDS(SCALAR, VECTOR)                                                                \
    SCALAR(lambda) SCALAR(kernel_sum) SCALAR(gamma) VECTOR(normal) VECTOR(grad_rho)                \
    SCALAR(nu_t) SCALAR(nu_delta) VECTOR(shift) VECTOR(correction) SCALAR(diff_rho)
// clang-format on
#define COUNT_SCALAR(name) +1
#define COUNT_VECTOR(name) +DIM
enum { N_FIELDS = 0 PASS_FIELDS(COUNT_SCALAR, COUNT_VECTOR) };

/* The passes' outputs, the rates of the first stage and the volume rate, with the rows `nl`,
 * into `out` (n_fluid x (N_FIELDS + PARTICLE_N_RATED) + 3 doubles). */
static void run_passes(solver *s, const neighbour_list *nl, double *out)
{
    particles *p = &s->p;
    size_t n = p->n_fluid;
    tank_frame frame = solver_frame(s, s->t);
    step_fields_geometry(&s->pp, &s->tank, p, nl);
    freesurface_test(&s->pp.k, s->pp.dr, s->pp.normal_reference, p, nl); /* normalises */
    step_diffusion diffusion = {.mass = false, .dt = s->dt};
    step_fields_shifting_and_correction(&s->pp, p, nl, true, true, &diffusion,
                                        DIFFUSION_ROWS_OFF_WALLS);
    step_fields_frozen_terms(&s->pp, p, nl, &frame, &diffusion, DIFFUSION_ROWS_AT_WALLS);
    double *next = out;
/* element by element: some fields are single precision (core/particles.h: frozen_real) */
#define COPY_SCALAR(name)                                                                          \
    {                                                                                              \
        for (size_t i = 0; i < n; i++) next[i] = p->name[i];                                       \
        next += n;                                                                                 \
    }
#define COPY_VECTOR(name)                                                                          \
    for (int d = 0; d < DIM; d++) COPY_SCALAR(name[d])
    PASS_FIELDS(COPY_SCALAR, COPY_VECTOR)
    rates k;
#define STAGE_RATE_SCALAR(name) k.d##name = next, next += n;
#define STAGE_RATE_VECTOR(name)                                                                    \
    for (int d = 0; d < DIM; d++) k.d##name[d] = next, next += n;
    PARTICLE_RATED(STAGE_RATE_SCALAR, STAGE_RATE_VECTOR)
    rhs_compute(&s->pp, p, nl, &frame, 1.0, &k);
    volume_rates rate;
    volume_rate(&s->pp.k, p, nl, s->dv.cell_volume, s->scratch, solver_reducer(s), &rate);
    *next++ = rate.u;
    *next++ = rate.shift;
    *next++ = rate.correction;
}

static void near_rows_give_the_whole_rows_bits(int width)
{
    lanes_limit(width);
    if (lanes_width() != width) skip();
    config cfg;
    solver s;
    disordered_block(ALE_BLOCK_CASE, 0.2, 7, &cfg, &s);
    s.pp.volume_correction = true;
    /* the skin holds pairs: rows beyond their near parts */
    size_t skin = 0;
    for (size_t i = 0; i < s.nl.n_rows; i++) skin += (size_t)(s.nl.count[i] - s.nl.near[i]);
    assert_true(skin > 0);
    size_t n_values = s.p.n_fluid * (N_FIELDS + PARTICLE_N_RATED) + 3;
    double *whole = calloc(n_values, sizeof *whole), *near = calloc(n_values, sizeof *near);
    neighbour_list near_rows = neighbours_near(&s.nl);
    run_passes(&s, &s.nl, whole);
    run_passes(&s, &near_rows, near);
    size_t differ = 0, nonzero = 0;
    for (size_t v = 0; v < n_values; v++) {
        differ += memcmp(&whole[v], &near[v], sizeof(double)) != 0;
        nonzero += whole[v] != 0.0;
    }
    if (differ) fail_msg("%d lanes: %zu of %zu values differ", width, differ, n_values);
    assert_true(nonzero > n_values / 2); /* the comparison compared something */
    free(whole);
    free(near);
    solver_free(&s);
}

static void test_near_rows(void **state)
{
    near_rows_give_the_whole_rows_bits(*(const int *)*state);
}

/* The passes' declared writes (the registry of core/particles.h) leave the positions alone,
 * and the registry answers: the passes write something. */
static void test_no_pass_moves_particles(void **state)
{
    (void)state;
    uint64_t writes = passes_prepare_writes();
    assert_true(writes != 0);
    assert_false(writes & FIELD_MASK(x));
}

int main(void)
{
    static int one = 0, four = 4, eight = 8;
    const struct CMUnitTest tests[] = {
        {"test_near_rows_scalar", test_near_rows, NULL, NULL, &one},
        {"test_near_rows_in_4_lanes", test_near_rows, NULL, NULL, &four},
        {"test_near_rows_in_8_lanes", test_near_rows, NULL, NULL, &eight},
        cmocka_unit_test(test_no_pass_moves_particles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
