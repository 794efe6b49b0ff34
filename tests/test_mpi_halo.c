/* The slab decomposition (parallel/slabs.h) keeps the one-process order, run by ctest on 1 to
 * 4 processes in 2D and 3D: jittered particles in a long box (no walls) go through two steps,
 * the second after every particle has moved by up to 0.4 search radii, so that some cross
 * from one slab to the next and the split itself moves. At each step, on every process:
 * the particles it owns, in its order, are the one-process sorted order's range for its slab
 * (the ids gathered in rank order equal that order); a neighbour sum over the own particles,
 * halo included, equals the one-process sum to the bit, for the kernel sum and for the
 * first moment sum W_ij r_ji (whose terms cancel, so any other order of the neighbours would
 * show); and the global sum of the kernel sums equals reduce_sum's. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "core/pair.h"
#include "core/reduce.h"
#include "noise.h"
#include "parallel/mpi_reduce.h"
#include "parallel/slabs.h"

#include <stdlib.h>
#include <string.h>

enum { COLUMNS = 70, ROWS = DIM == 2 ? 12 : 5 }; /* lattice: COLUMNS search radii along x */
static int n_ranks, rank;

typedef struct {
    kernel k;
    double dr, cutoff;
    cell_grid g;
    size_t n; /* particles in all */
} box;

static void box_setup(box *b)
{
    b->dr = 1.0;
    b->k = kernel_make(DIM == 2 ? 2.0 : 1.5);
    b->cutoff = 2.0 * b->k.h;
    double lo[DIM], hi[DIM];
    for (int d = 0; d < DIM; d++) {
        double length = d == 0 ? COLUMNS * b->cutoff : ROWS * b->dr;
        lo[d] = -b->cutoff;
        hi[d] = length + b->cutoff;
    }
    memset(&b->g, 0, sizeof b->g);
    assert_int_equal(cells_setup(&b->g, lo, hi, b->cutoff, 0.0), 0);
    b->n = (size_t)(COLUMNS * b->cutoff / b->dr) * ROWS * (DIM == 3 ? ROWS : 1);
}

/* The lattice, jittered by 0.3 dr, ids in lattice order (x fastest). */
static void lattice(const box *b, particles *p)
{
    size_t nx = (size_t)(COLUMNS * b->cutoff / b->dr);
    assert_int_equal(particles_reserve(p, b->n), 0);
    uint64_t seed = 3;
    for (size_t i = 0; i < b->n; i++) {
        size_t c[3] = {i % nx, (i / nx) % ROWS, i / (nx * ROWS)};
        for (int d = 0; d < DIM; d++) p->x[d][i] = (c[d] + 0.5 + 0.3 * noise(&seed)) * b->dr;
        p->id[i] = (int64_t)i;
    }
    p->n_fluid = p->n_total = b->n;
}

/* Every particle moves by up to 0.4 search radii, the same for a given id on any process. */
static void move(const box *b, particles *p)
{
    for (size_t i = 0; i < p->n_fluid; i++) {
        uint64_t seed = 1000 + (uint64_t)p->id[i];
        for (int d = 0; d < DIM; d++) p->x[d][i] += 0.4 * b->cutoff * noise(&seed);
    }
}

/* Stable sort of the fluid by cell, as the solver does every step. */
static void sort_by_cell(box *b, particles *p)
{
    uint32_t *order = malloc((p->n_fluid + 1) * sizeof *order);
    double *scratch = malloc((p->n_fluid + 1) * sizeof *scratch);
    assert_int_equal(cells_bin(&b->g, p->x, p->n_fluid), 0);
    cells_sort_order(&b->g, p->n_fluid, order);
    particles_permute_fluid(p, order, scratch);
    free(order);
    free(scratch);
}

/* The kernel sum and the first moment of each of the first n_rows particles. */
static void neighbour_sums(box *b, particles *p, double *sum_w, double *moment)
{
    neighbour_list nl = {0};
    assert_int_equal(cells_bin(&b->g, p->x, p->n_total), 0);
    assert_int_equal(
        neighbours_build(&nl, &b->g, p->x, p->n_fluid, b->cutoff, 0.0, (cells_room){0}), 0);
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec xi = vec_load(p->x, i);
        double w_sum = kernel_w(&b->k, 0.0), m = 0.0;
        pair pr;
        FOR_EACH_PAIR (&b->k, p->x, &nl, i, xi, pr) {
            double w = kernel_w(&b->k, pr.r);
            w_sum += w;
            m += w * pr.r_ji.c[0];
        }
        sum_w[i] = w_sum;
        moment[i] = m;
    }
    neighbours_free(&nl);
}

