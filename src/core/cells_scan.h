/* cells_scan: the candidates of one run of cells tested against the search radius, for
 * neighbours_build (core/cells.c), in SIMD blocks where the processor has them. */
#ifndef VCSPH_CELLS_SCAN_H
#define VCSPH_CELLS_SCAN_H

#include "core/cells.h"
#include "core/vec.h"

/* One row as the scan finds it, in two parts: the neighbours within the kernel's support
 * (squared distance below near2) and those in the skin beyond it (below r2max), each in item
 * order; each part holds at most `cap` entries and its count goes on past `cap` (an
 * overflowing row is redone). */
typedef struct {
    int32_t *near, *skin;
    int32_t n_near, n_skin, cap;
    double near2, r2max;
} scan_row;

/* Appends to the row the binned particles item[first .. last) other than `self` that lie
 * within sqrt(r2max) of xi, in item order, to the part their distance puts them in. Reads the
 * positions from the grid's copy in item order (cell_grid.xs). */
typedef void (*cells_scan_fn)(const cell_grid *g, size_t first, size_t last, vec xi, uint32_t self,
                              scan_row *row);

#define cells_scan_form DIM_NAME(cells_scan_form)

/* The form for the processor and core/lanes_switch.h's limit: eight candidates at a time with
 * AVX-512, four with AVX2, one by one otherwise. All find the same neighbours in the same
 * order and parts (the squared distance is added as vec_norm2 adds it, so that a pair loop at
 * the positions of the build finds a pair within 2h where the scan does, to the bit). */
cells_scan_fn cells_scan_form(void);

#endif
