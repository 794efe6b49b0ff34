/* Neighbour search (cell list + lists) against brute force, with particles near every wall,
 * edge and corner and their ghosts, in each form of the scan (core/cells_scan.h) and each form
 * of the rows (16-bit windows or whole); and the sort by cell. */
#include "boundary/tank.h"
#include "core/cells.h"
#include "core/lanes_switch.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include <omp.h>

#include "check.h"

static int compare_int32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* The list's rows, unpacked (neighbour_row), cap entries apart in a new array. */
static int32_t *rows_of(const neighbour_list *nl, size_t cap)
{
    int32_t *rows = malloc(nl->n_rows * cap * sizeof *rows);
    int32_t entries[nl->row_capacity];
    for (size_t i = 0; i < nl->n_rows; i++)
        memcpy(rows + i * cap, neighbour_row(nl, i, entries), (size_t)nl->count[i] * sizeof *rows);
    return rows;
}

static void assert_rows_equal(const neighbour_list *nl, const int32_t *rows, size_t cap)
{
    int32_t *now = rows_of(nl, cap);
    for (size_t i = 0; i < nl->n_rows; i++)
        for (int32_t k = 0; k < nl->count[i]; k++)
            assert_int_equal(now[i * cap + (size_t)k], rows[i * cap + (size_t)k]);
    free(now);
}

/* Random particles in a unit tank, a third of them pressed against walls and corners. */
/* Cells of side `size` over the unit box [0, 1]^DIM */
static void unit_box_cells(cell_grid *g, double size)
{
    double lo[DIM], hi[DIM];
    for (int d = 0; d < DIM; d++) lo[d] = 0.0, hi[d] = 1.0;
    assert_int_equal(cells_setup(g, lo, hi, size, 0.0), 0);
}

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

/* The rows in two parts (cells.h) with the kernel's support at 0.6 radius, in each form of the
 * scan and of the rows: the first near[i] entries are those of the row in scan order
 * (`scan_rows`, built with no near part) whose squared distance, added as vec_norm2 adds it,
 * lies below the support's, and the rest are the others, each part in the scan's order; and
 * neighbours_near's rows are the near parts. */
static void check_near_parts(cell_grid *grid, const particles *p, double radius,
                             const int32_t *scan_rows, size_t cap)
{
    double near2 = 0.36 * radius * radius;
    size_t near_pairs = 0, skin_pairs = 0;
    for (int form = 0; form < 4; form++) { /* scalar, four, eight lanes, whole rows */
        neighbour_list nl = {0};
        lanes_limit(form == 0 ? 0 : form == 1 ? 4 : 8);
        nl.wide = form == 3;
        assert_int_equal(
            neighbours_build(&nl, grid, p->x, p->n_fluid, radius, near2, (cells_room){0}), 0);
        neighbour_list near = neighbours_near(&nl);
        int32_t entries[nl.row_capacity], near_entries[nl.row_capacity];
        for (size_t i = 0; i < p->n_fluid; i++) {
            const int32_t *row = neighbour_row(&nl, i, entries), *scan = scan_rows + i * cap;
            int32_t n_near = 0, n_skin = 0;
            for (int32_t k = 0; k < nl.count[i]; k++) {
                double r2 = vec_norm2(vec_sub(vec_load(p->x, (size_t)scan[k]), vec_load(p->x, i)));
                if (r2 < near2)
                    assert_int_equal(row[n_near++], scan[k]);
                else
                    assert_int_equal(row[nl.near[i] + n_skin++], scan[k]);
            }
            assert_int_equal(nl.near[i], n_near);
            assert_int_equal(near.count[i], n_near);
            const int32_t *near_row = neighbour_row(&near, i, near_entries);
            for (int32_t k = 0; k < n_near; k++) assert_int_equal(near_row[k], row[k]);
            near_pairs += (size_t)n_near;
            skin_pairs += (size_t)n_skin;
        }
        neighbours_free(&nl);
    }
    lanes_limit(8);
    assert_true(near_pairs > 0 && skin_pairs > 0); /* both parts tried */
}

/* cells_marked_around, after cells_mark of a sparse set of particles (every 97th of the
 * first n_fluid + 5, ghosts among them): true wherever a marked particle lies within the radius
 * of a fluid particle (brute force), and false for some. */
