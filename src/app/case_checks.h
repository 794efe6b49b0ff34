/* case_checks: what `vcsph run` and `vcsph check` ask of a case beyond its keys, inside the
 * case file's load so that every refusal names the file, line and key: the motion table reads,
 * the derived numbers make a runnable case (derived_problem), and the case is not absurd: a
 * periodic motion of fewer than CASE_STEPS_PER_PERIOD_MIN time steps a period, or a run
 * estimated at more than a day (ESTIMATE_DAY_S) whose tank acceleration exceeds CASE_G_MAX_ABSURD g
 * or whose sound speed exceeds CASE_C0_ABSURD times Eq. (6)'s (a unit error, a typo). --insist runs
 * those all the same. */
#ifndef VCSPH_CASE_CHECKS_H
#define VCSPH_CASE_CHECKS_H

#include "core/config.h"
#include "core/derived.h"
#include "scheme/estimate.h"

#include <stdbool.h>

#define CASE_STEPS_PER_PERIOD_MIN 20.0
#define CASE_G_MAX_ABSURD         100.0 /* in units of fluid.gravity */
#define CASE_C0_ABSURD            100.0 /* times Eq. (6)'s c0 */

typedef struct {
    bool insist;      /* --insist: no refusal of an absurd case */
    derived dv;       /* the derived numbers, once the check has passed */
    run_estimate est; /* the run's memory and wall time */
} case_check_state;

/* The config_case_check of a run or a check; user is a case_check_state. */
int case_runnable(const config *cfg, void *user, const char **key, char *why, size_t why_len);

#endif
