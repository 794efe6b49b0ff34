/* simulation: a whole run, from the validated case to the output files. Dimension-free
 * declarations of the 2D and 3D builds; main dispatches on case.dim. */
#ifndef VCSPH_SIMULATION_H
#define VCSPH_SIMULATION_H

#include "core/config.h"
#include "diag/packing_figures.h"
#include <stdbool.h>
#include <stddef.h>

typedef struct {
    const char *output_dir; /* created if missing; locked while the run writes there */
    bool quiet;             /* no terminal output (tests) */
    bool overwrite; /* a fresh run removes an earlier run's files there instead of refusing */
    const struct run_team *team; /* the processes of an MPI run (core/run_team.h), NULL: one */
    const char *program;         /* the command as the user started it (argv[0]), for the hints */
} run_options;

/* Exit statuses (docs/architecture.md). RUN_INTERRUPTED: SIGTERM or SIGINT stopped the run after a
 * step, and its state is in OUTDIR/checkpoint.h5 (`vcsph run --restart` continues it). */
enum { RUN_OK = 0, RUN_FAILED = 1, RUN_BAD_INPUT = 2, RUN_BREAKDOWN = 3, RUN_INTERRUPTED = 4 };

int simulation_run_2d(const config *cfg, const run_options *opt);
int simulation_run_3d(const config *cfg, const run_options *opt);

struct checkpoint_data;
/* Continues the run whose checkpoint cd holds (read whole and verified by checkpoint_read),
 * cfg its case (the checkpoint's text, with only case.t_end and [output] changed), in
 * opt->output_dir, the checkpoint's folder. A checkpoint that does not fit the case or the
 * files there is refused with RUN_BAD_INPUT before any file is touched. */
int simulation_resume_2d(const config *cfg, const run_options *opt,
                         const struct checkpoint_data *cd);
int simulation_resume_3d(const config *cfg, const run_options *opt,
                         const struct checkpoint_data *cd);
/* What simulation_resume does with cd before it touches a file: the solver set up for cfg
 * and the checkpoint's state loaded into it and checked (app/restart.c), then everything
 * freed. Returns RUN_OK, RUN_BAD_INPUT with a message in err for a checkpoint that does not
 * fit, or the status of a failed solver_init. For the checkpoint reader's fuzz target. */
int simulation_check_checkpoint_2d(const config *cfg, const struct checkpoint_data *cd, char *err,
                                   size_t err_len);
int simulation_check_checkpoint_3d(const config *cfg, const struct checkpoint_data *cd, char *err,
                                   size_t err_len);

struct snapshot_info;
/* `vcsph volume`: eps_v1, eps_gm, eps_fs and the free surface's packing of one snapshot file
 * whose case is cfg. */
typedef struct {
    double eps_v1, eps_gm, eps_fs;
    surface_packing packing;
} snapshot_figures;
int snapshot_volume_2d(const config *cfg, const char *path, const struct snapshot_info *info,
                       snapshot_figures *out, char *err, size_t err_len);
int snapshot_volume_3d(const config *cfg, const char *path, const struct snapshot_info *info,
                       snapshot_figures *out, char *err, size_t err_len);

static inline int simulation_run(const config *cfg, const run_options *opt)
{
    return cfg->dim == 3 ? simulation_run_3d(cfg, opt) : simulation_run_2d(cfg, opt);
}

static inline int simulation_resume(const config *cfg, const run_options *opt,
                                    const struct checkpoint_data *cd)
{
    return cfg->dim == 3 ? simulation_resume_3d(cfg, opt, cd) : simulation_resume_2d(cfg, opt, cd);
}

static inline int simulation_check_checkpoint(const config *cfg, const struct checkpoint_data *cd,
                                              char *err, size_t err_len)
{
    return cfg->dim == 3 ? simulation_check_checkpoint_3d(cfg, cd, err, err_len)
                         : simulation_check_checkpoint_2d(cfg, cd, err, err_len);
}

#endif
