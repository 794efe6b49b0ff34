/* cells_scan: the candidates of one run of cells tested against the search radius, for
 * neighbours_build (core/cells.c), in SIMD blocks where the processor has them. */
#ifndef VCSPH_CELLS_SCAN_H
#define VCSPH_CELLS_SCAN_H

#include "core/cells.h"
#include "core/vec.h"

/* Appends to row (from entry `found`, at most `cap` entries stored) the binned particles
 * item[first .. last) other than `self` that lie within sqrt(r2max) of xi, in item order, and
 * returns the new count (which goes on counting past `cap`: an overflowing row is redone).
 * Reads the positions from the grid's copy in item order (cell_grid.xs). */
typedef int32_t (*cells_scan_fn)(const cell_grid *g, size_t first, size_t last, vec xi,
                                 uint32_t self, double r2max, int32_t *row, int32_t found,
                                 int32_t cap);

#define cells_scan_form DIM_NAME(cells_scan_form)

/* The form for the processor and core/lanes_switch.h's limit: eight candidates at a time with
 * AVX-512, four with AVX2, one by one otherwise. All find the same neighbours in the same
 * order (the squared distance is added as vec_norm2 adds it). */
cells_scan_fn cells_scan_form(void);

#endif
