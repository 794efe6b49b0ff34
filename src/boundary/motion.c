/* motion: sway, heave, decay, phase, duration, and tabulated motion (theory §6). */
#include "boundary/motion.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Displacement s(t) = A e^{-lt} f(wt + phase), its first and second derivatives, for
 * f = sin (sway) or f = -cos (heave). With theta = wt + phase and E = A e^{-lt}:
 *   sway:  x = E sin(theta),  x' = E (w cos - l sin),  x'' = E [(l^2 - w^2) sin - 2 l w cos]
 *   heave: y = -E cos(theta), y' = E (l cos + w sin),  y'' = E [(w^2 - l^2) cos - 2 l w sin] */
static void harmonic(const motion *mo, double t, double *pos, double *vel, double *acc)
{
    double w = mo->omega, l = mo->decay;
    double e = mo->amplitude * exp(-l * t);
    double th = w * t + mo->phase, s = sin(th), c = cos(th);
    if (mo->kind == MOTION_SWAY) {
        *pos = e * s;
        *vel = e * (w * c - l * s);
        *acc = e * ((l * l - w * w) * s - 2.0 * l * w * c);
    } else {
        *pos = -e * c;
        *vel = e * (l * c + w * s);
        *acc = e * ((w * w - l * l) * c - 2.0 * l * w * s);
    }
}

