/* invariant: a broken run-time invariant of the debug build (invariant.h). */
#include "core/invariant.h"

#include <stdlib.h>

void invariant_broken(const char *where, const char *what)
{
    fprintf(stderr, "vcsph: invariant broken in %s: %s\n", where, what);
    fflush(stderr);
    abort();
}
