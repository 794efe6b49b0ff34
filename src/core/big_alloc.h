/* big_alloc: the allocation of the arrays that grow with the particles (the store's fields, the
 * neighbour rows, the cell grid, the RK4 and work arrays). Beyond a few MiB each such array is
 * offered to the kernel for transparent huge pages (madvise MADV_HUGEPAGE; Debian's default
 * mode is "madvise", which backs only the ranges a program asks for): the passes stream a few
 * dozen arrays side by side, each page of each a translation to look up, and a 2D tank of 1e6
 * particles took about a fifth longer a step with 4 KiB pages (docs/performance.md). Free
 * with free(). Where the kernel has no huge pages, or they are off, nothing changes. */
#ifndef VCSPH_BIG_ALLOC_H
#define VCSPH_BIG_ALLOC_H

#include <stddef.h>

/* malloc(bytes), and the block's whole huge pages advised. */
void *big_malloc(size_t bytes);
/* realloc(block, bytes), and the new block's whole huge pages advised. */
void *big_realloc(void *block, size_t bytes);

#endif
