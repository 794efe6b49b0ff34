/* loads: the walls' share of the momentum equation, summed over the liquid (loads.h). */
#include "scheme/loads.h"
#include "core/reduce.h"
#include "scheme/momentum.h"

#include <stdlib.h>

/* The force per unit volume of particle i's wall images on it. */
static inline vec wall_force_density(const physics_params *pp, const particles *p,
                                     const neighbour_list *nl, size_t i, const bool les,
                                     const bool ale)
{
    momentum_particle mi = momentum_particle_of(pp, p, i);
    vec xi = vec_load(p->x, i), force = vec_zero();
    pair pr;
    FOR_EACH_PAIR (&pp->k, p->x, nl, i, xi, pr)
        if (particle_is_wall_image(p, pr.j))
            force = momentum_pair_add(force, pp, p, &mi, &pr, les, ale);
    return force;
}

enum { COLUMNS = 12 }; /* force, moment, momentum, body force: 3 each, per particle */

int loads_compute(const physics_params *pp, const particles *p, const neighbour_list *nl,
                  const tank_frame *frame, const reducer *r, tank_loads *out)
{
    size_t n = p->n_fluid;
    double *column = malloc(COLUMNS * (n ? n : 1) * sizeof *column);
    if (!column) return -1;
    const bool les = pp->les, ale = pp->shifting;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) {
        vec f = wall_force_density(pp, p, nl, i, les, ale);
        vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
        vec body = frame_body_force(frame, xi, ui);
        double row[COLUMNS] = {0.0}, arm[3] = {0.0, 0.0, 0.0};
        for (int d = 0; d < DIM; d++) {
            row[d] = -p->vol[i] * f.c[d]; /* on the tank: minus the walls' force on the liquid */
            arm[d] = xi.c[d] - frame->center[d];
            row[6 + d] = p->m[i] * ui.c[d];
            row[9 + d] = p->m[i] * body.c[d];
        }
        frame_cross(arm, row, row + 3);
        for (int c = 0; c < COLUMNS; c++) column[c * n + i] = row[c];
    }
    double sum[COLUMNS];
    for (int c = 0; c < COLUMNS; c++) sum[c] = reducer_sum(r, column + c * n, n);
    free(column);
    for (int d = 0; d < 3; d++) {
        out->force[d] = sum[d];
        out->moment[d] = sum[3 + d];
        out->momentum[d] = sum[6 + d];
        out->body[d] = sum[9 + d];
    }
    return 0;
}
