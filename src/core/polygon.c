/* polygon: checks of a tank's section, and the inside test and wall distance on it. */
#include "core/polygon.h"

#include <math.h>
#include <stdio.h>

/* Twice the signed area of the triangle a, b, c: > 0 when c lies left of a -> b. */
static double orient(const double a[2], const double b[2], const double c[2])
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

/* Whether c, known to lie on the line a-b, lies on the segment a-b. */
static int within_segment(const double a[2], const double b[2], const double c[2])
{
    return fmin(a[0], b[0]) <= c[0] && c[0] <= fmax(a[0], b[0]) && fmin(a[1], b[1]) <= c[1] &&
           c[1] <= fmax(a[1], b[1]);
}

/* Whether the segments a-b and c-d share a point (the orientation test of Cormen et al.,
 * Introduction to Algorithms, sec. 33.1). */
static int segments_meet(const double a[2], const double b[2], const double c[2], const double d[2])
{
    int o1 = sign_of(orient(a, b, c)), o2 = sign_of(orient(a, b, d));
    int o3 = sign_of(orient(c, d, a)), o4 = sign_of(orient(c, d, b));
    if (o1 != o2 && o3 != o4) return 1;
    return (o1 == 0 && within_segment(a, b, c)) || (o2 == 0 && within_segment(a, b, d)) ||
           (o3 == 0 && within_segment(c, d, a)) || (o4 == 0 && within_segment(c, d, b));
}

static double signed_double_area(const double *xy, int n)
{
    double s = 0.0;
    for (int k = 0; k < n; k++) {
        int l = (k + 1) % n;
        s += xy[2 * k] * xy[2 * l + 1] - xy[2 * l] * xy[2 * k + 1];
    }
    return s;
}

/* Whether the edges from corner `shared` to p and to q run along one ray: two edges that share
 * a corner meet only there unless one folds back over the other. */
static int folds_back(const double p[2], const double shared[2], const double q[2])
{
    double dot = (p[0] - shared[0]) * (q[0] - shared[0]) + (p[1] - shared[1]) * (q[1] - shared[1]);
    return orient(p, shared, q) == 0.0 && dot > 0.0;
}

/* The first pair of edges (in the user's numbering, edge k from corner k to k + 1) that cross,
 * touch or fold back on each other; 0 when there is none. */
static int first_crossing(const double *xy, int n, int *e1, int *e2)
{
    for (int k = 0; k < n; k++) {
        const double *a = xy + 2 * k, *b = xy + 2 * ((k + 1) % n);
        for (int l = k + 1; l < n; l++) {
            const double *c = xy + 2 * l, *d = xy + 2 * ((l + 1) % n);
            int meet = l == k + 1         ? folds_back(a, b, d) /* edge l starts where k ends */
                       : (l + 1) % n == k ? folds_back(b, a, c) /* edge l ends where k starts */
                                          : segments_meet(a, b, c, d);
            if (meet) {
                *e1 = k;
                *e2 = l;
                return 1;
            }
        }
    }
    return 0;
}

int polygon_make(polygon *pg, const double *xy, int n, char *err, size_t err_len)
{
    pg->n = 0;
    if (n < 3 || n > POLYGON_CORNERS_MAX) {
        snprintf(err, err_len, "a polygon needs at least three corners and at most %d, %d given",
                 POLYGON_CORNERS_MAX, n);
        return -1;
    }
    for (int k = 0; k < n; k++) {
        int l = (k + 1) % n;
        if (xy[2 * k] == xy[2 * l] && xy[2 * k + 1] == xy[2 * l + 1]) {
            snprintf(err, err_len, "corners %d and %d are the same point (%g, %g)", k + 1, l + 1,
                     xy[2 * k], xy[2 * k + 1]);
            return -1;
        }
    }
    int e1, e2;
    if (first_crossing(xy, n, &e1, &e2)) {
        snprintf(err, err_len,
                 "the polygon crosses itself: edge %d (corner %d to %d) meets edge %d (corner "
                 "%d to %d)",
                 e1 + 1, e1 + 1, (e1 + 1) % n + 1, e2 + 1, e2 + 1, (e2 + 1) % n + 1);
        return -1;
    }
    double area2 = signed_double_area(xy, n); /* not 0: a simple polygon encloses an area */
    pg->n = n;
    for (int k = 0; k < n; k++) {
        int from = area2 > 0.0 ? k : n - 1 - k; /* clockwise lists are reversed */
        pg->corner[k][0] = xy[2 * from];
        pg->corner[k][1] = xy[2 * from + 1];
        pg->order[k] = from + 1;
    }
    return 0;
}

