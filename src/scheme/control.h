/* control: the two volume controls of the paper: EdBC, Eq. (9), and the eta switch of
 * delta-plus-ALE-SPH (sec. 5.1.1, Fig. 9; theory §8). */
#ifndef VCSPH_CONTROL_H
#define VCSPH_CONTROL_H

#include "scheme/solver.h"

#define EDBC_LAMBDA 0.1 /* Eq. (9): particles of S_F with lambda below this */

#define control_edbc       DIM_NAME(control_edbc)
#define control_eta_switch DIM_NAME(control_eta_switch)

/* Eq. (9) on this step's geometry: p = 0, rho = rho0 (V = m / rho0) for the particles of S_F
 * with lambda < 0.1, when model.edbc is on (with-eta0: only while eta = 0). Sets s->n_edbc. */
void control_edbc(solver *s);

/* The paper's switch (delta-plus-ALE only): eta = 1 when eps_V1 > +threshold, eta = 0 when
 * eps_V1 < -threshold. Returns 1 when eta changed (and describes the switch in `detail`). */
int control_eta_switch(solver *s, double eps_v1, char *detail, size_t detail_len);

#endif
