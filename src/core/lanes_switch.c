/* lanes_switch: whether the passes run their lane forms (core/lanes.h). */
#include "core/lanes_switch.h"

#include <stdlib.h>

static int lanes_off = -1; /* -1: not decided yet */

bool lanes_in_use(void)
{
    if (lanes_off < 0) {
        const char *env = getenv("VCSPH_NO_LANES");
        lanes_off = env && *env && *env != '0';
    }
    return !lanes_off && __builtin_cpu_supports("x86-64-v3");
}

void lanes_turn_off(bool off) { lanes_off = off; }
