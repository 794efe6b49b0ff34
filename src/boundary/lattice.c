/* lattice: the initial particles (sec. 2.1). */
#include "boundary/lattice.h"
#include "physics/eos.h"

int lattice_fill(particles *p, const config *cfg, const derived *dv, size_t first, size_t end)
{
    size_t n = (size_t)dv->n_fluid, kept = 0;
    /* room for the fluid, and the images' head-room in the fields they hold */
    if (first > end || end > n || particles_reserve(p, end - first) ||
        particles_reserve_images(p, particles_initial_room(end - first)))
        return -1;
    double cell_volume = dv->cell_volume;
    /* the hydrostatic pressure below the top of the liquid box, whatever its shape (with
       gravity 0, the droplet tests, it is 0) */
    double surface = cfg->liquid_y0 + cfg->liquid_height;
    size_t i = 0;
    for (long c2 = 0; c2 < (DIM == 3 ? dv->n_axis[2] : 1); c2++)
        for (long c1 = 0; c1 < dv->n_axis[1]; c1++)
            for (long c0 = 0; c0 < dv->n_axis[0]; c0++) {
                double x[3];
                /* the predicate derived_compute counted n_fluid with */
                if (!derived_lattice_point(cfg, dv, c0, c1, c2, x)) continue;
                if (i == n) return -1; /* cannot happen: the count is the same loop */
                size_t index = i++;    /* the point's place in the lattice order: its id */
                if (index < first || index >= end) continue;
                size_t k = kept++;
                for (int d = 0; d < DIM; d++) {
                    p->x[d][k] = x[d];
                    p->u[d][k] = 0.0;
                }
                double pressure = cfg->density * cfg->gravity * (surface - p->x[1][k]);
                p->rho[k] = eos_density(pressure, cfg->density, dv->c0);
                p->p[k] = pressure;
                p->m[k] = p->rho[k] * cell_volume;
                p->vol[k] = p->m[k] / p->rho[k];
                p->id[k] = (int64_t)index;
            }
    if (i != n) return -1;
    p->n_fluid = p->n_total = kept;
    return 0;
}
