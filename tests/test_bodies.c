/* The bodies of liquid (scheme/bodies.h): the connected pieces of S_F, its particles joined
 * when within 2h. bodies_find unites the sets in parallel, in whatever order the threads reach
 * the pairs; the pieces and their numbering must not depend on that order. On a disordered
 * block of liquid whose S_F is a random share of the fluid (pieces of one to dozens of
 * particles, some at the walls): the bodies, their numbering, their walls and their members against
 * a flood fill of the same pairs, one particle after the other, for 1 to 4 threads, several
 * times each (more threads than cores interleave the unions in more ways). */
#include "core/pair.h"
#include "diag/freesurface.h"
#include "scheme/bodies.h"
#include "scheme/solver.h"

#include <omp.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "disordered_block.h"

/* The pieces by a flood fill from each unlabelled S_F particle in index order: piece k is the
 * k-th to be reached, so it is numbered by its least index, as bodies_find numbers them;
 * at_wall[k]: a wall's image within 2h of one of its particles. Returns the pieces. */
static size_t flood_fill(const solver *s, const neighbour_list *rows, int32_t *piece,
                         uint8_t *at_wall)
{
    const particles *p = &s->p;
    size_t n = p->n_fluid, pieces = 0;
    int32_t *queue = malloc(n * sizeof *queue);
    assert_non_null(queue);
    for (size_t i = 0; i < n; i++) piece[i] = -1;
    for (size_t seed = 0; seed < n; seed++) {
        if (p->surface[seed] == SURFACE_INTERIOR || piece[seed] >= 0) continue;
        size_t head = 0, tail = 0;
        piece[seed] = (int32_t)pieces;
        at_wall[pieces] = 0;
        queue[tail++] = (int32_t)seed;
        while (head < tail) {
            size_t i = (size_t)queue[head++];
            vec xi = vec_load(p->x, i);
            pair pr;
            FOR_EACH_PAIR (&s->pp.k, p->x, rows, i, xi, pr) {
                if (particle_is_wall_image(p, pr.j)) {
                    at_wall[pieces] = 1;
                } else if (p->surface[pr.j] != SURFACE_INTERIOR && piece[pr.j] < 0) {
                    piece[pr.j] = (int32_t)pieces;
                    queue[tail++] = (int32_t)pr.j;
                }
            }
        }
        pieces++;
    }
    free(queue);
    return pieces;
}

static void bodies_match_a_flood_fill(void **state)
{
    (void)state;
    config cfg;
    solver s;
    disordered_block(ALE_BLOCK_CASE, 0.3, 20261206, &cfg, &s);
    particles *p = &s.p;
    size_t n = p->n_fluid;
    neighbour_list rows = solver_prepared_rows(&s);
    /* S_F a random share of the fluid that gives each of its particles about four S_F
       neighbours within 2h: about a random geometric graph's percolation threshold (a mean of
       about 4.5 neighbours in 2D, 2.7 in 3D), pieces of every size, the largest of dozens of
       particles whose unions the threads race to make */
    double near = 0.0;
    for (size_t i = 0; i < n; i++) near += rows.count[i];
    double share = 4.0 / (near / (double)n);
    uint64_t seed = 7;
    size_t in_band = 0;
    for (size_t i = 0; i < n; i++) {
        p->surface[i] = 0.5 * (noise(&seed) + 1.0) < share ? SURFACE_FREE : SURFACE_INTERIOR;
        in_band += p->surface[i] != SURFACE_INTERIOR;
    }
    int32_t *piece = malloc(n * sizeof *piece);
    uint8_t *at_wall = malloc(n);
    assert_non_null(piece);
    assert_non_null(at_wall);
    size_t pieces = flood_fill(&s, &rows, piece, at_wall), walled = 0;
    for (size_t k = 0; k < pieces; k++) walled += at_wall[k];
    printf("%zu fluid particles, %zu in S_F, %zu pieces (%zu at a wall)\n", n, in_band, pieces,
           walled);
    /* several pieces, some of several particles, some at the walls and some not */
    assert_true(pieces >= 5 && pieces + 3 <= in_band && walled > 0 && walled < pieces);
    bodies b = {0};
    assert_int_equal(bodies_reserve(&b, particles_images_begin(p)), 0);
    for (int threads = 1; threads <= 4; threads++)
        for (int run = 0; run < 5; run++) {
            omp_set_num_threads(threads);
            assert_int_equal(bodies_find(&s.pp.k, p, &rows, NULL, &b), 0);
            assert_int_equal(b.count, pieces);
            assert_int_equal(b.n_members, in_band);
            size_t member = 0;
            for (size_t i = 0; i < n; i++) {
                assert_int_equal(b.id[i], piece[i]);
                if (piece[i] >= 0) assert_int_equal(b.members[member++], (int32_t)i);
            }
            for (size_t k = 0; k < pieces; k++) assert_int_equal(b.at_wall[k], at_wall[k]);
        }
    bodies_free(&b);
    free(piece);
    free(at_wall);
    solver_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(bodies_match_a_flood_fill)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
