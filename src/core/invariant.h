/* invariant: the checks of the debug build (cmake -DVCSPH_CHECKS=ON, which `make sanitize`
 * turns on): conditions the code relies on, checked at run time where they are cheap to state
 * and expensive to assume. In the release build INVARIANTS_ON is 0 and the checks compile
 * away. A broken invariant stops the run at once with where and what. */
#ifndef VCSPH_INVARIANT_H
#define VCSPH_INVARIANT_H

#include <stdio.h>

#ifdef VCSPH_CHECKS
#define INVARIANTS_ON 1
#else
#define INVARIANTS_ON 0
#endif

/* Prints "vcsph: invariant broken in <where>: <what>" on stderr and aborts. */
_Noreturn void invariant_broken(const char *where, const char *what);

#endif
