/* bodies: union-find over the band S_F, then a compact numbering of its sets. */
#include "scheme/bodies.h"
#include "core/pair.h"
#include "diag/freesurface.h"
#include <stdlib.h>
#include <string.h>

int bodies_reserve(bodies *b, size_t n)
{
    if (n <= b->capacity) return 0;
    bodies_free(b);
    b->parent = malloc(n * sizeof *b->parent);
    b->id = malloc(n * sizeof *b->id);
    b->at_wall = malloc(n * sizeof *b->at_wall);
    if (!b->parent || !b->id || !b->at_wall) {
        bodies_free(b);
        return -1;
    }
    b->capacity = n;
    return 0;
}

void bodies_free(bodies *b)
{
    free(b->parent);
    free(b->id);
    free(b->at_wall);
    memset(b, 0, sizeof *b);
}

static int32_t find_root(int32_t *parent, int32_t a)
{
    while (parent[a] != a) {
        parent[a] = parent[parent[a]];
        a = parent[a];
    }
    return a;
}

int32_t bodies_root(bodies *b, int32_t i) { return find_root(b->parent, i); }

/* the smaller root becomes the set's: each root is the smallest index of its set */
static void unite(int32_t *parent, int32_t a, int32_t b)
{
    a = find_root(parent, a);
    b = find_root(parent, b);
    if (a < b) parent[b] = a;
    if (b < a) parent[a] = b;
}

void bodies_find(const kernel *k, const particles *p, const neighbour_list *nl,
                 const bodies_domain *d, bodies *b)
{
    size_t n = p->n_fluid, n_nodes = particles_images_begin(p); /* the halo's too */
    for (size_t i = 0; i < n_nodes; i++) {
        b->parent[i] = (int32_t)i;
        b->at_wall[i] = 0; /* per particle first, per body below */
    }
    for (size_t i = 0; i < n; i++) {
        if (p->surface[i] == SURFACE_INTERIOR) continue;
        vec xi = vec_load(p->x, i);
        pair pr;
        FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) {
            if (particle_is_wall_image(p, pr.j))
                b->at_wall[i] = 1;
            else if (p->surface[pr.j] != SURFACE_INTERIOR)
                unite(b->parent, (int32_t)i, (int32_t)pr.j);
        }
    }
    /* number the roots in index order; a root precedes its set's other members, and a body
       is at a wall if any of its particles is (at_wall[id] <= at_wall[i] for id <= i) */
    b->count = 0;
    for (size_t i = 0; i < n; i++) {
        if (p->surface[i] == SURFACE_INTERIOR) {
            b->id[i] = -1;
            continue;
        }
        int32_t root = find_root(b->parent, (int32_t)i);
        uint8_t near_wall = b->at_wall[i];
        if ((size_t)root == i) {
            b->id[i] = (int32_t)b->count;
            b->at_wall[b->count++] = near_wall;
        } else {
            b->id[i] = b->id[root];
            b->at_wall[b->id[i]] |= near_wall;
        }
    }
    if (d) d->join(d, p, b);
}

void bodies_sum(const bodies_domain *d, const particles *p, const bodies *b, double *sums,
                int width, bodies_fold fold, void *context)
{
    if (d) {
        d->sum(d, p, b, sums, width, fold, context);
        return;
    }
    for (size_t k = 0; k < b->count * (size_t)width; k++) sums[k] = 0.0;
    fold(context, sums);
}
