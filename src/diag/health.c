/* health: breakdown detection. */
#include "diag/health.h"

#include <stdint.h>
#include <stdio.h>

typedef enum { SOUND, NOT_FINITE, OUTSIDE, DENSITY } verdict;

static verdict particle_verdict(const particles *p, const health_limits *lim, size_t i)
{
    for (int d = 0; d < DIM; d++)
        if (!isfinite(p->x[d][i]) || !isfinite(p->u[d][i])) return NOT_FINITE;
    if (!isfinite(p->rho[i]) || !isfinite(p->m[i])) return NOT_FINITE;
    if (!tank_contains(lim->tank, vec_load(p->x, i))) return OUTSIDE;
    double rho0 = lim->rho0, bound = lim->density_bound;
    if (p->rho[i] < rho0 * (1.0 - bound) || p->rho[i] > rho0 * (1.0 + bound)) return DENSITY;
    return SOUND;
}

int health_check(const particles *p, const health_limits *lim, double t, long step, char *msg,
                 size_t msg_len)
{
    size_t first = SIZE_MAX;
#pragma omp parallel for schedule(static) reduction(min : first)
    for (size_t i = 0; i < p->n_fluid; i++)
        if (i < first && particle_verdict(p, lim, i) != SOUND) first = i;
    if (first == SIZE_MAX) return 0;
    size_t i = first;
    int len = snprintf(msg, msg_len, "breakdown at t = %.9g s, step %ld: particle id %lld ", t,
                       step, (long long)p->id[i]);
    if (len < 0 || (size_t)len >= msg_len) return 1;
    char *rest = msg + len;
    size_t room = msg_len - (size_t)len;
    switch (particle_verdict(p, lim, i)) {
    case NOT_FINITE: snprintf(rest, room, "has a non-finite position, velocity or density"); break;
    case OUTSIDE: {
        int k = snprintf(rest, room, "left the tank (at");
        for (int d = 0; d < DIM && k > 0 && (size_t)k < room; d++)
            k += snprintf(rest + k, room - (size_t)k, " %.6g", p->x[d][i]);
        if (k > 0 && (size_t)k < room) snprintf(rest + k, room - (size_t)k, " m)");
        break;
    }
    case DENSITY:
        snprintf(rest, room,
                 "has density %.6g kg/m^3, outside rho0 (1 +- %g) (numerics.density_bound)",
                 p->rho[i], lim->density_bound);
        break;
    case SOUND: break;
    }
    return 1;
}
