/* run_outputs: the files a run writes (docs/outputs.md): the output folder, the CSV files
 * and their rows, snapshots with their XDMF index, particle images; opened fresh or rewound
 * for a restart. The time loop (simulation.c) decides when each is due. */
#include "app/output_folder.h"
#include "app/run_state.h"
#include "boundary/tank.h"
#include "core/log.h"
#include "diag/energy.h"
#include "diag/packing.h"
#include "diag/probes.h"
#include "diag/volume.h"
#include "io/csv.h"
#include "io/image.h"
#include "io/snapshot.h"
#include "scheme/edbc.h"
#include "scheme/loads.h"
#include "scheme/solver.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char timeseries_header[] =
    "t,step,dt,n_fluid,eps_v1,eps_v2,eps_v3,eps_gm,eps_sph,mass_err,eta,edbc,n_edbc,"
    "n_free_surface,ekin,epot,eint,work_in,ediss,com_x,com_y,com_z,xmin,xmax,ymax,umax,"
    "rho_min,rho_max,esurf,work_st,deps_u,deps_du,deps_corr,angmom_x,angmom_y,angmom_z,"
    "work_moves,eps_fs,fs_nn_median,fs_nn_p05";

void run_out_path(const run *r, char *buf, size_t len, const char *name)
{
    snprintf(buf, len, "%s/%s", r->opt->output_dir, name);
}

void run_event(run *r, const char *what, const char *detail)
{
    csv_put(&r->events, r->s.t);
    csv_put_text(&r->events, what);
    csv_put_text(&r->events, detail);
    csv_end_row(&r->events);
}

/* The graphical method's volume of the whole liquid from positions gathered on the process
 * that writes, handed to every process (the largest of theirs: the others draw nothing). */
static int gathered_graphical_volume(run *r, double *volume, char *err, size_t err_len)
{
    solver *s = &r->s;
    particles whole;
    run_gather(r, &s->p, RUN_GATHER_POSITIONS, &whole);
    *volume = 0.0;
    int failed = team_writes(r->team) &&
                 volume_graphical(&whole, s->tank.size, &s->dv, volume, err, err_len);
    run_gathered_free(r, &whole);
    if (team_first_message(r->team, failed, err, err_len)) return -1;
    *volume = reducer_max(solver_reducer(s), volume, 1);
    return 0;
}

/* The graphical method's volume of the whole liquid. A split solver's processes each draw the
 * pixels of their own part of the tank along x from their particles and halo, and their
 * counts are summed: the whole raster's count, each pixel summing the same sources in the
 * same order (raster_count_part). Before the first step has distributed the particles (the
 * initial lattice's count, at set-up) there are no parts yet, and rank 0 draws them all. */
static int graphical_volume(run *r, double *volume, char *err, size_t err_len)
{
    solver *s = &r->s;
    double lo = -INFINITY, hi = INFINITY;
    size_t n_halo_before = 0;
    if (r->split && s->domain->part_along_x(s->domain, s, &lo, &hi, &n_halo_before))
        return gathered_graphical_volume(r, volume, err, err_len);
    raster_count c;
    int failed =
        volume_graphical_part(&s->p, n_halo_before, lo, hi, s->tank.size, &s->dv, &c, err, err_len);
    if (team_first_message(r->team, failed, err, err_len)) return -1;
    for (size_t kind = 0; kind < sizeof c.count / sizeof c.count[0]; kind++)
        c.count[kind] = (unsigned long long)reducer_total(solver_reducer(s), (long)c.count[kind]);
    *volume = raster_count_volume(&c);
    return 0;
}

/* The graphical method, Eq. (15): eps_GM of the current positions (sec. 3.2) against the
 * initial configuration's count (run_graphical_reference). */
static int graphical_measure(run *r, double *eps_gm)
{
    char err[256];
    double volume;
    if (graphical_volume(r, &volume, err, sizeof err) == 0) {
        *eps_gm = graphical_error(volume, r->graphical_volume0);
        return 0;
    }
    log_error("vcsph: graphical method: %s", err);
    return -1;
}

