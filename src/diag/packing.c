/* packing: the free-surface particles' nearest neighbours (packing.h). */
#include "diag/packing.h"
#include "core/pair.h"
#include "core/quantile.h"
#include "diag/freesurface.h"

#include <math.h>

/* The distance to i's nearest fluid neighbour within 2h (another process's, in the halo,
 * included), or 0 when it has none. */
static double nearest_fluid_neighbour(const kernel *k, const particles *p, const neighbour_list *nl,
                                      size_t i)
{
    vec xi = vec_load(p->x, i);
    double nearest = INFINITY;
    size_t fluid_end = particles_images_begin(p);
    pair pr;
    FOR_EACH_PAIR_WHERE (k, p->x, nl, i, xi, pr, pr.j < fluid_end)
        if (pr.r < nearest) nearest = pr.r;
    return isinf(nearest) ? 0.0 : nearest;
}

/* The mean of `nearest` over the particles of class `surface` that have a neighbour, summed
 * in index order (NaN when there are none). */
static double class_mean(const particles *p, const double *nearest, int surface)
{
    double sum = 0.0;
    long n = 0;
    for (size_t i = 0; i < p->n_fluid; i++)
        if (p->surface[i] == surface && nearest[i] > 0.0) {
            sum += nearest[i];
            n++;
        }
    return n ? sum / (double)n : NAN;
}

void surface_packing_compute(const kernel *k, const particles *p, const neighbour_list *nl,
                             double dr, double *scratch, surface_packing *out)
{
    double *nearest = scratch;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) nearest[i] = nearest_fluid_neighbour(k, p, nl, i) / dr;
    out->n_free = out->n_clumped = 0;
    for (size_t i = 0; i < p->n_fluid; i++)
        if (p->surface[i] == SURFACE_FREE) {
            out->n_free++;
            out->n_clumped += nearest[i] > 0.0 && nearest[i] < PACKING_CLUMPED;
        }
    out->nearest_free = class_mean(p, nearest, SURFACE_FREE);
    out->nearest_band = class_mean(p, nearest, SURFACE_REGION);
    out->nearest_interior = class_mean(p, nearest, SURFACE_INTERIOR);
}

void surface_nearest_quantiles(const kernel *k, const particles *p, const neighbour_list *nl,
                               double dr, const run_team *team, double *scratch, double *median,
                               double *p05)
{
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++)
        scratch[i] =
            p->surface[i] == SURFACE_FREE ? nearest_fluid_neighbour(k, p, nl, i) / dr : 0.0;
    size_t n = 0;
    for (size_t i = 0; i < p->n_fluid; i++)
        if (scratch[i] > 0.0) scratch[n++] = scratch[i];
    double *all = scratch, *gathered = NULL;
    if (team) all = gathered = team->gather(team, scratch, n, sizeof *scratch, &n);
    *median = *p05 = NAN;
    if (all) {
        quantile_sort(all, n);
        *median = quantile_sorted(all, n, 0.5);
        *p05 = quantile_sorted(all, n, 0.05);
    }
    free(gathered);
}
