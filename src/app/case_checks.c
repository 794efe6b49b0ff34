/* case_checks: a case's checks beyond its keys (case_checks.h). */
#include "app/case_checks.h"
#include "boundary/motion.h"
#include "scheme/case_numbers.h"

#include <omp.h>
#include <stdio.h>

/* A periodic motion (dv->omega > 0: not none, not a table) whose period has fewer than the
 * minimum of steps. */
static int unresolved_period(const config *cfg, const derived *dv, const char **key, char *why,
                             size_t why_len)
{
    double steps = cfg->period / dv->dt;
    if (!(dv->omega > 0.0) || steps >= CASE_STEPS_PER_PERIOD_MIN) return 0;
    *key = "motion.period";
    snprintf(why, why_len,
             "a period of %.3g time steps (dt = %.3g s, Eq. 8) is no motion the time integration "
             "resolves; at least %.0f steps a period (a unit error? periods are in s; --insist "
             "runs it all the same)",
             steps, dv->dt, CASE_STEPS_PER_PERIOD_MIN);
    return 2;
}

/* More than a day's run that an absurd tank acceleration or sound speed makes so long. */
static int absurd_cost(const config *cfg, const derived *dv, const run_estimate *est,
                       const char **key, char *why, size_t why_len)
{
    if (!(est->seconds > ESTIMATE_DAY_S)) return 0;
    char wall[32];
    estimate_format_seconds(est->seconds, wall, sizeof wall);
    if (dv->g_max > CASE_G_MAX_ABSURD * cfg->gravity) {
        *key = cfg->motion == MOTION_TABLE ? "motion.file" : "motion.period";
        snprintf(why, why_len,
                 "the tank's largest acceleration makes g_max = %.3g m/s^2 (%.3g g), which sets "
                 "c0 = %.3g m/s and dt = %.3g s: a run estimated at %s for %ld particles. A unit "
                 "error? (periods in s, amplitudes in m); --insist runs it all the same",
                 dv->g_max, dv->g_max / cfg->gravity, dv->c0, dv->dt, wall, dv->n_fluid);
        return 2;
    }
    if (dv->c0 > CASE_C0_ABSURD * dv->c0_eq6) {
        *key = "numerics.sound_speed";
        snprintf(why, why_len,
                 "c0 is %.3g times Eq. (6)'s %.3g m/s, and dt = K_c h / c0 = %.3g s makes a run "
                 "estimated at %s for %ld particles; Eq. (6)'s value or auto keeps the density "
                 "within 1 %% (--insist runs it all the same)",
                 dv->c0 / dv->c0_eq6, dv->c0_eq6, dv->dt, wall, dv->n_fluid);
        return 2;
    }
    return 0;
}

int case_runnable(const config *cfg, void *user, const char **key, char *why, size_t why_len)
{
    case_check_state *state = user;
    motion mo;
    if (motion_init(&mo, cfg, why, why_len)) {
        *key = "motion.file";
        return 2;
    }
    case_numbers(cfg, &mo, &state->dv);
    motion_free(&mo);
    int status = derived_problem(cfg, &state->dv, key, why, why_len);
    if (status) return status;
    estimate_run(cfg, &state->dv, omp_get_max_threads(), &state->est);
    if (state->insist) return 0;
    status = unresolved_period(cfg, &state->dv, key, why, why_len);
    return status ? status : absurd_cost(cfg, &state->dv, &state->est, key, why, why_len);
}
