/* The passes that sum a row in blocks of eight entries (core/pair_block.h: the geometry pass,
 * the density and mass diffusion, the shifting and the correction velocity, scheme/step_fields.c)
 * sum the terms of their pair functions: on a disordered block of liquid in a tank (wall
 * ghosts, random velocities), each particle's kernel sums, diffusion terms, shifting and
 * correction velocities against the same terms summed pair by pair in the row's order with the
 * functions of src/physics. The two orders of summation differ by round-off only: recursive
 * summation of n terms errs by at most (n - 1) u sum |term| to first order, u = eps / 2 the unit
 * round-off (Higham, Accuracy and Stability of Numerical Algorithms, sec. 4.2), so two orders by
 * twice that; the tests allow 2 (n - 1) eps sum |term|, a factor 2 for the terms' own rounding
 * and the higher orders. The forms of the block sums against each other, bit for bit, are
 * test_lanes'. */
#include "core/pair.h"
#include "diag/freesurface.h"
#include "physics/ale.h"
#include "physics/diffusion.h"
#include "physics/shifting.h"
#include "physics/viscosity.h"
#include "physics/volume_correction.h"
#include "scheme/step_fields.h"
#include "scheme/solver.h"
#include "scheme/volume_correction.h"

#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "disordered_block.h"

/* A sum of terms kept with what its round-off may be: the number of terms and sum |term|. */
typedef struct {
    double sum, magnitude;
    int terms;
} checked_sum;

static void checked_add(checked_sum *s, double term)
{
    s->sum += term;
    s->magnitude += fabs(term);
    s->terms++;
}

/* Two orders of the same terms, scaled alike by `scale`, may differ by this much. */
static double reorder_bound(const checked_sum *s, double scale)
{
    return 2.0 * (s->terms > 0 ? s->terms - 1 : 0) * DBL_EPSILON * s->magnitude * fabs(scale);
}

static void assert_close(double got, double want, double bound, const char *what, size_t i)
{
    if (!(fabs(got - want) <= bound))
        fail_msg("%s of particle %zu: %.17g, pair by pair %.17g (round-off bound %.3g)", what, i,
                 got, want, bound);
}

/* The shifting velocity (Eq. 7) and the correction velocity from sums of shifting_pair and
 * volume_correction_pair, pair by pair; what follows the sums (the compression gradient's
 * floor, the limits, the surface's tangent) moves a difference of the sums by at most twice
 * its size, times h U_max. */
static void shifting_and_correction_follow_their_pair_functions(solver *s)
{
    const physics_params *pp = &s->pp;
    particles *p = &s->p;
    neighbour_list rows = neighbours_near(&s->nl);
    step_fields_shifting_and_correction(pp, p, &rows, true, true, NULL, DIFFUSION_ROWS_NONE);
    for (size_t i = 0; i < p->n_fluid; i++) {
        if (p->lambda[i] < SHIFTING_LAMBDA_MIN) continue;
        vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
        checked_sum shifting[DIM] = {{0}}, correction[DIM] = {{0}};
        double max_relative2 = 0.0;
        pair pr;
        FOR_EACH_PAIR (&pp->k, p->x, &rows, i, xi, pr) {
            vec sh = shifting_pair(pr.w, pp->w_dr, pr.r_ji, pr.f, p->vol[pr.j]);
            vec co = volume_correction_pair(p->volume_mismatch[i], p->volume_mismatch[pr.j],
                                            pr.r_ji, pr.f, p->vol[pr.j]);
            for (int d = 0; d < DIM; d++) {
                checked_add(&shifting[d], sh.c[d]);
                checked_add(&correction[d], co.c[d]);
            }
            double rel2 = vec_norm2(vec_sub(vec_load(p->u, pr.j), ui));
            if (rel2 > max_relative2) max_relative2 = rel2;
        }
        vec shifting_sum, correction_sum;
        double shifting_bound = 0.0, correction_bound = 0.0, scale = pp->k.h * pp->shift_u_max;
        for (int d = 0; d < DIM; d++) {
            shifting_sum.c[d] = shifting[d].sum;
            correction_sum.c[d] = correction[d].sum;
            shifting_bound += 2.0 * reorder_bound(&shifting[d], scale);
            correction_bound += 2.0 * reorder_bound(&correction[d], scale);
        }
        vec du = gradient_beyond_floor(shifting_sum,
                                       compression_gradient(vec_load(p->grad_rho, i), p->rho[i]));
        du = shifting_limit(vec_scale(du, -scale), sqrt(max_relative2), pp->shift_u_max);
        if (p->surface[i] != SURFACE_INTERIOR) du = shifting_tangential(du, vec_load(p->normal, i));
        if (p->surface[i] == SURFACE_FREE && pp->unpack_speed > 0.0)
            du = vec_add(du, surface_unpacking_shift(p->kernel_sum[i] * pp->surface_sum_scale,
                                                     pp->unpack_speed, vec_load(p->normal, i),
                                                     sqrt(max_relative2), pp->shift_u_max));
        vec dv = volume_correction_velocity_from(pp, p, i, correction_sum);
        for (int d = 0; d < DIM; d++) {
            /* the shifting is held in single precision (frozen_real): rounded once more */
            assert_close(p->shift[d][i], du.c[d],
                         shifting_bound + 0.5 * FLT_EPSILON * fabs(du.c[d]), "shifting", i);
            assert_close(p->correction[d][i], dv.c[d], correction_bound, "correction", i);
        }
    }
}

