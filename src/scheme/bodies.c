/* bodies: union-find over the band S_F, then a compact numbering of its sets. */
#include "scheme/bodies.h"
#include "core/pair.h"
#include "core/team_loop.h"
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
    free(b->members);
    memset(b, 0, sizeof *b);
}

/* The root of a's set. Halves the path on the way (each node passed is pointed at its
 * grandparent) where no other thread has moved its parent meanwhile: a compare-and-swap that
 * never writes a root's own entry, which only unite() links. */
static int32_t find_root(int32_t *parent, int32_t a)
{
    for (;;) {
        int32_t up = __atomic_load_n(&parent[a], __ATOMIC_RELAXED);
        if (up == a) return a;
        int32_t above = __atomic_load_n(&parent[up], __ATOMIC_RELAXED);
        if (above != up)
            __atomic_compare_exchange_n(&parent[a], &up, above, false, __ATOMIC_RELAXED,
                                        __ATOMIC_RELAXED);
        a = above;
    }
}

int32_t bodies_root(bodies *b, int32_t i) { return find_root(b->parent, i); }

/* Joins the sets of a and b, the larger root linked under the smaller, so that each root is
 * its set's smallest index; a compare-and-swap on that root's entry, tried again if another
 * thread linked it first. */
static void unite(int32_t *parent, int32_t a, int32_t b)
{
    for (;;) {
        a = find_root(parent, a);
        b = find_root(parent, b);
        if (a == b) return;
        int32_t low = a < b ? a : b, high = a < b ? b : a, expected = high;
        if (__atomic_compare_exchange_n(&parent[high], &expected, low, false, __ATOMIC_RELAXED,
                                        __ATOMIC_RELAXED))
            return;
    }
}

static int reserve_members(bodies *b, size_t n)
{
    if (n <= b->members_capacity) return 0;
    size_t capacity = n + n / 2;
    int32_t *grown = realloc(b->members, capacity * sizeof *grown);
    if (!grown) return -1;
    b->members = grown;
    b->members_capacity = capacity;
    return 0;
}

int bodies_find(const kernel *k, const particles *p, const neighbour_list *nl,
                const bodies_domain *d, bodies *b)
{
    size_t n = p->n_fluid, n_nodes = particles_images_begin(p); /* the halo's too */
    size_t n_members = 0;
#pragma omp parallel for schedule(static) reduction(+ : n_members)
    for (size_t i = 0; i < n_nodes; i++) {
        b->parent[i] = (int32_t)i;
        b->at_wall[i] = 0; /* per particle first, per body below */
        n_members += i < n && p->surface[i] != SURFACE_INTERIOR;
    }
    if (reserve_members(b, n_members)) return -1;
    TEAM_FOR (i, n) {
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
    b->n_members = 0;
    for (size_t i = 0; i < n; i++) {
        if (p->surface[i] == SURFACE_INTERIOR) {
            b->id[i] = -1;
            continue;
        }
        b->members[b->n_members++] = (int32_t)i;
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
    return 0;
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
