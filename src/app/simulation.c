/* simulation: the time loop (README.md, docs/architecture.md): what is due when, breakdowns,
 * checkpoints, start and restart; the files themselves are run_outputs.c's. */
#include "app/simulation.h"
#include "app/interrupt.h"
#include "app/motion_table.h"
#include "app/output_folder.h"
#include "app/run_summary.h"
#include "app/threads.h"
#include "app/progress.h"
#include "app/run_state.h"
#include "scheme/estimate.h"
#include "core/log.h"
#include "core/version.h"
#include "diag/energy.h"
#include "io/csv.h"
#include "io/text_file.h"
#include "scheme/solver.h"

#include <errno.h>
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdint.h>
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

static void close_run(run *r)
{
    csv_close(&r->timeseries);
    csv_close(&r->events);
    csv_close(&r->probes_csv);
    csv_close(&r->dissipation);
    csv_close(&r->loads);
    for (int k = 0; k < r->n_snapshots; k++) free(r->snapshot_files[k]);
    free(r->snapshot_files);
    free(r->snapshot_times);
    free(r->snapshot_counts);
    free(r->case_text);
    if (r->split) r->team->unsplit(DIM, r->split);
    solver_free(&r->s);
    log_close();
    output_folder_release(r->lock_fd);
}

/* The first multiple of `every` after t. A time that landed on k every (a period end, the
 * end of the run) holds it exactly; the 1e-9 keeps t / every's rounding from taking k again. */
static double next_multiple(double t, double every)
{
    return (floor(t / every + 1e-9) + 1.0) * every;
}

/* Whether an output with interval `every` (0: every step) is due at t; moves *next on. The
 * step lands on the multiples of every (step_stop), but a multiple reached as that of another
 * interval (0.3 as 30 x 0.01, against 3 x 0.1 = 0.30000000000000004) may differ in the last
 * bit: the same tolerance as next_multiple's counts it as reached. */
static int output_due(double t, double every, double *next, int last)
{
    if (every <= 0.0) return 1;
    if (t < *next - 1e-9 * every && !last) return 0;
    *next = next_multiple(t, every);
    return 1;
}

/* The time the next step may not pass, on which it lands when it would pass it: t_end; the
 * first period end after t, so that each period's dissipation is measured at its exact ends;
 * the next row of timeseries.csv and of probes.csv and the next snapshot, so that signals are
 * sampled at exact multiples of their interval (an FFT needs them evenly spaced). Every time
 * here is a multiple of a case's interval, the same whether the run started at 0 or at a
 * checkpoint, and a run extended past t_end lands on t_end as one that ran longer from the
 * start does when t_end is a multiple of output.timeseries_every. */
static double step_stop(const run *r)
{
    const config *cfg = r->cfg;
    double t = r->s.t, stop = cfg->t_end, every[CONFIG_LANDINGS];
    config_landing_intervals(cfg, r->s.dv.omega, every);
    for (int k = 0; k < CONFIG_LANDINGS; k++)
        if (every[k] > 0.0) stop = fmin(stop, next_multiple(t, every[k]));
    return stop;
}

/* Writes the rows and snapshots that are due at the current time. */
static int outputs_due(run *r, int last)
{
    const config *cfg = r->cfg;
    double t = r->s.t;
    if (output_due(t, cfg->timeseries_every, &r->next_series, last)) {
        run_write_series_row(r, 1);
        run_write_loads_row(r);
    }
    if (config_has_probes(cfg) && output_due(t, cfg->probes_every, &r->next_probes, last))
        run_write_probes_row(r);
    if (run_has_periods(r) && t >= run_period_end(r) * (1.0 - 1e-12)) run_write_dissipation_row(r);
    if (cfg->image_every > 0 && output_due(t, cfg->image_every, &r->next_image, last) &&
        run_write_image(r))
        return -1;
    if (cfg->snapshot_every > 0 && output_due(t, cfg->snapshot_every, &r->next_snapshot, last))
        return run_write_snapshot(r);
    return 0;
}