/* The step's preparation sums the diffusion of the rows beside the shifting, over the same row
 * geometry: every row in a frame that does not rotate (this block's), the walls' images taking
 * their diffusion fields first, and in a rotating one the rows away from the walls, the frozen
 * terms the others after bounce-back (scheme/passes.c). Either way the same operations as the
 * diffusion pass over every row, so the same bits. */
static void diffusion_beside_the_shifting_is_the_diffusion_pass(solver *s, bool mass)
{
    particles *p = &s->p;
    size_t n = p->n_fluid, walls = 0;
    neighbour_list rows = neighbours_near(&s->nl);
    for (size_t i = 0; i < n; i++) walls += neighbour_row_has_ghosts(&rows, i);
    assert_true(walls > 0 && walls < n); /* both kinds of row */
    double *rho = malloc(n * sizeof *rho), *m = malloc(n * sizeof *m);
    memcpy(rho, p->diff_rho, n * sizeof *rho);
    memcpy(m, p->diff_m, n * sizeof *m);
    step_diffusion diffusion = {.mass = mass, .dt = s->dt};
    tank_frame frame = solver_frame(s, s->t);
    assert_false(frame.rotating);
    step_fields_frozen_terms(&s->pp, p, &rows, &frame, &diffusion, DIFFUSION_ROWS_ALL);
    assert_memory_equal(p->diff_rho, rho, n * sizeof *rho);
    assert_memory_equal(p->diff_m, m, n * sizeof *m);
    /* the rotating frame's split, from zero */
    memset(p->diff_rho, 0, n * sizeof *rho);
    memset(p->diff_m, 0, n * sizeof *m);
    step_fields_shifting_and_correction(&s->pp, p, &rows, false, false, &diffusion,
                                        DIFFUSION_ROWS_OFF_WALLS);
    step_fields_frozen_terms(&s->pp, p, &rows, &frame, &diffusion, DIFFUSION_ROWS_AT_WALLS);
    assert_memory_equal(p->diff_rho, rho, n * sizeof *rho);
    assert_memory_equal(p->diff_m, m, n * sizeof *m);
    free(rho);
    free(m);
}

/* ALE_BLOCK_CASE (delta-plus-ALE: eta = 0 at the start, constant masses) with its scheme
 * replaced by `scheme` */
static void block_with_scheme(const char *scheme, config *cfg, solver *s)
{
    static const char plus_ale[] = "scheme = delta-plus-ale\n";
    const char *at = strstr(ALE_BLOCK_CASE, plus_ale);
    assert_non_null(at);
    char text[sizeof ALE_BLOCK_CASE + 64];
    snprintf(text, sizeof text, "%.*sscheme = %s\n%s", (int)(at - ALE_BLOCK_CASE), ALE_BLOCK_CASE,
             scheme, at + strlen(plus_ale));
    disordered_block(text, 0.2, 7, cfg, s);
}

