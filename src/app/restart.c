/* restart: a run's state to and from checkpoint.h5 (run_state.h), for a restart that
 * continues bit for bit as if the run had never stopped.
 *
 * What is saved is the state just after a step, before the next solver_prepare: everything
 * that solver_prepare and the outputs read and do not recompute. That is, per fluid particle
 * in the current order (the order decides the next cell sort, and with it the order of every
 * sum): id, x, u, rho, m (p and V follow from them by solver_update_eos; the per-step
 * fields lambda, surface, shifting, diffusion, ... are recomputed by solver_prepare); the
 * scalars that the next time step and neighbour skin read (max_acc) or that accumulate
 * (work_in, work_st, work_moves); the whole eta controller, its adaptive history included (EdBC's
 * state is its mode, in the case, and the controller's eta0_regime; n_edbc is recomputed by
 * solver_prepare and saved for the record); and the bookkeeping of the outputs.
 *
 * Layout (checkpoint.h, version 2): one dataset each, scalars grouped with their "columns":
 *   case              bytes  the resolved case text (what `vcsph run --restart` runs)
 *   sound_speed       f64    c0 as the run computed it (a restart keeps it; main.c)
 *   motion_table      bytes  motion.type = table only: the table's text (motion_table.h)
 *   solver_f64        f64    t, last_dt, max_acc, work_in, work_st, work_moves (without
 *                            work_moves in checkpoints from before it: it resumes at 0)
 *   solver_i64        i64    dim, n_fluid, step, n_edbc
 *   eta_f64           f64    threshold, period, eta, t_last, eps_last, integral, eps_mean,
 *                            eps_expected
 *   eta_i64           i64    switching, kind, eta0_regime, switches, n_samples
 *   eta_samples       f64    ETA_HISTORY samples of the adaptive control's running integral
 *   run_f64           f64    mech_energy0, mass0, v0, ediss_period_start,
 *                            surface_loss_period_start, next_series, next_snapshot,
 *                            next_image (mech_energy0: ekin + epot + eint at t = 0; the
 *                            name changed when the surface energy left it, so that an older
 *                            checkpoint is refused)
 *   run_i64           i64    period, n_snapshots, n_images, speed_warned
 *   probes_f64        f64    with probes only: the next row of probes.csv, then each pressure
 *                            probe's filter state (y, rate, u, t, started; sensor_filter.h)
 *                            (absent in checkpoints from before probes.every: the rows
 *                            resume with timeseries.csv's)
 *   csv_sizes         i64    bytes of timeseries.csv, events.csv, dissipation.csv, probes.csv,
 *                            loads.csv (the first four in checkpoints from before loads.csv)
 *                            (-1: the run does not write it)
 *   snapshot_times    f64    n_snapshots: the XDMF index
 *   snapshot_counts   i64    n_snapshots
 *   snapshot_files    bytes  n_snapshots names, each ended by a NUL
 *   id                i64    n_fluid
 *   x_0 .. x_{DIM-1}  f64    n_fluid, positions
 *   u_0 .. u_{DIM-1}  f64    n_fluid, velocities
 *   rho, m            f64    n_fluid */
#include "app/run_state.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SOLVER_F64 "t,last_dt,max_acc,work_in,work_st,work_moves"
/* a checkpoint from before work_moves: its run resumes with work_moves = 0 */
#define SOLVER_F64_BEFORE_MOVES "t,last_dt,max_acc,work_in,work_st"
#define SOLVER_I64              "dim,n_fluid,step,n_edbc"
#define ETA_F64                 "threshold,period,eta,t_last,eps_last,integral,eps_mean,eps_expected"
#define ETA_I64                 "switching,kind,eta0_regime,switches,n_samples"
#define RUN_F64                                                                                    \
    "mech_energy0,mass0,v0,ediss_period_start,surface_loss_period_start,next_series,"              \
    "next_snapshot,next_image"
#define RUN_I64   "period,n_snapshots,n_images,speed_warned"
#define CSV_SIZES "timeseries,events,dissipation,probes,loads"
/* a checkpoint from before loads.csv: its run resumes with a new loads.csv */
#define CSV_SIZES_BEFORE_LOADS "timeseries,events,dissipation,probes"

/* The particles' persistent state (core/particles.h, FIELD_STATE), one item per scalar field
 * and per component of a vector field ("x_0", "x_1", ...), int64 or float64. */
