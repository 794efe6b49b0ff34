/* simulation: the time loop (design §1, §2): what is due when, breakdowns, checkpoints,
 * start and restart; the files themselves are run_outputs.c's. */
#include "app/simulation.h"
#include "app/interrupt.h"
#include "app/progress.h"
#include "app/run_state.h"
#include "core/log.h"
#include "core/version.h"
#include "diag/energy.h"
#include "diag/health.h"
#include "io/csv.h"
#include "scheme/solver.h"

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define simulation_run_dim              DIM_NAME(simulation_run)
#define simulation_resume_dim           DIM_NAME(simulation_resume)
#define simulation_check_checkpoint_dim DIM_NAME(simulation_check_checkpoint)

/* The eta switch (theory §8) acts in solver_prepare; its events are written here. */
static void control_step(run *r)
{
    if (r->s.eta_switched) run_event(r, "eta_switch", r->s.eta_switch_detail);
}

static char *resolved_case_text(const config *cfg)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f) return NULL;
    config_write(cfg, f);
    fclose(f);
    return text;
}

static void close_run(run *r)
{
    csv_close(&r->timeseries);
    csv_close(&r->events);
    csv_close(&r->probes_csv);
    csv_close(&r->dissipation);
    for (int k = 0; k < r->n_snapshots; k++) free(r->snapshot_files[k]);
    free(r->snapshot_files);
    free(r->snapshot_times);
    free(r->snapshot_counts);
    free(r->case_text);
    solver_free(&r->s);
    log_close();
}

/* The first multiple of `every` after t. A time that landed on k every (a period end, the
 * end of the run) holds it exactly; the 1e-9 keeps t / every's rounding from taking k again. */
static double next_multiple(double t, double every)
{
    return (floor(t / every + 1e-9) + 1.0) * every;
}

/* Whether an output with interval `every` (0: every step) is due at t; moves *next on. */
static int output_due(double t, double every, double *next, int last)
{
    if (every <= 0.0) return 1;
    if (t < *next && !last) return 0;
    *next = next_multiple(t, every);
    return 1;
}

/* The time the next step may not pass: t_end, or the first period end after t, on which the
 * step lands so that each period's dissipation is measured at its exact ends. */
static double step_stop(const run *r)
{
    double t_end = r->cfg->t_end;
    if (!run_has_periods(r)) return t_end;
    double next = next_multiple(r->s.t, r->cfg->period);
    return next < t_end ? next : t_end;
}

/* Writes the rows and snapshots that are due at the current time. */
static int outputs_due(run *r, int last)
{
    const config *cfg = r->cfg;
    double t = r->s.t;
    if (output_due(t, cfg->timeseries_every, &r->next_series, last)) {
        run_write_series_row(r, 1);
        if (run_has_probes(cfg)) run_write_probes_row(r);
    }
    if (run_has_periods(r) && t >= run_period_end(r) * (1.0 - 1e-12)) run_write_dissipation_row(r);
    if (cfg->image_every > 0 && output_due(t, cfg->image_every, &r->next_image, last) &&
        run_write_image(r))
        return -1;
    if (cfg->snapshot_every > 0 && output_due(t, cfg->snapshot_every, &r->next_snapshot, last))
        return run_write_snapshot(r);
    return 0;
}

/* Stops the run on a breakdown (design §2): message, event, a last row and snapshot. */
static int breakdown(run *r)
{
    char msg[512];
    if (!health_check(&r->s, msg, sizeof msg)) return 0;
    progress_clear(&r->pr);
    log_error("vcsph: %s", msg);
    run_event(r, "breakdown", msg);
    run_write_series_row(r, 0);
    if (run_write_snapshot(r) == 0)
        log_error("vcsph: last state written to %s/%s", r->opt->output_dir,
                  r->snapshot_files[r->n_snapshots - 1]);
    return 1;
}

static int prepare(run *r)
{
    r->t_stop = step_stop(r);
    if (solver_prepare(&r->s, r->t_stop) == 0) return 0;
    progress_clear(&r->pr);
    log_error("vcsph: out of memory at step %ld (or more than 2^31 - 1 particles with the "
              "ghosts)",
              r->s.step);
    return -1;
}

