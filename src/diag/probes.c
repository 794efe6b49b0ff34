/* probes: wave gauges and pressure probes. Serial sums in particle order: a probe costs one
 * pass over the particles per time-series row, and the result is the same for any number of
 * threads. */
#include "diag/probes.h"

#include <math.h>

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

void probes_init(probes *pr, double h, double tank_width)
{
    pr->k = kernel_make(h);
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

double probes_pressure(const probes *pr, const particles *p, const double x[3])
{
    double weighted = 0.0, shepard = 0.0;
    for (size_t j = 0; j < p->n_total; j++) {
        double r2 = 0.0;
        for (int d = 0; d < DIM; d++) {
            double dx = p->x[d][j] - x[d];
            r2 += dx * dx;
        }
        if (r2 >= pr->k.support2) continue;
        double wv = kernel_w(&pr->k, sqrt(r2)) * p->vol[j];
        weighted += p->p[j] * wv;
        shepard += wv;
    }
    return shepard > 0.0 ? weighted / shepard : 0.0;
}
