/* fields: per-step geometry and the frozen diffusion terms. */
#include "scheme/fields.h"
#include "diag/freesurface.h"
#include "physics/ale.h"
#include "physics/diffusion.h"
#include "physics/shifting.h"
#include "physics/viscosity.h"
#include "scheme/volume_correction.h"
#include "core/pair.h"

/* Sums of one particle over its neighbours: the geometry (Eqs. 10, 11, A.2) and the raw
 * sums of the renormalized gradients (theory §2). */
typedef struct {
    mat l;               /* L_i = sum r_ji (x) r_ji F V_j, Eq. (10) */
    vec grad_one;        /* sum r_ji F V_j = sum grad_i W_ij V_j: -normal before L^-1 */
    double w, wv;        /* sum W_ij and sum W_ij V_j (self terms added after) */
    vec drho;            /* sum (rho_j - rho_i) r_ji F V_j */
    double du[DIM][DIM]; /* du[a][b] = sum (u_j - u_i)_a (r_ji)_b F V_j */
} neighbour_sums;

static inline void neighbour_sums_add(neighbour_sums *s, const pair *pr, double w, double vol_j,
                                      double drho, vec du)
{
    double fv = pr->f * vol_j;
    mat_add_outer(&s->l, fv, pr->r_ji, pr->r_ji);
    s->grad_one = vec_axpy(s->grad_one, fv, pr->r_ji);
    s->w += w;
    s->wv += w * vol_j;
    s->drho = vec_axpy(s->drho, drho * fv, pr->r_ji);
    for (int a = 0; a < DIM; a++)
        for (int b = 0; b < DIM; b++) s->du[a][b] += du.c[a] * pr->r_ji.c[b] * fv;
}

/* ||D|| = sqrt(2 D:D), D the symmetric part of the velocity gradient G[a][b] = du_a/dx_b */
static inline double strain_norm(double g[DIM][DIM])
{
    double dd = 0.0;
    for (int a = 0; a < DIM; a++)
        for (int b = 0; b < DIM; b++) {
            double d = 0.5 * (g[a][b] + g[b][a]);
            dd += d * d;
        }
    return sqrt(2.0 * dd);
}

void fields_geometry(const physics_params *pp, const tank *t, particles *p,
                     const neighbour_list *nl)
{
    const kernel *k = &pp->k;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
        double rhoi = p->rho[i];
        neighbour_sums s = {mat_zero(), vec_zero(), 0.0, 0.0, vec_zero(), {{0}}};
        /* a row that reaches no ghost has no wall image to ask for its u_wall */
        bool ghosts = neighbour_row_has_ghosts(nl, i);
        pair pr;
        FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) {
            size_t j = pr.j;
            vec uj = ghosts ? particle_viscous_velocity(p, j) : vec_load(p->u, j);
            neighbour_sums_add(&s, &pr, pr.w, p->vol[j], p->rho[j] - rhoi, vec_sub(uj, ui));
        }
        double lambda = mat_min_eigenvalue(&s.l);
        p->lambda[i] = lambda;
        p->kernel_sum[i] = s.w + k->norm; /* self term W(0) */
        p->gamma[i] = s.wv + k->norm * p->vol[i];
        /* near-singular L (drops, jets): fall back to the plain gradient (theory §2) */
        mat l_inv = renormalization(&s.l, lambda, pp->lambda_renormalize);
        vec_store(p->normal, i, outward_normal(&l_inv, s.grad_one, &p->normal_raw[i]));
        vec_store(p->grad_rho, i, mat_mul_vec(&l_inv, s.drho));
        double g[DIM][DIM];
        for (int a = 0; a < DIM; a++) {
            vec row_a;
            for (int b = 0; b < DIM; b++) row_a.c[b] = s.du[a][b];
            vec ga = mat_mul_vec(&l_inv, row_a);
            for (int b = 0; b < DIM; b++) g[a][b] = ga.c[b];
        }
        double dnorm = strain_norm(g);
        p->nu_delta[i] = diffusion_coefficient(pp->c_delta, pp->filter_length, dnorm);
        double damping = 1.0;
        if (pp->van_driest) {
            vec n = vec_zero();
            double y = tank_wall_distance(t, xi, &n);
            vec tangential = vec_axpy(ui, -vec_dot(ui, n), n);
            damping = van_driest_factor(y, vec_norm(tangential), pp->nu);
        }
        p->nu_t[i] = pp->les ? eddy_viscosity(pp->filter_length, damping, dnorm) : 0.0;
    }
}