/* Stops the run on a breakdown (docs/architecture.md): message, event, a last row and snapshot. */
static int breakdown(run *r)
{
    char msg[512] = "";
    int bad = solver_health(&r->s, msg, sizeof msg);
    /* with a team: the diagnosis of the lowest rank, whose first bad particle comes first in
       the global order */
    if (!team_first_message(r->team, bad, msg, sizeof msg)) return 0;
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
    if (!team_agree(r->team, solver_prepare(&r->s, r->t_stop) != 0)) return 0;
    progress_clear(&r->pr);
    if (r->team)
        log_error("vcsph: out of memory at step %ld, or the liquid cannot be split among %d "
                  "processes: each takes whole strips of cells along x, and there are fewer "
                  "strips (docs/mpi.md); run on fewer processes",
                  r->s.step, r->team->size);
    else
        log_error("vcsph: out of memory at step %ld (or more than 2^31 - 1 particles with the "
                  "ghosts)",
                  r->s.step);
    return -1;
}

/* A CSV row that did not reach its file (a full disk) stops the run with the system's reason:
 * going on would leave a record with a hole in it. Only the process that writes knows. */
static int rows_lost(run *r)
{
    for (int k = 0; k < RUN_N_CSV; k++) {
        int e = csv_error(run_csv(r, k));
        if (!e) continue;
        progress_clear(&r->pr);
        log_error("vcsph: cannot write %s/%s: %s", r->opt->output_dir, run_csv_name(k),
                  strerror(e));
        return 1;
    }
    return 0;
}

/* The outputs due now, and whether every process can go on: none failed to write. */
static int outputs_failed(run *r, int last)
{
    int failed = outputs_due(r, last) != 0;
    return team_agree(r->team, rows_lost(r) || failed);
}

/* The rest of a step once its RK4 stages are done: the next step's neighbours and geometry
 * (also this state's diagnostics), the control events and the outputs due. A restarted run
 * begins here, with the state of the checkpoint. */
static int finish_step(run *r)
{
    double wall = progress_wall_time();
    if (thread_tuner_due(&r->threads, wall) &&
        thread_tuner_step(&r->threads, wall, threads_run_delay(), r->s.step))
        log_info("vcsph: at t = %.4g s one thread ran faster than %d (another process shares "
                 "the cores?): the run measures again every %g s and takes the faster",
                 r->s.t, r->threads.max, THREADS_WINDOW_S * (THREADS_KEEP_WINDOWS + 2));
    if (prepare(r)) return RUN_FAILED;
    control_step(r);
    int last = r->s.t >= r->cfg->t_end;
    if (outputs_failed(r, last)) return RUN_FAILED;
    progress_update(&r->pr, r->s.t, r->s.step, last);
    return RUN_OK;
}

/* The command that continues this run, as the user started it (argv[0]) so that it pastes:
 * the same processes' (any number of them would do). */
static void run_command(const run *r, char *buf, size_t len)
{
    if (r->team)
        snprintf(buf, len, "mpirun -n %d %s run", r->team->size, r->opt->program);
    else
        snprintf(buf, len, "%s run", r->opt->program);
}

static const char *signal_name(int sig)
{
    return sig == SIGTERM ? "SIGTERM" : sig == SIGINT ? "SIGINT" : "a signal";
}

/* Writes checkpoint.h5 when output.checkpoint_every wall-clock seconds have passed, a signal
 * asked the run to stop, or the run reached t_end (so that a finished run can be extended
 * with a later t_end), with the state between two steps that a restart starts from
 * (restart.c). Returns RUN_OK to go on, RUN_INTERRUPTED after a signal. A checkpoint that
 * cannot be written is reported and the run goes on (the last one stays whole). */
