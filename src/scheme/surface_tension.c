/* surface_tension: interface function, curvature, the CSF force and its momentum balance. */
#include "scheme/surface_tension.h"
#include "core/team_loop.h"
#include "boundary/tank.h"
#include "core/reduce.h"
#include "diag/freesurface.h"
#include "physics/moment.h"
#include "physics/surface_tension.h"
#include "core/pair.h"
#include "core/pair_block.h"

#include <stdlib.h>
#include <string.h>

surface_tension_params surface_tension_setup(const kernel *k, double dr, double sigma,
                                             double lambda_min)
{
    surface_tension_params st = {sigma, dr, 0.0, lambda_min};
    /* the layers within the support of the top one: the depth of S_F on a flat surface */
    int layers = (int)ceil(2.0 * k->h / dr) + 1;
    for (int depth = 0; depth < layers; depth++) {
        mat l;
        vec grad_one;
        freesurface_flat_sums(k, dr, depth, &l, &grad_one);
        st.flat_integral += 2.0 * vec_norm(grad_one) * dr;
    }
    return st;
}

static int reserve_bodies(surface_tension_work *w, size_t n_bodies)
{
    if (n_bodies <= w->body_capacity) return 0;
    double *first = realloc(w->first, n_bodies * BALANCE_FIRST * sizeof *first);
    if (first) w->first = first;
    double *second = realloc(w->second, n_bodies * BALANCE_SECOND * sizeof *second);
    if (second) w->second = second;
    if (!first || !second) return -1;
    w->body_capacity = n_bodies;
    return 0;
}

int surface_tension_reserve(surface_tension_work *w, size_t n_sources, size_t n_bodies)
{
    if (n_sources <= w->capacity) return reserve_bodies(w, n_bodies);
    surface_tension_free(w);
    int ok = 1;
    for (int d = 0; d < DIM; d++) ok &= (w->smooth[d] = malloc(n_sources * sizeof(double))) != NULL;
    ok &= (w->band_sum = malloc(n_sources * sizeof(double))) != NULL;
    if (!ok) {
        surface_tension_free(w);
        return -1;
    }
    w->capacity = n_sources;
    return reserve_bodies(w, n_bodies);
}

void surface_tension_free(surface_tension_work *w)
{
    for (int d = 0; d < DIM; d++) free(w->smooth[d]);
    free(w->band_sum);
    free(w->first);
    free(w->second);
    memset(w, 0, sizeof *w);
}

/* The sums of particle i over its row for the interface function and the normal: L (Eq. 10),
 * sum grad W V and the band's share sum W V over the neighbours in S_F (self terms added
 * after). */
typedef struct {
    mat l;
    vec grad_one;
    double band;
} interface_sums;

PAIR_BLOCK_INLINE interface_sums interface_row_sums(const kernel *k, const particles *p,
                                                    const neighbour_list *nl, size_t i)
{
    vec xi = vec_load(p->x, i);
    PAIR_ROW(k, p->x, nl, i, xi, row);
    /* lane by lane (core/pair_block.h): lane l sums the row's entries n = l mod PAIR_BLOCK */
    pair_block_moments moments;
    __builtin_memset(&moments, 0, sizeof moments);
    pair_block band = {0};
    pair_block_geometry b;
    FOR_EACH_PAIR_BLOCK_OF_ROW (&row, b) {
        pair_block vol_j = pair_block_gather(p->vol, b.j), in_band;
        for (int l = 0; l < PAIR_BLOCK; l++)
            in_band[l] = p->surface[b.j[l]] != SURFACE_INTERIOR ? 1.0 : 0.0;
        pair_block_moments_add(&moments, b.f * vol_j, b.r_ji);
        band += b.w * vol_j * in_band; /* W = 0 beyond 2h: an exact zero there */
    }
    interface_sums s;
    pair_block_moments_total(&moments, &s.l, &s.grad_one);
    s.band = block_total(band);
    return s;
}

PAIR_BLOCK_FORMS(interface_sums, interface_row_sums,
                 (const kernel *k, const particles *p, const neighbour_list *nl, size_t i),
                 (k, p, nl, i))

