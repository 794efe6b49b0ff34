/* arrays: the large per-particle arrays (the particle store's fields, the RK4 work arrays and
 * rates), each starting its own cache line past a page boundary. glibc gives a block of
 * ARRAY_STAGGERED bytes or more pages of its own, so without this every such array of a run
 * of more than 16,384 particles starts at the same offset in its page: the same particle's
 * entries of all of them fall into one set of the L1 cache (64 sets of 8 lines) and alias one
 * another in the processor's 4 KiB store-to-load check. Smaller arrays come from the heap at
 * offsets of its own and are left there (a page of alignment each would cost 20 bytes a
 * particle at 7,560 particles). docs/performance.md gives what it measured. */
#ifndef VCSPH_ARRAYS_H
#define VCSPH_ARRAYS_H

#include <stdlib.h>
#include <string.h>

#define ARRAY_PAGE      4096
#define ARRAY_LINE      64
#define ARRAY_STAGGERED (128 * 1024) /* glibc's mmap threshold at start */

/* How far past a page boundary array number k of `bytes` bytes starts: k cache lines, modulo
 * a page, for a large array; 0 (where the heap puts it) for a small one. The numbers:
 * core/particles.c's for the store's fields, scheme/solver.c's for the work arrays after them;
 * arrays read in the same loop should have different ones. */
static inline size_t array_page_offset(int k, size_t bytes)
{
    return bytes >= ARRAY_STAGGERED ? (size_t)k * ARRAY_LINE % ARRAY_PAGE : 0;
}

/* Frees array number k, a, of `bytes` bytes (array_grow's, with the size it was given; NULL:
 * nothing). */
static inline void array_free(void *a, size_t bytes, int k)
{
    if (a) free((char *)a - array_page_offset(k, bytes));
}

/* Grows array number k, *a, from `old` bytes to `bytes`, keeping the first `kept` (at most
 * both) and zeroing the rest (a NULL *a holds nothing). Returns 0, or -1 when out of memory
 * (*a unchanged). */
static inline int array_grow(void **a, size_t old, size_t kept, size_t bytes, int k)
{
    if (kept > bytes) kept = bytes;
    size_t offset = array_page_offset(k, bytes);
    void *block = NULL;
    if (offset ? posix_memalign(&block, ARRAY_PAGE, bytes + offset) != 0
               : (block = malloc(bytes ? bytes : 1)) == NULL)
        return -1;
    char *grown = (char *)block + offset;
    if (*a) memcpy(grown, *a, kept);
    array_free(*a, old, k);
    memset(grown + kept, 0, bytes - kept);
    *a = grown;
    return 0;
}

#endif