double polygon_area(const polygon *pg)
{
    return 0.5 * signed_double_area(&pg->corner[0][0], pg->n);
}

void polygon_bounds(const polygon *pg, double lo[2], double hi[2])
{
    for (int d = 0; d < 2; d++) lo[d] = hi[d] = pg->corner[0][d];
    for (int k = 1; k < pg->n; k++)
        for (int d = 0; d < 2; d++) {
            lo[d] = fmin(lo[d], pg->corner[k][d]);
            hi[d] = fmax(hi[d], pg->corner[k][d]);
        }
}

int polygon_contains(const polygon *pg, double x, double y)
{
    const double c[2] = {x, y};
    int inside = 0;
    for (int k = 0; k < pg->n; k++) {
        const double *a = pg->corner[k], *b = pg->corner[(k + 1) % pg->n];
        if (orient(a, b, c) == 0.0 && within_segment(a, b, c)) return 1;
        /* the crossing rule: the edges that straddle the horizontal line through the point and
           cross it to its right */
        if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
            inside = !inside;
    }
    return inside;
}

/* The point of edge k nearest to (x, y): its parameter t along the edge (0 at corner k, 1 at
 * corner k + 1), and its distance. */
static double edge_foot(const polygon *pg, int k, double x, double y, double *t)
{
    const double *a = pg->corner[k], *b = pg->corner[(k + 1) % pg->n];
    double ex = b[0] - a[0], ey = b[1] - a[1];
    *t = fmin(1.0, fmax(0.0, ((x - a[0]) * ex + (y - a[1]) * ey) / (ex * ex + ey * ey)));
    return hypot(x - (a[0] + *t * ex), y - (a[1] + *t * ey));
}

/* The feature that holds the point of edge k at parameter t. */
static int feature_of(const polygon *pg, int k, double t)
{
    return t > 0.0 && t < 1.0 ? k : t == 0.0 ? pg->n + k : pg->n + (k + 1) % pg->n;
}

double polygon_wall_distance(const polygon *pg, double x, double y, double normal[2], int *feature)
{
    double best = INFINITY, best_t = 0.0;
    int best_edge = 0;
    for (int k = 0; k < pg->n; k++) {
        double t, d = edge_foot(pg, k, x, y, &t);
        if (d < best) {
            best = d;
            best_t = t;
            best_edge = k;
        }
    }
    double sign = polygon_contains(pg, x, y) ? 1.0 : -1.0;
    const double *a = pg->corner[best_edge], *b = pg->corner[(best_edge + 1) % pg->n];
    if (best == 0.0 || (best_t > 0.0 && best_t < 1.0)) {
        /* the edge's own normal: left of a -> b, into the polygon */
        double len = hypot(b[0] - a[0], b[1] - a[1]);
        normal[0] = -(b[1] - a[1]) / len;
        normal[1] = (b[0] - a[0]) / len;
    } else { /* nearest to a corner: along the line from it, towards the inside */
        const double *q = best_t == 0.0 ? a : b;
        normal[0] = sign * (x - q[0]) / best;
        normal[1] = sign * (y - q[1]) / best;
    }
    if (feature) *feature = feature_of(pg, best_edge, best_t);
    return sign * best;
}