/* In S_F, from the current positions: delta_Sigma = 2 |sum grad W V| / flat_integral
 * (theory §4: the factor 2 because the gas half of the kernel is missing; the calibration
 * makes its integral across a flat lattice surface exactly 1) and the normal
 * -L^-1 sum grad W V, as step_fields_geometry computes it at the start of the step. Both are
 * taken again at every stage: a force that stays where the surface was while the particles
 * move pumps energy into the surface's short waves (docs/surface-tension.md). 0 in the
 * interior. The row's sums in blocks, as the geometry pass's (scheme/step_fields.c). */
static void interface_and_normals(const surface_tension_params *st, const kernel *k, particles *p,
                                  const neighbour_list *nl, surface_tension_work *w,
                                  double *const normal[DIM])
{
    __auto_type sums_of = interface_row_sums_form();
    TEAM_FOR (i, p->n_fluid) {
        double delta = 0.0, band = 0.0;
        vec n = vec_zero();
        if (p->surface[i] != SURFACE_INTERIOR) {
            interface_sums s = sums_of(k, p, nl, i);
            band = k->norm * p->vol[i] + s.band;
            delta = 2.0 * vec_norm(s.grad_one) / st->flat_integral;
            mat l_inv = renormalization(&s.l, mat_eigenvalues_above(&s.l, st->lambda_min));
            double length;
            n = outward_normal(&l_inv, s.grad_one, &length);
        }
        p->interface[i] = delta;
        w->band_sum[i] = band;
        vec_store(normal, i, n);
    }
}

/* The normals of the free-surface particles, Shepard-averaged over their free-surface
 * neighbours and normalised: the curvature differentiates these. A surface cut out of a
 * lattice is a staircase whose flat steps and sharp corners make the normal jump; averaging
 * it over 2h along the surface before taking its divergence cuts the noise of the curvature
 * there by a third (rms 53 -> 34 % on a circle of R/dr = 20) and halves its bias (the
 * ball's mean +11.4 -> +5.7 %), and leaves a smooth surface as it was
 * (docs/surface-tension.md). Other fluid particles keep their own normal; ghosts get their
 * source's, mirrored. */
static void smoothed_normals(const kernel *k, const particles *p, const neighbour_list *nl,
                             const bodies_domain *d, double *const normal[DIM],
                             double *const smooth[DIM])
{
    TEAM_FOR (i, p->n_fluid) {
        vec xi = vec_load(p->x, i), sum = vec_scale(vec_load(normal, i), k->norm * p->vol[i]);
        if (p->surface[i] == SURFACE_FREE) {
            pair pr;
            FOR_EACH_PAIR_WHERE (k, p->x, nl, i, xi, pr, p->surface[pr.j] == SURFACE_FREE)
                sum = vec_axpy(sum, pr.w * p->vol[pr.j], particle_source_vector(p, normal, pr.j));
        }
        double norm = vec_norm(sum);
        vec_store(smooth, i, norm > 0.0 ? vec_scale(sum, 1.0 / norm) : sum);
    }
    for (int c = 0; c < DIM; c++) bodies_share(d, p, smooth[c]);
}

/* The curvature of the free-surface particles, from their free-surface neighbours only: the
 * outermost layer is where the normal is reliable, and deeper layers would measure the
 * larger curvature of the parallel surfaces below it. Ghosts read their source's. */
static void surface_curvature(const surface_tension_params *st, const kernel *k, const particles *p,
                              const neighbour_list *nl, const bodies_domain *d,
                              double *const normal[DIM], double *kappa)
{
    TEAM_FOR (i, p->n_fluid) {
        kappa[i] = 0.0;
        if (p->surface[i] != SURFACE_FREE) continue;
        vec xi = vec_load(p->x, i), ni = vec_load(normal, i);
        curvature_sums sums = {0.0, 0.0};
        pair pr;
        FOR_EACH_PAIR_WHERE (k, p->x, nl, i, xi, pr, p->surface[pr.j] == SURFACE_FREE)
            curvature_pair(&sums, ni, particle_source_vector(p, normal, pr.j), pr.r_ji, pr.f,
                           p->vol[pr.j]);
        kappa[i] = curvature_value(&sums, DIM, st->dr);
    }
    bodies_share(d, p, kappa);
}

