/* Particle shifting, Eq. (7) (theory §4): it regularises a disordered lattice, and near the
 * free surface it moves no particle along the surface normal. */
#include "diag/freesurface.h"
#include "scheme/solver.h"

#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "check.h"
#include "disordered_block.h"

#if DIM == 2
static const char block_case[] = "[case]\nname = block\ndim = 2\nt_end = 1\n"
                                 "[tank]\nlength = 0.4\nheight = 0.3\n"
                                 "[liquid]\nheight = 0.2\n[model]\nscheme = delta-plus\n"
                                 "[numerics]\nresolution = 20\n";
#else
static const char block_case[] = "[case]\nname = block\ndim = 3\nt_end = 1\n"
                                 "[tank]\nlength = 0.24\nheight = 0.2\nwidth = 0.12\n"
                                 "[liquid]\nheight = 0.12\n[model]\nscheme = delta-plus\n"
                                 "[numerics]\nresolution = 12\n";
#endif

static int deep_inside(const solver *s, size_t i)
{
    const particles *p = &s->p;
    double band = 2.0 * s->dv.h;
    for (int d = 0; d < DIM; d++)
        if (p->x[d][i] < band || p->x[d][i] > s->tank.size[d] - band) return 0;
    return p->surface[i] == SURFACE_INTERIOR;
}

/* standard deviation of lambda over the particles deep inside */
static double lambda_spread(const solver *s)
{
    double sum = 0.0, sum2 = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < s->p.n_fluid; i++) {
        if (!deep_inside(s, i)) continue;
        sum += s->p.lambda[i];
        sum2 += s->p.lambda[i] * s->p.lambda[i];
        n++;
    }
    double mean = sum / (double)n;
    return sqrt(sum2 / (double)n - mean * mean);
}

/* Moving the particles of a disordered block by their shifting velocity alone, over 40 time
 * steps of the run (dt of Eq. 8), narrows the distribution of lambda: the lattice is
 * regularised (a perfect lattice has one lambda). Asserted: the spread falls by half. */
static void test_shifting_regularises(void **state)
{
    (void)state;
    config cfg;
    solver s;
    disordered_block(block_case, 0.2, 42, &cfg, &s);
    double before = lambda_spread(&s), tau = s.dt;
    for (int k = 0; k < 40; k++) {
        particles *p = &s.p;
        for (size_t i = 0; i < p->n_fluid; i++)
            for (int d = 0; d < DIM; d++) p->x[d][i] += tau * p->shift[d][i];
        assert_int_equal(solver_prepare(&s, cfg.t_end), 0);
    }
    double after = lambda_spread(&s);
    printf("%dD disordered block (0.2 dr): spread of lambda %.4f before, %.4f after shifting\n",
           DIM, before, after);
    assert_true(after < 0.5 * before);
    solver_free(&s);
}

/* Near the free surface the shifting velocity is tangential: no component along the normal
 * of the particle (free surface) or of the surface above it (rest of S_F: its nearest free-surface
 * neighbour's, equidistant ones averaged), to round-off of |du| (theory §4) and du's rounding to
 * single precision. */
static void test_no_normal_shifting_at_surface(void **state)
{
    (void)state;
    config cfg;
    solver s;
    disordered_block(block_case, 0.1, 7, &cfg, &s);
    const particles *p = &s.p;
    size_t checked = 0, moving = 0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        if (p->surface[i] == SURFACE_INTERIOR) continue;
        vec du = vec_load(p->shift, i), n = vec_load(p->normal, i);
        /* du is held in single precision (frozen_real): each component rounded by at most
           half an ulp, which moves du . n by at most FLT_EPSILON / 2 |du| (|n| = 1) */
        assert_close(vec_dot(du, n), 0.0,
                     1e-12 * s.pp.shift_u_max + 0.5 * FLT_EPSILON * vec_norm(du));
        checked++;
        moving += vec_norm(du) > 1e-6 * s.pp.shift_u_max;
    }
    printf("%dD: %zu particles of S_F checked, %zu of them shifted tangentially\n", DIM, checked,
           moving);
    assert_true(checked > 0 && moving > checked / 2);
    solver_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shifting_regularises),
        cmocka_unit_test(test_no_normal_shifting_at_surface),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
