/* lanes_switch: how many lanes the passes' lane forms run (core/lanes.h). */
#ifndef VCSPH_LANES_SWITCH_H
#define VCSPH_LANES_SWITCH_H

/* The widest lane form the processor runs and the user allows: 8 with AVX-512 (x86-64-v4), 4
 * with AVX2 (x86-64-v3), 0 (the scalar form) otherwise. The build's baseline (x86-64-v2, SSE)
 * would split every lane operation and run slower than scalar code, so each width is compiled
 * for its own instruction set and chosen here at run time. Every width gives the same bits;
 * lanes_limit lets the tests (and a user who doubts it: VCSPH_NO_LANES=1 in the environment for
 * the scalar form, VCSPH_LANES=4 for at most four lanes) run the narrower forms to compare. */
int lanes_width(void);
/* At most `widest` lanes from now on (0: the scalar form; 8: as many as the processor has). */
void lanes_limit(int widest);

#endif