/* The force on the particles of S_F, -sigma kappa n delta V, with all three factors taken as
 * Shepard averages within the support, which depend on the surface and not on the
 * particle's own neighbourhood:
 * - kappa and n: the averages of the free-surface particles' curvature and smoothed normal;
 * - delta: each particle's delta V spread over S_F within its support in proportion to W V,
 *   delta~_i = sum_j W_ij delta_j V_j / sum_k W_jk V_k, which keeps sum delta V, the area,
 *   exact (a Shepard average would not, and weakened the force by a tenth).
 * A particle's own delta and normal below the surface measure the holes around it: the CSF
 * force is the gradient of a negative pressure -sigma kappa c (c the colour), and along
 * those it pulls each particle towards its crowded side, a tensile instability that roughens
 * the surface and feeds it energy at water's viscosity (docs/surface-tension.md). */
static void band_force(const surface_tension_params *st, const kernel *k, particles *p,
                       const neighbour_list *nl, double *const smooth[DIM],
                       const double *kappa_surface, const double *band_sum)
{
    TEAM_FOR (i, p->n_fluid) {
        double kappa = 0.0;
        vec force = vec_zero();
        if (p->interface[i] > 0.0) {
            vec xi = vec_load(p->x, i);
            double self = k->norm * p->vol[i]; /* the self term W(0) V_i */
            double w_free = p->surface[i] == SURFACE_FREE ? self : 0.0;
            double sum_free = w_free, sum_kappa = w_free * kappa_surface[i];
            vec sum_normal = vec_scale(vec_load(smooth, i), w_free);
            double delta = self * p->interface[i] / band_sum[i];
            pair pr;
            FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) {
                double interface_j = particle_source_scalar(p, p->interface, pr.j);
                if (interface_j == 0.0) continue;
                double w = pr.w, wv = w * p->vol[pr.j];
                delta += w * interface_j * p->vol[pr.j] / particle_source_scalar(p, band_sum, pr.j);
                if (p->surface[pr.j] != SURFACE_FREE) continue;
                sum_free += wv;
                sum_kappa += wv * particle_source_scalar(p, kappa_surface, pr.j);
                sum_normal = vec_axpy(sum_normal, wv, particle_source_vector(p, smooth, pr.j));
            }
            double length = vec_norm(sum_normal);
            if (sum_free > 0.0 && length > 0.0) {
                kappa = sum_kappa / sum_free;
                force = csf_force(st->sigma, kappa, delta, p->vol[i],
                                  vec_scale(sum_normal, 1.0 / length));
            }
        }
        p->curvature[i] = kappa;
        vec_store(p->st_force, i, force);
    }
}

typedef struct {
    particles *p;
    const bodies *bs;
    const double *first; /* the first fold's totals, for the second */
} balance_folds;

static void add_force_and_centre(void *context, double *sums)
{
    const balance_folds *c = context;
    const particles *p = c->p;
    FOR_EACH_MEMBER (c->bs, i) {
        if (p->interface[i] == 0.0) continue;
        double *b = sums + (size_t)c->bs->id[i] * BALANCE_FIRST;
        double wi = p->interface[i] * p->vol[i];
        for (int d = 0; d < DIM; d++) b[BALANCE_FORCE + d] += p->st_force[d][i];
        b[BALANCE_WEIGHT] += wi;
        for (int d = 0; d < DIM; d++) b[BALANCE_CENTRE + d] += wi * p->x[d][i];
    }
}

static inline bool is_balanced(const bodies *bs, const double *first, int32_t id)
{
    return !bs->at_wall[id] && first[(size_t)id * BALANCE_FIRST + BALANCE_WEIGHT] > 0.0;
}

/* r of particle i from its body's centre */
static inline vec from_centre(const particles *p, const double *b, size_t i)
{
    vec centre;
    for (int d = 0; d < DIM; d++) centre.c[d] = b[BALANCE_CENTRE + d];
    return vec_sub(vec_load(p->x, i), vec_scale(centre, 1.0 / b[BALANCE_WEIGHT]));
}

