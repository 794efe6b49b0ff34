/* polygon_images: the wall images of a tank whose section is a polygon, the box's mirror ghosts
 * (Colagrossi & Landrini 2003) carried to any wall: a particle near a wall has its image across
 * the wall's line; near a convex corner, also its image through the corner (the point
 * reflection, which at a right angle is the box's product of the two walls' reflections). Each
 * image is kept only where it falls in the part of the solid nearest to the wall or corner it
 * was made across (that feature's Voronoi region), so that the images tile the solid along the
 * walls once: for a convex polygon every such region is the mirror of a region of the liquid,
 * and the images stand at the liquid's own spacing, as the tangent-line images of Yildiz, Rook
 * and Suleman (Int. J. Numer. Meth. Eng. 77, 2009) do along a curved wall. By a reflex corner
 * (a notch, a baffle's end) the part of the solid that neither wall's images reach is left
 * empty. Two-dimensional: the section of a 2D tank or of a prism tank. */
#ifndef VCSPH_POLYGON_IMAGES_H
#define VCSPH_POLYGON_IMAGES_H

#include "core/polygon.h"

/* An image's map: x' = a x + b (positions), v' = a v (vectors). */
typedef struct {
    double a[2][2], b[2];
} polygon_image_map;

/* The maps of pg's images, 2 n of them: entry k the reflection across the line of edge k,
 * entry n + k the point reflection through corner k. */
void polygon_image_maps(const polygon *pg, polygon_image_map *maps);

/* The images the point (x, y), inside pg, has within `reach` of its walls: the entries of
 * polygon_image_maps whose image of the point lies in the solid, in the region nearest to the
 * edge or corner it was made across, and closer to the point than 2 reach. Writes at most `max`
 * entries into `features`, in increasing order; returns how many there are. */
int polygon_images_of(const polygon *pg, double x, double y, double reach, int *features, int max);

#endif
