/* disordered_block: a case's liquid with every fluid particle moved by up to `frac` dr and given
 * a random velocity of the order of the shifting's U_max (so that the limiter of Eq. (7),
 * max |u_ij| / 2, does not hold the shifting back), prepared for its first step. Include after
 * <cmocka.h>. */
#ifndef VCSPH_TEST_DISORDERED_BLOCK_H
#define VCSPH_TEST_DISORDERED_BLOCK_H

#include "noise.h"
#include "scheme/solver.h"

/* A block of liquid in a tank, delta-plus-ALE with LES (every term of the right-hand side's
 * loop), for the tests that run the same passes two ways and compare the bits (test_lanes,
 * test_near_rows): its particle count is not a multiple of four or eight. */
#if DIM == 2
#define ALE_BLOCK_CASE                                                                             \
    "[case]\nname = block\ndim = 2\nt_end = 1\n"                                                   \
    "[tank]\nlength = 0.4\nheight = 0.3\n"                                                         \
    "[liquid]\nheight = 0.2\n[model]\nscheme = delta-plus-ale\n"                                   \
    "les = true\n[numerics]\nresolution = 19\n"
#else
#define ALE_BLOCK_CASE                                                                             \
    "[case]\nname = block\ndim = 3\nt_end = 1\n"                                                   \
    "[tank]\nlength = 0.24\nheight = 0.2\nwidth = 0.12\n"                                          \
    "[liquid]\nheight = 0.12\n[model]\nscheme = delta-plus-ale\n"                                  \
    "les = true\n[numerics]\nresolution = 11\n"
#endif

static inline void disordered_block(const char *case_text, double frac, uint64_t seed, config *cfg,
                                    solver *s)
{
    char err[1024];
    if (config_load_string(cfg, case_text, "test", NULL, 0, err, sizeof err)) fail_msg("%s", err);
    if (solver_init(s, cfg, err, sizeof err)) fail_msg("%s", err);
    particles *p = &s->p;
    for (size_t i = 0; i < p->n_fluid; i++)
        for (int d = 0; d < DIM; d++) {
            p->x[d][i] += frac * s->dv.dr * noise(&seed);
            p->u[d][i] = s->pp.shift_u_max * noise(&seed);
        }
    assert_int_equal(solver_prepare(s, cfg->t_end), 0);
}

#endif
