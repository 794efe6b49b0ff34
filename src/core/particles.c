/* particles: allocation and reordering of the SoA store. */
#include "core/particles.h"

#include <stdlib.h>
#include <string.h>

/* Every double array of the store, so that allocation and growth treat them alike. */
static int double_arrays(particles *p, double ***out)
{
    int n = 0;
    for (int d = 0; d < DIM; d++) {
        out[n++] = &p->x[d];
        out[n++] = &p->u[d];
        out[n++] = &p->u_wall[d];
        out[n++] = &p->grad_rho[d];
        out[n++] = &p->shift[d];
        out[n++] = &p->correction[d];
        out[n++] = &p->normal[d];
        out[n++] = &p->st_force[d];
    }
    out[n++] = &p->rho;
    out[n++] = &p->p;
    out[n++] = &p->m;
    out[n++] = &p->vol;
    out[n++] = &p->nu_t;
    out[n++] = &p->nu_delta;
    out[n++] = &p->lambda;
    out[n++] = &p->diff_rho;
    out[n++] = &p->normal_raw;
    out[n++] = &p->kernel_sum;
    out[n++] = &p->gamma;
    out[n++] = &p->volume_mismatch;
    out[n++] = &p->diff_m;
    out[n++] = &p->interface;
    out[n++] = &p->curvature;
    return n;
}

#define MAX_ARRAYS (8 * DIM + 15)

static int grow(void **ptr, size_t count, size_t size)
{
    void *q = realloc(*ptr, count * size);
    if (!q) return -1;
    *ptr = q;
    return 0;
}

int particles_reserve(particles *p, size_t capacity)
{
    if (capacity <= p->capacity) return 0;
    double **arrays[MAX_ARRAYS];
    int n = double_arrays(p, arrays);
    for (int k = 0; k < n; k++)
        if (grow((void **)arrays[k], capacity, sizeof(double))) return -1;
    if (grow((void **)&p->id, capacity, sizeof(int64_t)) ||
        grow((void **)&p->ghost_source, capacity, sizeof(int32_t)) ||
        grow((void **)&p->ghost_walls, capacity, sizeof(uint8_t)) ||
        grow((void **)&p->surface, capacity, sizeof(uint8_t)) ||
        grow((void **)&p->is_free, capacity, sizeof(uint8_t)))
        return -1;
    /* new slots start as zeros: shifting and lambda are read before anything writes them */
    for (int k = 0; k < n; k++)
        memset(*arrays[k] + p->capacity, 0, (capacity - p->capacity) * sizeof(double));
    p->capacity = capacity;
    return 0;
}

int particles_init(particles *p, size_t capacity)
{
    memset(p, 0, sizeof *p);
    return particles_reserve(p, capacity < 16 ? 16 : capacity);
}

void particles_free(particles *p)
{
    double **arrays[MAX_ARRAYS];
    int n = double_arrays(p, arrays);
    for (int k = 0; k < n; k++) free(*arrays[k]);
    free(p->id);
    free(p->ghost_source);
    free(p->ghost_walls);
    free(p->surface);
    free(p->is_free);
    memset(p, 0, sizeof *p);
}

size_t particles_bytes_per_slot(void)
{
    particles p;
    double **arrays[MAX_ARRAYS];
    int n = double_arrays(&p, arrays);
    /* the doubles, then id, ghost_source, ghost_walls, surface, is_free */
    return (size_t)n * sizeof(double) + sizeof(int64_t) + sizeof(int32_t) + 3 * sizeof(uint8_t);
}

static void permute(double *a, const size_t *order, size_t n, double *scratch)
{
    for (size_t k = 0; k < n; k++) scratch[k] = a[order[k]];
    memcpy(a, scratch, n * sizeof *a);
}

void particles_permute_fluid(particles *p, const size_t *order, double *scratch)
{
    size_t n = p->n_fluid;
    for (int d = 0; d < DIM; d++) {
        permute(p->x[d], order, n, scratch);
        permute(p->u[d], order, n, scratch);
    }
    permute(p->rho, order, n, scratch);
    permute(p->m, order, n, scratch);
    /* ids are integers: move them through the same scratch bytes */
    int64_t *ids = (int64_t *)scratch;
    for (size_t k = 0; k < n; k++) ids[k] = p->id[order[k]];
    memcpy(p->id, ids, n * sizeof *ids);
}
