/* bodies: the bodies of liquid of the step, as the connected pieces of the band S_F (its
 * particles connected when within 2h). Found once per step, after the geometry, for the
 * passes that act on a body as a whole: surface tension removes each free body's net force
 * and moment, the volume correction moves each body's surface at one normal speed. */
#ifndef VCSPH_BODIES_H
#define VCSPH_BODIES_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/particles.h"
#include <stdbool.h>
#include <stdint.h>

typedef struct {
    size_t capacity; /* particles */
    /* union-find over the fluid and the halo, each root its set's smallest index */
    int32_t *parent;
    /* each S_F particle's body (the halo's too), 0 .. count - 1 in the order of the bodies'
       first particles; -1 inside */
    int32_t *id;
    uint8_t *at_wall; /* per body: a wall's ghost is within 2h of its surface */
    size_t count;     /* bodies of the step */
    /* the fluid's S_F particles of the step in index order: the per-body folds and loops go
       through these and not the whole fluid (their order, and so their sums, the same) */
    int32_t *members;
    size_t n_members, members_capacity;
} bodies;

/* i over the step's S_F particles of this process's fluid (b->members), in index order */
#define FOR_EACH_MEMBER(b, i)                                                                      \
    for (size_t i##_k = 0, i = 0;                                                                  \
         i##_k < (b)->n_members && (i = (size_t)(b)->members[i##_k], true); i##_k++)

/* Adds this process's particles' shares, in index order, to sums[id * width + c] of each
 * body. */
typedef void (*bodies_fold)(void *context, double *sums);

/* A liquid split among processes (the MPI build's parallel/mpi_domain.h): bodies that span
 * processes, numbered and summed as on one process. NULL: one process. */
typedef struct bodies_domain {
    /* After bodies_find on every process: joins the bodies across the processes, renumbers
       them globally (b->id of the fluid and the halo, b->count, b->at_wall). */
    void (*join)(const struct bodies_domain *d, const particles *p, bodies *b);
    /* The per-body sums of the whole liquid, as bodies_sum on one process: every process
       gets the totals of its bodies. */
    void (*sum)(const struct bodies_domain *d, const particles *p, const bodies *b, double *sums,
                int width, bodies_fold fold, void *context);
    /* Copies this process's values of a per-particle array (not a registry field: a work
       array of a pass) into the other processes' halos, values[n_fluid .. + n_halo). */
    void (*share)(const struct bodies_domain *d, const particles *p, double *values);
    void *context;
} bodies_domain;

/* The halo's values of a work array, through d (NULL: one process, no halo). */
static inline void bodies_share(const bodies_domain *d, const particles *p, double *values)
{
    if (d) d->share(d, p, values);
}

#define bodies_reserve DIM_NAME(bodies_reserve)
#define bodies_sum     DIM_NAME(bodies_sum)
#define bodies_root    DIM_NAME(bodies_root)
#define bodies_find    DIM_NAME(bodies_find)
#define bodies_free    DIM_NAME(bodies_free)

/* Makes room for n particles. Returns 0, or -1 when out of memory. */
int bodies_reserve(bodies *b, size_t n);
void bodies_free(bodies *b);

/* The bodies of the step's S_F (p->surface), joined across processes through d (NULL: one
 * process), and their members. The sets are united in parallel, in any order: the connected
 * pieces, and each one's least index (the root), are the same for any order; the numbering
 * that follows is serial and in index order, so it does not depend on the thread count.
 * Returns 0, or -1 when out of memory. */
int bodies_find(const kernel *k, const particles *p, const neighbour_list *nl,
                const bodies_domain *d, bodies *b);

/* The root of particle i's set in the union-find of the last bodies_find (fluid or halo). */
int32_t bodies_root(bodies *b, int32_t i);

/* sums[b->count * width] of fold's shares, each body's sum taken in the order of the
 * particles from 0 (on one process: zeroed, then fold). The sums therefore do not depend on
 * the number of processes or threads. */
void bodies_sum(const bodies_domain *d, const particles *p, const bodies *b, double *sums,
                int width, bodies_fold fold, void *context);

#endif
