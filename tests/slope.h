/* slope: the least-squares line through points, for the tests that measure a rate (an
 * energy's decay, a growth) as the slope of a logarithm in time. */
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

#endif
