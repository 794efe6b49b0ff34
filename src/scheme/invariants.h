/* invariants: what must hold of a run's state after a step's preparation (bounce-back done,
 * the rows built), checked in the debug build (core/invariant.h): every fluid particle's
 * state finite, its density and mass positive, its position inside the tank; every row's
 * entries other particles of the store; on one process, the liquid's total mass the one it
 * started the check with (mass moves between particles, never in or out). */
#ifndef VCSPH_INVARIANTS_H
#define VCSPH_INVARIANTS_H

#include "scheme/solver.h"

#include <stddef.h>

#define solver_invariants_broken DIM_NAME(solver_invariants_broken)
#define solver_check_invariants  DIM_NAME(solver_check_invariants)

/* Relative change of the total mass that breaks it: mass moves between particles by pair terms
 * equal and opposite, so the total keeps to round-off (the time series' mass_err, measured: at
 * most 1.3e-14 over INM1, INM2 and UPM runs of 4 to 26 s at N = 25); 1e-9 leaves room for
 * many times longer runs. */
#define INVARIANT_MASS_TOLERANCE 1e-9

/* 0 when every invariant holds of s; else 1, with what broke first in `what`. mass_reference 0:
 * the total mass is not checked. */
int solver_invariants_broken(const solver *s, double mass_reference, char *what, size_t size);

/* Stops the run (invariant_broken) when one breaks; the first call takes the total mass of
 * one process's liquid as the reference. Does nothing unless INVARIANTS_ON. */
void solver_check_invariants(solver *s);

#endif
