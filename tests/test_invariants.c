/* The debug build's invariants (scheme/invariants.h), on a tank prepared for its first step:
 * they hold there, and each breaks where it should: a particle outside the tank, a non-finite
 * velocity, a negative density, a row entry past the store, a total mass changed by more than
 * INVARIANT_MASS_TOLERANCE (and not by less). The pass write masks' check (scheme/passes.c)
 * runs in every step of the debug build's tests. */
#include "scheme/invariants.h"
#include "scheme/solver.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "check.h"

static const char tank_case[] = "[case]\nname = invariants\nt_end = 1\n"
                                "[tank]\nlength = 0.4\nheight = 0.3\nwidth = 0.1\n"
                                "[liquid]\nheight = 0.1\n"
                                "[numerics]\nresolution = 8\n";

static void prepared_tank(config *cfg, solver *s)
{
    char err[1024], dim[32];
    snprintf(dim, sizeof dim, "case.dim=%d", DIM);
    const char *overrides[] = {dim};
    if (config_load_string(cfg, tank_case, "test", overrides, 1, err, sizeof err))
        fail_msg("%s", err);
    if (solver_init(s, cfg, err, sizeof err)) fail_msg("%s", err);
    if (solver_prepare(s, 1.0)) fail_msg("solver_prepare");
}

static double total_mass(const particles *p)
{
    double sum = 0.0;
    for (size_t i = 0; i < p->n_fluid; i++) sum += p->m[i];
    return sum;
}

/* Whether the invariants break after `breaking` changed particle i, the message naming `word` */
static void expect_broken(solver *s, double mass, const char *word)
{
    char what[256] = "";
    assert_int_equal(solver_invariants_broken(s, mass, what, sizeof what), 1);
    if (!strstr(what, word)) fail_msg("'%s' does not name '%s'", what, word);
}

static void test_invariants(void **state)
{
    (void)state;
    config cfg;
    solver s;
    prepared_tank(&cfg, &s);
    particles *p = &s.p;
    double mass = total_mass(p);
    char what[256] = "";
    assert_int_equal(solver_invariants_broken(&s, mass, what, sizeof what), 0);

    size_t i = p->n_fluid / 2;
    double x0 = p->x[0][i];
    p->x[0][i] = -1e-6; /* beyond the wall at x = 0 */
    expect_broken(&s, mass, "outside the tank");
    p->x[0][i] = x0;

    double u0 = p->u[1][i];
    p->u[1][i] = NAN;
    expect_broken(&s, mass, "non-finite");
    p->u[1][i] = u0;

    double rho0 = p->rho[i];
    p->rho[i] = -rho0;
    expect_broken(&s, mass, "density");
    p->rho[i] = rho0;

    /* the mass: a relative change of 1e-8 breaks it, 1e-11 does not */
    double m0 = p->m[i];
    p->m[i] += 1e-8 * mass;
    expect_broken(&s, mass, "total mass");
    p->m[i] = m0 + 1e-11 * mass;
    assert_int_equal(solver_invariants_broken(&s, mass, what, sizeof what), 0);
    p->m[i] = m0;

    /* a row entry past the store: the wide form holds indices as they are */
    if (s.nl.wide && s.nl.count[0] > 0) {
        int32_t j0 = s.nl.index[0];
        s.nl.index[0] = (int32_t)p->n_total;
        expect_broken(&s, mass, "row 0");
        s.nl.index[0] = j0;
    } else if (!s.nl.wide && s.nl.count[0] > 0) {
        int32_t base0 = s.nl.base[0];
        s.nl.base[0] = (int32_t)p->n_total; /* the fluid window moved past the store */
        expect_broken(&s, mass, "row 0");
        s.nl.base[0] = base0;
    }
    assert_int_equal(solver_invariants_broken(&s, mass, what, sizeof what), 0);
    solver_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_invariants)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
