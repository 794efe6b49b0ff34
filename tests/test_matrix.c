/* The symmetric matrices of the renormalization (core/vec.h): the smallest eigenvalue
 * (lambda of Eq. 10) and whether every eigenvalue exceeds a floor, on matrices built with
 * known eigenvalues, Q diag(lambda) Q^T with Q a random rotation.
 *
 * Tolerances: the built matrix carries a round-off E of a few eps max|lambda| per entry, which
 * moves each eigenvalue by at most ||E|| (Weyl's inequality); the closed form's own error is
 * largest where eigenvalues nearly coincide, the arc cosine's argument near +-1, where an
 * error eps in the argument becomes sqrt(2 eps) in the angle: about 3e-8 of the spread. The
 * eigenvalue is held to 1e-7 max|lambda|, and the floor test must answer right for every floor
 * farther than that from the smallest eigenvalue. */
#include "core/vec.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "noise.h"

#define TOLERANCE 1e-7 /* of max |lambda|: the header's bound */

/* A random rotation: 2D one angle; 3D the product of rotations about the three axes. */
static mat random_rotation(uint64_t *seed)
{
    mat q = mat_identity();
    for (int axis = 0; axis < (DIM == 2 ? 1 : 3); axis++) {
        double angle = M_PI * noise(seed), c = cos(angle), s = sin(angle);
        int u = DIM == 2 ? 0 : (axis + 1) % 3, v = DIM == 2 ? 1 : (axis + 2) % 3;
        mat r = mat_identity(), product = mat_zero();
        r.a[u][u] = c;
        r.a[u][v] = -s;
        r.a[v][u] = s;
        r.a[v][v] = c;
        for (int i = 0; i < DIM; i++)
            for (int j = 0; j < DIM; j++)
                for (int k = 0; k < DIM; k++) product.a[i][j] += r.a[i][k] * q.a[k][j];
        q = product;
    }
    return q;
}

/* Q diag(lambda) Q^T, made exactly symmetric */
static mat with_eigenvalues(const double lambda[DIM], uint64_t *seed)
{
    mat q = random_rotation(seed), m = mat_zero();
    for (int i = 0; i < DIM; i++)
        for (int j = i; j < DIM; j++) {
            for (int k = 0; k < DIM; k++) m.a[i][j] += q.a[i][k] * lambda[k] * q.a[j][k];
            m.a[j][i] = m.a[i][j];
        }
    return m;
}

/* Eigenvalues in [-scale, scale], some cases with two or three (nearly) equal: where the
 * closed form is least accurate. */
static void random_eigenvalues(uint64_t *seed, int kind, double lambda[DIM], double *smallest,
                               double *largest)
{
    double scale = pow(10.0, 3.0 * noise(seed));
    for (int d = 0; d < DIM; d++) lambda[d] = scale * noise(seed);
    if (kind == 1) lambda[1] = lambda[0];
    if (kind == 2) lambda[1] = lambda[0] * (1.0 + 1e-12);
    if (kind == 3)
        for (int d = 1; d < DIM; d++) lambda[d] = lambda[0];
    *smallest = INFINITY;
    *largest = 0.0;
    for (int d = 0; d < DIM; d++) {
        *smallest = fmin(*smallest, lambda[d]);
        *largest = fmax(*largest, fabs(lambda[d]));
    }
}

static void smallest_eigenvalue_is_known_one(void **state)
{
    (void)state;
    uint64_t seed = 11;
    double worst = 0.0;
    for (int trial = 0; trial < 20000; trial++) {
        double lambda[DIM], smallest, largest;
        random_eigenvalues(&seed, trial % 4, lambda, &smallest, &largest);
        mat m = with_eigenvalues(lambda, &seed);
        double error = fabs(mat_min_eigenvalue(&m) - smallest) / largest;
        worst = fmax(worst, error);
        if (!(error <= TOLERANCE))
            fail_msg("trial %d: smallest eigenvalue %.17g, computed %.17g", trial, smallest,
                     mat_min_eigenvalue(&m));
    }
    printf("smallest eigenvalue: worst error %.2e of max |lambda| (allowed %.0e)\n", worst,
           TOLERANCE);
}

static void floor_test_answers_as_the_eigenvalue(void **state)
{
    (void)state;
    uint64_t seed = 12;
    int above = 0, below = 0;
    for (int trial = 0; trial < 20000; trial++) {
        double lambda[DIM], smallest, largest;
        random_eigenvalues(&seed, trial % 4, lambda, &smallest, &largest);
        mat m = with_eigenvalues(lambda, &seed);
        /* floors just clear of the round-off band around the smallest eigenvalue, and
           anywhere in the spectrum's range */
        double margin = 10.0 * TOLERANCE * largest;
        double floors[3] = {smallest - margin, smallest + margin, largest * noise(&seed)};
        for (int k = 0; k < 3; k++) {
            if (fabs(floors[k] - smallest) < margin) continue;
            bool want = smallest > floors[k];
            if (mat_eigenvalues_above(&m, floors[k]) != want)
                fail_msg("trial %d: smallest eigenvalue %.17g, floor %.17g: answered %s", trial,
                         smallest, floors[k], want ? "no" : "yes");
            above += want;
            below += !want;
        }
    }
    printf("floor test: %d floors below the smallest eigenvalue, %d above, all answered right\n",
           above, below);
    assert_true(above > 1000 && below > 1000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(smallest_eigenvalue_is_known_one),
        cmocka_unit_test(floor_test_answers_as_the_eigenvalue),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