#define STATE_ITEM_TYPE(type)                                                                      \
    _Generic((type *)0, int64_t * : CHECKPOINT_I64, double * : CHECKPOINT_F64, default : -1)
#define STATE_ITEM_CHECK(type, name, flags, snapshot, comment)                                     \
    _Static_assert(!((flags)&FIELD_STATE) || STATE_ITEM_TYPE(type) >= 0, #name);
PARTICLE_FIELDS(STATE_ITEM_CHECK, STATE_ITEM_CHECK)
#define COMPONENT_NAME(name, d) ((const char *const[3]){#name "_0", #name "_1", #name "_2"}[d])

typedef struct {
    checkpoint_item items[CHECKPOINT_MAX_ITEMS];
    int n;
} item_list;

static void add(item_list *l, const char *name, checkpoint_type type, size_t n, const void *data,
                const char *columns)
{
    l->items[l->n++] = (checkpoint_item){name, type, n, data, columns};
}

/* The float64 scalars, group by group in the order of their columns: restart_save gathers
 * them through these pointers and restart_load puts them back, so both follow one list. */
enum { F64_GROUPS = 3, F64_GROUP_MAX = 8 };

typedef struct {
    const char *name, *columns;
    int n;
    double *field[F64_GROUP_MAX];
    const char *columns_before; /* an older layout without the last field (NULL: none) */
} f64_group;

static void f64_groups(run *r, f64_group g[F64_GROUPS])
{
    solver *s = &r->s;
    eta_controller *e = &s->eta_control;
    g[0] = (f64_group){"solver_f64",
                       SOLVER_F64,
                       6,
                       {&s->t, &s->last_dt, &s->max_acc, &s->work_in, &s->work_st, &s->work_moves},
                       SOLVER_F64_BEFORE_MOVES};
    g[1] = (f64_group){"eta_f64",
                       ETA_F64,
                       8,
                       {&e->threshold, &e->period, &e->eta, &e->t_last, &e->eps_last, &e->integral,
                        &e->eps_mean, &e->eps_expected},
                       NULL};
    g[2] = (f64_group){"run_f64",
                       RUN_F64,
                       8,
                       {&r->energy0, &r->mass0, &r->v0, &r->ediss_period_start,
                        &r->surface_loss_period_start, &r->next_series, &r->next_snapshot,
                        &r->next_image},
                       NULL};
}

static void add_particles(item_list *l, const particles *p)
{
    size_t n = p->n_fluid;
#define ADD_SCALAR(type, name, flags, snapshot, comment)                                           \
    if ((flags)&FIELD_STATE) add(l, #name, STATE_ITEM_TYPE(type), n, p->name, NULL);
#define ADD_VECTOR(type, name, flags, snapshot, comment)                                           \
    if ((flags)&FIELD_STATE)                                                                       \
        for (int d = 0; d < DIM; d++)                                                              \
            add(l, COMPONENT_NAME(name, d), STATE_ITEM_TYPE(type), n, p->name[d], NULL);
    PARTICLE_FIELDS(ADD_SCALAR, ADD_VECTOR)
}

/* The snapshot names one after the other, each with its NUL; free() it. */
static char *join_names(char *const *names, int n, size_t *len)
{
    *len = 0;
    for (int k = 0; k < n; k++) *len += strlen(names[k]) + 1;
    char *buf = malloc(*len ? *len : 1);
    if (!buf) return NULL;
    for (size_t at = 0, k = 0; k < (size_t)n; k++) {
        size_t size = strlen(names[k]) + 1;
        memcpy(buf + at, names[k], size);
        at += size;
    }
    return buf;
}

/* The rows written so far reach the disk before the checkpoint that counts them. */
static int sync_csv_files(run *r, int64_t sizes[RUN_N_CSV], char *err, size_t err_len)
{
    for (int k = 0; k < RUN_N_CSV; k++) {
        if (csv_sync(run_csv(r, k))) {
            snprintf(err, err_len, "checkpoint: cannot sync %s/%s: %s", r->opt->output_dir,
                     run_csv_name(k), strerror(errno));
            return -1;
        }
        sizes[k] = csv_size(run_csv(r, k));
    }
    return 0;
}

/* The checkpoint file of the run's state with the gathered particles `whole`, on the process
 * that writes. */
static int write_checkpoint(run *r, const particles *whole, const char *path, char *err,
                            size_t err_len)
{
    const solver *s = &r->s;
    const eta_controller *e = &s->eta_control;
    int64_t csv_sizes[RUN_N_CSV];
    if (sync_csv_files(r, csv_sizes, err, err_len)) return -1;
    f64_group groups[F64_GROUPS];
    f64_groups(r, groups);
    double f64_values[F64_GROUPS][F64_GROUP_MAX];
    for (int g = 0; g < F64_GROUPS; g++)
        for (int k = 0; k < groups[g].n; k++) f64_values[g][k] = *groups[g].field[k];
    const int64_t solver_i64[] = {DIM, (int64_t)whole->n_fluid, s->step, s->n_edbc};
    const int64_t eta_i64[] = {e->switching, e->kind, e->eta0_regime, e->switches, e->n_samples};
    const int64_t run_i64[] = {r->period, r->n_snapshots, r->n_images, r->speed_warned};
    size_t n_snap = (size_t)r->n_snapshots, names_len;
    int64_t *counts = malloc((n_snap ? n_snap : 1) * sizeof *counts);
    char *names = join_names(r->snapshot_files, r->n_snapshots, &names_len);
    if (!counts || !names) {
        free(counts);
        free(names);
        snprintf(err, err_len, "checkpoint: out of memory");
        return -1;
    }
    for (size_t k = 0; k < n_snap; k++) counts[k] = (int64_t)r->snapshot_counts[k];

    item_list l = {.n = 0};
    add(&l, "case", CHECKPOINT_BYTES, strlen(r->case_text), r->case_text, NULL);
    /* the sound speed the run started with: `auto` depends on t_end with a motion table, and
       a restart that extends the run must not change the equation of state */
    add(&l, "sound_speed", CHECKPOINT_F64, 1, &s->dv.c0, NULL);
    if (r->cfg->motion_table) /* the table the run read, whatever happens to its file */
        add(&l, "motion_table", CHECKPOINT_BYTES, strlen(r->cfg->motion_table),
            r->cfg->motion_table, NULL);
    for (int g = 0; g < F64_GROUPS; g++)
        add(&l, groups[g].name, CHECKPOINT_F64, (size_t)groups[g].n, f64_values[g],
            groups[g].columns);
    add(&l, "solver_i64", CHECKPOINT_I64, 4, solver_i64, SOLVER_I64);
    add(&l, "eta_i64", CHECKPOINT_I64, 5, eta_i64, ETA_I64);
    add(&l, "eta_samples", CHECKPOINT_F64, ETA_HISTORY, e->samples, NULL);
    add(&l, "run_i64", CHECKPOINT_I64, 4, run_i64, RUN_I64);
    double probes_state[RUN_PROBES_STATE_MAX];
    if (config_has_probes(r->cfg))
        add(&l, "probes_f64", CHECKPOINT_F64, run_probes_state(r, probes_state), probes_state,
            NULL);
    add(&l, "csv_sizes", CHECKPOINT_I64, RUN_N_CSV, csv_sizes, CSV_SIZES);
    add(&l, "snapshot_times", CHECKPOINT_F64, n_snap, r->snapshot_times, NULL);
    add(&l, "snapshot_counts", CHECKPOINT_I64, n_snap, counts, NULL);
    add(&l, "snapshot_files", CHECKPOINT_BYTES, names_len, names, NULL);
    add_particles(&l, whole);
    int rc = checkpoint_write(path, l.items, l.n, err, err_len);
    free(counts);
    free(names);
    return rc;
}

int restart_save(run *r, const char *path, char *err, size_t err_len)
{
    particles whole;
    run_gather(r, &r->s.p, RUN_GATHER_STATE, &whole);
    err[0] = '\0';
    int failed = team_writes(r->team) && write_checkpoint(r, &whole, path, err, err_len);
    run_gathered_free(r, &whole);
    return team_agree(r->team, failed) ? -1 : 0;
}

/* ---- loading ----------------------------------------------------------------------------- */

/* Copies rows first .. first + count - 1 of array `name`, checked for its type, length n and
 * columns, into out. */
static int take_rows(const checkpoint_data *cd, const char *name, checkpoint_type type, size_t n,
                     size_t first, size_t count, const char *columns, void *out, char *err,
                     size_t err_len)
{
    const checkpoint_array *a = checkpoint_find(cd, name, type, n, columns, err, err_len);
    if (!a) return -1;
    size_t size = checkpoint_type_size(type);
    if (count > 0) memcpy(out, (const char *)a->data + first * size, count * size);
    return 0;
}

/* Copies array `name`, checked for its type, length and columns, into out. */
static int take(const checkpoint_data *cd, const char *name, checkpoint_type type, size_t n,
                const char *columns, void *out, char *err, size_t err_len)
{
    return take_rows(cd, name, type, n, 0, n, columns, out, err, err_len);
}

/* The fluid of the checkpoint, or with the solver split among a team this process's share of
 * it (the rows of its part of the checkpoint's order, which is the global order: reduce_share,
 * as solver_init_part set up its share of the lattice). */
static int load_particles(run *r, const checkpoint_data *cd, char *err, size_t err_len)
{
    solver *s = &r->s;
    int64_t head[4];
    if (take(cd, "solver_i64", CHECKPOINT_I64, 4, SOLVER_I64, head, err, err_len)) return -1;
    particles *p = &s->p;
    size_t n = (size_t)s->dv.n_fluid, first = 0, end = n;
    if (head[0] != DIM || head[1] != (int64_t)n) {
        snprintf(err, err_len,
                 "it holds %lld particles in %lldD, where its case makes %zu in %dD (a "
                 "checkpoint of another case?)",
                 (long long)head[1], (long long)head[0], n, DIM);
        return -1;
    }
    if (r->split) reduce_share(n, r->team->rank, r->team->size, &first, &end);
    if (p->n_fluid != end - first) {
        snprintf(err, err_len, "this process holds %zu particles, not its share of %zu", p->n_fluid,
                 end - first);
        return -1;
    }
    s->step = head[2];
    s->n_edbc = head[3];
    int rc = 0;
    size_t count = end - first;
#define TAKE_SCALAR(type, name, flags, snapshot, comment)                                          \
    if ((flags)&FIELD_STATE && rc == 0)                                                            \
        rc = take_rows(cd, #name, STATE_ITEM_TYPE(type), n, first, count, NULL, p->name, err,      \
                       err_len);
#define TAKE_VECTOR(type, name, flags, snapshot, comment)                                          \
    for (int d = 0; d < DIM && (flags)&FIELD_STATE && rc == 0; d++)                                \
        rc = take_rows(cd, COMPONENT_NAME(name, d), STATE_ITEM_TYPE(type), n, first, count, NULL,  \
                       p->name[d], err, err_len);
    PARTICLE_FIELDS(TAKE_SCALAR, TAKE_VECTOR)
    p->n_total = p->n_fluid; /* the ghosts are made again by the next solver_prepare */
    return rc ? -1 : 0;
}

static int load_f64_scalars(run *r, const checkpoint_data *cd, char *err, size_t err_len)
{
    f64_group groups[F64_GROUPS];
    f64_groups(r, groups);
    for (int g = 0; g < F64_GROUPS; g++) {
        double v[F64_GROUP_MAX];
        if (take(cd, groups[g].name, CHECKPOINT_F64, (size_t)groups[g].n, groups[g].columns, v, err,
                 err_len)) {
            char older[256];
            if (!groups[g].columns_before ||
                take(cd, groups[g].name, CHECKPOINT_F64, (size_t)groups[g].n - 1,
                     groups[g].columns_before, v, older, sizeof older))
                return -1; /* with the message of the present layout */
            v[groups[g].n - 1] = 0.0;
        }
        for (int k = 0; k < groups[g].n; k++) *groups[g].field[k] = v[k];
    }
    return 0;
}

static int load_eta_control(eta_controller *e, const checkpoint_data *cd, char *err, size_t err_len)
{
    int64_t k[5];
    if (take(cd, "eta_i64", CHECKPOINT_I64, 5, ETA_I64, k, err, err_len) ||
        take(cd, "eta_samples", CHECKPOINT_F64, ETA_HISTORY, NULL, e->samples, err, err_len))
        return -1;
    /* the kind of control and whether it switches follow from the case (eta_control_init,
       called by solver_init): another value is no state of this case's run */
    if ((k[0] != 0) != e->switching || k[1] != (int64_t)e->kind) {
        snprintf(err, err_len, "dataset 'eta_i64' holds another eta control than the case's");
        return -1;
    }
    e->eta0_regime = k[2] != 0;
    e->switches = k[3];
    e->n_samples = k[4];
    return 0;
}

/* The XDMF index: n names (each NUL-ended, one after the other), times and counts. The
 * arrays are found with n entries before anything is allocated for n. */
static int load_snapshot_index(run *r, const checkpoint_data *cd, int n, char *err, size_t err_len)
{
    const checkpoint_array *names = checkpoint_find(cd, "snapshot_files", CHECKPOINT_BYTES,
                                                    SIZE_MAX, NULL, err, err_len),
                           *times = checkpoint_find(cd, "snapshot_times", CHECKPOINT_F64, (size_t)n,
                                                    NULL, err, err_len),
                           *counts = checkpoint_find(cd, "snapshot_counts", CHECKPOINT_I64,
                                                     (size_t)n, NULL, err, err_len);
    if (!names || !times || !counts) return -1;
    if (run_reserve_snapshots(r, n)) {
        snprintf(err, err_len, "out of memory for the index of %d snapshots", n);
        return -1;
    }
    const int64_t *count = counts->data;
    const char *at = names->data, *end = at ? at + names->n : NULL;
    for (int k = 0; k < n; k++) {
        const char *nul = at < end ? memchr(at, '\0', (size_t)(end - at)) : NULL;
        char expected[32];
        snapshot_name(k, expected, sizeof expected);
        if (!nul || strcmp(at, expected) || count[k] < 0 || !(r->snapshot_files[k] = strdup(at))) {
            snprintf(err, err_len,
                     "datasets 'snapshot_files' and 'snapshot_counts' do not hold the index of "
                     "%d snapshots",
                     n);
            return -1;
        }
        r->snapshot_times[k] = ((const double *)times->data)[k];
        r->snapshot_counts[k] = (size_t)count[k];
        r->n_snapshots = k + 1; /* what close_run frees */
        at = nul + 1;
    }
    return 0;
}

static int load_outputs(run *r, const checkpoint_data *cd, char *err, size_t err_len)
{
    int64_t k[4], sizes[RUN_N_CSV];
    if (take(cd, "run_i64", CHECKPOINT_I64, 4, RUN_I64, k, err, err_len)) return -1;
    if (take(cd, "csv_sizes", CHECKPOINT_I64, RUN_N_CSV, CSV_SIZES, sizes, err, err_len)) {
        char older[256];
        if (take(cd, "csv_sizes", CHECKPOINT_I64, RUN_CSV_LOADS, CSV_SIZES_BEFORE_LOADS, sizes,
                 older, sizeof older))
            return -1; /* with the message of the present layout */
        sizes[RUN_CSV_LOADS] = -1;
    }
    if (k[1] < 0 || k[1] > INT32_MAX || k[2] < 0 || k[2] > INT32_MAX) {
        snprintf(err, err_len, "dataset 'run_i64' holds impossible counts");
        return -1;
    }
    r->period = k[0];
    r->n_images = (int)k[2];
    r->speed_warned = (int)k[3];
    for (int c = 0; c < RUN_N_CSV; c++) r->resume_sizes[c] = sizes[c];
    if (config_has_probes(r->cfg)) {
        double state[RUN_PROBES_STATE_MAX];
        size_t n = run_probes_state(r, state); /* the count this case keeps */
        const checkpoint_array *a =
            checkpoint_find(cd, "probes_f64", CHECKPOINT_F64, n, NULL, err, err_len);
        run_probes_resume(r, a ? a->data : NULL);
        err[0] = '\0';
    }
    return load_snapshot_index(r, cd, (int)k[1], err, err_len);
}

/* ---- the loaded state, checked ----------------------------------------------------------- */

static bool all_finite(const double *v, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(v[k])) return false;
    return true;
}

/* The checkpoint's ids are 0 .. n-1 in some order (the lattice numbers them; a run only
 * reorders them), all of them, also where this process loaded its share alone. */
static bool ids_are_a_permutation(const checkpoint_data *cd, size_t n)
{
    char err[256];
    const checkpoint_array *a = checkpoint_find(cd, "id", CHECKPOINT_I64, n, NULL, err, sizeof err);
    const int64_t *ids = a ? a->data : NULL;
    unsigned char *seen = calloc(n ? n : 1, 1);
    bool ok = ids && seen;
    for (size_t i = 0; i < n && ok; i++) {
        int64_t id = ids[i];
        ok = id >= 0 && (uint64_t)id < n && !seen[id];
        if (ok) seen[id] = 1;
    }
    free(seen);
    return ok;
}

/* What every checkpoint this vcsph writes satisfies: it is written only after a step that
 * passed the health check (simulation.c), with counters that only grow from their start. A
 * file that fails this passed the header's hash, so it was made on purpose or by another
 * program; it is refused before the run indexes arrays or divides by what it holds. */
static int check_state(const run *r, const checkpoint_data *cd, char *err, size_t err_len)
{
    const solver *s = &r->s;
    const eta_controller *e = &s->eta_control;
    const double scalars[] = {s->t,
                              s->last_dt,
                              s->max_acc,
                              s->work_in,
                              s->work_st,
                              s->work_moves,
                              e->threshold,
                              e->period,
                              e->t_last,
                              e->eps_last,
                              e->integral,
                              r->energy0,
                              r->mass0,
                              r->v0,
                              r->ediss_period_start,
                              r->surface_loss_period_start,
                              r->next_series,
                              r->next_snapshot,
                              r->next_image};
    const char *why = NULL;
    char health[512], failed[600];
    if (!all_finite(scalars, sizeof scalars / sizeof scalars[0]) ||
        !all_finite(e->samples, ETA_HISTORY) ||
        !all_finite(r->snapshot_times, (size_t)r->n_snapshots))
        why = "a time, energy or control value that is not finite";
    else if (s->t < 0.0 || s->last_dt < 0.0 || s->step < 0 || s->n_edbc < 0 || r->period < 1 ||
             r->mass0 <= 0.0 || r->v0 <= 0.0)
        why = "a negative time, step or count, or no mass or volume";
    else if (!(e->eta >= 0.0 && e->eta <= 1.0) || e->n_samples < 0 || e->switches < 0)
        why = "an eta outside [0, 1] or a negative count of the eta control";
    else if (!ids_are_a_permutation(cd, (size_t)s->dv.n_fluid))
        why = "particle ids that are not 0 .. n-1";
    else if (solver_health(s, health, sizeof health)) {
        snprintf(failed, sizeof failed, "particles that fail the health check (%s)", health);
        why = failed;
    }
    for (int k = 0; k < RUN_N_CSV && !why; k++)
        if (r->resume_sizes[k] < -1) why = "a negative size of an output file";
    if (!why) return 0;
    snprintf(err, err_len, "it holds a state that no run of its case writes: %s", why);
    return -1;
}

int restart_load(run *r, const checkpoint_data *cd, char *err, size_t err_len)
{
    solver *s = &r->s;
    if (load_particles(r, cd, err, err_len) || load_f64_scalars(r, cd, err, err_len) ||
        load_eta_control(&s->eta_control, cd, err, err_len) || load_outputs(r, cd, err, err_len) ||
        check_state(r, cd, err, err_len))
        return -1;
    if (s->t > r->cfg->t_end) {
        snprintf(err, err_len, "case.t_end = %g s is before the checkpoint's time, t = %.9g s",
                 r->cfg->t_end, s->t);
        return -1;
    }
    r->resumed = true;
    solver_update_eos(s); /* p and V of the loaded state */
    return 0;
}

/* ---- the output files -------------------------------------------------------------------- */

int restart_check_outputs(run *r, char *err, size_t err_len)
{
    for (int k = 0; k < RUN_N_CSV; k++) {
        if (r->resume_sizes[k] < 0) continue;
        char path[CONFIG_PATH_MAX + 64];
        snprintf(path, sizeof path, "%s/%s", r->opt->output_dir, run_csv_name(k));
        struct stat st;
        if (stat(path, &st)) {
            snprintf(err, err_len, "%s: %s", path, strerror(errno));
            return -1;
        }
        if (!S_ISREG(st.st_mode) || (long long)st.st_size < r->resume_sizes[k]) {
            snprintf(err, err_len,
                     "%s holds %lld bytes, fewer than the %lld the checkpoint recorded (not the "
                     "run that wrote the checkpoint?)",
                     path, (long long)st.st_size, r->resume_sizes[k]);
            return -1;
        }
    }
    return 0;
}
