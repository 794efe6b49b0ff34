/* edbc: EdBC, Eq. (9); the eta of the step is set by eta_control. */
#include "scheme/edbc.h"
#include "core/reduce.h"
#include "diag/freesurface.h"
#include "physics/eos.h"

int edbc_acts(const solver *s)
{
    edbc_mode edbc = s->cfg->edbc;
    return edbc == EDBC_ON || (edbc == EDBC_WITH_ETA0 && s->eta_control.eta0_regime);
}

void edbc_correct(solver *s)
{
    s->n_edbc = 0;
    if (!edbc_acts(s)) return;
    particles *p = &s->p;
    double rho0 = s->pp.rho0;
    long n = 0;
#pragma omp parallel for schedule(static) reduction(+ : n)
    for (size_t i = 0; i < p->n_fluid; i++) {
        if (p->surface[i] == SURFACE_INTERIOR || p->lambda[i] >= EDBC_LAMBDA) continue;
        p->rho[i] = rho0;
        p->p[i] = 0.0;
        p->vol[i] = p->m[i] / rho0;
        n++;
    }
    s->n_edbc = reducer_total(solver_reducer(s), n);
}
