/* team_loop: a parallel loop over the fluid in which each thread takes its static share (the
 * share `schedule(static)` would give it, to within a chunk), front to back, and a thread that
 * has finished its own takes what is left of the others' shares from their backs, a chunk at a
 * time. A particle stays with the thread, and the core's cache, that every pass of the step
 * gives it, except the tail that a thread slowed down for a moment (a virtual core, another
 * process) would otherwise leave the others waiting for at the loop's end. A loop whose
 * particles each compute and write only their own entries (docs/architecture.md, "Gather, not
 * scatter") gives the same bits whichever thread takes a chunk.
 *
 *     TEAM_FOR (i, n) { ... }               a parallel loop over i = 0 .. n - 1
 *
 * or, where the body takes the chunks' items itself (a multiple of `chunk` from the start):
 *
 *     TEAM_LOOP_SHARES(q, n, chunk);         before the parallel region: the loop over n items
 *     #pragma omp parallel
 *     TEAM_LOOP_FOR (&q, begin, end) { ... items begin .. end - 1 ... }
 *
 * Each share is one 64-bit word on a cache line of its own, its first and last chunk not yet
 * taken: the owner takes the first with a compare-and-swap on a line in its own cache, a thief
 * the last; the two meet without taking a chunk twice. */
#ifndef VCSPH_TEAM_LOOP_H
#define VCSPH_TEAM_LOOP_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif

typedef struct {
    _Alignas(64) uint64_t range; /* the chunks [front, back): front in the low 32 bits */
} team_share;

typedef struct {
    team_share *shares;
    int threads;
    size_t n, chunk;
} team_loop;

/* A thread's way through the loop: its own share, then the others' in turn. */
typedef struct {
    int thread, victim; /* the share it takes from; its own first */
} team_cursor;

static inline uint64_t team_range(uint32_t front, uint32_t back)
{
    return (uint64_t)front | (uint64_t)back << 32;
}

/* The threads a parallel region may have */
static inline int team_loop_threads(void)
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

/* Within a parallel region: this thread's number, and the region's threads */
static inline int team_thread(void)
{
#ifdef _OPENMP
    return omp_get_thread_num();
#else
    return 0;
#endif
}

static inline int team_threads(void)
{
#ifdef _OPENMP
    return omp_get_num_threads();
#else
    return 1;
#endif
}

/* n items in chunks of `chunk`, split into `threads` static shares (shares: room for them). */
static inline void team_loop_init(team_loop *q, team_share *shares, int threads, size_t n,
                                  size_t chunk)
{
    size_t chunks = (n + chunk - 1) / chunk;
    for (int t = 0; t < threads; t++)
        shares[t].range = team_range((uint32_t)(chunks * (size_t)t / (size_t)threads),
                                     (uint32_t)(chunks * (size_t)(t + 1) / (size_t)threads));
    *q = (team_loop){shares, threads, n, chunk};
}

/* Declares the loop q over n items and its shares, in the enclosing block */
#define TEAM_LOOP_SHARES(q, n, chunk)                                                              \
    team_loop q;                                                                                   \
    team_share q##_shares[team_loop_threads()];                                                    \
    team_loop_init(&(q), q##_shares, team_loop_threads(), (n), (chunk))

static inline team_cursor team_cursor_start(const team_loop *q)
{
    (void)q;
    return (team_cursor){team_thread(), team_thread()};
}

/* Takes a chunk from the front of share s (own) or its back (another's); false if none is
 * left there. */
static inline bool team_take(team_share *s, bool own, uint32_t *chunk)
{
    uint64_t old = __atomic_load_n(&s->range, __ATOMIC_ACQUIRE);
    for (;;) {
        uint32_t front = (uint32_t)old, back = (uint32_t)(old >> 32);
        if (front >= back) return false;
        uint64_t next = own ? team_range(front + 1, back) : team_range(front, back - 1);
        if (__atomic_compare_exchange_n(&s->range, &old, next, false, __ATOMIC_ACQ_REL,
                                        __ATOMIC_ACQUIRE)) {
            *chunk = own ? front : back - 1;
            return true;
        }
    }
}

/* The next items [*begin, *end) for the cursor's thread; false when the loop is done. */
static inline bool team_loop_next(team_loop *q, team_cursor *c, size_t *begin, size_t *end)
{
    for (;;) {
        uint32_t k;
        if (team_take(&q->shares[c->victim], c->victim == c->thread, &k)) {
            *begin = (size_t)k * q->chunk;
            *end = *begin + q->chunk < q->n ? *begin + q->chunk : q->n;
            return true;
        }
        c->victim = (c->victim + 1) % q->threads;
        if (c->victim == c->thread) return false;
    }
}

#define TEAM_LOOP_FOR(q, begin, end)                                                               \
    for (team_cursor begin##_cursor = team_cursor_start(q), *begin##_on = &begin##_cursor;         \
         begin##_on; begin##_on = NULL)                                                            \
        for (size_t begin = 0, end = 0; team_loop_next((q), &begin##_cursor, &begin, &end);)

/* Particles a chunk: eight blocks of eight lanes, 512 bytes of a field, whole cache lines */
#define TEAM_CHUNK 64

/* `#pragma omp parallel for schedule(static)` over i = 0 .. n - 1 as a team loop. It declares
 * the shares (i_shares, i_q) in the enclosing block, so one block holds one such loop per name
 * i. No reduction clause: a loop that reduces keeps its own pragma. */
#define TEAM_FOR(i, n)                                                                             \
    TEAM_LOOP_SHARES(i##_q, (n), TEAM_CHUNK);                                                      \
    _Pragma("omp parallel")                                                                        \
        TEAM_LOOP_FOR (&i##_q, i##_begin, i##_end) for (size_t i = i##_begin; i < i##_end; i++)

#endif