/* The rest of a step once its RK4 stages are done: the next step's neighbours and geometry
 * (also this state's diagnostics), the control events and the outputs due. A restarted run
 * begins here, with the state of the checkpoint. */
static int finish_step(run *r)
{
    if (prepare(r)) return RUN_FAILED;
    control_step(r);
    int last = r->s.t >= r->cfg->t_end;
    if (outputs_due(r, last)) return RUN_FAILED;
    progress_update(&r->pr, r->s.t, r->s.step, last);
    return RUN_OK;
}

static const char *signal_name(int sig)
{
    return sig == SIGTERM ? "SIGTERM" : sig == SIGINT ? "SIGINT" : "a signal";
}

/* Writes checkpoint.h5 when output.checkpoint_every wall-clock seconds have passed or a
 * signal asked the run to stop, with the state between two steps that a restart starts from
 * (restart.c). Returns RUN_OK to go on, RUN_INTERRUPTED after a signal. A checkpoint that
 * cannot be written is reported and the run goes on (the last one stays whole). */
static int checkpoint_due(run *r)
{
    const config *cfg = r->cfg;
    int sig = interrupt_signal();
    if (!sig && !(cfg->checkpoint_every > 0.0 && progress_wall_time() >= r->next_checkpoint))
        return RUN_OK;
    char path[CONFIG_PATH_MAX + 64], err[1024];
    run_out_path(r, path, sizeof path, "checkpoint.h5");
    int failed = restart_save(r, path, err, sizeof err);
    r->next_checkpoint = progress_wall_time() + cfg->checkpoint_every;
    if (failed) {
        progress_clear(&r->pr);
        log_error("vcsph: %s", err);
        if (sig) return RUN_FAILED;
        run_event(r, "checkpoint_failed", err);
        return RUN_OK;
    }
    if (!sig) return RUN_OK;
    progress_clear(&r->pr);
    log_info("vcsph: stopped by %s at t = %.9g s, step %ld; state saved in %s; continue with: "
             "vcsph run --restart %s",
             signal_name(sig), r->s.t, r->s.step, path, path);
    return RUN_INTERRUPTED;
}

static int time_loop(run *r)
{
    solver *s = &r->s;
    const config *cfg = r->cfg;
    char msg[512];
    int status;
    progress_start(&r->pr, cfg->t_end, s->p.n_fluid, s->step, r->opt->quiet);
    r->next_checkpoint = progress_wall_time() + cfg->checkpoint_every;
    if (r->resumed) {
        if ((status = finish_step(r))) return status;
    } else {
        /* the initial state too: a sound speed too low for the hydrostatic column fails here */
        if (breakdown(r)) return RUN_BREAKDOWN;
        if (prepare(r)) return RUN_FAILED;
        control_step(r);
        if (outputs_due(r, 0)) return RUN_FAILED;
    }
    while (s->t < cfg->t_end) {
        solver_advance(s, r->t_stop);
        if (s->max_displacement > 0.5 * s->skin) {
            snprintf(msg, sizeof msg, "a particle moved %.3g m > skin/2 = %.3g m in one step",
                     s->max_displacement, 0.5 * s->skin);
            run_event(r, "neighbour_skin_exceeded", msg);
        }
        /* a broken state is never checkpointed: the last good checkpoint stays */
        if (breakdown(r)) return RUN_BREAKDOWN;
        if ((status = checkpoint_due(r))) return status;
        if ((status = finish_step(r))) return status;
    }
    progress_clear(&r->pr);
    return RUN_OK;
}

/* The state at t = 0: the lattice of solver_init, its mass and volume the references. */
static void start_fresh(run *r)
{
    r->v0 = r->s.dv.v0;
    solver_update_eos(&r->s);
    diagnostics dg;
    diagnostics_compute(&r->s, &dg);
    r->mass0 = dg.mass;
    r->period = 1;
}

