/* slabs: migration and halo of the slab decomposition, through the field registry. */
#include "parallel/slabs.h"
#include "parallel/decomposition.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* A particle's fields travel as a record of doubles, one per component of each field of the
 * set (the registry guarantees each fits in a double, core/particles.c). */
static size_t record_doubles(uint64_t fields)
{
    size_t n = 0;
#define COUNT_SCALAR(type, name, flags, snapshot, comment) n += (fields & FIELD_MASK(name)) ? 1 : 0;
#define COUNT_VECTOR(type, name, flags, snapshot, comment)                                         \
    n += (fields & FIELD_MASK(name)) ? DIM : 0;
    PARTICLE_FIELDS(COUNT_SCALAR, COUNT_VECTOR)
    return n;
}

/* The persistent state: what a particle that changes process takes with it. */
static uint64_t state_fields(void)
{
    uint64_t fields = 0;
#define STATE_SCALAR(type, name, flags, snapshot, comment)                                         \
    if ((flags)&FIELD_STATE) fields |= FIELD_MASK(name);
    PARTICLE_FIELDS(STATE_SCALAR, STATE_SCALAR)
    return fields;
}

static void pack(const particles *p, size_t i, uint64_t fields, double *record)
{
    double *at = record;
#define PACK_SCALAR(type, name, flags, snapshot, comment)                                          \
    if (fields & FIELD_MASK(name)) {                                                               \
        *at = 0.0;                                                                                 \
        memcpy(at++, &p->name[i], sizeof(type));                                                   \
    }
#define PACK_VECTOR(type, name, flags, snapshot, comment)                                          \
    if (fields & FIELD_MASK(name))                                                                 \
        for (int d = 0; d < DIM; d++) {                                                            \
            *at = 0.0;                                                                             \
            memcpy(at++, &p->name[d][i], sizeof(type));                                            \
        }
    PARTICLE_FIELDS(PACK_SCALAR, PACK_VECTOR)
}

static void unpack(particles *p, size_t i, uint64_t fields, const double *record)
{
    const double *at = record;
#define UNPACK_SCALAR(type, name, flags, snapshot, comment)                                        \
    if (fields & FIELD_MASK(name)) memcpy(&p->name[i], at++, sizeof(type));
#define UNPACK_VECTOR(type, name, flags, snapshot, comment)                                        \
    if (fields & FIELD_MASK(name))                                                                 \
        for (int d = 0; d < DIM; d++) memcpy(&p->name[d][i], at++, sizeof(type));
    PARTICLE_FIELDS(UNPACK_SCALAR, UNPACK_VECTOR)
}

int slabs_balance(slabs *s, const cell_grid *g, const particles *p, MPI_Comm comm)
{
    MPI_Comm_size(comm, &s->n_ranks);
    MPI_Comm_rank(comm, &s->rank);
    s->n_strips = cells_n_strips(g);
    uint64_t *mine = calloc(2 * s->n_strips, sizeof *mine), *all = mine + s->n_strips;
    size_t *count = malloc(s->n_strips * sizeof *count);
    size_t *first = realloc(s->first_strip, ((size_t)s->n_ranks + 1) * sizeof *first);
    if (!mine || !count || !first) MPI_Abort(comm, 3); /* a collective follows: do not leave */
    s->first_strip = first;
    for (size_t i = 0; i < p->n_fluid; i++) mine[cells_strip_of(g, p->x[0][i])]++;
    MPI_Allreduce(mine, all, (int)s->n_strips, MPI_UINT64_T, MPI_SUM, comm);
    for (size_t k = 0; k < s->n_strips; k++) count[k] = (size_t)all[k];
    int status = decomposition_balance(count, s->n_strips, s->n_ranks, s->first_strip);
    free(mine);
    free(count);
    return status;
}

