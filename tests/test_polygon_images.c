/* The wall images of a polygon tank (boundary/polygon_images.c), against what mirror ghosts
 * must give whatever the section:
 * - a square turned by 30 degrees and filled with a lattice along its sides: the liquid and
 *   its images are the lattice continued past every wall and corner, so each particle's kernel
 *   sum dr^2 sum_j W_ij is the whole lattice's (kernel_lattice_sum) to round-off (1e-12), at
 *   the walls and in the corners alike;
 * - a chamfered section (a box with its four corners cut at 45 degrees, eight convex corners of
 *   135 degrees) filled with an axis lattice that the chamfers cut at a slant: the images of
 *   the particles within w of the walls fill the solid band of width w around the section,
 *   whose area is P w + pi w^2 for a convex polygon of perimeter P (Steiner's formula): the
 *   images' count times dr^2 matches it within 0.3 %, where the count of lattice points in the
 *   slanted strips is known to a row's worth of points; a corner whose wedge the images missed
 *   would take 1.1 % off, one the two walls' images both filled would add as much (w^2 / 2 of
 *   0.045 m^2);
 * - no two images closer than dr / 2, in the chamfered section and in an L (a reflex corner):
 *   the images tile the solid once; and no image inside the section. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "boundary/polygon_images.h"
#include "core/kernel.h"

#include <math.h>
#include <stdlib.h>

#define MAX_FEATURES 8

typedef struct {
    int n;
    double (*x)[2];
} points;

static void push(points *pts, double x, double y)
{
    pts->x = realloc(pts->x, (size_t)(pts->n + 1) * sizeof *pts->x);
    assert_non_null(pts->x);
    pts->x[pts->n][0] = x;
    pts->x[pts->n][1] = y;
    pts->n++;
}

static void map_point(const polygon_image_map *m, const double x[2], double out[2])
{
    for (int r = 0; r < 2; r++) out[r] = m->a[r][0] * x[0] + m->a[r][1] * x[1] + m->b[r];
}

/* The images of the liquid's particles within `reach` of the walls. */
static points images_of(const polygon *pg, const points *liquid, double reach)
{
    polygon_image_map *maps = malloc(2 * (size_t)pg->n * sizeof *maps);
    assert_non_null(maps);
    polygon_image_maps(pg, maps);
    points images = {0};
    for (int i = 0; i < liquid->n; i++) {
        int features[MAX_FEATURES];
        int n =
            polygon_images_of(pg, liquid->x[i][0], liquid->x[i][1], reach, features, MAX_FEATURES);
        assert_true(n <= MAX_FEATURES);
        for (int f = 0; f < n; f++) {
            double image[2];
            map_point(&maps[features[f]], liquid->x[i], image);
            push(&images, image[0], image[1]);
        }
    }
    free(maps);
    return images;
}

static polygon make(const double *xy, int n)
{
    polygon pg;
    char err[200];
    if (polygon_make(&pg, xy, n, err, sizeof err)) fail_msg("%s", err);
    return pg;
}

static void test_turned_square_continues_the_lattice(void **state)
{
    (void)state;
    const double side = 0.5, dr = side / 20, angle = M_PI / 6;
    const double c = cos(angle), s = sin(angle), ox = 0.3, oy = 0.1;
    double xy[8];
    const double corners[4][2] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
    for (int k = 0; k < 4; k++) {
        xy[2 * k] = ox + c * corners[k][0] - s * corners[k][1];
        xy[2 * k + 1] = oy + s * corners[k][0] + c * corners[k][1];
    }
    polygon pg = make(xy, 4);
    points liquid = {0};
    for (int a = 0; a < 20; a++)
        for (int b = 0; b < 20; b++) {
            double u = (a + 0.5) * dr, v = (b + 0.5) * dr;
            push(&liquid, ox + c * u - s * v, oy + s * u + c * v);
        }
    kernel k = kernel_make(2.0 * dr);
    points images = images_of(&pg, &liquid, 2.0 * k.h);
    double whole = kernel_lattice_sum(&k, dr, 0), worst = 0.0;
    for (int i = 0; i < liquid.n; i++) {
        double sum = 0.0;
        const points *sets[2] = {&liquid, &images};
        for (int set = 0; set < 2; set++)
            for (int j = 0; j < sets[set]->n; j++)
                sum += kernel_w(&k, hypot(sets[set]->x[j][0] - liquid.x[i][0],
                                          sets[set]->x[j][1] - liquid.x[i][1]));
        worst = fmax(worst, fabs(sum * dr * dr / whole - 1.0));
    }
    print_message("turned square: largest |kernel sum / lattice's - 1| %.2e over %d particles, "
                  "%d images\n",
                  worst, liquid.n, images.n);
    assert_true(worst < 1e-12);
    free(liquid.x);
    free(images.x);
}

