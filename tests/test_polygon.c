/* A tank's section as a polygon (boundary/polygon.c), against figures known without it:
 * - the area of a box, of a chamfered section (the box less two right triangles) and of an L,
 *   exact to round-off, in either direction of the corner list;
 * - the inside test on points of known side, on the edges and at the corners, including the
 *   notch of a non-convex L;
 * - the wall distance against hand-computed distances to the nearest edge or corner, with the
 *   normal into the polygon, inside (positive) and outside (negative), at a chamfer's slanted
 *   wall, off a convex corner and by an L's reflex corner, where the nearest point is the
 *   corner itself, and which edge or corner holds that point;
 * - the refusals, each naming what the user wrote: fewer than three corners, a corner repeated,
 *   corners on one line, edges that cross (a bow tie), touch (a corner on another edge) or fold
 *   back (a spike), with the edges numbered as the list numbers them. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "core/polygon.h"

#include <math.h>
#include <string.h>

#define ROUND_OFF 1e-14

static polygon make(const double *xy, int n)
{
    polygon pg;
    char err[200] = "";
    int rc = polygon_make(&pg, xy, n, err, sizeof err);
    if (rc) fail_msg("polygon refused: %s", err);
    return pg;
}

/* A box 1 x 0.5, the same with its lower corners cut at 45 degrees by 0.1 (an LNG tank's
 * lower chamfers), and an L: the unit square less its upper right quarter. */
static const double box[] = {0, 0, 1, 0, 1, 0.5, 0, 0.5};
static const double chamfer[] = {0.1, 0, 0.9, 0, 1, 0.1, 1, 0.5, 0, 0.5, 0, 0.1};
static const double ell[] = {0, 0, 1, 0, 1, 0.5, 0.5, 0.5, 0.5, 1, 0, 1};

static void reversed(const double *xy, int n, double *out)
{
    for (int k = 0; k < n; k++) {
        out[2 * k] = xy[2 * (n - 1 - k)];
        out[2 * k + 1] = xy[2 * (n - 1 - k) + 1];
    }
}

static void test_area_either_direction(void **state)
{
    (void)state;
    const double *shapes[] = {box, chamfer, ell};
    const int corners[] = {4, 6, 6};
    const double area[] = {0.5, 0.5 - 2 * 0.5 * 0.1 * 0.1, 0.75};
    for (int s = 0; s < 3; s++) {
        double back[12];
        reversed(shapes[s], corners[s], back);
        polygon a = make(shapes[s], corners[s]), b = make(back, corners[s]);
        assert_true(fabs(polygon_area(&a) - area[s]) < ROUND_OFF);
        assert_true(fabs(polygon_area(&b) - area[s]) < ROUND_OFF);
        /* the clockwise list is reversed, and each corner keeps the number the user gave it */
        assert_int_equal(b.order[0], corners[s]);
        assert_true(b.corner[0][0] == shapes[s][0] && b.corner[0][1] == shapes[s][1]);
        double lo[2], hi[2];
        polygon_bounds(&b, lo, hi);
        assert_true(lo[0] == 0 && lo[1] == 0 && hi[0] == 1 && hi[1] == (s == 2 ? 1 : 0.5));
    }
}

static void test_contains(void **state)
{
    (void)state;
    polygon l = make(ell, 6), c = make(chamfer, 6);
    assert_true(polygon_contains(&l, 0.25, 0.75));  /* the L's upright */
    assert_true(polygon_contains(&l, 0.75, 0.25));  /* its foot */
    assert_false(polygon_contains(&l, 0.75, 0.75)); /* the notch */
    assert_true(polygon_contains(&l, 0.5, 0.75));   /* on an edge */
    assert_true(polygon_contains(&l, 0.5, 0.5));    /* the re-entrant corner */
    assert_false(polygon_contains(&l, -0.01, 0.5));
    assert_false(polygon_contains(&c, 0.02, 0.02)); /* cut off by the chamfer */
    assert_true(polygon_contains(&c, 0.06, 0.06));
    assert_true(polygon_contains(&c, 0.05, 0.05)); /* on the chamfer */
}

