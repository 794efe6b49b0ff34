/* volume_command: `vcsph volume SNAPSHOT...`: the volume errors of saved snapshots, with the
 * same definitions as the time-series columns (eps_v1 of Eq. 12, eps_gm of Eq. 15), and how
 * closely the free surface's particles sit (diag/packing.h). */
#include "app/simulation.h"
#include "diag/packing.h"
#include "diag/volume.h"
#include "io/snapshot_read.h"
#include "scheme/solver.h"

#include <stdio.h>
#include <string.h>

#define snapshot_volume_dim DIM_NAME(snapshot_volume)

/* The case of the snapshot rebuilds the tank and its lattice (for the particle count and the
 * kernel); the snapshot's positions, velocities, densities and masses replace the lattice's;
 * solver_prepare then computes the geometry of that state as a run does. */
int snapshot_volume_dim(const config *cfg, const char *path, const snapshot_info *info,
                        snapshot_figures *out, char *err, size_t err_len)
{
    solver s;
    if (solver_init(&s, cfg, err, err_len)) return RUN_BAD_INPUT;
    particles *p = &s.p;
    int status = RUN_OK;
    double initial_volume, volume; /* eps_gm against the initial lattice's count, as a run */
    if (volume_graphical(p, s.tank.size, &s.dv, &initial_volume, err, err_len)) {
        status = RUN_FAILED;
    } else if (info->n != p->n_fluid) {
        snprintf(err, err_len, "%s: %zu particles, its case makes %zu", path, info->n, p->n_fluid);
        status = RUN_BAD_INPUT;
    } else if (snapshot_read_doubles(path, "position", DIM, p->x, info->n, err, err_len) ||
               snapshot_read_doubles(path, "velocity", DIM, p->u, info->n, err, err_len) ||
               snapshot_read_doubles(path, "density", 1, &p->rho, info->n, err, err_len) ||
               snapshot_read_doubles(path, "mass", 1, &p->m, info->n, err, err_len)) {
        status = RUN_BAD_INPUT;
    } else {
        s.t = info->time;
        s.step = info->step;
        if (solver_prepare(&s, info->time)) {
            snprintf(err, err_len, "out of memory");
            status = RUN_FAILED;
        } else {
            volume_errors ve;
            volume_compute(p, s.dv.cell_volume, s.scratch, NULL, &ve);
            out->eps_v1 = ve.eps_v1;
            out->eps_fs = volume_free_surface_packing(p, s.dv.cell_volume, s.pp.surface_kernel_sum,
                                                      s.scratch, NULL);
            surface_packing_compute(&s.pp.k, p, &s.nl, s.dv.dr, s.scratch, &out->packing);
            if (volume_graphical(p, s.tank.size, &s.dv, &volume, err, err_len))
                status = RUN_FAILED;
            else
                out->eps_gm = graphical_error(volume, initial_volume);
        }
    }
    solver_free(&s);
    return status;
}