int run_graphical_reference(run *r, char *err, size_t err_len)
{
    if (!r->cfg->graphical) return 0;
    return graphical_volume(r, &r->graphical_volume0, err, err_len);
}

/* The energy the liquid stores in its motion, its height and its compression (theory §10). */
static double mechanical_energy(const diagnostics *dg) { return dg->ekin + dg->epot + dg->eint; }

/* sigma x the interface area (sum delta V), 0 without surface tension */
static double surface_energy(solver *s)
{
    return s->pp.surface_tension
               ? surface_tension_energy(&s->st, &s->p, s->scratch, solver_reducer(s))
               : 0.0;
}

/* ediss = work_in + work_st + work_moves - (E(t) - E(0)): the mechanical energy theorem of
 * the discrete liquid, every force's work counted as integrated (theory §10; docs/energy.md),
 * and the potential energy of the moves beyond the flow (shifting, the volume correction, mass
 * fluxes) booked apart, since they relocate mass without a force. The surface
 * energy enters through the work of the surface-tension force, not through the measured
 * area: the area's measure drifts with the particles' disorder by a few 1e-3 of itself,
 * which on a flat surface is more than the liquid dissipates. */
static double dissipated_energy(run *r, double energy)
{
    return r->s.work_in + r->s.work_st + r->s.work_moves - (energy - r->energy0);
}

/* What the surface lost beyond the work of its force, -(work_st + esurf): the surface energy
 * that reconnections release without the discrete force having done the work (docs/energy.md). */
static double surface_loss(run *r, double esurf) { return -(r->s.work_st + esurf); }

/* One row of loads.csv: t, the force and the moment about motion.center in the tank's axes,
 * both in the inertial axes (R F, R M), then the liquid's momentum and body force in the tank
 * frame (docs/loads.md). */
void run_write_loads_row(run *r)
{
    solver *s = &r->s;
    tank_loads l;
    tank_frame frame = solver_frame(s, s->t);
    neighbour_list rows = solver_prepared_rows(s); /* a step's outputs follow solver_prepare */
    if (loads_compute(&s->pp, &s->p, &rows, &frame, solver_reducer(s), &l)) {
        log_error("vcsph: loads: out of memory; loads.csv misses t = %.9g s", s->t);
        return;
    }
    double rot[3][3], force[3], moment[3];
    motion_rotation(&s->mo, s->t, rot);
    mat3_apply(rot, l.force, force);
    mat3_apply(rot, l.moment, moment);
    csv_file *c = &r->loads;
    csv_put(c, s->t);
    for (int frame = 0; frame < 2; frame++) {
        const double *f = frame ? force : l.force, *m = frame ? moment : l.moment;
        for (int d = 0; d < DIM; d++) csv_put(c, f[d]);
        for (int d = 0; d < 3; d++) csv_put(c, m[d]);
    }
    for (int d = 0; d < DIM; d++) csv_put(c, l.momentum[d]);
    for (int d = 0; d < DIM; d++) csv_put(c, l.body[d]);
    csv_end_row(c);
}

/* One row of timeseries.csv (docs/outputs.md). The volume columns need this step's geometry
 * (solver_prepare at the current state); a breakdown row has none and leaves them empty. */
