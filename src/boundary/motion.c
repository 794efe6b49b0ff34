/* motion: sway, heave, roll, pitch, yaw, their decay, phase and duration, and tabulated motion
 * (theory §6). */
#include "boundary/motion.h"
#include "core/decimal.h"
#include "core/suggest.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Displacement s(t) = A e^{-lt} f(wt + phase), its first and second derivatives, for
 * f = sin (sway, and every rotation) or f = -cos (heave). With theta = wt + phase and
 * E = A e^{-lt}:
 *   sin:  x = E sin(theta),  x' = E (w cos - l sin),  x'' = E [(l^2 - w^2) sin - 2 l w cos]
 *   -cos: y = -E cos(theta), y' = E (l cos + w sin),  y'' = E [(w^2 - l^2) cos - 2 l w sin] */
static void harmonic(const motion *mo, int channel, double t, double *pos, double *vel, double *acc)
{
    bool rotation = channel == mo->rotation;
    double w = mo->omega, l = mo->decay;
    double e = (rotation ? mo->angle : mo->amplitude) * exp(-l * t);
    double th = w * t + (rotation ? mo->phase + mo->angle_phase : mo->phase);
    double s = sin(th), c = cos(th);
    if (rotation || mo->kind == MOTION_SWAY || mo->kind == MOTION_SWAY_ROLL) {
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

static bool driven(const motion *mo, int channel)
{
    if (mo->kind == MOTION_TABLE) return mo->pos[channel] != NULL;
    return channel == mo->translation || channel == mo->rotation;
}

static int in_motion(const motion *mo, double t)
{
    if (mo->kind == MOTION_NONE) return 0;
    if (mo->duration > 0.0 && t > mo->duration) return 0;
    if (mo->kind == MOTION_TABLE) return t >= mo->t[0] && t <= mo->t[mo->n_knots - 1];
    return 1;
}

/* Second derivative of one channel at t (zero after `duration` and outside a table). */
static double channel_acceleration(const motion *mo, int channel, double t)
{
    if (!driven(mo, channel) || !in_motion(mo, t)) return 0.0;
    if (mo->kind == MOTION_TABLE) { /* the spline's second derivative is linear between knots */
        size_t k = knot_interval(mo, t);
        double w = (t - mo->t[k]) / (mo->t[k + 1] - mo->t[k]);
        return (1.0 - w) * mo->acc[channel][k] + w * mo->acc[channel][k + 1];
    }
    double pos, vel, acc;
    harmonic(mo, channel, t, &pos, &vel, &acc);
    return acc;
}

void motion_acceleration(const motion *mo, double t, double a[3])
{
    for (int d = 0; d < 3; d++) a[d] = channel_acceleration(mo, d, t);
}

/* Value and rate of one channel without the `duration` cut; a table's ends hold still. */
static void channel_state(const motion *mo, int channel, double t, double *x, double *v)
{
    *x = *v = 0.0;
    if (!driven(mo, channel)) return;
    if (mo->kind != MOTION_TABLE) {
        double acc;
        harmonic(mo, channel, t, x, v, &acc);
        return;
    }
    const double *y = mo->pos[channel], *y2 = mo->acc[channel];
    if (t <= mo->t[0] || t >= mo->t[mo->n_knots - 1]) {
        *x = y[t <= mo->t[0] ? 0 : mo->n_knots - 1];
        return;
    }
    /* the cubic spline between knots k and k+1, and its derivative */
    size_t k = knot_interval(mo, t);
    double hk = mo->t[k + 1] - mo->t[k];
    double b = (t - mo->t[k]) / hk, a = 1.0 - b;
    *x = a * y[k] + b * y[k + 1] +
         ((a * a * a - a) * y2[k] + (b * b * b - b) * y2[k + 1]) * hk * hk / 6.0;
    *v = (y[k + 1] - y[k]) / hk +
         (-(3.0 * a * a - 1.0) * y2[k] + (3.0 * b * b - 1.0) * y2[k + 1]) * hk / 6.0;
}

/* Value and rate with the cut: after `duration` the channel goes on at the rate it had. */
static void channel_at(const motion *mo, int channel, double t, double *x, double *v)
{
    double d = mo->duration;
    if (!(d > 0.0 && t > d)) {
        channel_state(mo, channel, t, x, v);
        return;
    }
    channel_state(mo, channel, d, x, v);
    *x += *v * (t - d);
}

void motion_position(const motion *mo, double t, double x[3])
{
    for (int d = 0; d < 3; d++) {
        double v;
        channel_at(mo, d, t, &x[d], &v);
    }
}

void motion_angles(const motion *mo, double t, double q[3], double q_dot[3], double q_ddot[3])
{
    for (int k = 0; k < 3; k++) {
        channel_at(mo, MOTION_ROLL_ANGLE + k, t, &q[k], &q_dot[k]);
        q_ddot[k] = channel_acceleration(mo, MOTION_ROLL_ANGLE + k, t);
    }
}

/* ---- the orientation R = R_y(yaw) R_x(pitch) R_z(roll) and its rates -------------------- */

/* The rotation by `angle` about the coordinate axis `axis` (right-handed). */
static void axis_rotation(int axis, double angle, double r[3][3])
{
    int a = (axis + 1) % 3, b = (axis + 2) % 3;
    double c = cos(angle), s = sin(angle);
    memset(r, 0, 9 * sizeof(double));
    r[axis][axis] = 1.0;
    r[a][a] = c, r[a][b] = -s;
    r[b][a] = s, r[b][b] = c;
}

static void mat_mul(double a[3][3], double b[3][3], double out[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
}

/* The chain of elementary rotations about the axes a_k = R_1 ... R_{k-1} e_k, with angles q_k,
 * has the angular velocity w = sum q_k' a_k and, since a_k' = w_{<k} x a_k with w_{<k} the
 * velocity of the rotations before k, the angular acceleration
 * w' = sum (q_k'' a_k + q_k' w_{<k} x a_k) (inertial axes). */
static void orientation(const double q[3], const double q_dot[3], const double q_ddot[3],
                        double r[3][3], double w[3], double w_dot[3])
{
    /* chain order yaw (y), pitch (x), roll (z); q holds roll, pitch, yaw */
    static const int axis[3] = {1, 0, 2}, angle_of[3] = {2, 1, 0};
    double chain[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int d = 0; d < 3; d++) w[d] = w_dot[d] = 0.0;
    for (int k = 0; k < 3; k++) {
        int a = axis[k], n = angle_of[k];
        double ak[3] = {chain[0][a], chain[1][a], chain[2][a]}, turn[3];
        frame_cross(w, ak, turn); /* w is w_{<k} here */
        for (int d = 0; d < 3; d++) {
            w_dot[d] += q_ddot[n] * ak[d] + q_dot[n] * turn[d];
            w[d] += q_dot[n] * ak[d];
        }
        double rk[3][3], next[3][3];
        axis_rotation(a, q[n], rk);
        mat_mul(chain, rk, next);
        memcpy(chain, next, sizeof chain);
    }
    memcpy(r, chain, sizeof chain);
}

/* The orientation and its rates at time t, from the motion's angles. */
static void orientation_at(const motion *mo, double t, double r[3][3], double w[3], double w_dot[3])
{
    double q[3], q_dot[3], q_ddot[3];
    motion_angles(mo, t, q, q_dot, q_ddot);
    orientation(q, q_dot, q_ddot, r, w, w_dot);
}

void motion_rotation(const motion *mo, double t, double r[3][3])
{
    double w[3], w_dot[3];
    orientation_at(mo, t, r, w, w_dot);
}

tank_frame motion_frame(const motion *mo, double gravity, double t)
{
    tank_frame f = {.gravity = {0.0, -gravity, 0.0}, .rotating = false};
    if (mo->duration > 0.0 && t > mo->duration) f.damping = mo->settling;
    motion_acceleration(mo, t, f.origin_acc);
    memcpy(f.center, mo->center, sizeof f.center);
    if (!mo->rotates) return f;
    double r[3][3], w[3], w_dot[3], a[3], g[3] = {0.0, -gravity, 0.0};
    orientation_at(mo, t, r, w, w_dot);
    memcpy(a, f.origin_acc, sizeof a);
    mat3_apply_transposed(r, g, f.gravity);
    mat3_apply_transposed(r, a, f.origin_acc);
    mat3_apply_transposed(r, w, f.omega);
    mat3_apply_transposed(r, w_dot, f.omega_dot);
    for (int d = 0; d < 3; d++) f.rotating |= f.omega[d] != 0.0 || f.omega_dot[d] != 0.0;
    return f;
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
        double t = horizon * k / samples, g;
        if (mo->rotates) {
            tank_frame f = motion_frame(mo, gravity, t);
            double uniform[3];
            for (int d = 0; d < 3; d++) uniform[d] = f.gravity[d] - f.origin_acc[d];
            double w = vec3_norm(f.omega);
            g = vec3_norm(uniform) + (vec3_norm(f.omega_dot) + w * w) * mo->reach;
        } else {
            double a[3];
            motion_acceleration(mo, t, a);
            double gx = -a[0], gy = -gravity - a[1], gz = -a[2];
            g = sqrt(gx * gx + gy * gy + gz * gz);
        }
        if (g > g_max) g_max = g;
    }
    return g_max;
}

/* Calls visit(x, v, ctx) with the channels' values and rates at the table's knots and 15
   points between each two, over [t[0], min(t_end, duration, t[n-1])]: the samples of the
   table's speed and range. */
static void sample_table(const motion *mo, double t_end,
                         void (*visit)(const double *x, const double *v, void *ctx), void *ctx)
{
    double stop = t_end;
    if (mo->duration > 0.0 && mo->duration < stop) stop = mo->duration;
    for (size_t k = 0; k + 1 < mo->n_knots && mo->t[k] <= stop; k++)
        for (int j = 0; j <= 16; j++) {
            double t = mo->t[k] + (mo->t[k + 1] - mo->t[k]) * j / 16.0;
            double x[MOTION_CHANNELS], v[MOTION_CHANNELS];
            if (t > stop) t = stop;
            /* channel_state holds the ends still: sample just inside the last interval */
            if (t >= mo->t[mo->n_knots - 1]) t = nextafter(mo->t[mo->n_knots - 1], 0.0);
            for (int c = 0; c < MOTION_CHANNELS; c++) channel_state(mo, c, t, &x[c], &v[c]);
            visit(x, v, ctx);
        }
}

typedef struct {
    double reach, most;
} speed_sample;

/* the centre's speed, and the largest rotation speed at the reach (|w| <= sum |q_k'|) */
static void keep_speed(const double *x, const double *v, void *ctx)
{
    (void)x;
    speed_sample *s = ctx;
    double speed = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
                   s->reach * (fabs(v[MOTION_ROLL_ANGLE]) + fabs(v[MOTION_PITCH_ANGLE]) +
                               fabs(v[MOTION_YAW_ANGLE]));
    if (speed > s->most) s->most = speed;
}

double motion_max_speed(const motion *mo, double t_end)
{
    if (mo->kind == MOTION_NONE) return 0.0;
    if (mo->kind != MOTION_TABLE) {
        double rate = sqrt(mo->omega * mo->omega + mo->decay * mo->decay), speed = 0.0;
        if (mo->translation >= 0) speed += fabs(mo->amplitude) * rate;
        if (mo->rotation >= 0) speed += fabs(mo->angle) * rate * mo->reach;
        return speed;
    }
    speed_sample s = {mo->reach, 0.0};
    sample_table(mo, t_end, keep_speed, &s);
    return s.most;
}

static void keep_range(const double *x, const double *v, void *ctx)
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
        if (mo->translation >= 0) out[mo->translation] = fabs(mo->amplitude);
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

/* A table's column names: t, then the channels' in their order. */
static const char *const column_names[MOTION_CHANNELS + 1] = {"t",    "x",     "y",  "z",
                                                              "roll", "pitch", "yaw"};
static const char *const *const channel_names = column_names + 1;
#define COLUMNS_SPELLED "t, then any of x, y, z (m) and roll, pitch, yaw (rad)"

/* The table's columns: channel[k] is the channel of column k + 1 (column 0 is t). */
typedef struct {
    int n, channel[MOTION_CHANNELS];
} table_columns;

/* The comma-separated decimal numbers of a line, at most `room`; their count, or -1 when
 * anything else is on the line (a word, an empty field, more than `room` numbers). */
static int line_numbers(const char *line, double *v, int room)
{
    const char *p = line;
    for (int k = 0;; k++) {
        char *end;
        double x = decimal_strtod(p, &end);
        if (end == p || !isfinite(x) || k == room) return -1;
        v[k] = x;
        p = end;
        while (isspace((unsigned char)*p)) p++;
        if (*p == '\0') return k + 1;
        if (*p++ != ',') return -1;
    }
}

/* A header's fields: `t` first, then channel names (exactly as documented, lower case), each
 * at most once. Returns false with a message naming the line and the word otherwise. */
static bool header_columns(const char *header, table_columns *cols, const char *path, size_t lineno,
                           char *err, size_t err_len)
{
    char text[4096];
    snprintf(text, sizeof text, "%s", header);
    cols->n = -1; /* t first */
    int seen = 0;
    char *save = NULL;
    for (char *field = strtok_r(text, ",\r\n", &save); field;
         field = strtok_r(NULL, ",\r\n", &save)) {
        while (isspace((unsigned char)*field)) field++;
        size_t len = strlen(field);
        while (len > 0 && isspace((unsigned char)field[len - 1])) field[--len] = '\0';
        int c = 0;
        while (c <= MOTION_CHANNELS && strcmp(field, column_names[c]) != 0) c++;
        const char *why = NULL;
        if (c > MOTION_CHANNELS)
            why = "is not a column";
        else if ((cols->n < 0) != (c == 0))
            why = c == 0 ? "comes twice" : "comes before t; t must be the first column";
        else if (c > 0 && (seen & (1 << c)))
            why = "comes twice";
        if (why) {
            const char *hint =
                c > MOTION_CHANNELS ? word_suggest(field, column_names, MOTION_CHANNELS + 1) : NULL;
            snprintf(err, err_len, "%s:%zu: motion table header: '%s' %s%s%s%s; the columns are %s",
                     path, lineno, field, why, hint ? " (did you mean '" : "", hint ? hint : "",
                     hint ? "'?)" : "", COLUMNS_SPELLED);
            return false;
        }
        if (c == 0) {
            cols->n = 0;
            continue;
        }
        seen |= 1 << c;
        cols->channel[cols->n++] = c - 1;
    }
    if (cols->n > 0) return true;
    snprintf(err, err_len, "%s:%zu: motion table header: %s; the columns are %s", path, lineno,
             cols->n < 0 ? "empty" : "names t alone", COLUMNS_SPELLED);
    return false;
}

/* A table without a header: a first line of 3 or 4 numbers is t,x,y or t,x,y,z by position. */
static bool positional_columns(int count, table_columns *cols, const char *path, size_t lineno,
                               char *err, size_t err_len)
{
    if (count == 3 || count == 4) {
        *cols = (table_columns){count - 1, {MOTION_X, MOTION_Y, MOTION_Z}};
        return true;
    }
    snprintf(err, err_len,
             "%s:%zu: a motion table without a header has t,x,y or t,x,y,z by position; this "
             "first row has %d number(s): give a header (%s)",
             path, lineno, count, COLUMNS_SPELLED);
    return false;
}

static int append_knot(motion *mo, size_t *cap, const table_columns *cols, const double *v)
{
    if (mo->n_knots == *cap) {
        size_t n = *cap ? 2 * *cap : 256;
        double *t = realloc(mo->t, n * sizeof *t);
        if (!t) return -1;
        mo->t = t;
        for (int k = 0; k < cols->n; k++) {
            int c = cols->channel[k];
            double *p = realloc(mo->pos[c], n * sizeof *p);
            if (!p) return -1;
            mo->pos[c] = p;
        }
        *cap = n;
    }
    mo->t[mo->n_knots] = v[0];
    for (int k = 0; k < cols->n; k++) mo->pos[cols->channel[k]][mo->n_knots] = v[k + 1];
    mo->n_knots++;
    return 0;
}

/* The columns as a header would name them, "t,x,y,roll", into buf. */
static void spell_columns(const table_columns *cols, char *buf, size_t size)
{
    size_t used = (size_t)snprintf(buf, size, "t");
    for (int k = 0; k < cols->n && used < size; k++)
        used += (size_t)snprintf(buf + used, size - used, ",%s", channel_names[cols->channel[k]]);
}

/* The message of a data row that does not hold exactly the columns' numbers. */
static void row_error(const table_columns *cols, bool by_position, const char *path, size_t lineno,
                      char *err, size_t err_len)
{
    char spelled[96];
    spell_columns(cols, spelled, sizeof spelled);
    snprintf(err, err_len, "%s:%zu: expected %d decimal numbers %s (s, m, rad), as %s", path,
             lineno, cols->n + 1, spelled, by_position ? "the first row has" : "the header names");
}

/* CSV whose first line (after blank and `#` lines) is a header, t then any of x,y,z (m) and
 * roll,pitch,yaw (rad), or already a row of 3 or 4 numbers, t,x,y[,z] by position. From the
 * text, if given, else from the file `path` (named in the messages either way). */
static int read_table(motion *mo, const char *path, const char *text, int dim, char *err,
                      size_t err_len)
{
    FILE *f = text ? fmemopen((void *)text, strlen(text), "r") : fopen(path, "r");
    if (!f) {
        snprintf(err, err_len, "%s: cannot open motion table: %s", path, strerror(errno));
        return 2;
    }
    char line[4096];
    size_t cap = 0, lineno = 0;
    int status = 0;
    bool first = true;
    table_columns cols = {0, {0}};
    while (status == 0 && fgets(line, sizeof line, f)) {
        lineno++;
        const char *p = line;
        while (isspace((unsigned char)*p)) p++;
        if (*p == '#' || *p == '\0') continue;
        double v[MOTION_CHANNELS + 1];
        int count = line_numbers(line, v, MOTION_CHANNELS + 1);
        if (first) { /* the header, or the first row of a table without one */
            first = false;
            mo->table_by_position = count > 0;
            bool read = count > 0 ? positional_columns(count, &cols, path, lineno, err, err_len)
                                  : header_columns(line, &cols, path, lineno, err, err_len);
            if (!read) status = 2;
            if (!read || count <= 0) continue;
        }
        if (count != cols.n + 1) {
            row_error(&cols, mo->table_by_position, path, lineno, err, err_len);
            status = 2;
        } else if (mo->n_knots > 0 && !(v[0] > mo->t[mo->n_knots - 1])) {
            snprintf(err, err_len, "%s:%zu: times must increase", path, lineno);
            status = 2;
        } else if (append_knot(mo, &cap, &cols, v)) {
            snprintf(err, err_len, "%s: out of memory", path);
            status = 2;
        }
    }
    fclose(f);
    if (status == 0 && mo->n_knots < 4) {
        snprintf(err, err_len, "%s: a motion table needs at least 4 rows", path);
        status = 2;
    }
    if (status == 0 && dim == 2 && (mo->pos[MOTION_PITCH_ANGLE] || mo->pos[MOTION_YAW_ANGLE])) {
        snprintf(err, err_len,
                 "%s: pitch and yaw turn the tank out of the x-y plane: 3D only (a 2D tank has "
                 "t,x,y,roll)",
                 path);
        status = 2;
    }
    for (int c = 0; status == 0 && c < MOTION_CHANNELS; c++) {
        if (!mo->pos[c]) continue;
        mo->acc[c] = malloc(mo->n_knots * sizeof(double));
        if (!mo->acc[c] || spline_second_derivatives(mo->t, mo->pos[c], mo->n_knots, mo->acc[c])) {
            snprintf(err, err_len, "%s: out of memory", path);
            status = 2;
        }
        if (c >= MOTION_ROLL_ANGLE) mo->rotates = true;
    }
    return status;
}

void motion_table_columns(const motion *mo, char *buf, size_t size)
{
    table_columns cols = {0, {0}};
    for (int c = 0; c < MOTION_CHANNELS; c++)
        if (mo->pos[c]) cols.channel[cols.n++] = c;
    spell_columns(&cols, buf, size);
}

/* Largest distance from the rotation axis's point to a corner of the tank. */
static double reach_of(const config *cfg, const double center[3])
{
    const double size[3] = {cfg->tank_length, cfg->tank_height,
                            cfg->dim == 3 ? cfg->tank_width : center[2]};
    double most = 0.0;
    for (int corner = 0; corner < 8; corner++) {
        double r2 = 0.0;
        for (int d = 0; d < 3; d++) {
            double dx = ((corner >> d) & 1 ? size[d] : 0.0) - center[d];
            r2 += dx * dx;
        }
        if (r2 > most) most = r2;
    }
    return sqrt(most);
}

int motion_init(motion *mo, const config *cfg, char *err, size_t err_len)
{
    memset(mo, 0, sizeof *mo);
    mo->kind = cfg->motion;
    int axis = config_motion_translation_axis(mo->kind), angle = config_motion_rotation(mo->kind);
    mo->translation = axis >= 0 ? MOTION_X + axis : -1;
    mo->rotation = angle >= 0 ? MOTION_ROLL_ANGLE + angle : -1;
    mo->rotates = mo->rotation >= 0;
    mo->amplitude = cfg->amplitude;
    mo->angle = cfg->angle;
    mo->omega = cfg->period > 0.0 ? 2.0 * M_PI / cfg->period : 0.0;
    mo->decay = cfg->decay;
    mo->phase = cfg->phase;
    mo->angle_phase = cfg->angle_phase;
    mo->duration = cfg->duration;
    mo->settling = cfg->settling;
    memcpy(mo->center, cfg->motion_center, sizeof mo->center);
    mo->reach = reach_of(cfg, mo->center);
    if (mo->kind != MOTION_TABLE) return 0;
    int status = read_table(mo, cfg->motion_file, cfg->motion_table, cfg->dim, err, err_len);
    if (status) motion_free(mo);
    return status;
}

void motion_free(motion *mo)
{
    free(mo->t);
    for (int c = 0; c < MOTION_CHANNELS; c++) {
        free(mo->pos[c]);
        free(mo->acc[c]);
    }
    memset(mo, 0, sizeof *mo);
}
