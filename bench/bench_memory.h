/* bench_memory: the bytes a solver holds per fluid particle (particle store, RK work arrays,
 * neighbour lists, cell grid), shared by the benchmarks. Include after scheme/solver.h with
 * DIM set. */
#ifndef VCSPH_BENCH_MEMORY_H
#define VCSPH_BENCH_MEMORY_H

#include "scheme/solver.h"

static double bytes_per_particle(const solver *s)
{
    const particles *p = &s->p;
    /* the double arrays of particles.c, the id, ghost source and walls, surface flags */
    double store = (double)particles_bytes_per_slot() * (double)p->capacity;
    /* y0, sum and the rates; the masses' three only once they have varied (solver.h) */
    double rk = 2.0 * RK_VARS + PARTICLE_N_RATED - (s->k.dm ? 0.0 : 3.0);
    double work =
        (rk + 1.0) * sizeof(double) * (double)p->n_fluid + sizeof(uint32_t) * (double)p->n_fluid;
    double lists = (double)s->nl.index_capacity * sizeof(int32_t) +
                   (double)s->nl.capacity_rows * sizeof(int32_t);
    double cells = (double)s->grid.item_capacity * (2.0 * sizeof(uint32_t) + DIM * sizeof(double)) +
                   (double)s->grid.cells_capacity * sizeof(size_t);
    return (store + work + lists + cells) / (double)p->n_fluid;
}

#endif
