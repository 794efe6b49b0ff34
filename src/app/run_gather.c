/* run_gather: a split run's fluid brought together on the process that writes the files
 * (run_state.h, run_gather). Particle code: compiled for DIM = 2 and 3. */
#include "app/run_state.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The fields the probes read, and those tank_make_ghosts and tank_refresh_ghosts read to
 * make the walls' images the probes read. */
static bool probe_field(const char *snapshot)
{
    static const char *const names[] = {"id",      "position", "velocity", "pressure",
                                        "density", "mass",     "volume"};
    for (size_t k = 0; snapshot && k < sizeof names / sizeof names[0]; k++)
        if (!strcmp(snapshot, names[k])) return true;
    return false;
}

/* Whether run_gather brings a field of the registry (core/particles.h) for `which`. */
static bool gathered(const run *r, uint64_t flags, const char *snapshot, run_gather_kind which)
{
    if (which == RUN_GATHER_STATE) return flags & FIELD_STATE;
    if (which == RUN_GATHER_POSITIONS) return snapshot && !strcmp(snapshot, "position");
    if (which == RUN_GATHER_PROBES) return probe_field(snapshot);
    return snapshot && (r->s.pp.surface_tension || !(flags & FIELD_SURFACE_TENSION));
}

/* Every process's n elements of component d of field `field`, on the process that writes, in
 * the store's layout (NULL on the others). */
static void *gathered_field(const run_team *t, int field, int d, const void *mine, size_t n,
                            size_t size, size_t *n_total)
{
    void *all = t->gather(t, mine, n, size, n_total);
    void *copy = particles_field_copy(field, d, all, *n_total, size);
    free(all);
    return copy;
}

void run_gather(const run *r, const particles *p, run_gather_kind which, particles *whole)
{
    const run_team *t = r->team;
    if (!r->split) {
        *whole = *p;
        return;
    }
    memset(whole, 0, sizeof *whole);
    size_t n = 0;
    /* each gathered array copied into the store's layout (particles_field_copy), which
       run_gathered_free and rebuild_whole's particles_reserve expect of every array */
#define GATHER_SCALAR(type, name, flags, snapshot, comment)                                        \
    if (gathered(r, flags, snapshot, which))                                                       \
        whole->name =                                                                              \
            gathered_field(t, FIELD_BIT_##name, 0, p->name, p->n_fluid, sizeof *p->name, &n);
#define GATHER_VECTOR(type, name, flags, snapshot, comment)                                        \
    if (gathered(r, flags, snapshot, which))                                                       \
        for (int d = 0; d < DIM; d++)                                                              \
            whole->name[d] = gathered_field(t, FIELD_BIT_##name, d, p->name[d], p->n_fluid,        \
                                            sizeof *p->name[d], &n);
    PARTICLE_FIELDS(GATHER_SCALAR, GATHER_VECTOR)
    whole->n_fluid = whole->n_total = whole->capacity = whole->sources_capacity = n;
}

void run_gathered_free(const run *r, particles *whole)
{
    if (r->split) particles_free(whole); /* its own copies (no arrays: nothing) */
}
