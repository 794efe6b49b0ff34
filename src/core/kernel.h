/* kernel: Wendland C2 (paper sec. 2.2; theory §1), support radius 2h. */
#ifndef VCSPH_KERNEL_H
#define VCSPH_KERNEL_H

#include "core/dim.h"
#include <math.h>

typedef struct {
    double h;        /* smoothing length */
    double support2; /* (2h)^2 */
    double inv_h;
    double norm;   /* a_n: 7/(4 pi h^2) in 2D, 21/(16 pi h^3) in 3D */
    double f_norm; /* 5 a_n / h^2, the prefactor of F */
} kernel;

static inline kernel kernel_make(double h)
{
    kernel k;
    k.h = h;
    k.support2 = 4.0 * h * h;
    k.inv_h = 1.0 / h;
#if DIM == 2
    k.norm = 7.0 / (4.0 * M_PI * h * h);
#else
    k.norm = 21.0 / (16.0 * M_PI * h * h * h);
#endif
    k.f_norm = 5.0 * k.norm / (h * h);
    return k;
}

/* W(r) = a_n (1 - q/2)^4 (1 + 2q), q = r/h < 2 */
static inline double kernel_w(const kernel *k, double r)
{
    double q = r * k->inv_h;
    if (q >= 2.0) return 0.0;
    double s = 1.0 - 0.5 * q;
    double s2 = s * s;
    return k->norm * s2 * s2 * (1.0 + 2.0 * q);
}

/* F(r) = -(1/r) dW/dr = 5 a_n (1 - q/2)^3 / h^2 > 0, so that grad_i W_ij = r_ji F_ij
 * (paper sec. 2.2, theory §1). */
static inline double kernel_f(const kernel *k, double r)
{
    double q = r * k->inv_h;
    if (q >= 2.0) return 0.0;
    double s = 1.0 - 0.5 * q;
    return k->f_norm * s * s * s;
}

/* dr^n sum_j W(|r_j|) over the points r_j of the lattice of spacing dr, self included: the
 * whole lattice (Eq. 11's reading of a regular lattice, kappa), or with `half` only the rows
 * at and below the particle's own along y, the top row of a flat free surface. */
static inline double kernel_lattice_sum(const kernel *k, double dr, int half)
{
    int reach = (int)ceil(2.0 * k->h / dr);
    int reach_z = DIM == 3 ? reach : 0;
    double sum = 0.0;
    for (int a = -reach; a <= reach; a++)
        for (int b = -reach; b <= (half ? 0 : reach); b++)
            for (int c = -reach_z; c <= reach_z; c++)
                sum += kernel_w(k, dr * sqrt((double)(a * a + b * b + c * c)));
    return sum * pow(dr, DIM);
}

#endif
