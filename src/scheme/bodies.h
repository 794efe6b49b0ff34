/* bodies: the bodies of liquid of the step, as the connected pieces of the band S_F (its
 * particles connected when within 2h). Found once per step, after the geometry, for the
 * passes that act on a body as a whole: surface tension removes each free body's net force
 * and moment, the volume correction moves each body's surface at one normal speed. */
#ifndef VCSPH_BODIES_H
#define VCSPH_BODIES_H

#include "core/cells.h"
#include "core/kernel.h"
#include "core/particles.h"
#include <stdint.h>

typedef struct {
    size_t capacity;  /* particles */
    int32_t *parent;  /* union-find over the fluid, each root the smallest index of its set */
    int32_t *id;      /* each S_F particle's body, 0 .. count - 1 in index order; -1 inside */
    uint8_t *at_wall; /* per body: a wall's ghost is within 2h of its surface */
    size_t count;     /* bodies of the step */
} bodies;

#define bodies_reserve DIM_NAME(bodies_reserve)
#define bodies_find    DIM_NAME(bodies_find)
#define bodies_free    DIM_NAME(bodies_free)

/* Makes room for n particles. Returns 0, or -1 when out of memory. */
int bodies_reserve(bodies *b, size_t n);
void bodies_free(bodies *b);

/* The bodies of the step's S_F (p->surface, fields_geometry). Serial and in index order, so
 * the numbering does not depend on the thread count. */
void bodies_find(const kernel *k, const particles *p, const neighbour_list *nl, bodies *b);

#endif