static int checkpoint_due(run *r)
{
    const config *cfg = r->cfg;
    /* with a team: a signal to any process (mpirun forwards it to all) and the clock of the
       process that writes */
    int sig = team_agree(r->team, interrupt_signal());
    bool at_end = r->s.t >= cfg->t_end;
    if (!sig && !at_end &&
        !team_agree(r->team, team_writes(r->team) && cfg->checkpoint_every > 0.0 &&
                                 progress_wall_time() >= r->next_checkpoint))
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
    char command[CONFIG_PATH_MAX + 64];
    run_command(r, command, sizeof command);
    log_info("vcsph: stopped by %s at t = %.9g s, step %ld; state saved in %s; continue with: "
             "%s --restart %s",
             signal_name(sig), r->s.t, r->s.step, path, command, path);
    return RUN_INTERRUPTED;
}

static int time_loop(run *r)
{
    solver *s = &r->s;
    const config *cfg = r->cfg;
    char msg[512];
    int status;
    progress_start(&r->pr, s->t, cfg->t_end, s->dv.n_fluid, s->step,
                   r->opt->quiet || !team_writes(r->team));
    r->next_checkpoint = progress_wall_time() + cfg->checkpoint_every;
    thread_tuner_start(&r->threads, progress_wall_time(), threads_run_delay(), s->step);
    if (r->resumed) {
        if ((status = finish_step(r))) return status;
    } else {
        /* the initial state too: a sound speed too low for the hydrostatic column fails here */
        if (breakdown(r)) return RUN_BREAKDOWN;
        if (prepare(r)) return RUN_FAILED;
        control_step(r);
        if (outputs_failed(r, 0)) return RUN_FAILED;
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
    solver_diagnostics(&r->s, &dg);
    r->mass0 = dg.mass;
    r->period = 1;
}

static void log_warning(const char *msg, void *ctx)
{
    (void)ctx;
    log_error("vcsph: warning: %s", msg);
}

static void log_start(const run *r)
{
    const config *cfg = r->cfg;
    const derived *dv = &r->s.dv;
    log_info("vcsph %s: %s, %dD, %s, %ld particles, dr = %.4g m, c0 = %.4g m/s, t_end = %g s, "
             "%d thread%s",
             vcsph_version(), cfg->name, DIM, config_scheme_name(cfg->scheme), dv->n_fluid, dv->dr,
             dv->c0, cfg->t_end, omp_get_max_threads(), omp_get_max_threads() == 1 ? "" : "s");
    /* the warnings and estimates of `vcsph check` (core/derived.c, scheme/estimate.c) */
    derived_warnings(cfg, dv, log_warning, NULL);
    run_estimate est;
    char memory[256], wall[256];
    estimate_run(cfg, dv, omp_get_max_threads(), &est);
    if (r->resumed && cfg->t_end > 0.0) { /* the steps left from the checkpoint's time */
        double left = fmax(0.0, 1.0 - r->s.t / cfg->t_end);
        est.steps *= left;
        est.seconds *= left;
        est.output_seconds *= left;
    }
    estimate_describe(&est, memory, sizeof memory, wall, sizeof wall);
    log_info("vcsph: memory estimate %s; wall time estimate %s", memory, wall);
    estimate_cost_warning(&est, wall, sizeof wall);
    if (wall[0]) log_warning(wall, NULL);
    if (r->s.mo.kind == MOTION_TABLE) { /* theory §6: say once how the table was read */
        char columns[64];
        motion_table_columns(&r->s.mo, columns, sizeof columns);
        log_info("vcsph: motion table %s: columns %s (%s), %zu rows, t in [%g, %g] s, "
                 "accelerations from a natural cubic spline (zero outside the table), largest "
                 "|g - a_tank| = %.4g m/s^2",
                 cfg->motion_file, columns,
                 r->s.mo.table_by_position ? "no header: by position" : "named by its header",
                 r->s.mo.n_knots, r->s.mo.t[0], r->s.mo.t[r->s.mo.n_knots - 1], dv->g_max);
    }
    if (r->resumed)
        log_info("vcsph: restarted from the checkpoint at t = %.9g s, step %ld", r->s.t, r->s.step);
    log_info("vcsph: output in %s", r->opt->output_dir);
}

/* Each process of a team takes whole strips of cells along x (docs/mpi.md): more processes
 * than strips are refused before anything is written. */
static int check_strips(const run *r, char *err, size_t err_len)
{
    size_t strips = solver_strips_at_most(&r->s);
    if ((size_t)r->team->size <= strips) return RUN_OK;
    snprintf(err, err_len,
             "%d processes, but the tank has at most %zu strips of cells along x at this "
             "resolution, and each process takes whole strips (docs/mpi.md): run on at most %zu "
             "processes",
             r->team->size, strips, strips);
    return RUN_BAD_INPUT;
}

/* The solver split among the run's team, each process keeping its share (docs/mpi.md). */
static int split_solver(run *r, char *err, size_t err_len)
{
    if ((r->split = r->team->split(r->team, DIM, &r->s))) return RUN_OK;
    snprintf(err, err_len, "out of memory splitting the liquid among the processes");
    return RUN_FAILED;
}

/* The solver of cfg, and the state of checkpoint cd loaded into it unless cd is NULL. Touches
 * no file. With a team, split among its processes, each setting up its share of the lattice
 * alone and loading its share of the checkpoint (which every process reads whole). Returns
 * RUN_OK, solver_init's status, or RUN_BAD_INPUT for a checkpoint that does not fit, with a
 * message in err (the lowest failing rank's), the same on every process; close_run(r) in
 * every case. */
static int set_up_run(run *r, const config *cfg, const run_team *team, const checkpoint_data *cd,
                      char *err, size_t err_len)
{
    memset(r, 0, sizeof *r);
    r->lock_fd = -1;
    r->cfg = cfg;
    r->team = team;
    int status =
        solver_init_part(&r->s, cfg, team ? team->rank : 0, team ? team->size : 1, err, err_len);
    if (status == RUN_OK && team) status = check_strips(r, err, err_len);
    if (status == RUN_OK && team) status = split_solver(r, err, err_len);
    if ((status = team_agree(team, status))) return status;
    /* the initial lattice's raster, before a checkpoint's state replaces it */
    if (run_graphical_reference(r, err, err_len)) status = RUN_FAILED;
    if (status == RUN_OK && cd && restart_load(r, cd, err, err_len)) status = RUN_BAD_INPUT;
    team_first_message(team, status != RUN_OK, err, err_len);
    return team_agree(team, status);
}

int simulation_check_checkpoint_dim(const config *cfg, const checkpoint_data *cd, char *err,
                                    size_t err_len)
{
    run r;
    int status = set_up_run(&r, cfg, NULL, cd, err, err_len);
    close_run(&r);
    return status;
}

/* How a team's processes share the liquid at the end, on the terminal and in log.txt: the
 * balance of the slabs, which follow the liquid (docs/mpi.md). Collective. */
static void log_shares(const run *r)
{
    if (!r->split) return;
    int64_t mine = (int64_t)r->s.p.n_fluid;
    size_t n;
    int64_t *all = r->team->gather(r->team, &mine, 1, sizeof mine, &n);
    if (!all) return;
    char text[1024];
    int len = snprintf(text, sizeof text, "vcsph: particles per process at the end:");
    for (size_t q = 0; q < n && len > 0 && (size_t)len < sizeof text; q++)
        len += snprintf(text + len, sizeof text - (size_t)len, "%s %lld", q ? "," : "",
                        (long long)all[q]);
    log_info("%s", text);
    free(all);
}

/* The whole run's summary, line by line, on the terminal and in log.txt. */
static void log_summary(const char *dir)
{
    char text[2048];
    run_summary(dir, text, sizeof text);
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) log_info("%s", line);
}

