/* mpi_domain: slabs, migration and halos behind the solver's domain hooks. */
#include "parallel/mpi_domain.h"
#include "parallel/mpi_bodies.h"
#include "parallel/mpi_reduce.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static mpi_domain *of(const solver_domain *hooks) { return (mpi_domain *)hooks->context; }

/* After the step's sort: the slabs from this state's counts, every particle to its owner in
 * the global order, sorted by cell again (stably: within a cell the global order, as on one
 * process, docs/mpi.md), then the halo. */
static int distribute(const solver_domain *hooks, solver *s)
{
    mpi_domain *d = of(hooks);
    particles *p = &s->p;
    if (slabs_balance(&d->slabs, &s->grid, p, d->comm)) return -1;
    if (slabs_migrate(&d->slabs, &s->grid, p, d->comm)) return -1;
    if (solver_reserve(s, p->n_fluid) || cells_bin(&s->grid, p->x, p->n_fluid)) return -1;
    cells_sort_order(&s->grid, p->n_fluid, s->order);
    particles_permute_fluid(p, s->order, s->scratch);
    return halo_build(&d->halo, &d->slabs, &s->grid, p, d->comm);
}

static void refresh_halo(const solver_domain *hooks, particles *p, uint64_t fields)
{
    mpi_domain *d = of(hooks);
    halo_refresh(&d->halo, &d->slabs, p, fields, d->comm);
}

static int part_along_x(const solver_domain *hooks, const solver *s, double *lo, double *hi,
                        size_t *n_halo_before)
{
    const mpi_domain *d = of(hooks);
    const slabs *sl = &d->slabs;
    if (!sl->first_strip) return -1;
    const cell_grid *g = &s->grid;
    double first = cells_strip_column(g, sl->first_strip[sl->rank]),
           end = cells_strip_column(g, sl->first_strip[sl->rank + 1]);
    *lo = sl->rank == 0 ? -INFINITY : g->origin[0] + first * g->size;
    *hi = sl->rank == sl->n_ranks - 1 ? INFINITY : g->origin[0] + end * g->size;
    *n_halo_before = d->halo.n_recv[0];
    return 0;
}

static MPI_Comm comm_of(const reducer *r) { return ((mpi_domain *)r->context)->comm; }

static double sum(const reducer *r, const double *a, size_t n)
{
    return mpi_reduce_sum(a, n, comm_of(r));
}

static double max(const reducer *r, const double *a, size_t n)
{
    return mpi_reduce_max(a, n, comm_of(r));
}

static double min(const reducer *r, const double *a, size_t n)
{
    return mpi_reduce_min(a, n, comm_of(r));
}

static long total(const reducer *r, long local) { return mpi_reduce_total(local, comm_of(r)); }

void mpi_domain_attach(mpi_domain *d, solver *s, MPI_Comm comm)
{
    memset(d, 0, sizeof *d);
    d->comm = comm;
    d->hooks = (solver_domain){.distribute = distribute,
                               .refresh_halo = refresh_halo,
                               .part_along_x = part_along_x,
                               .reduce = {sum, max, min, total, d},
                               .bodies = mpi_bodies_domain(d),
                               .context = d};
    int rank, ranks;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &ranks);
    /* a contiguous share of the order: the shares in rank order are the global order. A
       process that set up the whole liquid keeps its share of it; one that set up its share
       alone (solver_init_part) keeps that. */
    particles *p = &s->p;
    size_t n = p->n_fluid, first, end;
    if (ranks > 1 && n == (size_t)s->dv.n_fluid) {
        reduce_share(n, rank, ranks, &first, &end);
        for (size_t k = 0; k < end - first; k++) s->order[k] = (uint32_t)(first + k);
        p->n_fluid = end - first;
        particles_permute_fluid(p, s->order, s->scratch);
    }
    p->n_total = p->n_fluid;
    s->domain = &d->hooks;
}

void mpi_domain_free(mpi_domain *d)
{
    slabs_free(&d->slabs);
    halo_free(&d->halo);
}

void *mpi_domain_split(void *s, MPI_Comm comm)
{
    mpi_domain *d = malloc(sizeof *d);
    if (d) mpi_domain_attach(d, s, comm);
    return d;
}

void mpi_domain_unsplit(void *d)
{
    if (!d) return;
    mpi_domain_free(d);
    free(d);
}
