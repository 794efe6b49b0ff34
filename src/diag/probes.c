/* probes: wave gauges and pressure probes. Serial sums in particle order: a probe costs one
 * pass over the particles per time-series row, and the result is the same for any number of
 * threads. */
#include "diag/probes.h"

#include <math.h>
#include <stdlib.h>

/* sub-intervals of the Simpson rule for one value of the projected kernel (even) */
#define PROJECTION_INTERVALS 512

/* P(s) = integral over y of W(sqrt(s^2 + y^2)) = 2 x the integral over [0, sqrt(4h^2 - s^2)]
 * (Simpson's rule: W is a smooth polynomial inside its support). */
static double projected_kernel(const kernel *k, double s)
{
    double reach2 = k->support2 - s * s;
    if (reach2 <= 0.0) return 0.0;
    double b = sqrt(reach2), step = b / PROJECTION_INTERVALS, sum = 0.0;
    for (int i = 0; i <= PROJECTION_INTERVALS; i++) {
        double y = i * step;
        double weight = (i == 0 || i == PROJECTION_INTERVALS) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += weight * kernel_w(k, sqrt(s * s + y * y));
    }
    return 2.0 * sum * step / 3.0;
}

void probes_init(probes *pr, double h, double dr, double cell_volume, double tank_width)
{
    pr->k = kernel_make(h);
    pr->colour = kernel_make(dr);
    pr->cell_volume = cell_volume;
    pr->centre_z = 0.5 * tank_width;
    for (int i = 0; i <= PROBES_TABLE; i++)
        pr->projected[i] = projected_kernel(&pr->k, 2.0 * h * i / PROBES_TABLE);
    pr->projected[PROBES_TABLE + 1] = 0.0; /* the interpolation may read one past 2h */
}

/* P at distance s from the table, linearly interpolated */
static inline double projected_at(const probes *pr, double s)
{
    double u = s * pr->k.inv_h * (0.5 * PROBES_TABLE);
    if (u >= PROBES_TABLE) return 0.0;
    int i = (int)u;
    double f = u - i;
    return (1.0 - f) * pr->projected[i] + f * pr->projected[i + 1];
}

/* Whether particle j counts for a gauge: the fluid and the ghosts that are not mirrored
 * across the bottom or the roof (their map keeps the vertical, axis 1, as it is). */
static inline int counts_for_gauge(const particles *p, size_t j)
{
    return !particle_is_wall_image(p, j) || particle_ghost_map(p, j)->a[1][1] > 0.0;
}

/* distance from particle j to the gauge's vertical line */
static inline double distance_to_line(const probes *pr, const particles *p, size_t j, double x)
{
    double dx = p->x[0][j] - x;
#if DIM == 3
    double dz = p->x[2][j] - pr->centre_z;
    return sqrt(dx * dx + dz * dz);
#else
    (void)pr;
    return fabs(dx);
#endif
}

double probes_gauge(const probes *pr, const particles *p, double x)
{
    double depth = 0.0;
    for (size_t j = 0; j < p->n_total; j++)
        if (counts_for_gauge(p, j))
            depth += p->vol[j] * projected_at(pr, distance_to_line(pr, p, j, x));
    return depth;
}

/* The particles within the colour kernel's reach of a gauge's line: their height and squared
 * distance to the line. */
typedef struct {
    double y, s2;
} line_particle;

/* C at height y on the line, from its particles */
static double colour_at(const probes *pr, const line_particle *near, size_t n, double y)
{
    double c = 0.0;
    for (size_t m = 0; m < n; m++) {
        double dy = near[m].y - y, r2 = near[m].s2 + dy * dy;
        if (r2 < pr->colour.support2) c += kernel_w(&pr->colour, sqrt(r2));
    }
    return c * pr->cell_volume;
}

double probes_level(const probes *pr, const particles *p, double x)
{
    double reach2 = pr->colour.support2, reach = sqrt(reach2);
    line_particle *near = malloc(p->n_total * sizeof *near);
    if (!near) return NAN;
    size_t n = 0;
    double top = -INFINITY, bottom = INFINITY;
    for (size_t j = 0; j < p->n_total; j++) {
        double s = distance_to_line(pr, p, j, x);
        if (s * s >= reach2) continue;
        near[n++] = (line_particle){p->x[1][j], s * s};
        top = fmax(top, p->x[1][j]);
        bottom = fmin(bottom, p->x[1][j]);
    }
    /* down the line from above every particle in steps of h_c / 8, then bisection (no
       particle near the line: top < bottom, no step) */
    double step = 0.125 * pr->colour.h, above = top + reach, level = 0.0;
    for (double below = above - step; below > bottom - reach - step; above = below, below -= step) {
        if (colour_at(pr, near, n, below) < 0.5) continue;
        while (above - below > 1e-3 * pr->colour.h) {
            double mid = 0.5 * (above + below);
            if (colour_at(pr, near, n, mid) >= 0.5)
                below = mid;
            else
                above = mid;
        }
        level = 0.5 * (above + below);
        break;
    }
    free(near);
    return level;
}

