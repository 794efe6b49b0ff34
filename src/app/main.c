/* main: the vcsph command; the only place that decides exit statuses (docs/architecture.md). */
#include "app/case_checks.h"
#include "app/cli.h"
#include "app/plot_command.h"
#include "core/run_team.h"
#include "app/simulation.h"
#include "core/config.h"
#include "core/derived.h"
#include "core/version.h"
#include "io/checkpoint.h"
#include "io/hdf5_errors.h"
#include "io/snapshot_read.h"
#include "scheme/estimate.h"

#ifdef VCSPH_MPI
#include "parallel/mpi_team.h"
#endif

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void warn_stderr(const char *msg, void *ctx)
{
    (void)ctx;
    fprintf(stderr, "vcsph: warning: %s\n", msg);
}

/* `vcsph check`: the derived numbers, or with --print the resolved case exactly as a run
 * writes it into case.ini (both config_write), printed only for a case that would run (the
 * load's case_runnable has passed). */
static int check_case(const config *cfg, const case_check_state *state, bool print)
{
    derived_warnings(cfg, &state->dv, warn_stderr, NULL);
    char msg[1024];
    estimate_cost_warning(&state->est, msg, sizeof msg);
    if (msg[0]) warn_stderr(msg, NULL);
    if (print) {
        config_write(cfg, stdout);
        return RUN_OK;
    }
    printf("%s: valid\n", cfg->name);
    derived_print(cfg, &state->dv, stdout);
    char memory[256], wall[256];
    estimate_describe(&state->est, memory, sizeof memory, wall, sizeof wall);
    printf("memory estimate  %s\n", memory);
    printf("wall time est.   %s\n", wall);
    return RUN_OK;
}

/* `vcsph volume`: one CSV row per snapshot, the columns of timeseries.csv. */
static int volume_of_snapshots(char **paths, int n)
{
    for (int k = 0; k < n; k++) {
        char err[2048];
        snapshot_info info;
        if (snapshot_read_info(paths[k], &info, err, sizeof err)) {
            fprintf(stderr, "vcsph: %s\n", err);
            return RUN_BAD_INPUT;
        }
        /* the tank motion does not enter the geometry: drop it, so that a motion table
           need not be found again */
        const char *const no_motion[] = {"motion.type=none", "motion.file="};
        static config cfg;
        int status =
            config_load_string(&cfg, info.case_text, paths[k], no_motion, 2, err, sizeof err);
        snapshot_figures f;
        if (status == 0)
            status = (info.dim == 3 ? snapshot_volume_3d : snapshot_volume_2d)(
                &cfg, paths[k], &info, &f, err, sizeof err);
        double time = info.time;
        snapshot_info_free(&info);
        if (status) {
            fprintf(stderr, "vcsph: %s\n", err);
            return status;
        }
        if (k == 0) /* after the first file reads, so that an error comes alone */
            printf("t,eps_v1,eps_gm,n_free_surface,n_clumped,nearest_free,nearest_band,"
                   "nearest_interior,eps_fs\n");
        const surface_packing *q = &f.packing;
        printf("%.10g,%.10g,%.10g,%ld,%ld,%.4f,%.4f,%.4f,%.10g\n", time, f.eps_v1, f.eps_gm,
               q->n_free, q->n_clumped, q->nearest_free, q->nearest_band, q->nearest_interior,
               f.eps_fs);
        fflush(stdout);
    }
    return RUN_OK;
}

/* `vcsph plot`: one line naming what was written (README.md). */
static int plot_run_dir(const char *dir)
{
    plot_report report;
    char err[2048];
    int status = plot_command_run(dir, &report, err, sizeof err);
    if (report.warning[0]) fprintf(stderr, "%s\n", report.warning);
    if (status) {
        fprintf(stderr, "%s\n", err);
        return status;
    }
    printf("vcsph plot: wrote %s in %s (script plot.gp)\n", report.written, report.images_dir);
    return RUN_OK;
}

/* The checkpoint's folder: a restarted run writes where the checkpoint was. */
static void folder_of(const char *path, char *dir, size_t size)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, size, ".");
    else if (slash == path)
        snprintf(dir, size, "/");
    else
        snprintf(dir, size, "%.*s", (int)(slash - path), path);
}

/* The case a checkpoint continues, its stored text with the allowed --set applied (cli.c). */
static int checkpoint_case(const checkpoint_data *cd, const cli_args *args, config *cfg)
{
    char err[2048];
    char *text = checkpoint_text(cd, "case", err, sizeof err);
    if (!text) {
        fprintf(stderr, "vcsph: %s: %s\n", args->restart_path, err);
        return RUN_BAD_INPUT;
    }
    int status = config_load_string(cfg, text, args->restart_path, args->overrides,
                                    args->n_overrides, err, sizeof err);
    free(text);
    if (status) {
        fprintf(stderr, "vcsph: %s\n", err);
        return RUN_BAD_INPUT;
    }
    /* the run's own c0: `sound_speed = auto` takes the largest |g - a_tank| up to t_end for a
       motion table, and a later t_end must not change the equation of state of a run under way
       (a checkpoint without it is older, and its case computes c0 as before) */
    const checkpoint_array *c0 =
        checkpoint_find(cd, "sound_speed", CHECKPOINT_F64, 1, NULL, err, sizeof err);
    if (c0) cfg->sound_speed = ((const double *)c0->data)[0];
    return RUN_OK;
}

