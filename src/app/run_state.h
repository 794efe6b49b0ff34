/* run_state: what a run holds besides the solver (its output files and the bookkeeping of
 * what is due next), shared by the time loop (simulation.c) and the checkpoints (restart.c).
 * Particle code: compiled for DIM = 2 and 3. */
#ifndef VCSPH_RUN_STATE_H
#define VCSPH_RUN_STATE_H

#include "app/progress.h"
#include "core/run_team.h"
#include "app/threads.h"
#include "app/simulation.h"
#include "diag/probes.h"
#include "diag/sensor_filter.h"
#include "io/checkpoint.h"
#include "io/csv.h"
#include "scheme/solver.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* The CSV files of a run, in the order of the checkpoint's csv_sizes. */
enum {
    RUN_CSV_TIMESERIES,
    RUN_CSV_EVENTS,
    RUN_CSV_DISSIPATION,
    RUN_CSV_PROBES,
    RUN_CSV_LOADS,
    RUN_N_CSV
};

typedef struct {
    solver s;
    const config *cfg;
    const run_options *opt;
    const run_team *team; /* the processes of an MPI run (run_team.h), NULL: one process */
    void *split;          /* the team's split of s (run_team.h), NULL: none */
    int lock_fd;          /* the output folder's lock (output_folder.h), -1 until taken */
    char *case_text;      /* resolved case.ini, also stored in every snapshot and checkpoint */
    csv_file timeseries, events, probes_csv, dissipation, loads;
    probes probes;
    double energy0; /* ekin + epot + eint at t = 0 */
    /* dissipation per excitation period (theory §10): the period that ends next, and
       ediss and the surface's loss beyond its force's work where it started */
    long period;
    double ediss_period_start, surface_loss_period_start;
    double t_stop; /* the prepared step ends at or before this time */
    double mass0, v0;
    double graphical_volume0; /* the graphical method's volume of the initial lattice */
    double next_series, next_snapshot, next_image;
    double next_probes;                      /* probes.csv's next row (probes.every) */
    sensor_filter sensor_filter;             /* the pressure sensors' bandwidth (probes.filter) */
    sensor_state sensors[CONFIG_PROBES_MAX]; /* each pressure probe's filter */
    int n_images;
    /* snapshot index for the XDMF file */
    int n_snapshots, cap_snapshots;
    char **snapshot_files;
    double *snapshot_times;
    size_t *snapshot_counts;
    int speed_warned; /* U_max > c0/10 reported and not yet back below */
    int speed_told;   /* the first such report was printed (this invocation) */
    progress pr;
    thread_tuner threads;   /* the thread count, measured as the run goes (threads.h) */
    double next_checkpoint; /* wall-clock time (progress_wall_time) of the next checkpoint */
    /* a restarted run: the sizes its CSV files had at the checkpoint (-1: not written) */
    bool resumed;
    long long resume_sizes[RUN_N_CSV];
} run;

/* The file name and the writer of CSV file k (RUN_CSV_...). */
static inline const char *run_csv_name(int k)
{
    static const char *const names[RUN_N_CSV] = {"timeseries.csv", "events.csv", "dissipation.csv",
                                                 "probes.csv", "loads.csv"};
    return names[k];
}

static inline csv_file *run_csv(run *r, int k)
{
    csv_file *files[RUN_N_CSV] = {&r->timeseries, &r->events, &r->dissipation, &r->probes_csv,
                                  &r->loads};
    return files[k];
}

/* The name of snapshot k in the output folder (the XDMF index lists these). */
static inline void snapshot_name(int k, char *name, size_t size)
{
    snprintf(name, size, "snapshots/%06d.h5", k);
}

/* Dissipation per period needs a periodic excitation (sway or heave with a period). */
static inline int run_has_periods(const run *r) { return r->s.dv.omega > 0.0; }

/* The end of the excitation period in progress, kT. */
static inline double run_period_end(const run *r) { return (double)r->period * r->cfg->period; }

#define run_out_path              DIM_NAME(run_out_path)
#define run_event                 DIM_NAME(run_event)
#define run_open_outputs          DIM_NAME(run_open_outputs)
#define run_write_series_row      DIM_NAME(run_write_series_row)
#define run_write_probes_row      DIM_NAME(run_write_probes_row)
#define run_probes_start          DIM_NAME(run_probes_start)
#define run_probes_state          DIM_NAME(run_probes_state)
#define run_probes_resume         DIM_NAME(run_probes_resume)
#define run_write_loads_row       DIM_NAME(run_write_loads_row)
#define run_write_dissipation_row DIM_NAME(run_write_dissipation_row)
#define run_write_snapshot        DIM_NAME(run_write_snapshot)
#define run_write_image           DIM_NAME(run_write_image)
#define run_graphical_reference   DIM_NAME(run_graphical_reference)
#define run_gather                DIM_NAME(run_gather)
#define run_gathered_free         DIM_NAME(run_gathered_free)

