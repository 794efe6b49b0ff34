/* fields: per-step geometry, the shifting and correction velocities and the frozen diffusion
 * terms, each pass summing a row a block of entries at a time (core/pair_block.h). */
#include "scheme/fields.h"
#include "diag/freesurface.h"
#include "physics/diffusion.h"
#include "physics/shifting.h"
#include "physics/viscosity.h"
#include "scheme/volume_correction.h"
#include "core/pair_block.h"

/* Sums of one particle over its neighbours: the geometry (Eqs. 10, 11, A.2) and the raw
 * sums of the renormalized gradients (theory §2). */
typedef struct {
    mat l;               /* L_i = sum r_ji (x) r_ji F V_j, Eq. (10) */
    vec grad_one;        /* sum r_ji F V_j = sum grad_i W_ij V_j: -normal before L^-1 */
    double w, wv;        /* sum W_ij and sum W_ij V_j (self terms added after) */
    vec drho;            /* sum (rho_j - rho_i) r_ji F V_j */
    double du[DIM][DIM]; /* du[a][b] = sum (u_j - u_i)_a (r_ji)_b F V_j */
} neighbour_sums;

/* neighbour_sums lane by lane (core/pair_block.h): lane l sums the row's entries n = l mod
 * PAIR_BLOCK. L is symmetric: its upper triangle is summed and mirrored. */
typedef struct {
    pair_block l[DIM][DIM], grad_one[DIM], w, wv, drho[DIM], du[DIM][DIM];
} neighbour_block_sums;

/* A block of pairs' terms of Eqs. (10), (11) and (A.2); each has a factor F or W, zero where
 * the entry does not count (pair_block_geometry). */
PAIR_BLOCK_INLINE void neighbour_block_sums_add(neighbour_block_sums *s,
                                                const pair_block_geometry *b, pair_block vol_j,
                                                pair_block drho, const pair_block du[DIM])
{
    pair_block fv = b->f * vol_j;
    for (int a = 0; a < DIM; a++) {
        pair_block fr = fv * b->r_ji[a];
        for (int c = a; c < DIM; c++) s->l[a][c] += fr * b->r_ji[c];
        s->grad_one[a] += fr;
        s->drho[a] += drho * fr;
        for (int c = 0; c < DIM; c++) s->du[c][a] += du[c] * fr;
    }
    s->w += b->w;
    s->wv += b->w * vol_j;
}

PAIR_BLOCK_INLINE neighbour_sums neighbour_sums_total(const neighbour_block_sums *bs)
{
    neighbour_sums s;
    for (int a = 0; a < DIM; a++) {
        for (int c = a; c < DIM; c++) s.l.a[a][c] = s.l.a[c][a] = block_total(bs->l[a][c]);
        s.grad_one.c[a] = block_total(bs->grad_one[a]);
        s.drho.c[a] = block_total(bs->drho[a]);
        for (int c = 0; c < DIM; c++) s.du[a][c] = block_total(bs->du[a][c]);
    }
    s.w = block_total(bs->w);
    s.wv = block_total(bs->wv);
    return s;
}

/* Particle i's neighbour sums over its row, a block of entries at a time. */
PAIR_BLOCK_INLINE neighbour_sums geometry_sums(const kernel *k, const particles *p,
                                               const neighbour_list *nl, size_t i)
{
    vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
    /* a row that reaches no ghost has no wall image to ask for its u_wall */
    bool ghosts = neighbour_row_has_ghosts(nl, i);
    PAIR_ROW(k, p->x, nl, i, xi, row);
    neighbour_block_sums bs;
    __builtin_memset(&bs, 0, sizeof bs);
    pair_block_geometry b;
    FOR_EACH_PAIR_BLOCK_OF_ROW (&row, b) {
        pair_block du[DIM];
        pair_block_viscous_velocity(p, &b, ghosts, du);
        for (int d = 0; d < DIM; d++) du[d] -= ui.c[d];
        pair_block drho = pair_block_gather(p->rho, b.j) - p->rho[i];
        neighbour_block_sums_add(&bs, &b, pair_block_gather(p->vol, b.j), drho, du);
    }
    return neighbour_sums_total(&bs);
}

PAIR_BLOCK_FORMS(neighbour_sums, geometry_sums,
                 (const kernel *k, const particles *p, const neighbour_list *nl, size_t i),
                 (k, p, nl, i))

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
    __auto_type sums_of = geometry_sums_form();
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
        neighbour_sums s = sums_of(k, p, nl, i);
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

