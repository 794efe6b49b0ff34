/* run_probes: probes.csv, its rows at their own interval (probes.every) and the pressure
 * sensors' bandwidth (probes.filter, diag/sensor_filter.h). Particle code: compiled for DIM =
 * 2 and 3. */
#include "app/run_state.h"
#include "boundary/tank.h"
#include "core/log.h"
#include "diag/probes.h"
#include "io/csv.h"

#include <stdio.h>

void run_probes_start(run *r, char *header, size_t size)
{
    const config *cfg = r->cfg;
    int len = snprintf(header, size, "t");
    for (int k = 0; k < cfg->n_gauges; k++)
        len += snprintf(header + len, size - (size_t)len, ",gauge_%d", k + 1);
    for (int k = 0; k < cfg->n_pressure_probes; k++)
        len += snprintf(header + len, size - (size_t)len, ",pressure_%d", k + 1);
    for (int k = 0; k < cfg->n_gauges; k++)
        len += snprintf(header + len, size - (size_t)len, ",level_%d", k + 1);
    if (cfg->probes_filter != PROBES_RAW)
        for (int k = 0; k < cfg->n_pressure_probes; k++)
            len += snprintf(header + len, size - (size_t)len, ",sensor_%d", k + 1);
    probes_init(&r->probes, r->s.dv.h, r->s.dv.dr, r->s.dv.cell_volume,
                cfg->dim == 3 ? cfg->tank_width : 1.0);
    r->sensor_filter = sensor_filter_make(cfg->probes_filter, cfg->probes_cutoff);
}

/* On a split solver, the liquid and its walls' images as one process holds them, for the
 * probes, on the process that writes: the fluid gathered in the global order into q, its
 * images made again at this state as solver_prepare made them (a process's own images would
 * miss the other processes' and its halo's would count twice). Free q with
 * run_gathered_free. Returns 0, or -1 when out of memory. */
static int rebuild_whole(run *r, particles *q)
{
    solver *s = &r->s;
    run_gather(r, &s->p, RUN_GATHER_PROBES, q);
    if (!team_writes(r->team)) return 0;
    /* room for the images; the fields not gathered get their arrays here */
    size_t n = q->n_fluid;
    if (particles_reserve(q, n + n / 2 + 64) ||
        tank_make_ghosts(&s->tank, q, 2.0 * s->dv.h + s->skin))
        return -1;
    tank_frame frame = solver_frame(s, s->t);
    tank_refresh_ghosts(q, &frame, s->pp.rho0, s->pp.c0);
    return 0;
}

/* The row's values from the liquid p: t, the gauges, the pressure probes (raw), the levels,
 * and with a filter each sensor's filtered signal, fed with this row's raw sample. */
static void put_row(run *r, const particles *p)
{
    const config *cfg = r->cfg;
    csv_file *c = &r->probes_csv;
    double raw[CONFIG_PROBES_MAX];
    csv_put(c, r->s.t);
    for (int k = 0; k < cfg->n_gauges; k++) csv_put(c, probes_gauge(&r->probes, p, cfg->gauges[k]));
    for (int k = 0; k < cfg->n_pressure_probes; k++) {
        const double *x = cfg->pressure_probes[k];
        raw[k] = x[3] > 0.0 ? probes_sensor(&r->probes, p, x, x[3], config_wall_axis(cfg, x))
                            : probes_pressure(&r->probes, p, x);
        csv_put(c, raw[k]);
    }
    for (int k = 0; k < cfg->n_gauges; k++)
        csv_put_number(c, probes_level(&r->probes, p, cfg->gauges[k]));
    if (cfg->probes_filter != PROBES_RAW)
        for (int k = 0; k < cfg->n_pressure_probes; k++)
            csv_put(c, sensor_filter_sample(&r->sensor_filter, &r->sensors[k], r->s.t, raw[k]));
    csv_end_row(c);
}

void run_write_probes_row(run *r)
{
    particles rebuilt;
    const particles *p = &r->s.p;
    int failed = 0;
    if (r->split) {
        failed = rebuild_whole(r, &rebuilt);
        p = &rebuilt;
    }
    if (failed)
        log_error("vcsph: probes: out of memory; probes.csv misses t = %.9g s", r->s.t);
    else if (team_writes(r->team))
        put_row(r, p);
    if (r->split) run_gathered_free(r, &rebuilt);
}

size_t run_probes_state(const run *r, double out[RUN_PROBES_STATE_MAX])
{
    size_t n = 0;
    out[n++] = r->next_probes;
    for (int k = 0; k < r->cfg->n_pressure_probes; k++, n += SENSOR_STATE_VALUES)
        sensor_state_pack(&r->sensors[k], out + n);
    return n;
}

void run_probes_resume(run *r, const double *in)
{
    if (!in) { /* a checkpoint from before probes.every: its rows came with timeseries.csv's */
        r->next_probes = r->next_series;
        return;
    }
    r->next_probes = in[0];
    for (int k = 0; k < r->cfg->n_pressure_probes; k++)
        sensor_state_unpack(&r->sensors[k], in + 1 + (size_t)k * SENSOR_STATE_VALUES);
}