/* |x_j - x|^2 */
static inline double distance2(const particles *p, size_t j, const double x[3])
{
    double r2 = 0.0;
    for (int d = 0; d < DIM; d++) {
        double dx = p->x[d][j] - x[d];
        r2 += dx * dx;
    }
    return r2;
}

/* The Shepard interpolation of the pressure at x over the particles `near` (all when NULL,
 * n_near ignored). */
static double shepard_pressure(const probes *pr, const particles *p, const double x[3],
                               const size_t *near, size_t n_near)
{
    double weighted = 0.0, shepard = 0.0;
    size_t n = near ? n_near : p->n_total;
    for (size_t m = 0; m < n; m++) {
        size_t j = near ? near[m] : m;
        double r2 = distance2(p, j, x);
        if (r2 >= pr->k.support2) continue;
        double wv = kernel_w(&pr->k, sqrt(r2)) * p->vol[j];
        weighted += p->p[j] * wv;
        shepard += wv;
    }
    return shepard > 0.0 ? weighted / shepard : 0.0;
}

double probes_pressure(const probes *pr, const particles *p, const double x[3])
{
    return shepard_pressure(pr, p, x, NULL, 0);
}

/* The particles within 2h of some point of a face of the given radius centred at x: those
 * within radius + 2h of x. NULL when out of memory (the caller then reads them all). */
static size_t *particles_near_face(const probes *pr, const particles *p, const double x[3],
                                   double radius, size_t *n_near)
{
    size_t *near = malloc((p->n_total ? p->n_total : 1) * sizeof *near);
    if (!near) return NULL;
    double reach = radius + 2.0 * pr->k.h, reach2 = reach * reach;
    size_t n = 0;
    for (size_t j = 0; j < p->n_total; j++)
        if (distance2(p, j, x) < reach2) near[n++] = j;
    *n_near = n;
    return near;
}

#if DIM == 2
/* Gauss-Legendre nodes and weights on [-1, 1], 8 points (the nodes in +- pairs) */
static const double legendre8_node[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                         0.9602898564975363};
static const double legendre8_weight[4] = {0.3626837833783620, 0.3137066458778873,
                                           0.2223810344533745, 0.1012285362903763};
#else
/* Gauss-Legendre nodes and weights on [-1, 1], 4 points, for the radius */
static const double legendre4_node[2] = {0.3399810435848563, 0.8611363115940526};
static const double legendre4_weight[2] = {0.6521451548625461, 0.3478548451374538};
#endif

double probes_sensor(const probes *pr, const particles *p, const double x[3], double diameter,
                     int wall_axis)
{
    double radius = 0.5 * diameter, sum = 0.0, point[3] = {x[0], x[1], x[2]};
    size_t n_near = 0, *near = particles_near_face(pr, p, x, radius, &n_near);
#if DIM == 2
    int along = wall_axis == 0 ? 1 : 0; /* the wall's direction in the plane */
    for (int k = 0; k < 8; k++) {
        double s = (k % 2 ? -1.0 : 1.0) * legendre8_node[k / 2];
        point[along] = x[along] + radius * s;
        sum += 0.5 * legendre8_weight[k / 2] * shepard_pressure(pr, p, point, near, n_near);
    }
#else
    int u = (wall_axis + 1) % 3, v = (wall_axis + 2) % 3; /* the wall's plane */
    for (int i = 0; i < 4; i++) {
        /* r = R (1 + s) / 2 in [0, R]; the mean over the disc is the integral of f r dr dtheta
           over pi R^2: (R / 2) w_i r_i x (2 pi / 8) / (pi R^2) = w_i r_i / (8 R) a point */
        double s = (i % 2 ? -1.0 : 1.0) * legendre4_node[i / 2];
        double r = 0.5 * radius * (1.0 + s), weight = legendre4_weight[i / 2] * r / (8.0 * radius);
        for (int a = 0; a < 8; a++) {
            double theta = 2.0 * M_PI * (a + 0.5) / 8.0;
            point[u] = x[u] + r * cos(theta);
            point[v] = x[v] + r * sin(theta);
            sum += weight * shepard_pressure(pr, p, point, near, n_near);
        }
    }
#endif
    free(near);
    return sum;
}
