/* lanes_switch: how many lanes the passes' lane forms run (core/lanes.h). */
#include "core/lanes_switch.h"

#include <stdlib.h>

/* -1: not read from the environment yet. Read and written atomically: the passes ask from
   inside their parallel loops (core/pair.c), so the first question may come from two threads. */
static int lanes_widest = -1;

/* VCSPH_NO_LANES=1: the scalar form; VCSPH_LANES=0, 4 or 8: at most that many lanes */
static int lanes_allowed(void)
{
    int widest = __atomic_load_n(&lanes_widest, __ATOMIC_RELAXED);
    if (widest < 0) {
        const char *off = getenv("VCSPH_NO_LANES"), *width = getenv("VCSPH_LANES");
        widest = 8;
        if (width && *width) widest = atoi(width);
        if (off && *off && *off != '0') widest = 0;
        __atomic_store_n(&lanes_widest, widest, __ATOMIC_RELAXED);
    }
    return widest;
}

int lanes_width(void)
{
    int widest = lanes_allowed();
    if (widest >= 8 && __builtin_cpu_supports("x86-64-v4")) return 8;
    if (widest >= 4 && __builtin_cpu_supports("x86-64-v3")) return 4;
    return 0;
}

void lanes_limit(int widest) { __atomic_store_n(&lanes_widest, widest, __ATOMIC_RELAXED); }
