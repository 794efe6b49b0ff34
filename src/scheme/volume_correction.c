/* volume_correction: the mismatch field e and the correction velocity. */
#include "scheme/volume_correction.h"
#include "core/team_loop.h"
#include "boundary/tank.h"
#include "diag/freesurface.h"
#include "physics/shifting.h"
#include "physics/volume_correction.h"
#include "core/pair.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* e off S_F, where the kernel support is whole (Eq. 12 measures only there). */
static void interior_mismatch(double lattice_sum, particles *p)
{
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++)
        p->volume_mismatch[i] = p->surface[i] == SURFACE_INTERIOR
                                    ? volume_mismatch(p->vol[i], p->kernel_sum[i], lattice_sum)
                                    : 0.0;
}

/* e in S_F: the Shepard average of the interior fluid neighbours' e. The band moves with the
 * liquid below it, and the free surface (no interior particle within 2h) keeps e = 0, the
 * condition that lets the surface, not the band, take up the change of volume. Reads only
 * interior entries and writes only the others, so the loop has no race. */
static void surface_band_mismatch(const kernel *k, particles *p, const neighbour_list *nl)
{
    TEAM_FOR (i, p->n_fluid) {
        if (p->surface[i] == SURFACE_INTERIOR) continue;
        vec xi = vec_load(p->x, i);
        double sum = 0.0, weight = 0.0;
        pair pr;
        FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) {
            size_t j = pr.j;
            if (particle_is_wall_image(p, j) || p->surface[j] != SURFACE_INTERIOR) continue;
            double w = pr.w * p->vol[j];
            sum += w * p->volume_mismatch[j];
            weight += w;
        }
        p->volume_mismatch[i] = weight > 0.0 ? sum / weight : 0.0;
    }
}

vec volume_correction_velocity_from(const physics_params *pp, const particles *p, size_t i, vec sum)
{
    /* beyond the compression gradient's floor, as the shifting (shifting.h), and at most
       U_max / 2, Eq. (7)'s cap (no relative-speed bound here) */
    sum = gradient_beyond_floor(sum, compression_gradient(vec_load(p->grad_rho, i), p->rho[i]));
    return shifting_limit(vec_scale(sum, -pp->k.h * pp->shift_u_max), INFINITY, pp->shift_u_max);
}

static int reserve(volume_correction_work *w, size_t n_bodies)
{
    if (n_bodies <= w->capacity) return 0;
    double *grown = realloc(w->sums, 2 * n_bodies * sizeof *grown);
    if (!grown) return -1;
    w->sums = grown;
    w->capacity = n_bodies;
    return 0;
}

void volume_correction_free(volume_correction_work *w)
{
    free(w->sums);
    memset(w, 0, sizeof *w);
}

/* Each body's S_F moves along its normal at one speed, the V-weighted mean of dv . n over
 * it, which keeps the body's rate of change of volume through its surface and drops the
 * rest. Why: where dv . n varies along a surface at rest, it moves the surface without
 * moving the liquid, and any such uneven move of a surface in equilibrium (a circle under
 * surface tension, a level surface under gravity) raises its surface or potential energy
 * at second order, energy that the restoring force then hands to the flow. The mismatch e
 * is never smooth at the particle scale, so those moves never cancel: on a drop of water at
 * rest (docs/surface-tension.md) they fed currents that grew over seconds. Where lambda <
 * 0.4 there is no reliable normal and no correction (correction_velocity): such particles
 * take no part. The sums are serial and in index order over the bodies' members (bodies_sum):
 * they do not depend on the thread count. */
static bool moves_with_its_body(const particles *p, const bodies *b, size_t i)
{
    return b->id[i] >= 0 && p->lambda[i] >= SHIFTING_LAMBDA_MIN;
}

typedef struct {
    const particles *p;
    const bodies *b;
} body_shares;

static void add_normal_flux(void *context, double *sums)
{
    const body_shares *c = context;
    const particles *p = c->p;
    FOR_EACH_MEMBER (c->b, i) {
        if (!moves_with_its_body(p, c->b, i)) continue;
        vec dv = vec_load(p->correction, i), n = vec_load(p->normal, i);
        double *sum = sums + 2 * (size_t)c->b->id[i];
        sum[0] += p->vol[i] * vec_dot(dv, n);
        sum[1] += p->vol[i];
    }
}

int volume_correction_per_body(particles *p, const bodies *b, const bodies_domain *d,
                               volume_correction_work *w)
{
    if (reserve(w, b->count)) return -1;
    body_shares shares = {p, b};
    bodies_sum(d, p, b, w->sums, 2, add_normal_flux, &shares);
#pragma omp parallel for schedule(static)
    for (size_t k = 0; k < b->n_members; k++) {
        size_t i = (size_t)b->members[k];
        if (!moves_with_its_body(p, b, i)) continue;
        vec dv = vec_load(p->correction, i), n = vec_load(p->normal, i);
        const double *sum = w->sums + 2 * (size_t)b->id[i];
        double mean = sum[0] / sum[1];
        vec_store(p->correction, i, vec_axpy(dv, mean - vec_dot(dv, n), n));
    }
    return 0;
}

void volume_correction_mismatch(const physics_params *pp, particles *p)
{
    interior_mismatch(pp->lattice_kernel_sum, p);
}

void volume_correction_band(const physics_params *pp, particles *p, const neighbour_list *nl)
{
    surface_band_mismatch(&pp->k, p, nl);
}

void volume_correction_ghost_mismatch(particles *p) { tank_copy_to_ghosts(p, p->volume_mismatch); }