/* The sums over particle i's row of the shifting (Eq. 7: sum_j [1 + R (W_ij/W(dr))^4]
 * grad_i W_ij V_j, and max_j |u_j - u_i|^2 for its limit) and of the volume correction
 * (sum_j (e_j - e_i) grad_i W_ij V_j). */
typedef struct {
    vec shifting, correction;
    double max_relative2;
} shift_sums;

/* shift_sums a block of entries at a time (core/pair_block.h): shifting_pair and
 * volume_correction_pair (src/physics) written out in blocks. The maximum takes only the pairs
 * within 2h, as the pair loops do (a maximum does not depend on the order). */
PAIR_BLOCK_INLINE shift_sums shift_sums_of(const physics_params *pp, const particles *p,
                                           const neighbour_list *nl, size_t i, bool shift,
                                           bool correct)
{
    vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
    double ei = p->volume_mismatch[i];
    PAIR_ROW(&pp->k, p->x, nl, i, xi, row);
    pair_block shifting[DIM] = {{0}}, correction[DIM] = {{0}}, max_relative2 = {0};
    pair_block_geometry b;
    FOR_EACH_PAIR_BLOCK_OF_ROW (&row, b) {
        pair_block vj = pair_block_gather(p->vol, b.j);
        if (shift) { /* shifting_pair */
            pair_block q = b.w / pp->w_dr, q2 = q * q;
            pair_block scale = (1.0 + SHIFTING_R * q2 * q2) * b.f * vj;
            pair_block rel2 = pair_block_broadcast(0.0);
            for (int d = 0; d < DIM; d++) {
                shifting[d] += b.r_ji[d] * scale;
                pair_block u_ji = pair_block_gather(p->u[d], b.j) - ui.c[d];
                rel2 += u_ji * u_ji;
            }
            rel2 = (pair_block)(b.inside & (pair_block_mask)rel2); /* |u_ji|^2 >= 0: 0 drops */
            max_relative2 = pair_block_select(rel2 > max_relative2, rel2, max_relative2);
        }
        if (correct) { /* volume_correction_pair */
            pair_block scale = (pair_block_gather(p->volume_mismatch, b.j) - ei) * b.f * vj;
            for (int d = 0; d < DIM; d++) correction[d] += b.r_ji[d] * scale;
        }
    }
    shift_sums s = {.max_relative2 = 0.0};
    for (int d = 0; d < DIM; d++) {
        s.shifting.c[d] = block_total(shifting[d]);
        s.correction.c[d] = block_total(correction[d]);
    }
    for (int l = 0; l < PAIR_BLOCK; l++)
        if (max_relative2[l] > s.max_relative2) s.max_relative2 = max_relative2[l];
    return s;
}

PAIR_BLOCK_FORMS(shift_sums, shift_sums_of,
                 (const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i,
                  bool shift, bool correct),
                 (pp, p, nl, i, shift, correct))

/* Eq. (7): du*_i = -xi h U_max sum_j [1 + R (W_ij/W(dr))^4] grad_i W_ij V_j, the sum taken
 * beyond the floor of the liquid's own compression gradient (shifting.h), limited, then
 * made tangential in S_F; the pass below switches it off where lambda < 0.4 (drops and jets:
 * no reliable normal; theory §4, inferred from Sun et al. 2017). */
static vec shifting_velocity(const physics_params *pp, const particles *p, size_t i,
                             const shift_sums *s)
{
    vec sum = gradient_beyond_floor(s->shifting, fields_compression_gradient(p, i));
    vec du = vec_scale(sum, -pp->k.h * pp->shift_u_max);
    du = shifting_limit(du, sqrt(s->max_relative2), pp->shift_u_max);
    if (p->surface[i] != SURFACE_INTERIOR)
        return shifting_tangential(du, vec_load(p->normal, i)); /* the surface's */
    return du;
}

void fields_shifting_and_correction(const physics_params *pp, particles *p,
                                    const neighbour_list *nl, bool shift, bool correct)
{
    __auto_type sums_of = shift_sums_of_form();
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        if (p->lambda[i] < SHIFTING_LAMBDA_MIN) { /* neither moves it: no row geometry */
            if (shift) vec_store(p->shift, i, vec_zero());
            if (correct) vec_store(p->correction, i, vec_zero());
            continue;
        }
        shift_sums s = sums_of(pp, p, nl, i, shift, correct);
        if (shift) vec_store(p->shift, i, shifting_velocity(pp, p, i, &s));
        if (correct)
            vec_store(p->correction, i, volume_correction_velocity_from(pp, p, i, s.correction));
    }
}