void run_write_series_row(run *r, int with_geometry)
{
    solver *s = &r->s;
    volume_errors ve;
    if (with_geometry) volume_compute(&s->p, s->dv.cell_volume, s->scratch, solver_reducer(s), &ve);
    diagnostics dg;
    solver_diagnostics(s, &dg);
    double esurf = surface_energy(s), energy = mechanical_energy(&dg);
    if (s->step == 0) {
        r->energy0 = energy;
        r->surface_loss_period_start = surface_loss(r, esurf);
    }
    csv_file *c = &r->timeseries;
    csv_put(c, s->t);
    csv_put_long(c, s->step);
    csv_put(c, s->last_dt);
    csv_put_long(c, reducer_total(solver_reducer(s), (long)s->p.n_fluid));
    if (with_geometry) {
        csv_put(c, ve.eps_v1);
        csv_put(c, ve.eps_v2);
        csv_put(c, ve.eps_v3);
    } else {
        for (int k = 0; k < 3; k++) csv_put_empty(c);
    }
    double eps_gm;
    if (with_geometry && r->cfg->graphical && graphical_measure(r, &eps_gm) == 0)
        csv_put(c, eps_gm);
    else
        csv_put_empty(c);
    csv_put(c, dg.vol_sph / r->v0 - 1.0);
    csv_put(c, dg.mass / r->mass0 - 1.0);
    csv_put(c, s->eta_control.eta);
    csv_put_long(c, edbc_acts(s));
    csv_put_long(c, s->n_edbc);
    if (with_geometry)
        csv_put_long(c, ve.n_free_surface);
    else
        csv_put_empty(c);
    csv_put(c, dg.ekin);
    csv_put(c, dg.epot);
    csv_put(c, dg.eint);
    csv_put(c, s->work_in);
    csv_put(c, dissipated_energy(r, energy));
    for (int d = 0; d < 3; d++) csv_put(c, dg.com[d]);
    csv_put(c, dg.xmin);
    csv_put(c, dg.xmax);
    csv_put(c, dg.ymax);
    csv_put(c, dg.umax);
    csv_put(c, dg.rho_min);
    csv_put(c, dg.rho_max);
    csv_put(c, esurf);
    csv_put(c, s->work_st);
    if (with_geometry) {
        volume_rates rate;
        neighbour_list rows = solver_prepared_rows(s); /* after solver_prepare, as the loads */
        volume_rate(&s->pp.k, &s->p, &rows, s->dv.cell_volume, s->scratch, solver_reducer(s),
                    &rate);
        csv_put(c, rate.u);
        csv_put(c, rate.shift);
        csv_put(c, rate.correction);
    } else {
        for (int k = 0; k < 3; k++) csv_put_empty(c);
    }
    for (int d = 0; d < 3; d++) csv_put(c, dg.angmom[d]);
    csv_put(c, s->work_moves);
    if (with_geometry) {
        csv_put(c, volume_free_surface_packing(&s->p, s->dv.cell_volume, s->pp.surface_kernel_sum,
                                               s->scratch, solver_reducer(s)));
        double median, p05;
        neighbour_list rows = solver_prepared_rows(s);
        surface_nearest_quantiles(&s->pp.k, &s->p, &rows, s->dv.dr, r->team, s->scratch, &median,
                                  &p05);
        csv_put_number(c, median);
        csv_put_number(c, p05);
    } else {
        for (int k = 0; k < 3; k++) csv_put_empty(c);
    }
    csv_end_row(c);

    /* Eq. (6): the sound speed assumes speeds below c0/10 */
    int fast = dg.umax > 0.1 * s->pp.c0;
    if (fast && !r->speed_warned) {
        char detail[128];
        snprintf(detail, sizeof detail, "U_max = %.4g m/s exceeds c0/10 = %.4g m/s (Eq. 6)",
                 dg.umax, 0.1 * s->pp.c0);
        run_event(r, "speed_above_c0_over_10", detail);
        if (!r->speed_told) { /* the first one on the terminal too; the rest are counted */
            progress_clear(&r->pr);
            log_info("vcsph: warning at t = %.4g s: %s; the sound speed may be too low for "
                     "this flow (later ones: events.csv, counted at the end)",
                     s->t, detail);
            r->speed_told = 1;
        }
    }
    r->speed_warned = fast;
}

