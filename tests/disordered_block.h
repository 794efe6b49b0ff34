/* disordered_block: a case's liquid with every fluid particle moved by up to `frac` dr and given
 * a random velocity of the order of the shifting's U_max (so that the limiter of Eq. (7),
 * max |u_ij| / 2, does not hold the shifting back), prepared for its first step. Include after
 * <cmocka.h>. */
#ifndef VCSPH_TEST_DISORDERED_BLOCK_H
#define VCSPH_TEST_DISORDERED_BLOCK_H

#include "noise.h"
#include "scheme/solver.h"

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
