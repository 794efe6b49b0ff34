/* control: EdBC and the eta switch. */
#include "scheme/control.h"
#include "diag/freesurface.h"
#include "physics/eos.h"

#include <stdio.h>

void control_edbc(solver *s)
{
    const config *cfg = s->cfg;
    s->n_edbc = 0;
    if (cfg->edbc == EDBC_OFF || (cfg->edbc == EDBC_WITH_ETA0 && s->eta != 0)) return;
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
    s->n_edbc = n;
}

int control_eta_switch(solver *s, double eps_v1, char *detail, size_t detail_len)
{
    if (s->cfg->scheme != SCHEME_DELTA_PLUS_ALE) return 0;
    double threshold = s->cfg->eta_threshold;
    int eta = s->eta;
    if (eps_v1 > threshold)
        eta = 1;
    else if (eps_v1 < -threshold)
        eta = 0;
    if (eta == s->eta) return 0;
    snprintf(detail, detail_len, "eta %d -> %d at eps_v1 = %.4g (threshold %g)", s->eta, eta,
             eps_v1, threshold);
    s->eta = eta;
    return 1;
}