/* `vcsph run --restart`: the whole checkpoint is read and verified before anything else
 * (by every process of a team). */
static int restart_run(const cli_args *args, const run_team *team, const char *program)
{
    checkpoint_data cd;
    char err[2048];
    if (checkpoint_read(args->restart_path, &cd, err, sizeof err)) {
        fprintf(stderr, "vcsph: cannot restart: %s\n", err);
        return RUN_BAD_INPUT;
    }
    static config cfg;
    int status = checkpoint_case(&cd, args, &cfg);
    if (status == RUN_OK) {
        char dir[CONFIG_PATH_MAX];
        folder_of(args->restart_path, dir, sizeof dir);
        run_options opt = {dir, args->quiet, false, team, program};
        status = simulation_resume(&cfg, &opt, &cd);
    }
    checkpoint_data_free(&cd);
    return status;
}

/* The number of processes an MPI launcher started this one among (Open MPI's mpirun sets
 * OMPI_COMM_WORLD_SIZE, MPICH's and Slurm's PMI launchers PMI_SIZE), 1 when none did. */
static long mpi_launch_size(void)
{
    const char *names[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        const char *v = getenv(names[k]);
        long n = v ? strtol(v, NULL, 10) : 0;
        if (n > 1) return n;
    }
    return 1;
}

/* `vcsph run` under `mpirun -np P`, P > 1, would be P whole runs into one folder: refused
 * before anything is written (the split run is vcsph-mpi's, docs/mpi.md). */
static int refuse_mpi_launch(void)
{
    long n = mpi_launch_size();
    if (n == 1) return 0;
    fprintf(stderr,
            "vcsph: started as one of %ld MPI processes: this vcsph does not split a run among "
            "processes, and each would run the whole case into the same folder; start it as "
            "one process, whose OpenMP threads use the cores (OMP_NUM_THREADS), or split the "
            "run with vcsph-mpi, the MPI build's command (docs/mpi.md)\n",
            n);
    return -1;
}

/* The vcsph command; team: the processes of `mpirun -n P vcsph-mpi` (NULL: vcsph, one
 * process). */
static int vcsph_main(int argc, char **argv, const run_team *team)
{
    hdf5_errors_quiet_exit();
    cli_args args;
    char err[2048];
    if (cli_parse(argc, argv, &args, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return RUN_BAD_INPUT;
    }
    /* the other commands are one process's work: rank 0 does them alone (`plot` would
       otherwise write its files once per process) */
    if (team && team->rank > 0 && args.command != CLI_RUN) return RUN_OK;
    if (args.command == CLI_HELP) {
        cli_usage(stdout);
        return RUN_OK;
    }
    if (args.command == CLI_VERSION) {
        printf("vcsph %s\n", vcsph_version());
        return RUN_OK;
    }
    if (args.command == CLI_VOLUME) return volume_of_snapshots(args.snapshots, args.n_snapshots);
    if (args.command == CLI_PLOT) return plot_run_dir(args.plot_dir);
    if (args.command == CLI_KEYS) {
        config_write_keys(stdout);
        return RUN_OK;
    }
    if (args.command == CLI_RUN && !team && refuse_mpi_launch()) return RUN_BAD_INPUT;
    if (args.restart_path) return restart_run(&args, team, argv[0]);
    static config cfg;
    static case_check_state state;
    state.insist = args.insist;
    if (config_load_checked(&cfg, args.case_path, args.overrides, args.n_overrides, case_runnable,
                            &state, err, sizeof err)) {
        fprintf(stderr, "vcsph: %s\n", err);
        return RUN_BAD_INPUT;
    }
    /* before check, so that check --print shows the case.ini that run -o DIR writes */
    if (args.output_dir) snprintf(cfg.output_dir, sizeof cfg.output_dir, "%s", args.output_dir);
    if (args.command == CLI_CHECK) return check_case(&cfg, &state, args.print);
    run_options opt = {cfg.output_dir, args.quiet, args.overwrite, team, argv[0]};
    return simulation_run(&cfg, &opt);
}

#ifdef VCSPH_MPI
/* vcsph-mpi: every process runs the command; rank 0 speaks for all (the others' terminal
 * output goes nowhere: they compute the same figures, and their statuses are agreed). Each
 * process may run OpenMP threads, which only the main one calls MPI from. */
int main(int argc, char **argv)
{
    int provided;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm comm = MPI_COMM_WORLD;
    run_team team;
    mpi_team_init(&team, &comm);
    if (team.rank > 0 && (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)))
        MPI_Abort(comm, RUN_FAILED);
    int status = vcsph_main(argc, argv, &team);
    MPI_Finalize();
    return status;
}
#else
int main(int argc, char **argv) { return vcsph_main(argc, argv, NULL); }
#endif
