/* slope: fits to sampled series: the least-squares line through points, for the tests that
 * measure a rate (an energy's decay, a growth) as the slope of a logarithm in time, and the
 * vertex of the parabola through three samples, for the tests that time an extremum. */
#ifndef VCSPH_TEST_SLOPE_H
#define VCSPH_TEST_SLOPE_H

#include <math.h>
#include <stddef.h>

/* The least-squares slope of y against x over n points and, where `error` is not NULL, its
 * standard error from the residuals (n >= 3 then). */
static inline double least_squares_slope(const double *x, const double *y, int n, double *error)
{
    double mx = 0.0, my = 0.0, sxx = 0.0, sxy = 0.0, residual2 = 0.0;
    for (int k = 0; k < n; k++) {
        mx += x[k] / n;
        my += y[k] / n;
    }
    for (int k = 0; k < n; k++) {
        sxx += (x[k] - mx) * (x[k] - mx);
        sxy += (x[k] - mx) * (y[k] - my);
    }
    double slope = sxy / sxx;
    if (error) {
        for (int k = 0; k < n; k++) {
            double r = y[k] - my - slope * (x[k] - mx);
            residual2 += r * r;
        }
        *error = sqrt(residual2 / (n - 2) / sxx);
    }
    return slope;
}

/* The vertex of the parabola through (-1, a), (0, b), (1, c): its abscissa (returned, in
 * sample spacings from b's) and its value (*value). The caller makes sure a - 2b + c != 0. */
static inline double parabola_vertex(double a, double b, double c, double *value)
{
    double shift = 0.5 * (a - c) / (a - 2.0 * b + c);
    *value = b - 0.25 * (a - c) * shift;
    return shift;
}

#endif
