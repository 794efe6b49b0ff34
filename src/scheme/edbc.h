/* edbc: the EdBC correction of the paper, Eq. (9). The other volume control, the eta of
 * delta-plus-ALE-SPH (sec. 5.1.1, Fig. 9; theory §8), is eta_control. */
#ifndef VCSPH_EDBC_H
#define VCSPH_EDBC_H

#include "scheme/solver.h"

#define EDBC_LAMBDA 0.1 /* Eq. (9): particles of S_F with lambda below this */

#define edbc_acts    DIM_NAME(edbc_acts)
#define edbc_correct DIM_NAME(edbc_correct)

/* Whether EdBC acts in the current state: model.edbc = true, or with-eta0 while the eta
 * control is in its eta = 0 regime. */
int edbc_acts(const solver *s);

/* Eq. (9) on this step's geometry: p = 0, rho = rho0 (V = m / rho0) for the particles of S_F
 * with lambda < 0.1, when edbc_acts. Sets s->n_edbc. */
void edbc_correct(solver *s);

#endif
