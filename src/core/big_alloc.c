/* big_alloc: arrays that grow with the particles, on huge pages where the kernel has them. */
/* madvise's MADV_HUGEPAGE is Linux's, beyond the X/Open interface the build asks for */
#define _DEFAULT_SOURCE
#include "core/big_alloc.h"

#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>

/* The transparent huge page of x86-64 (and of arm64 with 4 KiB pages). */
#define HUGE_PAGE ((uintptr_t)2 << 20)
/* Smaller blocks are left to malloc as they are: a block must hold whole huge pages to gain,
 * and a small one would round the process's memory up for nothing. */
#define BIG_BLOCK (2 * HUGE_PAGE)

/* Advises the whole huge pages inside [block, block + bytes); the advice is only a hint, so
 * its failure (no huge pages in this kernel) is no error. */
static void *advised(void *block, size_t bytes)
{
#ifdef MADV_HUGEPAGE
    if (block && bytes >= BIG_BLOCK) {
        uintptr_t first = ((uintptr_t)block + HUGE_PAGE - 1) & ~(HUGE_PAGE - 1);
        uintptr_t end = ((uintptr_t)block + bytes) & ~(HUGE_PAGE - 1);
        if (end > first) (void)madvise((void *)first, end - first, MADV_HUGEPAGE);
    }
#endif
    return block;
}

void *big_malloc(size_t bytes) { return advised(malloc(bytes), bytes); }

void *big_realloc(void *block, size_t bytes) { return advised(realloc(block, bytes), bytes); }