static void check_distance(const polygon *pg, double x, double y, double d, double nx, double ny)
{
    double n[2];
    double got = polygon_wall_distance(pg, x, y, n, NULL);
    if (fabs(got - d) > ROUND_OFF || fabs(n[0] - nx) > ROUND_OFF || fabs(n[1] - ny) > ROUND_OFF)
        fail_msg("at (%g, %g): distance %.17g normal (%.17g, %.17g), expected %.17g (%.17g, "
                 "%.17g)",
                 x, y, got, n[0], n[1], d, nx, ny);
}

static void test_wall_distance(void **state)
{
    (void)state;
    polygon c = make(chamfer, 6), l = make(ell, 6);
    const double r = M_SQRT1_2;
    check_distance(&c, 0.5, 0.1, 0.1, 0, 1);    /* above the floor */
    check_distance(&c, 0.5, -0.2, -0.2, 0, 1);  /* below it, outside */
    check_distance(&c, 0.98, 0.3, 0.02, -1, 0); /* by the right wall */
    /* from (0.1, 0.1) to the chamfer x + y = 0.1: 0.1 / sqrt(2), normal (1, 1) / sqrt(2) */
    check_distance(&c, 0.1, 0.1, 0.1 * r, r, r);
    check_distance(&c, 0.0, 0.0, -0.05 / r, r, r); /* the cut corner, outside */
    /* outside, off the box corner (1, 0.5): the corner is nearest, and the normal points from
       the point back to it */
    check_distance(&c, 1.1, 0.6, -0.1 / r, -r, -r);
    /* inside, by the L's reflex corner (0.5, 0.5): the corner is nearest to (0.45, 0.45), at
       0.05 sqrt(2), not either wall through it; the normal points away from it */
    check_distance(&l, 0.45, 0.45, 0.05 / r, -r, -r);
    int feature;
    double n[2];
    polygon_wall_distance(&l, 0.45, 0.45, n, &feature);
    assert_int_equal(feature, 6 + 3); /* corner 3, (0.5, 0.5) */
    polygon_wall_distance(&c, 1.1, 0.6, n, &feature);
    assert_int_equal(feature, 6 + 3); /* corner 3, (1, 0.5) */
    /* in the notch, outside: the nearer of the two walls through that corner */
    assert_true(fabs(polygon_wall_distance(&l, 0.6, 0.58, n, &feature) + 0.08) < ROUND_OFF);
    assert_int_equal(feature, 2); /* the edge from corner 2 (1, 0.5) to corner 3 (0.5, 0.5) */
    assert_true(n[0] == 0 && n[1] == -1);
}

static void refused(const double *xy, int n, const char *expected)
{
    polygon pg;
    char err[200] = "";
    assert_int_equal(polygon_make(&pg, xy, n, err, sizeof err), -1);
    if (!strstr(err, expected)) fail_msg("message \"%s\" lacks \"%s\"", err, expected);
    assert_int_equal(pg.n, 0);
}

static void test_refusals(void **state)
{
    (void)state;
    const double two[] = {0, 0, 1, 0};
    refused(two, 2, "at least three corners and at most 128, 2 given");
    const double repeated[] = {0, 0, 1, 0, 1, 0, 0, 1};
    refused(repeated, 4, "corners 2 and 3 are the same point");
    /* corners on one line: the last edge folds back over the others */
    const double line[] = {0, 0, 1, 0, 2, 0};
    refused(line, 3, "edge 1 (corner 1 to 2) meets edge 3 (corner 3 to 1)");
    const double bow_tie[] = {0, 0, 1, 1, 1, 0, 0, 1};
    refused(bow_tie, 4, "edge 1 (corner 1 to 2) meets edge 3 (corner 3 to 4)");
    /* corner 4 lies on edge 1 */
    const double touch[] = {0, 0, 2, 0, 2, 1, 1, 0, 0, 1};
    refused(touch, 5, "edge 1 (corner 1 to 2) meets edge 3 (corner 3 to 4)");
    /* corner 3 goes back along edge 2 */
    const double spike[] = {0, 0, 1, 0, 1, 1, 1, 0.5, 0, 1};
    refused(spike, 5, "edge 2 (corner 2 to 3) meets edge 3 (corner 3 to 4)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_area_either_direction),
        cmocka_unit_test(test_contains),
        cmocka_unit_test(test_wall_distance),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
