/* Wendland C2 kernel (theory §1): normalisation, F > 0 and F = -(1/r) dW/dr, and the lattice
 * sum that sets the floor of eps_V^(1) at t = 0. */
#include "core/kernel.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "check.h"

/* int W dV over the support by composite Simpson in r; the integrand is a polynomial of
 * degree <= 7 in r, so the quadrature error with 4000 intervals is far below 1e-10. */
static void test_normalisation(void **state)
{
    (void)state;
    for (double h = 0.01; h < 2.0; h *= 7.0) {
        kernel k = kernel_make(h);
        const int n = 4000;
        double a = 2.0 * h / n, sum = 0.0;
        for (int m = 0; m <= n; m++) {
            double r = m * a;
            double shell = DIM == 2 ? 2.0 * M_PI * r : 4.0 * M_PI * r * r;
            double w = (m == 0 || m == n) ? 1.0 : (m % 2 ? 4.0 : 2.0);
            sum += w * kernel_w(&k, r) * shell;
        }
        sum *= a / 3.0;
        assert_close(sum, 1.0, 1e-10);
    }
}

/* F > 0 inside the support, 0 outside, and equal to -(1/r) dW/dr (central differences,
 * truncation error ~ eps^2 W''' ~ 1e-8 relative). */
static void test_f_positive_and_derivative(void **state)
{
    (void)state;
    kernel k = kernel_make(0.1);
    for (double q = 0.01; q < 2.0; q += 0.01) {
        double r = q * k.h, eps = 1e-5 * k.h;
        double f = kernel_f(&k, r);
        assert_true(f > 0.0);
        double dwdr = (kernel_w(&k, r + eps) - kernel_w(&k, r - eps)) / (2.0 * eps);
        assert_close(f, -dwdr / r, 1e-6 * k.f_norm);
    }
    assert_true(kernel_f(&k, 2.0 * k.h) == 0.0);
    assert_true(kernel_w(&k, 2.0 * k.h + 1e-12) == 0.0);
}

/* sum_j W_ij dr^n - 1 on an infinite lattice (self term included), against the brute-force
 * values of theory §1: +1.206e-3 (2D, h/dr = 2) and +3.14e-3 (3D, h/dr = 1.5), to the
 * digits given there. */
static void test_lattice_sum(void **state)
{
    (void)state;
    const double dr = 1.0;
#if DIM == 2
    const double h_over_dr = 2.0, expected = 1.206e-3, digits = 0.5e-6;
#else
    const double h_over_dr = 1.5, expected = 3.14e-3, digits = 0.5e-5;
#endif
    kernel k = kernel_make(h_over_dr * dr);
    int reach = (int)ceil(2.0 * h_over_dr) + 1;
    double sum = 0.0;
    for (int a = -reach; a <= reach; a++)
        for (int b = -reach; b <= reach; b++)
#if DIM == 3
            for (int c = -reach; c <= reach; c++)
#else
            for (int c = 0; c <= 0; c++)
#endif
                sum += kernel_w(&k, dr * sqrt((double)(a * a + b * b + c * c)));
    double cell = DIM == 2 ? dr * dr : dr * dr * dr;
    assert_close(sum * cell - 1.0, expected, digits);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_normalisation),
        cmocka_unit_test(test_f_positive_and_derivative),
        cmocka_unit_test(test_lattice_sum),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
