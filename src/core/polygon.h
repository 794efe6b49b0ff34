/* polygon: a tank's section as a simple polygon in the x-y plane of the tank frame (a 2D tank,
 * or the section a prism tank extrudes along z): checked once when it is read, then asked
 * whether a point is inside, how far the nearest wall is and which way it faces. Independent of
 * DIM: a section is always two-dimensional. */
#ifndef VCSPH_POLYGON_H
#define VCSPH_POLYGON_H

#include <stddef.h>

/* The most corners a section may have, so that a polygon is a value a case's config can hold
 * (a circle of 128 sides is within 0.04 % of its area). */
#define POLYGON_CORNERS_MAX 128

/* The corners, counter-clockwise (the liquid on the left of each edge), edge k running from
 * corner k to corner k + 1 (mod n). `order` maps a corner back to its place in the list the
 * user gave (1-based, as messages name it), since a clockwise list is reversed. A value: it
 * holds no memory of its own. */
typedef struct {
    int n;
    double corner[POLYGON_CORNERS_MAX][2];
    int order[POLYGON_CORNERS_MAX];
} polygon;

/* The polygon of the n corners xy[0..2n): (x, y) pairs in metres, in either direction, closed
 * automatically. Refused, with a message in err that names the corners as the list numbers
 * them (1-based): fewer than three corners or more than POLYGON_CORNERS_MAX, two consecutive
 * corners at one point, two edges that cross, touch or fold back on each other other than at a
 * shared corner (corners on one line fold back). Returns 0, or -1 (err says why). */
int polygon_make(polygon *pg, const double *xy, int n, char *err, size_t err_len);

/* The area enclosed, in m^2 (positive). */
double polygon_area(const polygon *pg);

/* The bounding box: lo[0..1], hi[0..1]. */
void polygon_bounds(const polygon *pg, double lo[2], double hi[2]);

/* Whether (x, y) lies inside (points on an edge count as inside). */
int polygon_contains(const polygon *pg, double x, double y);

/* The distance from (x, y) to the nearest point of the boundary, positive inside and negative
 * outside; the unit normal of the wall there pointing into the polygon (at a corner, along the
 * line from that corner to the point, towards the inside); and the feature that holds that
 * point: k for the inside of edge k (from corner k to k + 1), n + k for corner k. */
double polygon_wall_distance(const polygon *pg, double x, double y, double normal[2], int *feature);

#endif