/* The output folder for this run alone: locked, and for a fresh run free of another run's
 * files (removed with --overwrite). Returns RUN_OK, or RUN_BAD_INPUT (in use, or holds an
 * earlier run) or RUN_FAILED (cannot be made or cleared) with a message in err. */
static int claim_output_folder(run *r, bool fresh, char *err, size_t err_len)
{
    const run_options *opt = r->opt;
    bool busy;
    r->lock_fd = output_folder_lock(opt->output_dir, &busy, err, err_len);
    if (r->lock_fd < 0) return busy ? RUN_BAD_INPUT : RUN_FAILED;
    char found[CONFIG_PATH_MAX + 300];
    if (!fresh || !output_folder_holds_run(opt->output_dir, found, sizeof found)) return RUN_OK;
    if (opt->overwrite)
        return output_folder_clear(opt->output_dir, err, err_len) ? RUN_FAILED : RUN_OK;
    snprintf(err, err_len,
             "%s holds another run's outputs (%.100s); give --overwrite to replace them, -o "
             "for another folder, or --restart with its checkpoint.h5 to continue that run",
             opt->output_dir, found + strlen(opt->output_dir) + 1);
    return RUN_BAD_INPUT;
}

/* The text of the case's motion table, read once: from the file at the start, from the
 * checkpoint on a restart (motion_table.h). NULL with err[0] = 0 for a case without one. */