static void block_sums_follow_the_pair_functions(const char *scheme, bool mass)
{
    config cfg;
    solver s;
    block_with_scheme(scheme, &cfg, &s);
    const physics_params *pp = &s.pp;
    const particles *p = &s.p;
    neighbour_list rows = neighbours_near(&s.nl);
    assert_true(pp->c_delta > 0.0);
    assert_int_equal(s.eta_control.eta > 0.0, mass);
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec xi = vec_load(p->x, i), gi = vec_load(p->grad_rho, i);
        double rhoi = p->rho[i], nui = p->nu_delta[i], mi = p->m[i], vi = p->vol[i];
        checked_sum w = {0}, wv = {0}, rho = {0}, m = {0}, rate = {0};
        pair pr;
        FOR_EACH_PAIR (&pp->k, p->x, &rows, i, xi, pr) {
            size_t j = pr.j;
            checked_add(&w, pr.w);
            checked_add(&wv, pr.w * p->vol[j]);
            double delta_ij = harmonic_mean_capped(nui, p->nu_delta[j], pp->delta_cap);
            checked_add(&rho,
                        diffusion_rho_pair(delta_ij, rhoi, p->rho[j], gi, vec_load(p->grad_rho, j),
                                           pr.r_ji, pr.f, p->vol[j]));
            checked_add(&rate, diffusion_rate_pair(delta_ij, pr.f, p->vol[j]));
            if (mass && !particle_is_wall_image(p, j))
                checked_add(&m,
                            mass_diffusion_pair(pp->delta_c0_h, mi, p->m[j], pr.f, vi, p->vol[j]));
        }
        assert_close(p->kernel_sum[i], w.sum + pp->k.norm, reorder_bound(&w, 1.0), "kernel sum", i);
        assert_close(p->gamma[i], wv.sum + pp->k.norm * vi, reorder_bound(&wv, 1.0), "gamma", i);
        /* the stability factor, 1 / (rate dt) or 1, takes the rate's round-off too */
        double factor = diffusion_stability_factor(rate.sum, s.dt);
        double rate_error = factor < 1.0 ? reorder_bound(&rate, 1.0) / rate.sum : 0.0;
        assert_close(p->diff_rho[i], rho.sum * factor,
                     reorder_bound(&rho, factor) + fabs(rho.sum * factor) * 2.0 * rate_error,
                     "D^rho", i);
        assert_close(p->diff_m[i], m.sum, reorder_bound(&m, 1.0), "D^m", i);
    }
    diffusion_beside_the_shifting_is_the_diffusion_pass(&s, mass);
    shifting_and_correction_follow_their_pair_functions(&s);
    solver_free(&s);
}

/* model.surface_unpacking: the free surface's inward shift is bounded by Eq. (7)'s limit, so a
 * liquid at rest (every u_ij = 0, the walls' images included) gets none, also where the
 * surface is packed (S_i > S_flat, which the disordered block's top rows have); with random
 * velocities the shift is the pair functions' with the unpacking added. */
static void test_surface_unpacking(void **state)
{
    (void)state;
    config cfg;
    solver s;
    block_with_scheme("delta-plus-ale\nsurface_unpacking = true", &cfg, &s);
    assert_true(s.pp.unpack_speed > 0.0);
    shifting_and_correction_follow_their_pair_functions(&s);
    particles *p = &s.p;
    for (size_t i = 0; i < p->n_total; i++)
        for (int d = 0; d < DIM; d++) p->u[d][i] = 0.0;
    neighbour_list rows = neighbours_near(&s.nl);
    step_fields_shifting_and_correction(&s.pp, p, &rows, true, false, NULL, DIFFUSION_ROWS_NONE);
    size_t packed = 0;
    for (size_t i = 0; i < p->n_fluid; i++) {
        if (p->surface[i] != SURFACE_FREE || p->lambda[i] < SHIFTING_LAMBDA_MIN) continue;
        packed += p->kernel_sum[i] * s.pp.surface_sum_scale > 1.0;
        for (int d = 0; d < DIM; d++) assert_true(p->shift[d][i] == 0.0);
    }
    assert_true(packed > 0);
    solver_free(&s);
}

/* delta-plus-ALE at the start (eta = 0): the density diffusion */
static void test_delta_plus_ale(void **state)
{
    (void)state;
    block_sums_follow_the_pair_functions("delta-plus-ale", false);
}

/* delta-ALE (eta = 1, variable masses): the mass diffusion too */
static void test_delta_ale(void **state)
{
    (void)state;
    block_sums_follow_the_pair_functions("delta-ale", true);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_delta_plus_ale),
        cmocka_unit_test(test_delta_ale),
        cmocka_unit_test(test_surface_unpacking),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
