/* health: detection of a numerical breakdown (docs/architecture.md): a NaN, a particle outside the
 * tank, or a density outside rho0 (1 +- numerics.density_bound), 0.2 unless the case says. */
#ifndef VCSPH_HEALTH_H
#define VCSPH_HEALTH_H

#include "boundary/tank.h"
#include "core/particles.h"

#include <stddef.h>

#define health_check DIM_NAME(health_check)

/* What a sound particle stays within. */
typedef struct {
    const tank *tank;
    double rho0, density_bound; /* rho in rho0 (1 +- density_bound) */
} health_limits;

/* Returns 0 when every fluid particle is sound; otherwise 1 and a message naming the first
 * bad particle (lowest index, so the same for any thread count), the time t and the step. */
int health_check(const particles *p, const health_limits *lim, double t, long step, char *msg,
                 size_t msg_len);

#endif