static char *motion_table_text(const config *cfg, const checkpoint_data *cd, char *err,
                               size_t err_len)
{
    err[0] = '\0';
    if (cfg->motion != MOTION_TABLE) return NULL;
    if (!cd) return text_file_read(cfg->motion_file, "motion table", err, err_len);
    char *text = checkpoint_text(cd, "motion_table", err, err_len);
    if (!text)
        snprintf(err, err_len,
                 "the checkpoint holds no motion table (written by a vcsph that did not store "
                 "it): the table it ran with cannot be known");
    return text;
}

/* The output folder for this run, checked against a checkpoint cd, with the motion table's
 * copy; on the process that writes. Returns RUN_OK or the status, with a message in err. */
static int claim_files(run *r, config *cfg, const checkpoint_data *cd, char *err, size_t err_len)
{
    const char *table = cfg->motion_table;
    int status = claim_output_folder(r, cd == NULL, err, err_len);
    /* a checkpoint that does not fit is refused before any file is touched (docs/architecture.md)
     */
    if (status == RUN_OK && cd && restart_check_outputs(r, err, err_len)) status = RUN_BAD_INPUT;
    if (status == RUN_OK && table &&
        motion_table_store(r->opt->output_dir, table, cfg->motion_file, sizeof cfg->motion_file,
                           err, err_len))
        status = RUN_FAILED;
    return status;
}

/* Whether OUTDIR/case.ini differs from the case the checkpoint holds (edited since the run
 * wrote it): a restart runs the checkpoint's case and rewrites case.ini with it. */
static bool case_edited(const run *r, const checkpoint_data *cd)
{
    char err[CONFIG_PATH_MAX + 256], path[CONFIG_PATH_MAX + 64];
    run_out_path(r, path, sizeof path, "case.ini");
    char *stored = checkpoint_text(cd, "case", err, sizeof err);
    char *on_disk = text_file_read(path, "case", err, sizeof err);
    bool edited = stored && on_disk && strcmp(stored, on_disk) != 0;
    free(stored);
    free(on_disk);
    return edited;
}

static void report_edited_case(const run *r)
{
    char command[CONFIG_PATH_MAX + 64], path[CONFIG_PATH_MAX + 64];
    run_command(r, command, sizeof command);
    run_out_path(r, path, sizeof path, "case.ini");
    log_error("vcsph: warning: %s had been edited since the run wrote it: a restart runs the case "
              "its checkpoint holds, changed only by --set case.t_end=... and --set "
              "output.KEY=..., and has rewritten %s with that case; to run the edit, start a "
              "new run from an edited copy (%s COPY.ini -o NEWDIR)",
              path, path, command);
}

