/* simulation: a whole run, from the validated case to the output files. Dimension-free
 * declarations of the 2D and 3D builds; main dispatches on case.dim. */
#ifndef VCSPH_SIMULATION_H
#define VCSPH_SIMULATION_H

#include "core/config.h"
#include <stdbool.h>
#include <stddef.h>

typedef struct {
    const char *output_dir; /* created if missing */
    bool quiet;             /* no terminal output (tests) */
} run_options;

/* Exit statuses (design §2) */
enum { RUN_OK = 0, RUN_FAILED = 1, RUN_BAD_INPUT = 2, RUN_BREAKDOWN = 3 };

int simulation_run_2d(const config *cfg, const run_options *opt);
int simulation_run_3d(const config *cfg, const run_options *opt);

struct snapshot_info;
/* `vcsph volume`: eps_v1 and eps_gm of one snapshot file whose case is cfg. */
int snapshot_volume_2d(const config *cfg, const char *path, const struct snapshot_info *info,
                       double *eps_v1, double *eps_gm, char *err, size_t err_len);
int snapshot_volume_3d(const config *cfg, const char *path, const struct snapshot_info *info,
                       double *eps_v1, double *eps_gm, char *err, size_t err_len);

static inline int simulation_run(const config *cfg, const run_options *opt)
{
    return cfg->dim == 3 ? simulation_run_3d(cfg, opt) : simulation_run_2d(cfg, opt);
}

#endif
