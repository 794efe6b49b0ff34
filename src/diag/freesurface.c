/* freesurface: Marrone et al. 2010 and the band S_F. */
#include "diag/freesurface.h"
#include "scheme/pair.h"

void freesurface_flat_sums(const kernel *k, double dr, int depth, mat *l, vec *s)
{
    /* the lattice below, beside and above a particle at the origin, up to the top layer
       `depth` rows above it, within the support */
    int reach = (int)ceil(2.0 * k->h / dr);
    int top = depth < reach ? depth : reach;
    double cell = pow(dr, DIM);
    *l = mat_zero();
    *s = vec_zero();
    for (int a = -reach; a <= reach; a++)
        for (int b = -reach; b <= top; b++)
#if DIM == 3
            for (int c = -reach; c <= reach; c++)
#else
            for (int c = 0; c <= 0; c++)
#endif
            {
                if (a == 0 && b == 0 && c == 0) continue;
                vec r = vec_zero();
                r.c[0] = a * dr;
                r.c[1] = b * dr;
                if (DIM == 3) r.c[DIM - 1] = c * dr;
                double f = kernel_f(k, vec_norm(r));
                mat_add_outer(l, f * cell, r, r);
                *s = vec_axpy(*s, f * cell, r);
            }
}

double freesurface_reference_normal(const kernel *k, double dr)
{
    mat l, l_inv;
    vec s;
    freesurface_flat_sums(k, dr, 0, &l, &s);
    if (mat_inverse(&l, &l_inv) == 0.0) return 0.0;
    return vec_norm(mat_mul_vec(&l_inv, s));
}

/* The umbrella test of Marrone et al. 2010 for a particle whose lambda is ambiguous: it is
 * interior if some neighbour lies in the scan region on the outer side, i.e. within radius R
 * of T = r_i + R n_i (far neighbours), or inside the square (octahedron) of half-diagonal R
 * around T (near neighbours). */
static int covered(const kernel *k, const particles *p, const neighbour_list *nl, size_t i,
                   double radius)
{
    vec xi = vec_load(p->x, i), n = vec_load(p->normal, i);
    vec target = vec_axpy(xi, radius, n);
    const int32_t *row = neighbour_row(nl, i);
    for (int32_t m = 0; m < nl->count[i]; m++) {
        pair pr;
        if (!pair_of(k, p->x, xi, row, m, &pr)) continue;
        vec d = vec_sub(vec_load(p->x, pr.j), target);
        if (pr.r2 >= 2.0 * radius * radius) {
            if (vec_norm2(d) < radius * radius) return 1;
        } else {
            double normal_part = vec_dot(n, d);
            double tangential = vec_norm(vec_axpy(d, -normal_part, n));
            if (fabs(normal_part) + tangential < radius) return 1;
        }
    }
    return 0;
}

void freesurface_detect(const kernel *k, double dr, double normal_reference, particles *p,
                        const neighbour_list *nl)
{
    double radius = FREESURFACE_SCAN_OVER_DR * dr;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        double lambda = p->lambda[i];
        int on_surface;
        if (lambda <= FREESURFACE_LAMBDA_FREE)
            on_surface = 1;
        else if (lambda > FREESURFACE_LAMBDA_INTERIOR)
            on_surface = 0;
        /* a nearly symmetric neighbourhood has no reliable normal: interior (theory §4) */
        else if (p->normal_raw[i] < 0.5 * normal_reference)
            on_surface = 0;
        else
            on_surface = !covered(k, p, nl, i, radius);
        p->is_free[i] = (uint8_t)on_surface;
    }
    /* S_F: the free surface and every fluid particle within 2h of it (ghosts add nothing: a
       mirror image is never closer than its source) */
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec xi = vec_load(p->x, i);
        if (p->is_free[i]) {
            p->surface[i] = SURFACE_FREE;
            p->surface_ref[i] = (int32_t)i;
            continue;
        }
        /* the nearest free-surface particle within the support, if any (its normal serves
           the shifting of this particle, theory §4) */
        double nearest = k->support2;
        int32_t ref = -1;
        const int32_t *row = neighbour_row(nl, i);
        for (int32_t m = 0; m < nl->count[i]; m++) {
            size_t j = (size_t)row[m];
            if (j >= p->n_fluid || !p->is_free[j]) continue;
            double r2 = vec_norm2(vec_sub(vec_load(p->x, j), xi));
            if (r2 < nearest) {
                nearest = r2;
                ref = (int32_t)j;
            }
        }
        p->surface[i] = ref >= 0 ? SURFACE_REGION : SURFACE_INTERIOR;
        p->surface_ref[i] = ref;
    }
}
