/* passes: the preparation of a step (solver_prepare after the neighbour lists) as a list of
 * passes, each with the fields it reads and writes; the wall ghosts are refreshed between
 * passes, in one place, when a pass is about to read what an earlier one changed. */
#ifndef VCSPH_PASSES_H
#define VCSPH_PASSES_H

#include "scheme/solver.h"

#define passes_prepare        DIM_NAME(passes_prepare)
#define passes_prepare_writes DIM_NAME(passes_prepare_writes)

/* The geometry and free surface, the eta control, EdBC, the shifting, the volume correction,
 * bounce-back, the frozen terms and the surface-tension force of stage 0, for the state at
 * s->t on the neighbour lists just built, in the tank frame of s->t. Returns 0, or -1 when out
 * of memory. */
int passes_prepare(solver *s, const tank_frame *frame);

/* The fields the passes may write (FIELD_MASK): never x, since the passes, the outputs and
 * the first stage read the rows' near parts, valid where the lists were built
 * (solver_prepared_rows). */
uint64_t passes_prepare_writes(void);

#endif
