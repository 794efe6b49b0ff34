/* fields: per-step geometry and the frozen diffusion terms. */
#include "scheme/fields.h"
#include "diag/freesurface.h"
#include "physics/diffusion.h"
#include "physics/viscosity.h"
#include "scheme/pair.h"

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

static void geometry_and_gradients(const physics_params *pp, const tank *t, particles *p,
                                   const neighbour_list *nl)
{
    const kernel *k = &pp->k;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
        double rhoi = p->rho[i];
        neighbour_sums s = {mat_zero(), vec_zero(), 0.0, 0.0, vec_zero(), {{0}}};
        const int32_t *row = neighbour_row(nl, i);
        for (int32_t n = 0; n < nl->count[i]; n++) {
            pair pr;
            if (!pair_of(k, p->x, xi, row, n, &pr)) continue;
            size_t j = pr.j;
            neighbour_sums_add(&s, &pr, kernel_w(k, sqrt(pr.r2)), p->vol[j], p->rho[j] - rhoi,
                               vec_sub(vec_load(p->u_wall, j), ui));
        }
        double lambda = mat_min_eigenvalue(&s.l);
        p->lambda[i] = lambda;
        p->kernel_sum[i] = s.w + k->norm; /* self term W(0) */
        p->gamma[i] = s.wv + k->norm * p->vol[i];
        /* near-singular L (drops, jets): fall back to the plain gradient (theory §2) */
        mat l_inv = mat_identity();
        if (lambda > pp->lambda_renormalize) mat_inverse(&s.l, &l_inv);
        vec normal = vec_scale(mat_mul_vec(&l_inv, s.grad_one), -1.0);
        double normal_norm = vec_norm(normal);
        p->normal_raw[i] = normal_norm;
        vec_store(p->normal, i, normal_norm > 0.0 ? vec_scale(normal, 1.0 / normal_norm) : normal);
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
            int axis = 0;
            double y = tank_wall_distance(t, xi, &axis);
            vec tangential = ui;
            tangential.c[axis] = 0.0;
            damping = van_driest_factor(y, vec_norm(tangential), pp->nu);
        }
        p->nu_t[i] = pp->les ? eddy_viscosity(pp->filter_length, damping, dnorm) : 0.0;
    }
}

static void density_diffusion(const physics_params *pp, particles *p, const neighbour_list *nl)
{
    const kernel *k = &pp->k;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec xi = vec_load(p->x, i), gi = vec_load(p->grad_rho, i);
        double rhoi = p->rho[i], nui = p->nu_delta[i], sum = 0.0;
        const int32_t *row = neighbour_row(nl, i);
        for (int32_t n = 0; n < nl->count[i]; n++) {
            pair pr;
            if (!pair_of(k, p->x, xi, row, n, &pr)) continue;
            size_t j = pr.j;
            double delta_ij = harmonic_mean_capped(nui, p->nu_delta[j], pp->delta_cap);
            sum += diffusion_rho_pair(delta_ij, rhoi, p->rho[j], gi, vec_load(p->grad_rho, j),
                                      pr.r_ji, pr.f, p->vol[j]);
        }
        p->diff_rho[i] = sum;
    }
}

void fields_compute(const physics_params *pp, const tank *t, particles *p, const neighbour_list *nl,
                    vec g_eff)
{
    geometry_and_gradients(pp, t, p, nl);
    freesurface_detect(&pp->k, pp->dr, pp->normal_reference, p, nl);
    tank_mirror_step_fields(t, p, g_eff, pp->c0);
    if (pp->c_delta > 0.0)
        density_diffusion(pp, p, nl);
    else
        for (size_t i = 0; i < p->n_fluid; i++) p->diff_rho[i] = 0.0;
}