int slabs_owner(const slabs *s, const cell_grid *g, double x)
{
    size_t strip = cells_strip_of(g, x);
    int lo = 0, hi = s->n_ranks - 1; /* the last rank whose first strip is <= strip */
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (s->first_strip[mid] <= strip)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

void slabs_free(slabs *s)
{
    free(s->first_strip);
    memset(s, 0, sizeof *s);
}

int slabs_migrate(slabs *s, const cell_grid *g, particles *p, MPI_Comm comm)
{
    size_t n = p->n_fluid, ranks = (size_t)s->n_ranks;
    uint64_t fields = state_fields();
    size_t width = record_doubles(fields);
    int *counts = calloc(4 * ranks, sizeof *counts);
    int *send = counts, *send_at = counts + ranks, *recv = counts + 2 * ranks,
        *recv_at = counts + 3 * ranks;
    int *dest = malloc((n ? n : 1) * sizeof *dest);
    double *out = malloc((n ? n : 1) * width * sizeof *out), *in = NULL;
    if (!counts || !dest || !out) MPI_Abort(comm, 3); /* a collective follows: do not leave */
    for (size_t i = 0; i < n; i++) send[dest[i] = slabs_owner(s, g, p->x[0][i])]++;
    MPI_Alltoall(send, 1, MPI_INT, recv, 1, MPI_INT, comm);
    size_t n_out = 0, n_in = 0;
    for (size_t q = 0; q < ranks; q++) {
        send_at[q] = (int)(n_out * width);
        recv_at[q] = (int)(n_in * width);
        n_out += (size_t)send[q];
        n_in += (size_t)recv[q];
    }
    /* records grouped by destination, each group in this process's order */
    size_t *cursor = calloc(ranks, sizeof *cursor);
    in = malloc((n_in ? n_in : 1) * width * sizeof *in);
    if (!cursor || !in || particles_reserve(p, n_in)) MPI_Abort(comm, 3);
    for (size_t i = 0; i < n; i++)
        pack(p, i, fields, out + (size_t)send_at[dest[i]] + cursor[dest[i]]++ * width);
    for (size_t q = 0; q < ranks; q++) {
        send[q] *= width;
        recv[q] *= width;
    }
    MPI_Alltoallv(out, send, send_at, MPI_DOUBLE, in, recv, recv_at, MPI_DOUBLE, comm);
    size_t kept = (size_t)send[s->rank] / width;
    s->sent_records += n - kept;
    s->sent_bytes += (n - kept) * width * sizeof(double);
    for (size_t i = 0; i < n_in; i++) unpack(p, i, fields, in + i * width);
    p->n_fluid = p->n_total = n_in;
    p->n_halo = 0;
    free(counts);
    free(dest);
    free(out);
    free(in);
    free(cursor);
    return 0;
}

/* The neighbour on each side, MPI_PROC_NULL at the ends of the tank. */
static int neighbour(const slabs *s, int side)
{
    int q = s->rank + (side ? 1 : -1);
    return q < 0 || q >= s->n_ranks ? MPI_PROC_NULL : q;
}

/* out[side] (count[side] items) to the neighbour on that side, in[side] from it; both sides
 * at once. A message sent to the left is tagged 0, one to the right 1, so what comes from
 * the left neighbour carries 1. */
static void exchange_sides(void *const out[2], const int n_out[2], void *const in[2],
                           const int n_in[2], MPI_Datatype type, const slabs *s, MPI_Comm comm)
{
    MPI_Request request[4];
    for (int side = 0; side < 2; side++) {
        MPI_Irecv(in[side], n_in[side], type, neighbour(s, side), 1 - side, comm, &request[side]);
        MPI_Isend(out[side], n_out[side], type, neighbour(s, side), side, comm, &request[2 + side]);
    }
    MPI_Waitall(4, request, MPI_STATUSES_IGNORE);
}

/* One value each way per side. */
static void exchange(unsigned long long *out, unsigned long long *in, int n, MPI_Datatype type,
                     const slabs *s, MPI_Comm comm)
{
    void *o[2] = {&out[0], &out[1]}, *i[2] = {&in[0], &in[1]};
    int counts[2] = {n, n};
    exchange_sides(o, counts, i, counts, type, s, comm);
}

static int plan_add(halo_plan *h, int side, size_t i)
{
    if (h->n_send[side] == h->capacity[side]) {
        size_t capacity = h->capacity[side] ? 2 * h->capacity[side] : 256;
        size_t *grown = realloc(h->send[side], capacity * sizeof *grown);
        if (!grown) return -1;
        h->send[side] = grown;
        h->capacity[side] = capacity;
    }
    h->send[side][h->n_send[side]++] = i;
    return 0;
}

int halo_build(halo_plan *h, slabs *s, const cell_grid *g, particles *p, MPI_Comm comm)
{
    int first_column = cells_strip_column(g, s->first_strip[s->rank]);
    int last_column = cells_strip_column(g, s->first_strip[s->rank + 1]) - 1;
    if (last_column > g->n[0] - 1) last_column = g->n[0] - 1;
    h->n_send[0] = h->n_send[1] = 0;
    int failed = 0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        int column = cells_column(g, p->x[0][i]);
        if (column == first_column && neighbour(s, 0) != MPI_PROC_NULL) failed |= plan_add(h, 0, i);
        if (column == last_column && neighbour(s, 1) != MPI_PROC_NULL) failed |= plan_add(h, 1, i);
    }
    if (failed) MPI_Abort(comm, 3);
    unsigned long long sent[2] = {h->n_send[0], h->n_send[1]}, got[2] = {0, 0};
    exchange(sent, got, 1, MPI_UNSIGNED_LONG_LONG, s, comm);
    h->n_recv[0] = (size_t)got[0];
    h->n_recv[1] = (size_t)got[1];
    size_t n_total = p->n_fluid + h->n_recv[0] + h->n_recv[1];
    if (particles_reserve(p, n_total) || particles_reserve_ghosts(p, n_total - p->n_fluid))
        MPI_Abort(comm, 3);
    for (size_t t = p->n_fluid; t < n_total; t++) {
        p->ghost_kind[t - p->n_fluid] = GHOST_HALO;
        p->ghost_map[t - p->n_fluid] = 0;
        p->ghost_source[t - p->n_fluid] = -1;
    }
    p->n_halo = n_total - p->n_fluid;
    p->n_total = n_total;
    return halo_refresh(h, s, p, state_fields(), comm);
}