/* A restart of a run that already reached its t_end: nothing to do, and how to extend it. */
static void report_complete(const run *r)
{
    char command[CONFIG_PATH_MAX + 64], checkpoint[CONFIG_PATH_MAX + 64];
    run_command(r, command, sizeof command);
    run_out_path(r, checkpoint, sizeof checkpoint, "checkpoint.h5");
    log_info("vcsph: the run in %s is complete: its checkpoint is at t = %.9g s, step %ld, and "
             "case.t_end = %g s; nothing to run. Extend it with: %s --restart %s --set "
             "case.t_end=LATER",
             r->opt->output_dir, r->s.t, r->s.step, r->cfg->t_end, command, checkpoint);
}

/* A run from t = 0 (cd NULL) or from a checkpoint, of cfg (the run's own copy: it points
 * motion.file at the folder's copy of the table). With a team, every process runs it and the
 * one that writes holds the folder. */
static int run_case_with(config *cfg, const run_options *opt, const checkpoint_data *cd)
{
    const run_team *team = opt->team;
    log_set_quiet(opt->quiet || !team_writes(team));
    run r;
    char err[CONFIG_PATH_MAX + 1024] = "";
    int status = set_up_run(&r, cfg, team, cd, err, sizeof err);
    r.opt = opt;
    if (status == RUN_OK && team_writes(team)) status = claim_files(&r, cfg, cd, err, sizeof err);
    status = team_agree(team, status);
    if (status) {
        if (cd)
            log_error("vcsph: cannot restart from the checkpoint in %s: %s", opt->output_dir, err);
        else
            log_error("vcsph: %s", err);
        close_run(&r);
        return status;
    }
    bool edited = cd && team_writes(team) && case_edited(&r, cd);
    if (cd && r.s.t >= cfg->t_end) { /* nothing left to run: the folder stays as it is */
        report_complete(&r);
        close_run(&r);
        return RUN_OK;
    }
    r.case_text = config_text(cfg);
    if (team_agree(team, !r.case_text || (team_writes(team) && run_open_outputs(&r)))) {
        log_error("vcsph: cannot write the outputs in %s: %s", opt->output_dir, strerror(errno));
        close_run(&r);
        return RUN_FAILED;
    }
    log_start(&r);
    if (edited) report_edited_case(&r);
    if (!cd) start_fresh(&r);
    long step0 = r.s.step;
    double wall0 = progress_wall_time();
    char checkpoint[CONFIG_PATH_MAX + 64];
    run_out_path(&r, checkpoint, sizeof checkpoint, "checkpoint.h5");
    interrupt_install(checkpoint);
    status = time_loop(&r);
    thread_tuner_stop(&r.threads);
    interrupt_restore();
    if (team_writes(team)) log_summary(opt->output_dir);
    log_shares(&r);
    /* the steps of this invocation: a restarted run counts from its checkpoint */
    double wall = progress_wall_time() - wall0;
    long steps = r.s.step - step0;
    char command[CONFIG_PATH_MAX + 64];
    run_command(&r, command, sizeof command);
    if (status == RUN_OK)
        log_info("vcsph: done: %ld steps in %.1f s (%.3g particle-steps/s); output in %s; "
                 "extend with: %s --restart %s --set case.t_end=LATER",
                 steps, wall, wall > 0 ? (double)steps * (double)r.s.dv.n_fluid / wall : 0.0,
                 opt->output_dir, command, checkpoint);
    close_run(&r);
    return status;
}

static int run_case(const config *cfg_given, const run_options *opt, const checkpoint_data *cd)
{
    config *cfg = malloc(sizeof *cfg);
    if (!cfg) return RUN_FAILED;
    *cfg = *cfg_given;
    char err[CONFIG_PATH_MAX + 256];
    char *table = motion_table_text(cfg, cd, err, sizeof err);
    int status = RUN_BAD_INPUT;
    if (table || !err[0]) {
        cfg->motion_table = table;
        status = run_case_with(cfg, opt, cd);
    } else {
        log_set_quiet(opt->quiet);
        log_error("vcsph: %s", err);
    }
    free(table);
    free(cfg);
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