/* The snapshot type of a field of the registry. */
#define SNAPSHOT_TYPE(type)                                                                        \
    _Generic((type *)0, double *: FIELD_DOUBLE, float *: FIELD_FLOAT, int64_t *: FIELD_INT64,      \
             int32_t *: FIELD_INT32, uint8_t *: FIELD_UINT8)

/* At most every field of the registry. */
#define COUNT_FIELD(type, name, flags, snapshot, comment) +1
enum { SNAPSHOT_FIELDS_MAX = 0 PARTICLE_FIELDS(COUNT_FIELD, COUNT_FIELD) };

/* The fields of docs/outputs.md: those of the registry with a snapshot name (core/particles.h),
 * in its order; lambda, surface and eps_vi from the geometry of this step. */
static int snapshot_fields(const solver *s, const particles *p, snapshot_field *f)
{
    int n = 0;
#define WRITTEN(flags, snapshot)                                                                   \
    ((snapshot) != NULL && (s->pp.surface_tension || !((flags)&FIELD_SURFACE_TENSION)))
#define SNAPSHOT_SCALAR(type, name, flags, snapshot, comment)                                      \
    if (WRITTEN(flags, snapshot))                                                                  \
        f[n++] = (snapshot_field){snapshot, SNAPSHOT_TYPE(type), 1, {p->name}};
#define SNAPSHOT_VECTOR(type, name, flags, snapshot, comment)                                      \
    if (WRITTEN(flags, snapshot)) {                                                                \
        f[n] = (snapshot_field){snapshot, SNAPSHOT_TYPE(type), DIM, {0}};                          \
        for (int d = 0; d < DIM; d++) f[n].component[d] = p->name[d];                              \
        n++;                                                                                       \
    }
    PARTICLE_FIELDS(SNAPSHOT_SCALAR, SNAPSHOT_VECTOR)
    return n;
}

int run_reserve_snapshots(run *r, int n)
{
    if (n <= r->cap_snapshots) return 0;
    int cap = r->cap_snapshots ? 2 * r->cap_snapshots : 64;
    while (cap < n) cap *= 2;
    char **files = realloc(r->snapshot_files, (size_t)cap * sizeof *files);
    if (files) r->snapshot_files = files;
    double *times = realloc(r->snapshot_times, (size_t)cap * sizeof *times);
    if (times) r->snapshot_times = times;
    size_t *counts = realloc(r->snapshot_counts, (size_t)cap * sizeof *counts);
    if (counts) r->snapshot_counts = counts;
    if (!files || !times || !counts) return -1;
    r->cap_snapshots = cap;
    return 0;
}

/* snapshots.xmf listing the snapshots written so far. */
static int write_xdmf(run *r, const snapshot_field *fields, int n_fields)
{
    char path[CONFIG_PATH_MAX + 96], err[512];
    run_out_path(r, path, sizeof path, "snapshots.xmf");
    if (snapshot_write_xdmf(path, r->n_snapshots, (const char *const *)r->snapshot_files,
                            r->snapshot_times, r->snapshot_counts, fields, n_fields, DIM, err,
                            sizeof err)) {
        log_error("vcsph: %s", err);
        return -1;
    }
    return 0;
}

/* eps_Vi of every fluid particle: the only field computed for the snapshots and images */
static void local_volume_errors(solver *s)
{
    for (size_t i = 0; i < s->p.n_fluid; i++)
        s->p.eps_vi[i] = volume_local_error(&s->p, i, s->dv.cell_volume);
}

/* Whether the processes of a split run write each snapshot together through parallel HDF5,
 * each its own rows, rather than gathering the liquid on the process that writes. */
static bool written_together(const run *r)
{
    return r->split && SNAPSHOT_PARALLEL && r->team->io_comm;
}

/* The file of snapshot k (the next one), of p: this process's particles when the team writes
 * it together, each its rows of the global order; else the whole liquid, gathered. Then the
 * XDMF index that lists it, by the process that writes. */
