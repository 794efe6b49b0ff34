/* lanes_switch: how many lanes the passes' lane forms run (core/lanes.h). */
#include "core/lanes_switch.h"

#include <stdlib.h>

static int lanes_widest = -1; /* -1: not read from the environment yet */

/* VCSPH_NO_LANES=1: the scalar form; VCSPH_LANES=0, 4 or 8: at most that many lanes */
static int lanes_allowed(void)
{
    if (lanes_widest < 0) {
        const char *off = getenv("VCSPH_NO_LANES"), *width = getenv("VCSPH_LANES");
        lanes_widest = 8;
        if (width && *width) lanes_widest = atoi(width);
        if (off && *off && *off != '0') lanes_widest = 0;
    }
    return lanes_widest;
}

int lanes_width(void)
{
    int widest = lanes_allowed();
    if (widest >= 8 && __builtin_cpu_supports("x86-64-v4")) return 8;
    if (widest >= 4 && __builtin_cpu_supports("x86-64-v3")) return 4;
    return 0;
}

void lanes_limit(int widest) { lanes_widest = widest; }
