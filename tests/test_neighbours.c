/* Neighbour search (cell list + lists) against brute force, with particles near every wall,
 * edge and corner and their ghosts, in each form of the scan (core/cells_scan.h); and the
 * sort by cell. */
#include "boundary/tank.h"
#include "core/cells.h"
#include "core/lanes_switch.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "check.h"

static int compare_int32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* Random particles in a unit tank, a third of them pressed against walls and corners. */
static void scatter(particles *p, size_t n, unsigned seed)
{
    srand(seed);
    particles_reserve(p, 16 * n);
    for (size_t i = 0; i < n; i++) {
        for (int d = 0; d < DIM; d++) {
            double r = (double)rand() / RAND_MAX;
            if (i % 3 == 0) r = (i / 3) % 2 ? 0.02 * r : 1.0 - 0.02 * r; /* near a wall */
            if (i % 50 == 0) r = 0.0; /* in a corner: its images lie on it, at distance 0 */
            p->x[d][i] = r;
        }
        p->id[i] = (int64_t)i;
    }
    p->n_fluid = p->n_total = n;
}

static void check_against_brute_force(size_t n, double radius)
{
    particles p;
    assert_int_equal(particles_init(&p, n), 0);
    scatter(&p, n, 7);
    tank t = tank_box((const double[3]){1.0, 1.0, 1.0}, WALL_NO_SLIP);
    assert_int_equal(tank_make_ghosts(&t, &p, radius), 0);
    for (size_t g = p.n_fluid; g < p.n_total; g++) {
        size_t i = (size_t)p.ghost_source[g - p.n_fluid];
        vec_store(p.x, g, ghost_map_point(particle_ghost_map(&p, g), vec_load(p.x, i)));
    }
    assert_true(p.n_total > p.n_fluid);

    cell_grid grid = {0};
    neighbour_list nl = {0};
    double lo[DIM], hi[DIM];
    for (int d = 0; d < DIM; d++) {
        lo[d] = -radius;
        hi[d] = 1.0 + radius;
    }
    assert_int_equal(cells_setup(&grid, lo, hi, radius), 0);
    assert_true(grid.size >= radius);
    assert_int_equal(cells_bin(&grid, p.x, p.n_total), 0);
    /* the scalar form's rows, in their order, for the lane forms to match */
    lanes_limit(0);
    nl.row_capacity = 4; /* force the overflow path */
    assert_int_equal(neighbours_build(&nl, &grid, p.x, p.n_fluid, radius), 0);
    size_t cap = nl.row_capacity;
    int32_t *scalar_rows = malloc(p.n_fluid * cap * sizeof *scalar_rows);
    memcpy(scalar_rows, nl.index, p.n_fluid * cap * sizeof *scalar_rows);
    for (int width = 4; width <= 8; width += 4) {
        lanes_limit(width);
        neighbours_free(&nl);
        nl.row_capacity = 4; /* force the overflow path */
        assert_int_equal(neighbours_build(&nl, &grid, p.x, p.n_fluid, radius), 0);
        assert_int_equal(nl.row_capacity, cap);
        for (size_t i = 0; i < p.n_fluid; i++)
            for (int32_t k = 0; k < nl.count[i]; k++)
                assert_int_equal(nl.index[i * cap + (size_t)k], scalar_rows[i * cap + (size_t)k]);
    }
    lanes_limit(8);

    int32_t *expected = malloc(p.n_total * sizeof *expected);
    int32_t *found = malloc(p.n_total * sizeof *found);
    size_t pairs = 0;
    for (size_t i = 0; i < p.n_fluid; i++) {
        int32_t m = 0;
        for (size_t j = 0; j < p.n_total; j++) {
            if (j == i) continue;
            if (vec_norm2(vec_sub(vec_load(p.x, j), vec_load(p.x, i))) < radius * radius)
                expected[m++] = (int32_t)j;
        }
        assert_int_equal(nl.count[i], m);
        for (int32_t k = 0; k < m; k++) found[k] = nl.index[i * nl.row_capacity + (size_t)k];
        qsort(found, (size_t)m, sizeof *found, compare_int32);
        for (int32_t k = 0; k < m; k++) assert_int_equal(found[k], expected[k]);
        pairs += (size_t)m;
    }
    assert_true(pairs > 0);

    /* The next build sizes its rows by this one's longest: a sixteenth more (cells.h), not
     * the 4 of the overflow test nor a fixed guess; same rows. */
    int32_t longest = 0;
    for (size_t i = 0; i < p.n_fluid; i++)
        if (nl.count[i] > longest) longest = nl.count[i];
    assert_int_equal(nl.longest, longest);
    assert_int_equal(neighbours_build(&nl, &grid, p.x, p.n_fluid, radius), 0);
    assert_int_equal(nl.row_capacity, (size_t)longest + (size_t)longest / 16);
    for (size_t i = 0; i < p.n_fluid; i++)
        for (int32_t k = 0; k < nl.count[i]; k++)
            assert_int_equal(nl.index[i * nl.row_capacity + (size_t)k],
                             scalar_rows[i * cap + (size_t)k]);
    free(scalar_rows);
    free(expected);
    free(found);
    cells_free(&grid);
    neighbours_free(&nl);
    particles_free(&p);
}

static void test_brute_force(void **state)
{
    (void)state;
    check_against_brute_force(DIM == 2 ? 600 : 1500, 0.09);
    check_against_brute_force(DIM == 2 ? 300 : 400, 0.33); /* few cells per axis */
}

/* After the sort, particles of one cell are contiguous and cells come in ascending order. */
static void test_sort_by_cell(void **state)
{
    (void)state;
    size_t n = 500;
    particles p;
    assert_int_equal(particles_init(&p, n), 0);
    scatter(&p, n, 11);
    for (size_t i = 0; i < n; i++) {
        p.rho[i] = (double)i;
        p.m[i] = 2.0 * (double)i;
        for (int d = 0; d < DIM; d++) p.u[d][i] = p.x[d][i];
    }
    cell_grid grid = {0};
    double lo[DIM], hi[DIM];
    for (int d = 0; d < DIM; d++) {
        lo[d] = 0.0;
        hi[d] = 1.0;
    }
    cells_setup(&grid, lo, hi, 0.1);
    cells_bin(&grid, p.x, n);
    uint32_t *order = malloc(n * sizeof *order);
    double *scratch = malloc(n * sizeof *scratch);
    cells_sort_order(&grid, n, order);
    particles_permute_fluid(&p, order, scratch);
    cells_bin(&grid, p.x, n);
    for (size_t i = 1; i < n; i++) assert_true(grid.cell_of[i] >= grid.cell_of[i - 1]);
    for (size_t i = 0; i < n; i++) {
        /* every field moved together */
        assert_true(p.m[i] == 2.0 * p.rho[i]);
        assert_true(p.id[i] == (int64_t)p.rho[i]);
        for (int d = 0; d < DIM; d++) assert_true(p.u[d][i] == p.x[d][i]);
    }
    free(order);
    free(scratch);
    cells_free(&grid);
    particles_free(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_brute_force),
        cmocka_unit_test(test_sort_by_cell),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