static int write_snapshot_file(run *r, const particles *p, int k, bool together)
{
    const solver *s = &r->s;
    char path[CONFIG_PATH_MAX + 96], err[512];
    run_out_path(r, path, sizeof path, r->snapshot_files[k]);
    snapshot_field fields[SNAPSHOT_FIELDS_MAX];
    int n_fields = snapshot_fields(s, p, fields);
    snapshot_attrs attrs = {s->t,     s->step, s->eta_control.eta, DIM,
                            s->dv.dr, s->dv.h, r->case_text};
    size_t first = together ? r->team->first_index(r->team, p->n_fluid) : 0;
    if (snapshot_write_part(path, p->n_fluid, first, r->snapshot_counts[k],
                            together ? r->team->io_comm : NULL, fields, n_fields, &attrs, err,
                            sizeof err)) {
        log_error("vcsph: %s", err);
        return -1;
    }
    return team_writes(r->team) ? write_xdmf(r, fields, n_fields) : 0;
}

int run_write_snapshot(run *r)
{
    solver *s = &r->s;
    local_volume_errors(s);
    bool together = written_together(r);
    particles gathered;
    const particles *p = &s->p;
    if (!together) {
        run_gather(r, &s->p, RUN_GATHER_SNAPSHOT, &gathered);
        p = &gathered;
    }
    char name[64];
    snapshot_name(r->n_snapshots, name, sizeof name);
    int k = r->n_snapshots, failed = run_reserve_snapshots(r, k + 1);
    if (!failed) {
        r->n_snapshots++;
        r->snapshot_files[k] = strdup(name);
        r->snapshot_times[k] = s->t;
        r->snapshot_counts[k] =
            together ? (size_t)reducer_total(solver_reducer(s), (long)s->p.n_fluid) : p->n_fluid;
        failed = !r->snapshot_files[k] ||
                 ((together || team_writes(r->team)) && write_snapshot_file(r, p, k, together));
    }
    if (!together) run_gathered_free(r, &gathered);
    return team_agree(r->team, failed) ? -1 : 0;
}

/* A restarted run's snapshots.xmf lists the snapshots of the checkpoint, not those written
 * after it (which open_files removed); none: no index, as in a fresh run. */
static int rewind_xdmf(run *r)
{
    if (r->n_snapshots > 0) {
        snapshot_field fields[SNAPSHOT_FIELDS_MAX];
        return write_xdmf(r, fields, snapshot_fields(&r->s, &r->s.p, fields));
    }
    char path[CONFIG_PATH_MAX + 96];
    run_out_path(r, path, sizeof path, "snapshots.xmf");
    return remove(path) == 0 || errno == ENOENT ? 0 : -1;
}

/* Particle images (README.md): the local volume error eps_Vi of every particle, like the
 * paper's Figs. 13 and 21; a 3D run shows its mid-width slice, the particles within 0.6 dr of
 * z = W/2 (one lattice layer, or the two either side of the middle). The colour bar reads in
 * per cent, the axes in metres. */
#define IMAGE_PIXELS    800  /* the tank's width in the image */
#define IMAGE_EPS_RANGE 0.02 /* colours span eps_Vi in [-2 %, +2 %] */