static void check_marked_cells(cell_grid *grid, const particles *p, double radius)
{
    size_t limit = p->n_fluid + 5;
    uint8_t *flag = calloc(p->n_total, 1);
    for (size_t j = 0; j < p->n_total; j += 97) flag[j] = 1;
    cells_mark(grid, flag, limit);
    size_t unmarked = 0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec xi = vec_load(p->x, i);
        bool near_flagged = false;
        for (size_t j = 0; j < limit; j++)
            if (j != i && flag[j] && vec_norm2(vec_sub(vec_load(p->x, j), xi)) < radius * radius)
                near_flagged = true;
        bool around = cells_marked_around(grid, i);
        if (near_flagged) assert_true(around);
        unmarked += !around;
    }
    assert_true(unmarked > 0);
    free(flag);
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
    assert_int_equal(cells_setup(&grid, lo, hi, radius, 0.0), 0);
    assert_true(grid.size >= radius);
    assert_int_equal(cells_bin(&grid, p.x, p.n_total), 0);
    /* the scalar form's rows, in their order, for the lane forms to match */
    lanes_limit(0);
    nl.row_capacity = 4; /* force the overflow path */
    assert_int_equal(neighbours_build(&nl, &grid, p.x, p.n_fluid, radius, 0.0, (cells_room){0}), 0);
    size_t cap = nl.row_capacity;
    /* a few thousand particles: every row fits its 16-bit windows (cells.h) */
    assert_false(nl.wide);
    int32_t *scalar_rows = rows_of(&nl, cap);
    for (int width = 4; width <= 8; width += 4) {
        lanes_limit(width);
        neighbours_free(&nl);
        nl.row_capacity = 4; /* force the overflow path */
        assert_int_equal(neighbours_build(&nl, &grid, p.x, p.n_fluid, radius, 0.0, (cells_room){0}),
                         0);
        assert_int_equal(nl.row_capacity, cap);
        assert_rows_equal(&nl, scalar_rows, cap);
    }
    lanes_limit(8);
    /* the rows kept whole, 32 bits an entry, are the same rows */
    neighbours_free(&nl);
    nl.wide = true;
    assert_int_equal(neighbours_build(&nl, &grid, p.x, p.n_fluid, radius, 0.0, (cells_room){0}), 0);
    assert_true(nl.wide);
    assert_rows_equal(&nl, scalar_rows, cap);
    neighbours_free(&nl);
    assert_int_equal(neighbours_build(&nl, &grid, p.x, p.n_fluid, radius, 0.0, (cells_room){0}), 0);

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
        memcpy(found, neighbour_row(&nl, i, found), (size_t)m * sizeof *found);
        qsort(found, (size_t)m, sizeof *found, compare_int32);
        for (int32_t k = 0; k < m; k++) assert_int_equal(found[k], expected[k]);
        pairs += (size_t)m;
    }
    assert_true(pairs > 0);
    check_marked_cells(&grid, &p, radius);

    /* The next build sizes its rows by this one's longest: a sixteenth more (cells.h), not
     * the 4 of the overflow test nor a fixed guess; same rows. */
    int32_t longest = 0;
    for (size_t i = 0; i < p.n_fluid; i++)
        if (nl.count[i] > longest) longest = nl.count[i];
    assert_int_equal(nl.longest, longest);
    assert_int_equal(neighbours_build(&nl, &grid, p.x, p.n_fluid, radius, 0.0, (cells_room){0}), 0);
    assert_int_equal(nl.row_capacity, (size_t)longest + (size_t)longest / 16);
    assert_rows_equal(&nl, scalar_rows, cap);

    /* Positions copied into room a caller lends (cells_room): the same rows, no room of the
     * grid's own, and the grid keeps no pointer into the lent room after the build. Room one
     * double short goes unused. */
    cells_free(&grid);
    assert_int_equal(cells_setup(&grid, lo, hi, radius, 0.0), 0);
    assert_int_equal(cells_bin(&grid, p.x, p.n_total), 0);
    size_t room = DIM * p.n_total;
    double *lent = malloc(room * sizeof *lent);
    assert_int_equal(
        neighbours_build(&nl, &grid, p.x, p.n_fluid, radius, 0.0, (cells_room){lent, room}), 0);
    assert_rows_equal(&nl, scalar_rows, cap);
    assert_null(grid.own_xs);
    for (int d = 0; d < DIM; d++) assert_null(grid.xs[d]);
    assert_int_equal(
        neighbours_build(&nl, &grid, p.x, p.n_fluid, radius, 0.0, (cells_room){lent, room - 1}), 0);
    assert_rows_equal(&nl, scalar_rows, cap);
    assert_non_null(grid.own_xs);
    check_near_parts(&grid, &p, radius, scalar_rows, cap);
    free(lent);
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

