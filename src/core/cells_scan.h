/* cells_scan: the candidates of one run of cells tested against the search radius, for
 * neighbours_build (core/cells.c), in SIMD blocks where the processor has them. */
#ifndef VCSPH_CELLS_SCAN_H
#define VCSPH_CELLS_SCAN_H

#include "core/cells.h"
#include "core/vec.h"

/* One row as the scan finds it: the neighbours in item order and the squared distance of
 * each (by which neighbours_build then puts those within the kernel's support first), at
 * most `cap` of them stored; `found` goes on counting past `cap` (an overflowing row is
 * redone). */
typedef struct {
    int32_t *entries;
    double *r2;
    int32_t found, cap;
} scan_row;

/* Appends to the row the binned particles item[first .. last) other than `self` that lie
 * within sqrt(r2max) of xi, in item order. Reads the positions from the grid's copy in item
 * order (cell_grid.xs). */
typedef void (*cells_scan_fn)(const cell_grid *g, size_t first, size_t last, vec xi, uint32_t self,
                              double r2max, scan_row *row);

/* Lays out the scanned row (`count` entries and their squared distances) in `row`: those below
 * near2 first, then the others, each part in the scanned order; returns the first part's
 * count. `row` and `skin` (work room) hold count + CELLS_SPLIT_SLACK entries: a SIMD form
 * stores whole blocks. */
#define CELLS_SPLIT_SLACK 8
typedef int32_t (*cells_split_fn)(const int32_t *entries, const double *r2, int32_t count,
                                  double near2, int32_t *row, int32_t *skin);

#define cells_scan_form  DIM_NAME(cells_scan_form)
#define cells_split_form DIM_NAME(cells_split_form)

/* The form for the processor and core/lanes_switch.h's limit: eight candidates at a time with
 * AVX-512, four with AVX2, one by one otherwise. All find the same neighbours in the same
 * order with the same squared distances, added as vec_norm2 adds them (so that a pair loop at
 * the positions of the build finds a pair within 2h where the scan does, to the bit). */
cells_scan_fn cells_scan_form(void);
/* The split's form for the processor: eight entries at a time with AVX-512, four with AVX2,
 * one by one otherwise; all give the same rows. */
cells_split_fn cells_split_form(void);

#endif
