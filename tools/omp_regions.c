/* omp_regions: a shared library for LD_PRELOAD (tools/omp-regions builds and loads it) that
 * times every OpenMP parallel region of a run, by wrapping libgomp's entry GOMP_parallel,
 * which GCC calls for each `#pragma omp parallel`: the wall time of each region, summed per
 * outlined function (the region's code), and the time between one region's end and the next
 * one's start, summed per pair of regions: there only the main thread works (serial code).
 * Writes at exit to $OMP_REGIONS_OUT, one line a record, addresses as offsets in their
 * object (for nm):
 *     region OFFSET CALLS SECONDS
 *     gap OFFSET_BEFORE OFFSET_AFTER COUNT SECONDS      (gaps under GAP_MAX only)
 *     long_gaps COUNT SECONDS                           (set-up, output, ...)  */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef void (*gomp_parallel_fn)(void (*)(void *), void *, unsigned, unsigned);

#define SLOTS   4096 /* open addressing: far more than a run's distinct regions and pairs */
#define GAP_MAX 0.01 /* s: a longer gap is the run's set-up or output, not a step's */

typedef struct {
    void *fn, *before; /* a region: before = NULL; a gap: the regions around it */
    long count;
    double seconds;
} slot;

static slot slots[SLOTS];
static void *previous;
static double previous_end, long_gap_seconds;
static long long_gaps;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void add(void *before, void *fn, double seconds)
{
    size_t h = (((uintptr_t)fn >> 4) * 31u + ((uintptr_t)before >> 4)) % SLOTS;
    while (slots[h].fn && !(slots[h].fn == fn && slots[h].before == before)) h = (h + 1) % SLOTS;
    slots[h].fn = fn;
    slots[h].before = before;
    slots[h].count++;
    slots[h].seconds += seconds;
}

void GOMP_parallel(void (*fn)(void *), void *data, unsigned threads, unsigned flags)
{
    static gomp_parallel_fn real;
    if (!real) real = (gomp_parallel_fn)dlsym(RTLD_NEXT, "GOMP_parallel");
    double start = now();
    if (previous) {
        double gap = start - previous_end;
        if (gap < GAP_MAX) {
            add(previous, (void *)fn, gap);
        } else {
            long_gaps++;
            long_gap_seconds += gap;
        }
    }
    real(fn, data, threads, flags);
    previous_end = now();
    add(NULL, (void *)fn, previous_end - start);
    previous = (void *)fn;
}

static unsigned long offset(void *address)
{
    Dl_info info;
    if (!dladdr(address, &info)) return (unsigned long)(uintptr_t)address;
    return (unsigned long)((char *)address - (char *)info.dli_fbase);
}

__attribute__((destructor)) static void write_records(void)
{
    const char *path = getenv("OMP_REGIONS_OUT");
    FILE *out = path ? fopen(path, "w") : NULL;
    if (!out) return;
    for (size_t h = 0; h < SLOTS; h++) {
        const slot *s = &slots[h];
        if (!s->fn) continue;
        if (s->before)
            fprintf(out, "gap %lx %lx %ld %.9f\n", offset(s->before), offset(s->fn), s->count,
                    s->seconds);
        else
            fprintf(out, "region %lx %ld %.9f\n", offset(s->fn), s->count, s->seconds);
    }
    fprintf(out, "long_gaps %ld %.9f\n", long_gaps, long_gap_seconds);
    fclose(out);
}