/* A row whose fluid neighbours lie further apart in index than a 16-bit window (cells.h): the
 * build keeps every row whole, with the same neighbours in the same order, and so does the
 * next build. Particles on a lattice wider than the radius, so that each has no neighbour,
 * but for particle 0, next to which lie particle 1 and the last. */
static void test_rows_beyond_window(void **state)
{
    (void)state;
    size_t side = DIM == 2 ? 200 : 35, n = 1;
    for (int d = 0; d < DIM; d++) n *= side;
    assert_true(n > NEIGHBOUR_WINDOW + 2);
    particles p;
    assert_int_equal(particles_init(&p, n), 0);
    double spacing = 1.0 / (double)side, radius = 0.4 * spacing;
    for (size_t i = 0; i < n; i++)
        for (int d = 0, rest = (int)i; d < DIM; d++, rest /= (int)side)
            p.x[d][i] = (0.5 + (double)(rest % (int)side)) * spacing;
    for (int d = 0; d < DIM; d++) {
        p.x[d][1] = p.x[d][0] + (d == 0 ? 0.1 : 0.0) * spacing;
        p.x[d][n - 1] = p.x[d][0] + (d == 1 ? 0.1 : 0.0) * spacing;
    }
    p.n_fluid = p.n_total = n;
    cell_grid grid = {0};
    unit_box_cells(&grid, radius);
    assert_int_equal(cells_bin(&grid, p.x, n), 0);
    neighbour_list nl = {0};
    for (int build = 0; build < 2; build++) {
        assert_int_equal(neighbours_build(&nl, &grid, p.x, n, radius, 0.0, (cells_room){0}), 0);
        assert_true(nl.wide);
        int32_t entries[nl.row_capacity];
        const int32_t *row = neighbour_row(&nl, 0, entries);
        assert_int_equal(nl.count[0], 2);
        assert_int_equal(row[0], 1);
        assert_int_equal(row[1], (int32_t)(n - 1));
        assert_int_equal(nl.count[1], 2);
        assert_int_equal(nl.count[2], 0);
    }
    cells_free(&grid);
    neighbours_free(&nl);
    particles_free(&p);
}

/* The binning on 1 to 4 threads (each counts and fills its share of the particles): the same
 * cells, starts and items, and each cell's particles in ascending order, as one thread sorts
 * them. */
static void test_bin_any_thread_count(void **state)
{
    (void)state;
    size_t n = 3001;
    particles p;
    assert_int_equal(particles_init(&p, n), 0);
    scatter(&p, n, 5);
    cell_grid one = {0}, grid = {0};
    unit_box_cells(&one, 0.07);
    unit_box_cells(&grid, 0.07);
    omp_set_num_threads(1);
    assert_int_equal(cells_bin(&one, p.x, n), 0);
    for (size_t c = 0; c < one.n_cells; c++)
        for (size_t m = one.start[c] + 1; m < one.start[c + 1]; m++)
            assert_true(one.item[m] > one.item[m - 1]);
    assert_int_equal(one.start[one.n_cells], n);
    for (int threads = 2; threads <= 4; threads++) {
        omp_set_num_threads(threads);
        assert_int_equal(cells_bin(&grid, p.x, n), 0);
        assert_memory_equal(grid.cell_of, one.cell_of, n * sizeof *one.cell_of);
        assert_memory_equal(grid.start, one.start, (one.n_cells + 1) * sizeof *one.start);
        assert_memory_equal(grid.item, one.item, n * sizeof *one.item);
    }
    cells_free(&one);
    cells_free(&grid);
    particles_free(&p);
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
    unit_box_cells(&grid, 0.1);
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
        cmocka_unit_test(test_rows_beyond_window),
        cmocka_unit_test(test_sort_by_cell),
        cmocka_unit_test(test_bin_any_thread_count),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