/* The points of the axis lattice of spacing dr (offset by dr / 2 from the bounding box) that lie
 * inside pg, at least `margin` from its walls. */
static points fill(const polygon *pg, double dr, double margin)
{
    double lo[2], hi[2], normal[2];
    polygon_bounds(pg, lo, hi);
    points liquid = {0};
    for (double y = lo[1] + 0.5 * dr; y < hi[1]; y += dr)
        for (double x = lo[0] + 0.5 * dr; x < hi[0]; x += dr)
            if (polygon_wall_distance(pg, x, y, normal, NULL) >= margin) push(&liquid, x, y);
    return liquid;
}

/* The smallest distance between two images, and the count of images inside pg. */
static double closest_pair(const polygon *pg, const points *images, int *inside)
{
    double closest = INFINITY;
    *inside = 0;
    for (int i = 0; i < images->n; i++) {
        *inside += polygon_contains(pg, images->x[i][0], images->x[i][1]);
        for (int j = i + 1; j < images->n; j++)
            closest = fmin(closest, hypot(images->x[i][0] - images->x[j][0],
                                          images->x[i][1] - images->x[j][1]));
    }
    return closest;
}

static void test_chamfered_section_band(void **state)
{
    (void)state;
    const double L = 0.3, H = 0.15, cut = 0.03, dr = 0.0015, w = 0.015;
    const double xy[] = {cut,     0, L - cut, 0, L, cut,     L, H - cut,
                         L - cut, H, cut,     H, 0, H - cut, 0, cut};
    polygon pg = make(xy, 8);
    points liquid = fill(&pg, dr, 0.0);
    points images = images_of(&pg, &liquid, w);
    double perimeter = 2 * (L - 2 * cut) + 2 * (H - 2 * cut) + 4 * cut * M_SQRT2;
    double band = perimeter * w + M_PI * w * w, counted = images.n * dr * dr;
    print_message("chamfered section: images' area %.6e m^2, band P w + pi w^2 %.6e m^2, "
                  "%+.3f %%\n",
                  counted, band, 100.0 * (counted / band - 1.0));
    assert_true(fabs(counted / band - 1.0) < 3e-3);
    int inside;
    double closest = closest_pair(&pg, &images, &inside);
    print_message("chamfered section: closest images %.3f dr apart, %d inside\n", closest / dr,
                  inside);
    assert_true(closest > 0.5 * dr);
    assert_int_equal(inside, 0);
    free(liquid.x);
    free(images.x);
}

static void test_reflex_corner_tiles_once(void **state)
{
    (void)state;
    const double dr = 0.01;
    const double xy[] = {0, 0, 0.4, 0, 0.4, 0.2, 0.2, 0.2, 0.2, 0.4, 0, 0.4};
    polygon pg = make(xy, 6);
    points liquid = fill(&pg, dr, 0.5 * dr - 1e-12);
    points images = images_of(&pg, &liquid, 4.0 * dr);
    int inside;
    double closest = closest_pair(&pg, &images, &inside);
    print_message("L: %d images, closest %.3f dr apart, %d inside\n", images.n, closest / dr,
                  inside);
    assert_true(closest > 0.5 * dr);
    assert_int_equal(inside, 0);
    free(liquid.x);
    free(images.x);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_turned_square_continues_the_lattice),
        cmocka_unit_test(test_chamfered_section_band),
        cmocka_unit_test(test_reflex_corner_tiles_once),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
