/* mpi_bodies: the bodies of liquid of a run split by slabs (bodies.h's bodies_domain). */
#include "parallel/mpi_bodies.h"
#include "parallel/mpi_reduce.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Bodies of liquid across processes (bodies.h). A body's global name is the global index of
 * its first particle, as its root is on one process: each process labels its part of every
 * body with the smallest global index it knows of, the halo brings the neighbours' labels,
 * and this repeats until no label changes anywhere (a body crossing k slabs takes k + 1
 * rounds). The bodies are then numbered in the order of their first particles, as on one
 * process. */
static bool in_band(const particles *p, size_t v) { return p->surface[v] != SURFACE_INTERIOR; }

/* One round: every set's smallest label over its members, own and halo; returns whether an
 * own label changed. */
static bool relabel(const particles *p, bodies *b, int64_t *label, int64_t *set_min)
{
    size_t n = p->n_fluid, nodes = particles_images_begin(p);
    for (size_t v = 0; v < nodes; v++) set_min[v] = INT64_MAX;
    for (size_t v = 0; v < nodes; v++) {
        if (!in_band(p, v)) continue;
        int32_t r = bodies_root(b, (int32_t)v);
        if (label[v] < set_min[r]) set_min[r] = label[v];
    }
    bool changed = false;
    for (size_t v = 0; v < n; v++) {
        if (!in_band(p, v)) continue;
        int64_t m = set_min[bodies_root(b, (int32_t)v)];
        changed |= m != label[v];
        label[v] = m;
    }
    return changed;
}

static int compare_int64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

static void join(const bodies_domain *hooks, const particles *p, bodies *b)
{
    mpi_domain *d = hooks->context;
    MPI_Comm comm = d->comm;
    size_t n = p->n_fluid, nodes = particles_images_begin(p);
    int64_t *label = malloc((nodes + 1) * sizeof *label);
    int64_t *set_min = malloc((nodes + 1) * sizeof *set_min);
    if (!label || !set_min) MPI_Abort(comm, 3);
    int64_t first = (int64_t)mpi_first_index(n, comm);
    for (size_t v = 0; v < n; v++) label[v] = first + (int64_t)v;
    int anywhere;
    do {
        halo_exchange_values(&d->halo, &d->slabs, label, label + n, sizeof *label, MPI_INT64_T,
                             comm);
        int changed = relabel(p, b, label, set_min);
        MPI_Allreduce(&changed, &anywhere, 1, MPI_INT, MPI_LOR, comm);
    } while (anywhere);
    /* the first particles of the bodies, in global order: the ranks' lists one after another */
    int count = 0, ranks = d->slabs.n_ranks;
    int *counts = malloc(2 * (size_t)ranks * sizeof *counts), *at = counts + ranks;
    int64_t *mine = set_min; /* its room, free now */
    if (!counts) MPI_Abort(comm, 3);
    for (size_t v = 0; v < n; v++)
        if (in_band(p, v) && label[v] == first + (int64_t)v) mine[count++] = label[v];
    MPI_Allgather(&count, 1, MPI_INT, counts, 1, MPI_INT, comm);
    size_t total = 0;
    for (int q = 0; q < ranks; q++) {
        at[q] = (int)total;
        total += (size_t)counts[q];
    }
    int64_t *roots = malloc((total + 1) * sizeof *roots);
    uint8_t *at_wall = calloc(total + 1, 1);
    if (!roots || !at_wall) MPI_Abort(comm, 3);
    MPI_Allgatherv(mine, count, MPI_INT64_T, roots, counts, at, MPI_INT64_T, comm);
    /* a body at a wall anywhere is at a wall: bodies_find's local flags, per global body */
    for (size_t v = 0; v < nodes; v++) {
        if (!in_band(p, v)) {
            b->id[v] = -1;
            continue;
        }
        int32_t local = b->id[v]; /* bodies_find's, for its at_wall */
        int64_t *root = bsearch(&label[v], roots, total, sizeof *roots, compare_int64);
        b->id[v] = root ? (int32_t)(root - roots) : -1; /* a halo body no own particle joins */
        if (v < n && root) at_wall[b->id[v]] |= b->at_wall[local];
    }
    uint8_t *grown = total > b->capacity ? realloc(b->at_wall, total) : b->at_wall;
    if (!grown) MPI_Abort(comm, 3);
    b->at_wall = grown;
    MPI_Allreduce(at_wall, b->at_wall, (int)total, MPI_UINT8_T, MPI_MAX, comm);
    b->count = total;
    free(label);
    free(set_min);
    free(counts);
    free(roots);
    free(at_wall);
}