/* The image of the gathered particles (their eps_Vi computed), on the process that writes. */
static int write_image_file(run *r, const particles *p)
{
    const solver *s = &r->s;
    size_t n = p->n_fluid, kept = 0;
    double *buf = malloc(3 * (n ? n : 1) * sizeof *buf);
    if (!buf) return -1;
    double *x = buf, *y = buf + n, *value = buf + 2 * n;
    for (size_t i = 0; i < n; i++) {
#if DIM == 3
        if (fabs(p->x[2][i] - 0.5 * s->tank.size[2]) >= 0.6 * s->dv.dr) continue;
#endif
        x[kept] = p->x[0][i];
        y[kept] = p->x[1][i];
        value[kept++] = p->eps_vi[i];
    }
    char title[CONFIG_NAME_MAX + 32], name[64], path[CONFIG_PATH_MAX + 96], err[512];
    snprintf(title, sizeof title, "%s%s", r->cfg->name, DIM == 3 ? " (mid-width)" : "");
    image_frame f = {.x = x,
                     .y = y,
                     .value = value,
                     .n = kept,
                     .radius = 0.5 * s->dv.dr,
                     .width = s->tank.size[0],
                     .height = s->tank.size[1],
                     .vmin = -IMAGE_EPS_RANGE,
                     .vmax = IMAGE_EPS_RANGE,
                     .label = "eps_Vi",
                     .title = title,
                     .time = s->t,
                     .percent = true};
    snprintf(name, sizeof name, "images/particles_%06d.png", r->n_images);
    run_out_path(r, path, sizeof path, name);
    int status = image_write_particles(path, &f, IMAGE_PIXELS, err, sizeof err);
    free(buf);
    if (status) log_error("vcsph: %s", err);
    return status ? -1 : 0;
}

int run_write_image(run *r)
{
    local_volume_errors(&r->s);
    particles whole;
    run_gather(r, &r->s.p, RUN_GATHER_SNAPSHOT, &whole);
    int failed = team_writes(r->team) && write_image_file(r, &whole);
    run_gathered_free(r, &whole);
    if (team_agree(r->team, failed)) return -1;
    r->n_images++;
    return 0;
}

/* Creates CSV file k with its header, or for a restarted run reopens it at its size at the
 * checkpoint (the rows written after it are dropped; a file from before a column was added
 * gains it, empty in the old rows). */
static int open_csv(run *r, int k, const char *header)
{
    char path[CONFIG_PATH_MAX + 64];
    run_out_path(r, path, sizeof path, run_csv_name(k));
    /* a checkpoint from before loads.csv recorded no size for it: it starts anew */
    if (r->resumed && r->resume_sizes[k] >= 0) {
        int rc = csv_reopen_with_header(run_csv(r, k), path, r->resume_sizes[k], header);
        if (rc == -2)
            log_error("vcsph: %s: its header is neither this version's nor an older one's", path);
        return rc ? -1 : 0;
    }
    return csv_open(run_csv(r, k), path, header);
}

/* probes.csv with its header (run_probes.c) */
static int open_probes(run *r)
{
    char header[RUN_PROBES_HEADER_MAX];
    run_probes_start(r, header, sizeof header);
    return open_csv(r, RUN_CSV_PROBES, header);
}

/* ---- a restart's rewind ---------------------------------------------------------------------- */

/* The rows of timeseries.csv after `size` bytes (the checkpoint's) whose time is past t, and
 * the time of the last; 0 if there are none or the file cannot be read. */
static long rows_after(const char *path, long long size, double t, double *t_last)
{
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    long rows = 0;
    char line[8192];
    if (fseeko(f, (off_t)size, SEEK_SET) == 0)
        while (fgets(line, sizeof line, f)) {
            double time = strtod(line, NULL);
            if (!strchr(line, '\n') || !(time > t)) continue;
            rows++;
            *t_last = time;
        }
    fclose(f);
    return rows;
}

/* Says on the terminal and in log.txt when the rewind drops rows after the checkpoint's time
 * (a run killed after its last checkpoint), before the files are cut back. */
static void report_rewind(const run *r)
{
    if (r->resume_sizes[RUN_CSV_TIMESERIES] < 0) return;
    char path[CONFIG_PATH_MAX + 64];
    snprintf(path, sizeof path, "%s/%s", r->opt->output_dir, run_csv_name(RUN_CSV_TIMESERIES));
    double t_last = r->s.t;
    long rows = rows_after(path, r->resume_sizes[RUN_CSV_TIMESERIES], r->s.t, &t_last);
    if (rows == 0) return; /* a finished run, or one stopped by a signal: nothing is lost */
    log_info("vcsph: the run had gone on after its checkpoint: rewinding to t = %.9g s removes "
             "%ld rows of timeseries.csv up to t = %.9g s, and the other rows, snapshots and "
             "images after the checkpoint; the restart computes them again",
             r->s.t, rows, t_last);
}