/* The plan's items, `per_item` elements of `type` (`item_bytes` bytes in all) each, from out
 * (the left side's, then the right side's) to the neighbours, and theirs into in (the left
 * neighbour's, then the right's); counted in s's traffic. */
static void exchange_plan(const halo_plan *h, slabs *s, void *out, void *in, int per_item,
                          size_t item_bytes, MPI_Datatype type, MPI_Comm comm)
{
    void *o[2] = {out, (char *)out + h->n_send[0] * item_bytes};
    void *i[2] = {in, (char *)in + h->n_recv[0] * item_bytes};
    int n_o[2] = {(int)h->n_send[0] * per_item, (int)h->n_send[1] * per_item};
    int n_i[2] = {(int)h->n_recv[0] * per_item, (int)h->n_recv[1] * per_item};
    exchange_sides(o, n_o, i, n_i, type, s, comm);
    s->sent_records += h->n_send[0] + h->n_send[1];
    s->sent_bytes += (h->n_send[0] + h->n_send[1]) * item_bytes;
}

/* Every item the plan sends, side by side: its own particle's index. */
static size_t plan_item(const halo_plan *h, size_t k)
{
    return k < h->n_send[0] ? h->send[0][k] : h->send[1][k - h->n_send[0]];
}

int halo_refresh(const halo_plan *h, slabs *s, particles *p, uint64_t fields, MPI_Comm comm)
{
    size_t width = record_doubles(fields);
    size_t n_out = h->n_send[0] + h->n_send[1], n_in = h->n_recv[0] + h->n_recv[1];
    double *out = malloc((n_out + 1) * width * sizeof *out);
    double *in = malloc((n_in + 1) * width * sizeof *in);
    if (!out || !in) MPI_Abort(comm, 3);
    for (size_t k = 0; k < n_out; k++) pack(p, plan_item(h, k), fields, out + k * width);
    exchange_plan(h, s, out, in, (int)width, width * sizeof *out, MPI_DOUBLE, comm);
    for (size_t k = 0; k < n_in; k++) unpack(p, p->n_fluid + k, fields, in + k * width);
    free(out);
    free(in);
    return 0;
}

void halo_exchange_values(const halo_plan *h, slabs *s, const void *own, void *halo, size_t size,
                          MPI_Datatype type, MPI_Comm comm)
{
    size_t n_out = h->n_send[0] + h->n_send[1];
    char *out = malloc((n_out + 1) * size);
    if (!out) MPI_Abort(comm, 3);
    for (size_t k = 0; k < n_out; k++)
        memcpy(out + k * size, (const char *)own + plan_item(h, k) * size, size);
    exchange_plan(h, s, out, halo, 1, size, type, comm);
    free(out);
}

void halo_free(halo_plan *h)
{
    free(h->send[0]);
    free(h->send[1]);
    memset(h, 0, sizeof *h);
}
