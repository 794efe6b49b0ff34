/* polygon_images: which walls and corners of a polygon tank mirror a particle. */
#include "boundary/polygon_images.h"

#include <math.h>

void polygon_image_maps(const polygon *pg, polygon_image_map *maps)
{
    int n = pg->n;
    for (int k = 0; k < n; k++) {
        const double *c = pg->corner[k], *next = pg->corner[(k + 1) % n];
        double len = hypot(next[0] - c[0], next[1] - c[1]);
        /* the edge's unit normal into the polygon, and the line n . x = distance */
        double normal[2] = {-(next[1] - c[1]) / len, (next[0] - c[0]) / len};
        double distance = normal[0] * c[0] + normal[1] * c[1];
        polygon_image_map *edge = &maps[k], *corner = &maps[n + k];
        for (int r = 0; r < 2; r++) {
            for (int s = 0; s < 2; s++) {
                edge->a[r][s] = (r == s ? 1.0 : 0.0) - 2.0 * normal[r] * normal[s];
                corner->a[r][s] = r == s ? -1.0 : 0.0;
            }
            edge->b[r] = 2.0 * distance * normal[r];
            corner->b[r] = 2.0 * c[r];
        }
    }
}

/* Whether the point `image`, made across `feature`, lies outside pg in the region nearest to
 * that same edge or corner. Images from two sides that meet on the bisector of a reflex corner
 * agree to round-off, so a tie within 1e-9 of the reach goes to the lower-numbered feature:
 * one of the two is kept. */
static int image_kept(const polygon *pg, const double image[2], int feature, double reach)
{
    return !polygon_contains(pg, image[0], image[1]) &&
           polygon_nearest_feature(pg, image[0], image[1], 1e-9 * reach) == feature;
}

int polygon_images_of(const polygon *pg, double x, double y, double reach, int *features, int max)
{
    int n = pg->n, count = 0;
    for (int k = 0; k < n; k++) { /* the walls: reflections across their lines */
        const double *c = pg->corner[k], *next = pg->corner[(k + 1) % n];
        double ex = next[0] - c[0], ey = next[1] - c[1], len = hypot(ex, ey);
        double t = ((x - c[0]) * ex + (y - c[1]) * ey) / (len * len);
        double depth = (ex * (y - c[1]) - ey * (x - c[0])) / len; /* left of the edge: inside */
        if (!(t >= 0.0 && t <= 1.0 && depth >= 0.0 && depth < reach)) continue;
        /* x - 2 depth n, n = (-ey, ex) / len the normal into the polygon */
        const double image[2] = {x + 2.0 * depth * ey / len, y - 2.0 * depth * ex / len};
        if (image_kept(pg, image, k, reach)) {
            if (count < max) features[count] = k;
            count++;
        }
    }
    for (int k = 0; k < n; k++) { /* the corners: point reflections through them */
        const double *c = pg->corner[k];
        if (!(hypot(x - c[0], y - c[1]) < reach)) continue;
        const double image[2] = {2.0 * c[0] - x, 2.0 * c[1] - y};
        if (image_kept(pg, image, n + k, reach)) {
            if (count < max) features[count] = n + k;
            count++;
        }
    }
    return count;
}
