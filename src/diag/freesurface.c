/* freesurface: Marrone et al. 2010 and the band S_F. */
#include "diag/freesurface.h"
#include "core/team_loop.h"
#include "core/pair.h"

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
    pair pr;
    FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) {
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

/* Two squared distances equal to round-off: mirror images of one configuration give
 * distances that differ in the last bits (1e-9 relative is 1e-12 m at dr = 1 mm). */
static inline int is_tie(double r2, double nearest2) { return r2 <= nearest2 * (1.0 + 1e-9); }

/* Whether neighbour j is a fluid particle on the free surface (found by the first loop). */
static inline bool free_surface_neighbour(const particles *p, size_t j)
{
    return !particle_is_wall_image(p, j) && p->is_free[j];
}

void freesurface_test(const kernel *k, double dr, double normal_reference, particles *p,
                      const neighbour_list *nl)
{
    double radius = FREESURFACE_SCAN_OVER_DR * dr;
    TEAM_FOR (i, p->n_fluid) {
        double lambda = p->lambda[i], length;
        vec_store(p->normal, i, unit_vector(vec_load(p->normal, i), &length));
        int on_surface;
        if (lambda <= FREESURFACE_LAMBDA_FREE)
            on_surface = 1;
        else if (lambda > FREESURFACE_LAMBDA_INTERIOR)
            on_surface = 0;
        /* a nearly symmetric neighbourhood has no reliable normal: interior (theory §4) */
        else if (length < 0.5 * normal_reference)
            on_surface = 0;
        else
            on_surface = !covered(k, p, nl, i, radius);
        p->is_free[i] = (uint8_t)on_surface;
    }
}

void freesurface_region(const kernel *k, particles *p, const neighbour_list *nl, cell_grid *g)
{
    /* the cells that hold a free-surface particle: a particle with none around it has no
       free-surface neighbour, and its row need not be read */
    cells_mark(g, p->is_free, particles_images_begin(p));
    /* S_F: the free surface and every fluid particle within 2h of it (ghosts add nothing: a
       mirror image is never closer than its source). Below the free surface, a particle of S_F
       takes the normal of the surface nearest to it, that of its nearest free-surface
       neighbour (theory §4): its own measures the holes of its neighbourhood, and an average
       over all free-surface neighbours cancels in thin jets and sheets, whose two faces point
       opposite ways. Equidistant ones (a lattice's corners, a mirror-symmetric flow) share
       the choice equally, so that no neighbour order breaks a symmetry of the flow. Only
       normals of the free surface are read, and only the others' are written. */
    TEAM_FOR (i, p->n_fluid) {
        if (p->is_free[i]) {
            p->surface[i] = SURFACE_FREE;
            continue;
        }
        if (!cells_marked_around(g, i)) {
            p->surface[i] = SURFACE_INTERIOR;
            continue;
        }
        vec xi = vec_load(p->x, i);
        double nearest2 = INFINITY;
        pair pr;
        FOR_EACH_PAIR_WHERE (k, p->x, nl, i, xi, pr, free_surface_neighbour(p, pr.j))
            nearest2 = fmin(nearest2, pr.r * pr.r);
        if (nearest2 == INFINITY) {
            p->surface[i] = SURFACE_INTERIOR;
            continue;
        }
        p->surface[i] = SURFACE_REGION;
        vec sum = vec_zero();
        FOR_EACH_PAIR_WHERE (k, p->x, nl, i, xi, pr, free_surface_neighbour(p, pr.j)) {
            if (is_tie(pr.r * pr.r, nearest2)) sum = vec_add(sum, vec_load(p->normal, pr.j));
        }
        double length = vec_norm(sum);
        if (length > 0.0) vec_store(p->normal, i, vec_scale(sum, 1.0 / length));
    }
}