/* Index k with t[k] <= t < t[k+1] (clamped), by bisection. */
static size_t knot_interval(const motion *mo, double t)
{
    size_t lo = 0, hi = mo->n_knots - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (mo->t[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

static int in_motion(const motion *mo, double t)
{
    if (mo->kind == MOTION_NONE) return 0;
    if (mo->duration > 0.0 && t > mo->duration) return 0;
    if (mo->kind == MOTION_TABLE) return t >= mo->t[0] && t <= mo->t[mo->n_knots - 1];
    return 1;
}

void motion_acceleration(const motion *mo, double t, double a[3])
{
    a[0] = a[1] = a[2] = 0.0;
    if (!in_motion(mo, t)) return;
    if (mo->kind == MOTION_TABLE) {
        /* the spline's second derivative is linear between knots */
        size_t k = knot_interval(mo, t);
        double w = (t - mo->t[k]) / (mo->t[k + 1] - mo->t[k]);
        for (int d = 0; d < 3; d++) a[d] = (1.0 - w) * mo->acc[d][k] + w * mo->acc[d][k + 1];
        return;
    }
    double pos, vel;
    harmonic(mo, t, &pos, &vel, &a[mo->kind == MOTION_SWAY ? 0 : 1]);
}

tank_frame motion_frame(const motion *mo, double gravity, double t)
{
    tank_frame f = {.gravity = {0.0, -gravity, 0.0}, .rotating = false};
    motion_acceleration(mo, t, f.origin_acc);
    return f;
}

/* Displacement and velocity without the `duration` cut; a table's ends hold still. */
static void state_at(const motion *mo, double t, double x[3], double v[3])
{
    for (int d = 0; d < 3; d++) x[d] = v[d] = 0.0;
    if (mo->kind == MOTION_NONE) return;
    if (mo->kind == MOTION_TABLE) {
        if (t <= mo->t[0] || t >= mo->t[mo->n_knots - 1]) {
            size_t k = t <= mo->t[0] ? 0 : mo->n_knots - 1;
            for (int d = 0; d < 3; d++) x[d] = mo->pos[d][k];
            return;
        }
        /* the cubic spline between knots k and k+1, and its derivative */
        size_t k = knot_interval(mo, t);
        double hk = mo->t[k + 1] - mo->t[k];
        double b = (t - mo->t[k]) / hk, a = 1.0 - b;
        for (int d = 0; d < 3; d++) {
            const double *y = mo->pos[d], *y2 = mo->acc[d];
            x[d] = a * y[k] + b * y[k + 1] +
                   ((a * a * a - a) * y2[k] + (b * b * b - b) * y2[k + 1]) * hk * hk / 6.0;
            v[d] = (y[k + 1] - y[k]) / hk +
                   (-(3.0 * a * a - 1.0) * y2[k] + (3.0 * b * b - 1.0) * y2[k + 1]) * hk / 6.0;
        }
        return;
    }
    int axis = mo->kind == MOTION_SWAY ? 0 : 1;
    double acc;
    harmonic(mo, t, &x[axis], &v[axis], &acc);
}

void motion_position(const motion *mo, double t, double x[3])
{
    double d = mo->duration, v[3];
    if (!(d > 0.0 && t > d)) {
        state_at(mo, t, x, v);
        return;
    }
    /* after `duration` the acceleration is zero: the tank goes on at the velocity it had */
    state_at(mo, d, x, v);
    for (int k = 0; k < 3; k++) x[k] += v[k] * (t - d);
}

double motion_max_effective_gravity(const motion *mo, double gravity, double t_end)
{
    double horizon = t_end;
    if (mo->kind == MOTION_NONE) return gravity;
    if (mo->kind != MOTION_TABLE && mo->decay == 0.0) {
        double period = 2.0 * M_PI / mo->omega;
        if (horizon > period) horizon = period;
    }
    const int samples = 20000;
    double g_max = gravity;
    for (int k = 0; k <= samples; k++) {
        double a[3];
        motion_acceleration(mo, horizon * k / samples, a);
        double gx = -a[0], gy = -gravity - a[1], gz = -a[2];
        double g = sqrt(gx * gx + gy * gy + gz * gz);
        if (g > g_max) g_max = g;
    }
    return g_max;
}

/* Calls visit(x, v, ctx) at the table's knots and 15 points between each two, over
   [t[0], min(t_end, duration, t[n-1])]: the samples of the table's speed and range. */
static void sample_table(const motion *mo, double t_end,
                         void (*visit)(const double x[3], const double v[3], void *ctx), void *ctx)
{
    double stop = t_end;
    if (mo->duration > 0.0 && mo->duration < stop) stop = mo->duration;
    for (size_t k = 0; k + 1 < mo->n_knots && mo->t[k] <= stop; k++)
        for (int j = 0; j <= 16; j++) {
            double t = mo->t[k] + (mo->t[k + 1] - mo->t[k]) * j / 16.0, x[3], v[3];
            if (t > stop) t = stop;
            /* state_at holds the ends still: sample just inside the last interval */
            if (t >= mo->t[mo->n_knots - 1]) t = nextafter(mo->t[mo->n_knots - 1], 0.0);
            state_at(mo, t, x, v);
            visit(x, v, ctx);
        }
}

static void keep_speed(const double x[3], const double v[3], void *ctx)
{
    (void)x;
    double s = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), *most = ctx;
    if (s > *most) *most = s;
}

double motion_max_speed(const motion *mo, double t_end)
{
    if (mo->kind == MOTION_NONE) return 0.0;
    if (mo->kind != MOTION_TABLE)
        return fabs(mo->amplitude) * sqrt(mo->omega * mo->omega + mo->decay * mo->decay);
    double most = 0.0;
    sample_table(mo, t_end, keep_speed, &most);
    return most;
}

static void keep_range(const double x[3], const double v[3], void *ctx)
{
    (void)v;
    double(*range)[3] = ctx; /* range[0]: lowest, range[1]: highest */
    for (int d = 0; d < 3; d++) {
        if (x[d] < range[0][d]) range[0][d] = x[d];
        if (x[d] > range[1][d]) range[1][d] = x[d];
    }
}

void motion_max_excursion(const motion *mo, double t_end, double out[3])
{
    out[0] = out[1] = out[2] = 0.0;
    if (mo->kind == MOTION_NONE) return;
    if (mo->kind != MOTION_TABLE) {
        out[mo->kind == MOTION_SWAY ? 0 : 1] = fabs(mo->amplitude);
        return;
    }
    double range[2][3] = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    sample_table(mo, t_end, keep_range, range);
    for (int d = 0; d < 3; d++)
        out[d] = range[1][d] >= range[0][d] ? 0.5 * (range[1][d] - range[0][d]) : 0.0;
}

/* Natural cubic spline: second derivatives y2 of y(t) at the knots (tridiagonal solve). */
static int spline_second_derivatives(const double *t, const double *y, size_t n, double *y2)
{
    double *c = malloc(n * sizeof *c);
    if (!c) return -1;
    y2[0] = c[0] = 0.0;
    for (size_t k = 1; k + 1 < n; k++) {
        double sig = (t[k] - t[k - 1]) / (t[k + 1] - t[k - 1]);
        double p = sig * y2[k - 1] + 2.0;
        y2[k] = (sig - 1.0) / p;
        double rhs = (y[k + 1] - y[k]) / (t[k + 1] - t[k]) - (y[k] - y[k - 1]) / (t[k] - t[k - 1]);
        c[k] = (6.0 * rhs / (t[k + 1] - t[k - 1]) - sig * c[k - 1]) / p;
    }
    y2[n - 1] = 0.0;
    for (size_t k = n - 1; k-- > 0;) y2[k] = y2[k] * y2[k + 1] + c[k];
    free(c);
    return 0;
}

static int append_knot(motion *mo, size_t *cap, const double v[4])
{
    if (mo->n_knots == *cap) {
        size_t n = *cap ? 2 * *cap : 256;
        double *t = realloc(mo->t, n * sizeof *t);
        if (!t) return -1;
        mo->t = t;
        for (int d = 0; d < 3; d++) {
            double *p = realloc(mo->pos[d], n * sizeof *p);
            if (!p) return -1;
            mo->pos[d] = p;
        }
        *cap = n;
    }
    mo->t[mo->n_knots] = v[0];
    for (int d = 0; d < 3; d++) mo->pos[d][mo->n_knots] = v[d + 1];
    mo->n_knots++;
    return 0;
}

/* CSV with header t,x,y[,z]; positions in m. From the text, if given, else from the file
 * `path` (named in the messages either way). */
static int read_table(motion *mo, const char *path, const char *text, char *err, size_t err_len)
{
    FILE *f = text ? fmemopen((void *)text, strlen(text), "r") : fopen(path, "r");
    if (!f) {
        snprintf(err, err_len, "%s: cannot open motion table: %s", path, strerror(errno));
        return 2;
    }
    char line[4096];
    size_t cap = 0, lineno = 0;
    int status = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        if (lineno == 1 || line[0] == '#' || line[0] == '\n') continue; /* header */
        double v[4] = {0, 0, 0, 0};
        int n = sscanf(line, "%lf ,%lf ,%lf ,%lf", &v[0], &v[1], &v[2], &v[3]);
        if (n < 3) {
            snprintf(err, err_len, "%s:%zu: expected t,x,y[,z] (numbers, m and s)", path, lineno);
            status = 2;
            break;
        }
        if (mo->n_knots > 0 && !(v[0] > mo->t[mo->n_knots - 1])) {
            snprintf(err, err_len, "%s:%zu: times must increase", path, lineno);
            status = 2;
            break;
        }
        if (append_knot(mo, &cap, v)) {
            snprintf(err, err_len, "%s: out of memory", path);
            status = 2;
            break;
        }
    }
    fclose(f);
    if (status == 0 && mo->n_knots < 4) {
        snprintf(err, err_len, "%s: a motion table needs at least 4 rows", path);
        status = 2;
    }
    for (int d = 0; status == 0 && d < 3; d++) {
        mo->acc[d] = malloc(mo->n_knots * sizeof(double));
        if (!mo->acc[d] || spline_second_derivatives(mo->t, mo->pos[d], mo->n_knots, mo->acc[d])) {
            snprintf(err, err_len, "%s: out of memory", path);
            status = 2;
        }
    }
    return status;
}

int motion_init(motion *mo, const config *cfg, char *err, size_t err_len)
{
    memset(mo, 0, sizeof *mo);
    mo->kind = cfg->motion;
    mo->amplitude = cfg->amplitude;
    mo->omega = cfg->period > 0.0 ? 2.0 * M_PI / cfg->period : 0.0;
    mo->decay = cfg->decay;
    mo->phase = cfg->phase;
    mo->duration = cfg->duration;
    if (mo->kind != MOTION_TABLE) return 0;
    int status = read_table(mo, cfg->motion_file, cfg->motion_table, err, err_len);
    if (status) motion_free(mo);
    return status;
}

void motion_free(motion *mo)
{
    free(mo->t);
    for (int d = 0; d < 3; d++) {
        free(mo->pos[d]);
        free(mo->acc[d]);
    }
    memset(mo, 0, sizeof *mo);
}
