/* bench_memory: the bytes a solver holds per fluid particle, shared by the benchmarks: the
 * process's heap in use while the solver is alive (glibc's mallinfo2, over every arena and the
 * large blocks it maps apart), so every array counts: the particle store, the RK4 work arrays,
 * the neighbour lists, the cell grid, surface tension's and the bodies' work arrays, and the
 * little else a run holds. (A sum of the arrays the benchmarks knew of left out surface
 * tension's and the bodies': 59 bytes a particle in 2D and 110 in 3D at 1e5 particles.)
 * Include after scheme/solver.h with DIM set. */
#ifndef VCSPH_BENCH_MEMORY_H
#define VCSPH_BENCH_MEMORY_H

#include "scheme/solver.h"

#include <malloc.h>

/* The process's heap in use, bytes. */
static inline double heap_in_use(void)
{
    struct mallinfo2 heap = mallinfo2();
    return (double)(heap.uordblks + heap.hblkhd);
}

static inline double bytes_per_particle(const solver *s)
{
    return heap_in_use() / (double)s->p.n_fluid;
}

#endif