/* The bodies whose particles lie in the halo of one side: sorted, once each. */
static size_t halo_bodies(const mpi_domain *d, const particles *p, const bodies *b, int side,
                          uint8_t *seen, int32_t *list)
{
    size_t from = p->n_fluid + (side ? d->halo.n_recv[0] : 0), n = d->halo.n_recv[side];
    memset(seen, 0, b->count);
    for (size_t k = 0; k < n; k++)
        if (b->id[from + k] >= 0) seen[b->id[from + k]] = 1;
    size_t count = 0;
    for (size_t id = 0; id < b->count; id++)
        if (seen[id]) list[count++] = (int32_t)id;
    return count;
}

static void share(const bodies_domain *hooks, const particles *p, double *values)
{
    mpi_domain *d = hooks->context;
    halo_exchange_values(&d->halo, &d->slabs, values, values + p->n_fluid, sizeof *values,
                         MPI_DOUBLE, d->comm);
}

enum { TAG_FORWARD = 11, TAG_BACKWARD = 12 };

/* Sends the sums of the `count` bodies of `list` to the neighbour on one side, as
 * (id, sums...) records */
static void send_sums(const mpi_domain *d, const double *sums, int width, int side, int tag,
                      const int32_t *list, size_t count)
{
    size_t record = 1 + (size_t)width;
    double *out = malloc((count * record + 1) * sizeof *out);
    if (!out) MPI_Abort(d->comm, 3);
    for (size_t k = 0; k < count; k++) {
        out[k * record] = list[k];
        memcpy(out + k * record + 1, sums + (size_t)list[k] * width, width * sizeof *out);
    }
    int to = d->slabs.rank + (side ? 1 : -1);
    MPI_Send(out, (int)(count * record), MPI_DOUBLE, to, tag, d->comm);
    free(out);
}

/* Receives a neighbour's (id, sums...) records into sums; their ids into list (room for every
 * body), returning how many. */
static size_t receive_sums(const mpi_domain *d, double *sums, int width, int from, int tag,
                           int32_t *list)
{
    MPI_Status status;
    int n;
    MPI_Probe(from, tag, d->comm, &status);
    MPI_Get_count(&status, MPI_DOUBLE, &n);
    double *in = malloc(((size_t)n + 1) * sizeof *in);
    if (!in) MPI_Abort(d->comm, 3);
    MPI_Recv(in, n, MPI_DOUBLE, from, tag, d->comm, MPI_STATUS_IGNORE);
    size_t record = 1 + (size_t)width, count = (size_t)n / record;
    for (size_t k = 0; k < count; k++) {
        list[k] = (int32_t)in[k * record];
        memcpy(sums + (size_t)list[k] * width, in + k * record + 1, width * sizeof *in);
    }
    free(in);
    return count;
}

/* A body's sum is a fold over its particles in global order, which is rank order: each
 * process starts its bodies' sums from the previous process's partial sums, folds its own
 * particles and hands them on; the last process holding a body has its total, which goes
 * back the same way. Forward, a process hands on the bodies in its right halo: those with
 * particles of its own on the next process. Back, it returns exactly the bodies it was
 * handed: a body whose particles reach into the next process's halo without any of its own
 * there (a body ending in a slab's last cell column) gets no total from there, which would be
 * that process's zeros. */
static void sum_bodies(const bodies_domain *hooks, const particles *p, const bodies *b,
                       double *sums, int width, bodies_fold fold, void *context)
{
    mpi_domain *d = hooks->context;
    int rank = d->slabs.rank, last = d->slabs.n_ranks - 1;
    uint8_t *seen = malloc(b->count + 1);
    int32_t *handed = malloc((b->count + 1) * sizeof *handed);
    int32_t *onward = malloc((b->count + 1) * sizeof *onward);
    if (!seen || !handed || !onward) MPI_Abort(d->comm, 3);
    for (size_t k = 0; k < b->count * (size_t)width; k++) sums[k] = 0.0;
    size_t n_handed = 0;
    if (rank > 0) n_handed = receive_sums(d, sums, width, rank - 1, TAG_FORWARD, handed);
    fold(context, sums);
    if (rank < last) {
        size_t n_onward = halo_bodies(d, p, b, 1, seen, onward);
        send_sums(d, sums, width, 1, TAG_FORWARD, onward, n_onward);
        receive_sums(d, sums, width, rank + 1, TAG_BACKWARD, onward);
    }
    if (rank > 0) send_sums(d, sums, width, 0, TAG_BACKWARD, handed, n_handed);
    free(seen);
    free(handed);
    free(onward);
}

bodies_domain mpi_bodies_domain(mpi_domain *d)
{
    return (bodies_domain){join, sum_bodies, share, d};
}
