/* volume: the three run-time volume errors. */
#include "diag/volume.h"
#include "core/reduce.h"
#include "diag/freesurface.h"
#include "diag/raster.h"
#include "core/pair.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef enum { MEASURE_KERNEL, MEASURE_GAMMA, MEASURE_LAMBDA } measure;

/* One particle's share, 1 on S_F: Vgeo_i / dr^n (Eq. 12), Gamma_i (A.2), lambda_i (A.3). */
static inline double share(const particles *p, measure m, size_t i, double cell_volume)
{
    if (p->surface[i] != SURFACE_INTERIOR) return 1.0;
    switch (m) {
    case MEASURE_KERNEL: return 1.0 / (p->kernel_sum[i] * cell_volume);
    case MEASURE_GAMMA: return p->gamma[i];
    case MEASURE_LAMBDA: return p->lambda[i];
    }
    return 1.0;
}

/* The mean over the n_all particles of every process. */
static double mean_share(const particles *p, measure m, double cell_volume, double n_all,
                         double *scratch, const reducer *r)
{
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) scratch[i] = share(p, m, i, cell_volume);
    return reducer_sum(r, scratch, p->n_fluid) / n_all;
}

void volume_compute(const particles *p, double cell_volume, double *scratch, const reducer *r,
                    volume_errors *out)
{
    /* Eq. (12): sum Vgeo / (N dr^n) - 1 */
    double n_all = (double)reducer_total(r, (long)p->n_fluid);
    out->eps_v1 = mean_share(p, MEASURE_KERNEL, cell_volume, n_all, scratch, r) - 1.0;
    out->eps_v2 = 1.0 - mean_share(p, MEASURE_GAMMA, cell_volume, n_all, scratch, r);
    out->eps_v3 = 1.0 - mean_share(p, MEASURE_LAMBDA, cell_volume, n_all, scratch, r);
    long n = 0;
#pragma omp parallel for schedule(static) reduction(+ : n)
    for (size_t i = 0; i < p->n_fluid; i++) n += p->surface[i] == SURFACE_FREE;
    out->n_free_surface = reducer_total(r, n);
}

double volume_free_surface_packing(const particles *p, double cell_volume, double flat_surface_sum,
                                   double *scratch, const reducer *r)
{
    double n_all = (double)reducer_total(r, (long)p->n_fluid);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++)
        scratch[i] = p->surface[i] == SURFACE_FREE
                         ? flat_surface_sum / (p->kernel_sum[i] * cell_volume) - 1.0
                         : 0.0;
    return reducer_sum(r, scratch, p->n_fluid) / n_all;
}

/* The velocity fields of Eq. (13)'s rates. */
typedef enum { RATE_VELOCITY, RATE_SHIFTING, RATE_CORRECTION } rate_field;

/* Field v at particle j, a wall's image included: the images hold u and the shifting (their
 * own, mirrored), not the correction (FIELD_SOURCES_ONLY), which an image reads from its
 * source, mirrored. A branch on v, the same for every pair of a pass (a function pointer
 * would not be inlined into the outlined OpenMP loop: twice the time, measured). */
static inline vec rate_field_at(const particles *p, rate_field v, size_t j)
{
    switch (v) {
    case RATE_SHIFTING: return vec_load(p->shift, j);
    case RATE_CORRECTION: return particle_source_vector(p, p->correction, j);
    default: return vec_load(p->u, j);
    }
}

/* Eq. (13) of particle i with the velocity field v: Vgeo_i^2 sum_j v_ji . grad_i W_ij. */
static double geometric_volume_rate(const kernel *k, const particles *p, const neighbour_list *nl,
                                    rate_field v, size_t i)
{
    vec xi = vec_load(p->x, i), vi = rate_field_at(p, v, i);
    double sum = 0.0;
    pair pr;
    FOR_EACH_PAIR (k, p->x, nl, i, xi, pr)
        sum += vec_dot(vec_sub(rate_field_at(p, v, pr.j), vi), pr.r_ji) * pr.f;
    double vgeo = 1.0 / p->kernel_sum[i];
    return vgeo * vgeo * sum;
}

static double interior_rate(const kernel *k, const particles *p, const neighbour_list *nl,
                            rate_field v, double v0, double *scratch, const reducer *r)
{
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++)
        scratch[i] =
            p->surface[i] == SURFACE_INTERIOR ? geometric_volume_rate(k, p, nl, v, i) : 0.0;
    return reducer_sum(r, scratch, p->n_fluid) / v0;
}

void volume_rate(const kernel *k, const particles *p, const neighbour_list *nl, double cell_volume,
                 double *scratch, const reducer *r, volume_rates *out)
{
    double v0 = (double)reducer_total(r, (long)p->n_fluid) * cell_volume;
    out->u = interior_rate(k, p, nl, RATE_VELOCITY, v0, scratch, r);
    out->shift = interior_rate(k, p, nl, RATE_SHIFTING, v0, scratch, r);
    out->correction = interior_rate(k, p, nl, RATE_CORRECTION, v0, scratch, r);
}

/* The rule of raster_params_default with the lattice's particle volume and spacing. */
static raster_params graphical_params(const derived *dv)
{
    raster_params rp = raster_params_default(DIM);
    rp.particle_volume = dv->cell_volume;
    for (int d = 0; d < DIM; d++) rp.spacing[d] = dv->spacing[d];
    return rp;
}

int volume_graphical(const particles *p, const double size[DIM], const derived *dv, double *volume,
                     char *err, size_t err_len)
{
    raster_count c;
    if (volume_graphical_part(p, 0, -INFINITY, INFINITY, size, dv, &c, err, err_len)) return -1;
    *volume = raster_count_volume(&c);
    return 0;
}

/* The positions along one axis of the own particles and the halo in their global order: the
 * first n_halo_before halo particles, the own ones, then the rest of the halo (malloc'd). */
static double *in_global_order(const double *x, size_t n_own, size_t n_halo, size_t n_halo_before)
{
    double *to = malloc((n_own + n_halo) * sizeof *to);
    if (!to) return NULL;
    const double *halo = x + n_own;
    memcpy(to, halo, n_halo_before * sizeof *to);
    memcpy(to + n_halo_before, x, n_own * sizeof *to);
    memcpy(to + n_halo_before + n_own, halo + n_halo_before, (n_halo - n_halo_before) * sizeof *to);
    return to;
}

int volume_graphical_part(const particles *p, size_t n_halo_before, double x_lo, double x_hi,
                          const double size[DIM], const derived *dv, raster_count *c, char *err,
                          size_t err_len)
{
    raster_params rp = graphical_params(dv);
    size_t n_own = p->n_fluid, n_halo = p->n_halo, n = n_own + n_halo;
    double *x[3] = {NULL, NULL, NULL}, box[3] = {0.0, 0.0, 0.0};
    int failed = 0;
    for (int d = 0; d < DIM; d++) {
        box[d] = size[d];
        /* own particles alone are in their order already */
        x[d] = n_halo ? in_global_order(p->x[d], n_own, n_halo, n_halo_before) : p->x[d];
        failed |= !x[d];
    }
    if (failed)
        snprintf(err, err_len, "graphical method: out of memory (%zu positions)", n);
    else
        failed = raster_count_part(DIM, n, x, dv->dr, box, &rp, x_lo, x_hi, c, err, err_len);
    if (n_halo)
        for (int d = 0; d < DIM; d++) free(x[d]);
    return failed ? -1 : 0;
}