/* The sums of D^rho and D^m of particle i (Eq. 5) and the rate of diffusion_stability_factor. */
typedef struct {
    double rho, m, rate;
} diffusion_sums;

/* The masses of the block's neighbours; a wall image, which has no mass of its own (the field
 * is the fluid's and the halo's), reads as m_i, so that its mass diffusion term is an exact 0:
 * no mass crosses a wall. */
PAIR_BLOCK_INLINE pair_block fluid_masses(const particles *p, const pair_block_geometry *b,
                                          double mi, bool ghosts)
{
    if (!ghosts) return pair_block_gather(p->m, b->j);
    pair_block mj;
    for (int l = 0; l < PAIR_BLOCK; l++)
        mj[l] = particle_is_wall_image(p, (size_t)b->j[l]) ? mi : p->m[b->j[l]];
    return mj;
}

/* Particle i's diffusion sums over its row, a block of entries at a time (core/pair_block.h):
 * harmonic_mean_capped, diffusion_rate_pair, diffusion_rho_pair and mass_diffusion_pair
 * (physics/), written out in blocks operation by operation. The mass diffusion runs between
 * fluid particles only: no mass crosses a wall, and the total mass stays exact. */
PAIR_BLOCK_INLINE diffusion_sums diffusion_sums_of(const physics_params *pp, const particles *p,
                                                   const neighbour_list *nl, size_t i,
                                                   const bool mass)
{
    const kernel *k = &pp->k;
    vec xi = vec_load(p->x, i), gi = vec_load(p->grad_rho, i);
    double rhoi = p->rho[i], nui = p->nu_delta[i], mi = p->m[i], vi = p->vol[i];
    bool ghosts = neighbour_row_has_ghosts(nl, i);
    PAIR_ROW(k, p->x, nl, i, xi, row);
    pair_block sum_rho = {0}, sum_m = {0}, rate = {0};
    pair_block_geometry b;
    FOR_EACH_PAIR_BLOCK_OF_ROW (&row, b) {
        pair_block vj = pair_block_gather(p->vol, b.j), nuj = pair_block_gather(p->nu_delta, b.j);
        /* harmonic_mean_capped */
        pair_block nu_sum = nui + nuj;
        pair_block delta =
            pair_block_select(nu_sum > 0.0, 2.0 * nui * nuj / nu_sum, pair_block_broadcast(0.0));
        delta =
            pair_block_select(delta < pp->delta_cap, delta, pair_block_broadcast(pp->delta_cap));
        /* diffusion_rate_pair, diffusion_rho_pair */
        pair_block rate_ij = 2.0 * delta * b.f * vj;
        pair_block linear = pair_block_broadcast(0.0);
        for (int d = 0; d < DIM; d++)
            linear += (gi.c[d] + pair_block_gather(p->grad_rho[d], b.j)) * b.r_ji[d];
        linear = 0.5 * linear;
        sum_rho += rate_ij * ((pair_block_gather(p->rho, b.j) - rhoi) - linear);
        rate += rate_ij;
        if (mass) { /* mass_diffusion_pair, 0 for a wall image */
            pair_block mj = fluid_masses(p, &b, mi, ghosts);
            pair_block term = 2.0 * pp->delta_c0_h * (mj - mi) * b.f;
            pair_block root = vi * vj;
            for (int l = 0; l < PAIR_BLOCK; l++) root[l] = __builtin_sqrt(root[l]);
            sum_m += term * root;
        }
    }
    diffusion_sums s = {block_total(sum_rho), block_total(sum_m), block_total(rate)};
    return s;
}

PAIR_BLOCK_FORMS(diffusion_sums, diffusion_sums_of,
                 (const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i,
                  bool mass),
                 (pp, p, nl, i, mass))

/* D^rho and D^m of Eq. (5), frozen over the step. */
static void diffusion(const physics_params *pp, particles *p, const neighbour_list *nl,
                      const bool mass, double dt)
{
    __auto_type sums_of = diffusion_sums_of_form();
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n_fluid; i++) {
        diffusion_sums s = sums_of(pp, p, nl, i, mass);
        p->diff_rho[i] = s.rho * diffusion_stability_factor(s.rate, dt);
        p->diff_m[i] = s.m;
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