static void log_start(const run *r)
{
    const config *cfg = r->cfg;
    const derived *dv = &r->s.dv;
    log_info("vcsph %s: %s, %dD, %s, %ld particles, dr = %.4g m, c0 = %.4g m/s, t_end = %g s",
             vcsph_version(), cfg->name, DIM, config_scheme_name(cfg->scheme), dv->n_fluid, dv->dr,
             dv->c0, cfg->t_end);
    if (r->s.mo.kind == MOTION_TABLE) /* theory §6: say once how the table was read */
        log_info("vcsph: motion table %s: %zu rows, t in [%g, %g] s, accelerations from a "
                 "natural cubic spline (zero outside the table), largest |g - a_tank| = %.4g m/s^2",
                 cfg->motion_file, r->s.mo.n_knots, r->s.mo.t[0], r->s.mo.t[r->s.mo.n_knots - 1],
                 dv->g_max);
    if (r->resumed)
        log_info("vcsph: restarted from the checkpoint at t = %.9g s, step %ld", r->s.t, r->s.step);
    log_info("vcsph: output in %s", r->opt->output_dir);
}

/* The solver of cfg, and the state of checkpoint cd loaded into it unless cd is NULL. Touches
 * no file. Returns RUN_OK, solver_init's status, or RUN_BAD_INPUT for a checkpoint that does
 * not fit, with a message in err; close_run(r) in every case. */
static int set_up_run(run *r, const config *cfg, const checkpoint_data *cd, char *err,
                      size_t err_len)
{
    memset(r, 0, sizeof *r);
    r->cfg = cfg;
    int status = solver_init(&r->s, cfg, err, err_len);
    if (status) return status;
    if (run_graphical_reference(r, err, err_len)) return RUN_FAILED;
    if (!cd) return RUN_OK;
    return restart_load(r, cd, err, err_len) ? RUN_BAD_INPUT : RUN_OK;
}

int simulation_check_checkpoint_dim(const config *cfg, const checkpoint_data *cd, char *err,
                                    size_t err_len)
{
    run r;
    int status = set_up_run(&r, cfg, cd, err, err_len);
    close_run(&r);
    return status;
}

/* A run from t = 0 (cd NULL) or from a checkpoint. */
static int run_case(const config *cfg, const run_options *opt, const checkpoint_data *cd)
{
    log_set_quiet(opt->quiet);
    run r;
    char err[1024];
    int status = set_up_run(&r, cfg, cd, err, sizeof err);
    r.opt = opt;
    /* a checkpoint that does not fit is refused before any file is touched (design §2) */
    if (status == RUN_OK && cd && restart_check_outputs(&r, err, sizeof err))
        status = RUN_BAD_INPUT;
    if (status) {
        if (cd)
            log_error("vcsph: cannot restart from the checkpoint in %s: %s", opt->output_dir, err);
        else
            log_error("vcsph: %s", err);
        close_run(&r);
        return status;
    }
    r.case_text = resolved_case_text(cfg);
    if (!r.case_text || run_open_outputs(&r)) {
        log_error("vcsph: cannot write the outputs in %s", opt->output_dir);
        close_run(&r);
        return RUN_FAILED;
    }
    log_start(&r);
    if (!cd) start_fresh(&r);
    long step0 = r.s.step;
    double wall0 = progress_wall_time();
    interrupt_install();
    status = time_loop(&r);
    interrupt_restore();
    /* the steps of this invocation: a restarted run counts from its checkpoint */
    double wall = progress_wall_time() - wall0;
    long steps = r.s.step - step0;
    if (status == RUN_OK)
        log_info("vcsph: done: %ld steps in %.1f s (%.3g particle-steps/s); output in %s", steps,
                 wall, wall > 0 ? (double)steps * (double)r.s.p.n_fluid / wall : 0.0,
                 opt->output_dir);
    close_run(&r);
    return status;
}

int simulation_run_dim(const config *cfg, const run_options *opt)
{
    return run_case(cfg, opt, NULL);
}

int simulation_resume_dim(const config *cfg, const run_options *opt, const checkpoint_data *cd)
{
    return run_case(cfg, opt, cd);
}
