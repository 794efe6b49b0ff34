/* lanes_switch: whether the passes run their four-lane forms (core/lanes.h). */
#ifndef VCSPH_LANES_SWITCH_H
#define VCSPH_LANES_SWITCH_H

#include <stdbool.h>

/* Whether the passes run their lane forms: the processor has 256-bit registers (AVX2,
 * x86-64-v3) and they have not been turned off. The build's baseline (x86-64-v2, SSE) would
 * split every lane operation in two and run slower than scalar code, so a pass compiles its
 * lane form with LANES_TARGET and runs it only where this holds. Both forms give the same bits;
 * lanes_turn_off lets the tests (and a user who doubts it: VCSPH_NO_LANES=1 in the
 * environment) run the scalar form to compare. */
bool lanes_in_use(void);
void lanes_turn_off(bool off);
#define LANES_TARGET __attribute__((target("arch=x86-64-v3")))

#endif