/* Eq. (7): du*_i = -xi h U_max sum_j [1 + R (W_ij/W(dr))^4] grad_i W_ij V_j, the sum taken
 * beyond the floor of the liquid's own compression gradient (shifting.h), limited, then
 * made tangential in S_F; the pass below switches it off where lambda < 0.4 (drops and jets:
 * no reliable normal; theory §4, inferred from Sun et al. 2017). */
static vec shifting_velocity(const physics_params *pp, const particles *p, size_t i,
                             const pair_row *row)
{
    const kernel *k = &pp->k;
    vec ui = vec_load(p->u, i), sum = vec_zero();
    double max_relative2 = 0.0;
    pair pr;
    FOR_EACH_PAIR_OF_ROW (row, pr) {
        sum = vec_add(sum, shifting_pair(pr.w, pp->w_dr, pr.r_ji, pr.f, p->vol[pr.j]));
        double rel2 = vec_norm2(vec_sub(vec_load(p->u, pr.j), ui));
        if (rel2 > max_relative2) max_relative2 = rel2;
    }
    sum = gradient_beyond_floor(sum, fields_compression_gradient(p, i));
    vec du = vec_scale(sum, -k->h * pp->shift_u_max);
    du = shifting_limit(du, sqrt(max_relative2), pp->shift_u_max);
    if (p->surface[i] != SURFACE_INTERIOR)
        return shifting_tangential(du, vec_load(p->normal, i)); /* the surface's */
    return du;
}

void fields_shifting_and_correction(const physics_params *pp, particles *p,
                                    const neighbour_list *nl, bool shift, bool correct)
{
    const kernel *k = &pp->k;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        if (p->lambda[i] < SHIFTING_LAMBDA_MIN) { /* neither moves it: no row geometry */
            if (shift) vec_store(p->shift, i, vec_zero());
            if (correct) vec_store(p->correction, i, vec_zero());
            continue;
        }
        vec xi = vec_load(p->x, i);
        PAIR_ROW(k, p->x, nl, i, xi, row);
        if (shift) vec_store(p->shift, i, shifting_velocity(pp, p, i, &row));
        if (correct) vec_store(p->correction, i, volume_correction_velocity_of(pp, p, i, &row));
    }
}

/* D^rho and D^m of Eq. (5), frozen over the step. The mass diffusion runs between fluid
 * particles only: no mass crosses a wall, and the total mass stays exact. */
static void diffusion(const physics_params *pp, particles *p, const neighbour_list *nl,
                      const bool mass, double dt)
{
    const kernel *k = &pp->k;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec xi = vec_load(p->x, i), gi = vec_load(p->grad_rho, i);
        double rhoi = p->rho[i], nui = p->nu_delta[i], mi = p->m[i], vi = p->vol[i];
        double sum_rho = 0.0, sum_m = 0.0, rate = 0.0;
        pair pr;
        FOR_EACH_PAIR (k, p->x, nl, i, xi, pr) {
            size_t j = pr.j;
            double delta_ij = harmonic_mean_capped(nui, p->nu_delta[j], pp->delta_cap);
            sum_rho += diffusion_rho_pair(delta_ij, rhoi, p->rho[j], gi, vec_load(p->grad_rho, j),
                                          pr.r_ji, pr.f, p->vol[j]);
            rate += diffusion_rate_pair(delta_ij, pr.f, p->vol[j]);
            if (mass && !particle_is_wall_image(p, j))
                sum_m += mass_diffusion_pair(pp->delta_c0_h, mi, p->m[j], pr.f, vi, p->vol[j]);
        }
        p->diff_rho[i] = sum_rho * diffusion_stability_factor(rate, dt);
        p->diff_m[i] = sum_m;
    }
}

void fields_frozen_terms(const physics_params *pp, particles *p, const neighbour_list *nl,
                         const tank_frame *frame, bool variable_mass, double dt)
{
    tank_mirror_step_fields(p, frame, pp->c0);
    if (pp->c_delta > 0.0) {
        if (variable_mass)
            diffusion(pp, p, nl, true, dt);
        else
            diffusion(pp, p, nl, false, dt);
    } else {
        for (size_t i = 0; i < p->n_fluid; i++) p->diff_rho[i] = p->diff_m[i] = 0.0;
    }
}