/* the resultant removed; moment and inertia of what is left */
static void remove_force_add_moment(void *context, double *sums)
{
    const balance_folds *c = context;
    particles *p = c->p;
    FOR_EACH_MEMBER (c->bs, i) {
        if (p->interface[i] == 0.0) continue;
        int32_t id = c->bs->id[i];
        if (!is_balanced(c->bs, c->first, id)) continue;
        const double *b = c->first + (size_t)id * BALANCE_FIRST;
        double wi = p->interface[i] * p->vol[i];
        vec force;
        for (int d = 0; d < DIM; d++) force.c[d] = b[BALANCE_FORCE + d];
        vec f = vec_axpy(vec_load(p->st_force, i), -wi / b[BALANCE_WEIGHT], force);
        vec_store(p->st_force, i, f);
        vec r = from_centre(p, b, i);
        double *m = sums + (size_t)id * BALANCE_SECOND;
        moment_add(m + BALANCE_MOMENT, 1.0, r, f);
        inertia_add((double(*)[3])(m + BALANCE_INERTIA), wi, r);
    }
}

/* In the continuum, the surface force on a closed body of liquid has no resultant and no
 * moment; the discrete one leaves small residuals of both, removed here body by body: the
 * resultant in proportion to delta V, the moment as the field delta V (Omega x r) about the
 * body's centre whose moment it is (a rigid rotation's pattern, which adds no resultant). A
 * body whose interface comes within 2h of a wall keeps both: the wall takes the reaction of
 * its contact lines. The bodies are the step's (bodies_find); their sums are folds
 * in index order over the interface particles, the bodies' members (bodies_sum): the result does
 * not depend on the thread count or, through d, the process count. */
static void balance_bodies(particles *p, const bodies *bs, const bodies_domain *d,
                           surface_tension_work *w)
{
    balance_folds folds = {p, bs, w->first};
    bodies_sum(d, p, bs, w->first, BALANCE_FIRST, add_force_and_centre, &folds);
    bodies_sum(d, p, bs, w->second, BALANCE_SECOND, remove_force_add_moment, &folds);
    FOR_EACH_MEMBER (bs, i) { /* the moment removed */
        if (p->interface[i] == 0.0) continue;
        int32_t id = bs->id[i];
        if (!is_balanced(bs, w->first, id)) continue;
        const double *b = w->first + (size_t)id * BALANCE_FIRST;
        double *m = w->second + (size_t)id * BALANCE_SECOND;
        vec r = from_centre(p, b, i);
        double wi = p->interface[i] * p->vol[i];
        vec f =
            vec_axpy(vec_load(p->st_force, i), -wi,
                     rotation_field((double(*)[3])(m + BALANCE_INERTIA), m + BALANCE_MOMENT, r));
        vec_store(p->st_force, i, f);
    }
}

void surface_tension_compute(const surface_tension_params *st, const kernel *k, particles *p,
                             const neighbour_list *nl, const bodies *b, const bodies_domain *d,
                             surface_tension_work *w, surface_tension_room room)
{
    interface_and_normals(st, k, p, nl, w, room.normal);
    bodies_share(d, p, p->interface);
    bodies_share(d, p, w->band_sum);
    for (int c = 0; c < DIM; c++) bodies_share(d, p, room.normal[c]);
    /* a wall's image reads its source's interface function and mirrored normals
       (particle_source_scalar and _vector; its S_F flag from tank_mirror_step_fields): the walls
       continue the surface at a right angle (no contact-angle model, docs/surface-tension.md) */
    smoothed_normals(k, p, nl, d, room.normal, w->smooth);
    surface_curvature(st, k, p, nl, d, w->smooth, room.kappa);
    band_force(st, k, p, nl, w->smooth, room.kappa, w->band_sum);
    balance_bodies(p, b, d, w);
}

double surface_tension_power(const particles *p, double *scratch, const reducer *r)
{
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++)
        scratch[i] = vec_dot(vec_load(p->st_force, i), vec_load(p->u, i));
    return reducer_sum(r, scratch, p->n_fluid);
}

double surface_tension_energy(const surface_tension_params *st, const particles *p, double *scratch,
                              const reducer *r)
{
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) scratch[i] = p->interface[i] * p->vol[i];
    return st->sigma * reducer_sum(r, scratch, p->n_fluid);
}