/* ---- run_gather.c, run_outputs.c: the fluid on the writing process, the files of a run ---- */

/* What run_gather brings together: the positions; the fields of a snapshot (docs/outputs.md);
 * the state a checkpoint keeps (FIELD_STATE); what the probes and the walls' images they read
 * need (id, position, velocity, pressure, density, mass, volume). */
typedef enum {
    RUN_GATHER_POSITIONS,
    RUN_GATHER_SNAPSHOT,
    RUN_GATHER_STATE,
    RUN_GATHER_PROBES
} run_gather_kind;

/* The fluid's fields of `which`, in the global order, on the process that writes the files
 * (run_team.h): with the solver split among a team, *whole holds copies of them gathered from
 * every process (on the other processes no arrays, the count alone); unsplit, *whole is p
 * itself. Collective. */
void run_gather(const run *r, const particles *p, run_gather_kind which, particles *whole);
void run_gathered_free(const run *r, particles *whole);

/* OUTDIR/name into buf. */
void run_out_path(const run *r, char *buf, size_t len, const char *name);
/* With output.graphical, the graphical method's volume of the particles as solver_init laid
 * them, the reference of every eps_gm (also on a restart, which rebuilds that lattice first;
 * collective on a split solver). Returns 0, or -1 with a message in err. */
int run_graphical_reference(run *r, char *err, size_t err_len);
/* A row of events.csv at the current time. */
void run_event(run *r, const char *what, const char *detail);
/* Creates the output folder and its files, or for a restarted run (r->resumed) reopens them
 * at their sizes at the checkpoint and removes what was written after it. Returns 0 or -1. */
int run_open_outputs(run *r);
/* One row of timeseries.csv (docs/outputs.md); with_geometry 0 (a breakdown row): the volume
 * columns empty. Raises the U_max > c0/10 event once per crossing. */
void run_write_series_row(run *r, int with_geometry);

/* ---- run_probes.c: probes.csv ---- */

/* room for probes.csv's header: t and four columns per probe at most */
#define RUN_PROBES_HEADER_MAX (32 + 24 * 4 * CONFIG_PROBES_MAX)
/* probes.csv's header into `header` (docs/outputs.md: t, gauge_k, pressure_k, level_k, and
 * with probes.filter sensor_k), and the probes and the sensors' filter set up for the run. */
void run_probes_start(run *r, char *header, size_t size);
/* One row of probes.csv at the current state, and each sensor's filter fed with it. */
void run_write_probes_row(run *r);
/* What a checkpoint keeps of probes.csv's writer: the next row's time and each pressure
 * probe's filter state; returns how many numbers it wrote into out. */
#define RUN_PROBES_STATE_MAX (1 + SENSOR_STATE_VALUES * CONFIG_PROBES_MAX)
size_t run_probes_state(const run *r, double out[RUN_PROBES_STATE_MAX]);
/* Takes that state back (in: run_probes_state's numbers), or with in = NULL, for a checkpoint
 * from before it, rows due with timeseries.csv's and the filters unstarted. */
void run_probes_resume(run *r, const double *in);
/* One row of loads.csv at the current state (docs/loads.md); needs this step's neighbours. */
void run_write_loads_row(run *r);
/* One row of dissipation.csv for the period that ends now, which it closes. */
void run_write_dissipation_row(run *r);
/* snapshots/NNNNNN.h5 of the current state and the XDMF index. Returns 0 or -1. */
int run_write_snapshot(run *r);
/* images/particles_NNNNNN.png of the current state. Returns 0 or -1. */
int run_write_image(run *r);

#define run_reserve_snapshots DIM_NAME(run_reserve_snapshots)
#define restart_save          DIM_NAME(restart_save)
#define restart_load          DIM_NAME(restart_load)
#define restart_check_outputs DIM_NAME(restart_check_outputs)

/* Room for n snapshots in the XDMF index. Returns 0 or -1. */
int run_reserve_snapshots(run *r, int n);

/* Writes the state just after a step (before the next solver_prepare) to `path` atomically
 * (checkpoint.h; the layout is in restart.c). The CSV files are synced first, so that the
 * sizes the checkpoint records are on the disk. With a team, the particles are gathered in
 * their global order and the process that writes writes the file (collective). Returns 0, or
 * -1 with a message (on the process that writes). */
int restart_save(run *r, const char *path, char *err, size_t err_len);

/* Takes a run's state from a checkpoint read whole (checkpoint_read) into r, set up by
 * solver_init for the checkpoint's case; with the solver split among a team (solver_init_part
 * and the split), this process's share of the particles. Touches no file. Returns 0, or -1
 * with a message when the checkpoint does not fit the case (particle count, dimension,
 * layout). */
int restart_load(run *r, const checkpoint_data *cd, char *err, size_t err_len);

/* Checks, touching nothing, that every CSV file the checkpoint recorded exists in the output
 * directory and is at least as long as it was then. Returns 0, or -1 with a message. */
int restart_check_outputs(run *r, char *err, size_t err_len);

#endif
