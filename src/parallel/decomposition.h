/* decomposition: how the tank is split among MPI processes (docs/mpi.md). Each process owns a
 * slab of whole strips of cells along x. core/cells.c numbers the cells strip by strip, so
 * the particles of a slab, sorted by cell, are one contiguous range of the global order,
 * which is the same for any number of processes: that is what lets a run give the same bytes
 * on 1 or P processes. Dimension-free: it sees only the particle count of each strip. */
#ifndef VCSPH_DECOMPOSITION_H
#define VCSPH_DECOMPOSITION_H

#include <stddef.h>

/* Splits the strips 0 .. n_strips - 1, whose particle counts are count[], into n_ranks
 * consecutive slabs of at least one strip each: rank r owns strips first[r] .. first[r+1] - 1
 * (first[0] = 0, first[n_ranks] = n_strips). Among all such splits it returns one whose
 * largest slab holds the fewest particles: the one that filling the slabs from the left, each
 * with as many strips as that bound allows, gives, so that the same counts always give the
 * same split. Sloshing carries the liquid
 * from one end of the tank to the other every period; calling this again with the counts of
 * the moment moves the boundaries with it. Returns 0, or -1 when there are fewer strips than
 * ranks (the case is too small for that many processes). */
int decomposition_balance(const size_t *count, size_t n_strips, int n_ranks, size_t *first);

/* The largest slab of a split: the particles of the busiest process. */
size_t decomposition_largest(const size_t *count, int n_ranks, const size_t *first);

#endif
