/* step_fields: per-step geometry, the shifting and correction velocities and the frozen diffusion
 * terms, each pass summing a row a block of entries at a time (core/pair_block.h). */
#include "scheme/step_fields.h"
#include "core/team_loop.h"
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
 * PAIR_BLOCK. */
typedef struct {
    pair_block_moments moments; /* L and sum grad W V */
    pair_block w, wv, drho[DIM], du[DIM][DIM];
} neighbour_block_sums;

/* A block of pairs' terms of Eqs. (10), (11) and (A.2); each has a factor F or W, zero where
 * the entry does not count (pair_block_geometry). */
PAIR_BLOCK_INLINE void neighbour_block_sums_add(neighbour_block_sums *s,
                                                const pair_block_geometry *b, pair_block vol_j,
                                                pair_block drho, const pair_block du[DIM])
{
    pair_block fv = b->f * vol_j;
    pair_block_moments_add(&s->moments, fv, b->r_ji);
    for (int a = 0; a < DIM; a++) {
        pair_block fr = fv * b->r_ji[a];
        s->drho[a] += drho * fr;
        for (int c = 0; c < DIM; c++) s->du[c][a] += du[c] * fr;
    }
    s->w += b->w;
    s->wv += b->w * vol_j;
}

PAIR_BLOCK_INLINE neighbour_sums neighbour_sums_total(const neighbour_block_sums *bs)
{
    neighbour_sums s;
    pair_block_moments_total(&bs->moments, &s.l, &s.grad_one);
    for (int a = 0; a < DIM; a++) {
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
    /* a row that reaches no ghost has no wall image to ask for its viscous velocity */
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

void step_fields_geometry(const physics_params *pp, const tank *t, particles *p,
                          const neighbour_list *nl)
{
    const kernel *k = &pp->k;
    __auto_type sums_of = geometry_sums_form();
    TEAM_FOR (i, p->n_fluid) {
        vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
        neighbour_sums s = sums_of(k, p, nl, i);
        double lambda = mat_min_eigenvalue(&s.l);
        p->lambda[i] = lambda;
        p->kernel_sum[i] = s.w + k->norm; /* self term W(0) */
        p->gamma[i] = s.wv + k->norm * p->vol[i];
        /* near-singular L (drops, jets): fall back to the plain gradient (theory §2) */
        mat l_inv = renormalization(&s.l, lambda > pp->lambda_renormalize);
        /* unnormalised: freesurface_test normalises it and tests its length */
        vec_store(p->normal, i, outward_direction(&l_inv, s.grad_one));
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

/* shift_sums lane by lane (core/pair_block.h) */
typedef struct {
    pair_block shifting[DIM], correction[DIM], max_relative2;
} shift_block_sums;

/* shifting_pair and volume_correction_pair (src/physics) written out in blocks. The maximum
 * takes only the pairs within 2h, as the pair loops do (a maximum does not depend on the
 * order). */
PAIR_BLOCK_INLINE void shift_block_sums_add(shift_block_sums *s, const physics_params *pp,
                                            const particles *p, const pair_block_geometry *b,
                                            pair_block vj, vec ui, double ei, bool shift,
                                            bool correct)
{
    if (shift) { /* shifting_pair */
        pair_block q = b->w / pp->w_dr, q2 = q * q;
        pair_block scale = (1.0 + SHIFTING_R * q2 * q2) * b->f * vj;
        pair_block rel2 = pair_block_broadcast(0.0);
        for (int d = 0; d < DIM; d++) {
            s->shifting[d] += b->r_ji[d] * scale;
            pair_block u_ji = pair_block_gather(p->u[d], b->j) - ui.c[d];
            rel2 += u_ji * u_ji;
        }
        rel2 = (pair_block)(b->inside & (pair_block_mask)rel2); /* |u_ji|^2 >= 0: 0 drops */
        s->max_relative2 = pair_block_select(rel2 > s->max_relative2, rel2, s->max_relative2);
    }
    if (correct) { /* volume_correction_pair */
        pair_block scale = (pair_block_gather(p->volume_mismatch, b->j) - ei) * b->f * vj;
        for (int d = 0; d < DIM; d++) s->correction[d] += b->r_ji[d] * scale;
    }
}

PAIR_BLOCK_INLINE shift_sums shift_sums_total(const shift_block_sums *bs)
{
    shift_sums s = {.max_relative2 = 0.0};
    for (int d = 0; d < DIM; d++) {
        s.shifting.c[d] = block_total(bs->shifting[d]);
        s.correction.c[d] = block_total(bs->correction[d]);
    }
    for (int l = 0; l < PAIR_BLOCK; l++)
        if (bs->max_relative2[l] > s.max_relative2) s.max_relative2 = bs->max_relative2[l];
    return s;
}

/* The sums of D^rho and D^m of particle i (Eq. 5) and the rate of diffusion_stability_factor. */
typedef struct {
    double rho, m, rate;
} diffusion_sums;

/* diffusion_sums lane by lane */
typedef struct {
    pair_block rho, m, rate;
} diffusion_block_sums;

/* What of particle i its diffusion terms read at every pair */
typedef struct {
    vec grad_rho;
    double rho, nu_delta, m, vol;
    bool ghosts; /* its row reaches a wall image */
} diffusion_particle;

PAIR_BLOCK_INLINE diffusion_particle diffusion_particle_of(const particles *p,
                                                           const neighbour_list *nl, size_t i)
{
    diffusion_particle d = {.grad_rho = vec_load(p->grad_rho, i),
                            .rho = p->rho[i],
                            .nu_delta = p->nu_delta[i],
                            .m = p->m[i],
                            .vol = p->vol[i],
                            .ghosts = neighbour_row_has_ghosts(nl, i)};
    return d;
}

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

/* harmonic_mean_capped, diffusion_rate_pair, diffusion_rho_pair and mass_diffusion_pair
 * (physics/), written out in blocks operation by operation. The mass diffusion runs between
 * fluid particles only: no mass crosses a wall, and the total mass stays exact. */
PAIR_BLOCK_INLINE void diffusion_block_sums_add(diffusion_block_sums *s, const physics_params *pp,
                                                const particles *p, const pair_block_geometry *b,
                                                pair_block vj, const diffusion_particle *i,
                                                const bool mass)
{
    pair_block nuj = pair_block_gather(p->nu_delta, b->j);
    /* harmonic_mean_capped */
    pair_block nu_sum = i->nu_delta + nuj;
    pair_block delta = pair_block_select(nu_sum > 0.0, 2.0 * i->nu_delta * nuj / nu_sum,
                                         pair_block_broadcast(0.0));
    delta = pair_block_select(delta < pp->delta_cap, delta, pair_block_broadcast(pp->delta_cap));
    /* diffusion_rate_pair, diffusion_rho_pair */
    pair_block rate_ij = 2.0 * delta * b->f * vj;
    pair_block linear = pair_block_broadcast(0.0);
    for (int d = 0; d < DIM; d++)
        linear += (i->grad_rho.c[d] + pair_block_gather(p->grad_rho[d], b->j)) * b->r_ji[d];
    linear = 0.5 * linear;
    s->rho += rate_ij * ((pair_block_gather(p->rho, b->j) - i->rho) - linear);
    s->rate += rate_ij;
    if (mass) { /* mass_diffusion_pair, 0 for a wall image */
        pair_block mj = fluid_masses(p, b, i->m, i->ghosts);
        pair_block term = 2.0 * pp->delta_c0_h * (mj - i->m) * b->f;
        pair_block root = i->vol * vj;
        for (int l = 0; l < PAIR_BLOCK; l++) root[l] = __builtin_sqrt(root[l]);
        s->m += term * root;
    }
}

PAIR_BLOCK_INLINE diffusion_sums diffusion_sums_total(const diffusion_block_sums *bs)
{
    diffusion_sums s = {block_total(bs->rho), block_total(bs->m), block_total(bs->rate)};
    return s;
}

/* What the shifting pass sums over a row: the shifting and correction sums and, with
 * `diffuse`, the diffusion's, all over one geometry of the row. */
typedef struct {
    shift_sums shift;
    diffusion_sums diffusion;
} shift_row_sums;

PAIR_BLOCK_INLINE shift_row_sums shift_row_sums_of(const physics_params *pp, const particles *p,
                                                   const neighbour_list *nl, size_t i, bool shift,
                                                   bool correct, bool diffuse, bool mass)
{
    vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
    double ei = p->volume_mismatch[i];
    diffusion_particle di = diffusion_particle_of(p, nl, i);
    PAIR_ROW(&pp->k, p->x, nl, i, xi, row);
    shift_block_sums sb;
    diffusion_block_sums db;
    __builtin_memset(&sb, 0, sizeof sb);
    __builtin_memset(&db, 0, sizeof db);
    pair_block_geometry b;
    FOR_EACH_PAIR_BLOCK_OF_ROW (&row, b) {
        pair_block vj = pair_block_gather(p->vol, b.j);
        shift_block_sums_add(&sb, pp, p, &b, vj, ui, ei, shift, correct);
        if (diffuse) diffusion_block_sums_add(&db, pp, p, &b, vj, &di, mass);
    }
    shift_row_sums s = {shift_sums_total(&sb), diffusion_sums_total(&db)};
    return s;
}

PAIR_BLOCK_FORMS(shift_row_sums, shift_row_sums_of,
                 (const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i,
                  bool shift, bool correct, bool diffuse, bool mass),
                 (pp, p, nl, i, shift, correct, diffuse, mass))

/* Eq. (7): du*_i = -xi h U_max sum_j [1 + R (W_ij/W(dr))^4] grad_i W_ij V_j, the sum taken
 * beyond the floor of the liquid's own compression gradient (shifting.h), limited, then
 * made tangential in S_F; the pass below switches it off where lambda < 0.4 (drops and jets:
 * no reliable normal; theory §4, inferred from Sun et al. 2017). */
static vec shifting_velocity(const physics_params *pp, const particles *p, size_t i,
                             const shift_sums *s)
{
    vec sum = gradient_beyond_floor(s->shifting,
                                    compression_gradient(vec_load(p->grad_rho, i), p->rho[i]));
    double max_relative_speed = sqrt(s->max_relative2);
    vec du = vec_scale(sum, -pp->k.h * pp->shift_u_max);
    du = shifting_limit(du, max_relative_speed, pp->shift_u_max);
    if (p->surface[i] == SURFACE_INTERIOR) return du;
    vec normal = vec_load(p->normal, i);
    du = shifting_tangential(du, normal); /* the surface's */
    if (p->surface[i] == SURFACE_FREE && pp->unpack_speed > 0.0)
        du = vec_add(du, surface_unpacking_shift(p->kernel_sum[i] * pp->surface_sum_scale,
                                                 pp->unpack_speed, normal, max_relative_speed,
                                                 pp->shift_u_max));
    return du;
}

/* D^rho and D^m of Eq. (5) from particle i's sums, frozen over the step dt */
static void store_diffusion(particles *p, size_t i, const diffusion_sums *s, double dt)
{
    p->diff_rho[i] = s->rho * diffusion_stability_factor(s->rate, dt);
    p->diff_m[i] = s->m;
}

/* The diffusion of a row that reaches no wall image reads only fields that are final once
 * EdBC has corrected the densities and volumes (the geometry's gradients and coefficients,
 * rho, V, m: bounce-back, between this pass and the frozen terms, changes velocities only),
 * so it is summed here, over the shifting's row geometry. A row that reaches one needs the
 * wall images' density gradients and coefficients, which in a rotating frame follow the
 * bounced velocities (step_fields_frozen_terms then sums it). */
void step_fields_shifting_and_correction(const physics_params *pp, particles *p,
                                         const neighbour_list *nl, bool shift, bool correct,
                                         const step_diffusion *diffusion, diffusion_rows rows)
{
    __auto_type sums_of = shift_row_sums_of_form();
    bool mass = diffusion && diffusion->mass;
    TEAM_FOR (i, p->n_fluid) {
        bool diffuse = diffusion && diffusion_rows_include(rows, neighbour_row_has_ghosts(nl, i));
        if (p->lambda[i] < SHIFTING_LAMBDA_MIN) { /* neither moves it */
            if (shift) vec_store(p->shift, i, vec_zero());
            if (correct) vec_store(p->correction, i, vec_zero());
            if (!diffuse) continue; /* no row geometry */
            shift_row_sums s = sums_of(pp, p, nl, i, false, false, true, mass);
            store_diffusion(p, i, &s.diffusion, diffusion->dt);
            continue;
        }
        shift_row_sums s = sums_of(pp, p, nl, i, shift, correct, diffuse, mass);
        if (shift) vec_store(p->shift, i, shifting_velocity(pp, p, i, &s.shift));
        if (correct)
            vec_store(p->correction, i,
                      volume_correction_velocity_from(pp, p, i, s.shift.correction));
        if (diffuse) store_diffusion(p, i, &s.diffusion, diffusion->dt);
    }
}

/* Particle i's diffusion sums over its row, a block of entries at a time (core/pair_block.h). */
PAIR_BLOCK_INLINE diffusion_sums diffusion_sums_of(const physics_params *pp, const particles *p,
                                                   const neighbour_list *nl, size_t i,
                                                   const bool mass)
{
    vec xi = vec_load(p->x, i);
    diffusion_particle di = diffusion_particle_of(p, nl, i);
    PAIR_ROW(&pp->k, p->x, nl, i, xi, row);
    diffusion_block_sums db;
    __builtin_memset(&db, 0, sizeof db);
    pair_block_geometry b;
    FOR_EACH_PAIR_BLOCK_OF_ROW (&row, b)
        diffusion_block_sums_add(&db, pp, p, &b, pair_block_gather(p->vol, b.j), &di, mass);
    return diffusion_sums_total(&db);
}

PAIR_BLOCK_FORMS(diffusion_sums, diffusion_sums_of,
                 (const physics_params *pp, const particles *p, const neighbour_list *nl, size_t i,
                  bool mass),
                 (pp, p, nl, i, mass))

/* D^rho and D^m of Eq. (5), frozen over the step, of the rows `rows` names. */
static void diffuse_rows(const physics_params *pp, particles *p, const neighbour_list *nl,
                         const step_diffusion *diffusion, diffusion_rows rows)
{
    __auto_type sums_of = diffusion_sums_of_form();
    TEAM_FOR (i, p->n_fluid) {
        if (!diffusion_rows_include(rows, neighbour_row_has_ghosts(nl, i))) continue;
        diffusion_sums s = sums_of(pp, p, nl, i, diffusion->mass);
        store_diffusion(p, i, &s, diffusion->dt);
    }
}

void step_fields_frozen_terms(const physics_params *pp, particles *p, const neighbour_list *nl,
                              const tank_frame *frame, const step_diffusion *diffusion,
                              diffusion_rows rows)
{
    tank_mirror_step_fields(p, frame, pp->c0);
    if (diffusion) {
        if (rows != DIFFUSION_ROWS_NONE) diffuse_rows(pp, p, nl, diffusion, rows);
    } else
        for (size_t i = 0; i < p->n_fluid; i++) p->diff_rho[i] = p->diff_m[i] = 0.0;
}