/* A fresh run starts the files; a restarted one rewinds them to the checkpoint. */
static int open_files(run *r)
{
    char path[CONFIG_PATH_MAX + 64];
    run_out_path(r, path, sizeof path, "log.txt");
    if (log_open(path, r->resumed)) return -1;
    if (r->resumed) report_rewind(r);
    run_out_path(r, path, sizeof path, "case.ini");
    FILE *f = fopen(path, "w");
    if (!f || fputs(r->case_text, f) == EOF || fclose(f)) return -1;
    if (open_csv(r, RUN_CSV_TIMESERIES, timeseries_header)) return -1;
    if (run_has_periods(r) &&
        open_csv(r, RUN_CSV_DISSIPATION, "period,t_start,t_end,e_diss,power,power_norm,e_surface"))
        return -1;
    if (config_has_probes(r->cfg) && open_probes(r)) return -1;
    if (open_csv(r, RUN_CSV_EVENTS, "t,event,detail")) return -1;
    if (open_csv(r, RUN_CSV_LOADS,
                 DIM == 2 ? "t,fx,fy,mx,my,mz,fx_inertial,fy_inertial,mx_inertial,my_inertial,"
                            "mz_inertial,px,py,bx,by"
                          : "t,fx,fy,fz,mx,my,mz,fx_inertial,fy_inertial,fz_inertial,mx_inertial,"
                            "my_inertial,mz_inertial,px,py,pz,bx,by,bz"))
        return -1;
    if (r->resumed) {
        /* snapshots and images numbered from the checkpoint's counts on, a half-written
           checkpoint.h5.tmp */
        output_folder_rewind(r->opt->output_dir, r->n_snapshots, r->n_images);
        return rewind_xdmf(r);
    }
    return 0; /* a fresh run starts in a folder without another run's files (simulation.c) */
}

int run_open_outputs(run *r)
{
    char path[CONFIG_PATH_MAX + 64];
    char images[CONFIG_PATH_MAX + 64];
    run_out_path(r, path, sizeof path, "snapshots");
    run_out_path(r, images, sizeof images, "images");
    if (output_folder_make(r->opt->output_dir) || output_folder_make(path) ||
        (r->cfg->image_every > 0 && output_folder_make(images))) {
        log_error("vcsph: cannot create output directory %s: %s", r->opt->output_dir,
                  strerror(errno));
        return -1;
    }
    return open_files(r);
}

/* One row of dissipation.csv, at the end of period k (theory §10):
 * e_diss(k) = ediss(kT) - ediss((k-1)T), P = e_diss / T, normalised by dW (dE_P with decay);
 * then e_surface, the surface's loss beyond its force's work over the period. */
void run_write_dissipation_row(run *r)
{
    double period = r->cfg->period;
    diagnostics dg;
    solver_diagnostics(&r->s, &dg);
    double ediss = dissipated_energy(r, mechanical_energy(&dg));
    double loss = surface_loss(r, surface_energy(&r->s));
    double e = ediss - r->ediss_period_start, norm = r->s.dv.dissipation_norm;
    csv_file *c = &r->dissipation;
    csv_put_long(c, r->period);
    csv_put(c, run_period_end(r) - period);
    csv_put(c, run_period_end(r));
    csv_put(c, e);
    csv_put(c, e / period);
    if (norm > 0.0)
        csv_put(c, e / norm);
    else
        csv_put_empty(c); /* no amplitude, no reference energy */
    csv_put(c, loss - r->surface_loss_period_start);
    csv_end_row(c);
    r->ediss_period_start = ediss;
    r->surface_loss_period_start = loss;
    r->period++;
}