/* What one process computes: the sorted ids and the sums, indexed by position in that order. */
typedef struct {
    int64_t *id;
    double *sum_w, *moment, total;
} reference;

static void one_process(box *b, particles *all, reference *r)
{
    sort_by_cell(b, all);
    all->n_total = all->n_fluid;
    neighbour_sums(b, all, r->sum_w, r->moment);
    memcpy(r->id, all->id, b->n * sizeof *r->id);
    r->total = reduce_sum(r->sum_w, b->n);
}

/* One step on the processes: balance, migrate, sort, halo, sums; checked against r. Returns
 * how many particles changed process (over all processes). */
static long distributed_step(box *b, particles *p, const reference *r, halo_plan *h)
{
    slabs s = {0};
    assert_int_equal(slabs_balance(&s, &b->g, p, MPI_COMM_WORLD), 0);
    long moved = 0;
    for (size_t i = 0; i < p->n_fluid; i++) moved += slabs_owner(&s, &b->g, p->x[0][i]) != rank;
    assert_int_equal(slabs_migrate(&s, &b->g, p, MPI_COMM_WORLD), 0);
    sort_by_cell(b, p);
    assert_int_equal(halo_build(h, &s, &b->g, p, MPI_COMM_WORLD), 0);
    if (n_ranks > 1) assert_true(p->n_total > p->n_fluid); /* every slab has a neighbour */
    double *sum_w = malloc((p->n_fluid + 1) * sizeof *sum_w);
    double *moment = malloc((p->n_fluid + 1) * sizeof *moment);
    neighbour_sums(b, p, sum_w, moment);

    /* this process's particles are the range of the one-process order after those of the
       processes before it */
    unsigned long long mine = p->n_fluid, before = 0;
    MPI_Exscan(&mine, &before, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    if (rank == 0) before = 0;
    assert_true(before + mine <= b->n);
    for (size_t i = 0; i < p->n_fluid; i++) {
        size_t at = (size_t)before + i;
        assert_int_equal(p->id[i], r->id[at]);
        assert_memory_equal(&sum_w[i], &r->sum_w[at], sizeof(double));
        assert_memory_equal(&moment[i], &r->moment[at], sizeof(double));
    }
    double total = mpi_reduce_sum(sum_w, p->n_fluid, MPI_COMM_WORLD);
    assert_memory_equal(&total, &r->total, sizeof total);
    assert_int_equal(mpi_reduce_total((long)p->n_fluid, MPI_COMM_WORLD), (long)b->n);
    free(sum_w);
    free(moment);
    slabs_free(&s);
    return mpi_reduce_total(moved, MPI_COMM_WORLD);
}

static void test_two_steps(void **state)
{
    (void)state;
    box b;
    box_setup(&b);
    assert_true(cells_n_strips(&b.g) >= 4); /* room for four slabs */
    particles all, p;
    assert_int_equal(particles_init(&all, b.n), 0);
    assert_int_equal(particles_init(&p, b.n), 0);
    reference r = {malloc(b.n * sizeof *r.id), malloc(b.n * sizeof(double)),
                   malloc(b.n * sizeof(double)), 0.0};
    lattice(&b, &all);
    if (rank == 0) lattice(&b, &p); /* the run starts on rank 0, in the lattice's order */
    halo_plan h = {0};

    one_process(&b, &all, &r);
    long moved = distributed_step(&b, &p, &r, &h);
    if (n_ranks > 1) assert_true(moved > 0); /* the start: everything leaves rank 0 but its own */

    move(&b, &all);
    move(&b, &p);
    one_process(&b, &all, &r);
    moved = distributed_step(&b, &p, &r, &h);
    if (n_ranks > 1) assert_true(moved > 0); /* particles crossed slab boundaries */

    halo_free(&h);
    particles_free(&all);
    particles_free(&p);
    cells_free(&b.g);
    free(r.id);
    free(r.sum_w);
    free(r.moment);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_two_steps)};
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    MPI_Finalize();
    return failed;
}
