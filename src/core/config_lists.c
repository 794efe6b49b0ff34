/* config_lists: the list-valued keys of the case file (core/config_lists.h), and the wall a
 * pressure point lies on. */
#include "core/config_lists.h"
#include "core/decimal.h"

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Reads one number of a list; `seps` are the characters that may follow it. */
static bool list_number(const ini_key *k, const char **p, const char *seps, double *v, char *why,
                        size_t n)
{
    char *end;
    *v = decimal_strtod(*p, &end);
    if (end == *p || !isfinite(*v) ||
        (*end && !isspace((unsigned char)*end) && !strchr(seps, *end))) {
        char stop[16];
        snprintf(stop, sizeof stop, " \t%s", seps);
        int len = (int)strcspn(*p, stop);
        if (len == 0)
            snprintf(why, n, "unexpected '%c'; must be %s", **p, k->allowed);
        else
            snprintf(why, n, "'%.*s' is not a finite decimal number; must be %s",
                     len > 40 ? 40 : len, *p, k->allowed);
        return false;
    }
    *p = ini_skip_space(end);
    return true;
}

/* Past a list's separator `sep` at *p and the spaces after it, which must be followed by
 * another item (`what`); false with the reason in why at the list's end. */
static bool skip_separator(const ini_key *k, const char **p, char sep, const char *what, char *why,
                           size_t n)
{
    if (**p != sep) return true;
    *p = ini_skip_space(*p + 1);
    if (**p) return true;
    snprintf(why, n, "a '%c' must be followed by %s; must be %s", sep, what, k->allowed);
    return false;
}

bool config_set_gauges(ini_session *ctx, const ini_key *k, const char *s, char *why, size_t n)
{
    double x[CONFIG_PROBES_MAX];
    int count = 0;
    for (const char *p = ini_skip_space(s); *p;) {
        if (count == CONFIG_PROBES_MAX) {
            snprintf(why, n, "more than %d gauges", CONFIG_PROBES_MAX);
            return false;
        }
        if (!list_number(k, &p, ",", &x[count++], why, n)) return false;
        if (!skip_separator(k, &p, ',', "a position", why, n)) return false;
    }
    config *cfg = ini_target(ctx);
    memset(cfg->gauges, 0, sizeof cfg->gauges);
    memcpy(cfg->gauges, x, (size_t)count * sizeof x[0]);
    cfg->n_gauges = count;
    return true;
}

/* Points "x y[ z][ d=D]; ...": 2 or 3 coordinates each, the same number for all, and an
 * optional diameter D >= 0 of a transducer (where it sits is checked with the tank); whether
 * the number of coordinates matches case.dim is checked once dim is final. */
bool config_set_points(ini_session *ctx, const ini_key *k, const char *s, char *why, size_t n)
{
    double pts[CONFIG_PROBES_MAX][4] = {{0}};
    int count = 0, coords = 0;
    const char *p = ini_skip_space(s);
    while (*p) {
        if (count == CONFIG_PROBES_MAX) {
            snprintf(why, n, "more than %d pressure probes", CONFIG_PROBES_MAX);
            return false;
        }
        int c = 0;
        while (*p && *p != ';') {
            if (strncmp(p, "d=", 2) == 0 && c >= 2) {
                p += 2;
                if (!list_number(k, &p, ";", &pts[count][3], why, n)) return false;
                if (pts[count][3] < 0.0 || (*p && *p != ';')) {
                    snprintf(why, n,
                             "point %d: the diameter must be a length >= 0 (m) after "
                             "the coordinates; must be %s",
                             count + 1, k->allowed);
                    return false;
                }
                break;
            }
            if (c == 3) {
                snprintf(why, n, "point %d has more than 3 coordinates; must be %s", count + 1,
                         k->allowed);
                return false;
            }
            if (!list_number(k, &p, ";", &pts[count][c++], why, n)) return false;
        }
        if (c < 2 || (coords && c != coords)) {
            snprintf(why, n, "point %d has %d coordinates%s; must be %s", count + 1, c,
                     coords && c != coords ? ", unlike point 1" : "", k->allowed);
            return false;
        }
        coords = c;
        count++;
        if (!skip_separator(k, &p, ';', "a point", why, n)) return false;
    }
    config *cfg = ini_target(ctx);
    memcpy(cfg->pressure_probes, pts, sizeof pts);
    cfg->n_pressure_probes = count;
    ((case_reading *)ini_user(ctx))->point_coords = coords;
    return true;
}

/* Appends prefix and the number v to buf (size bytes, `used` of them taken). False when the
 * text cannot be formatted; a full buffer leaves *used >= size, which ends the callers' loops. */
static bool append_number(char *buf, size_t size, size_t *used, const char *prefix, double v)
{
    char num[32];
    ini_format_double(v, num, sizeof num);
    int w = snprintf(buf + *used, size - *used, "%s%s", prefix, num);
    if (w < 0) return false;
    *used += (size_t)w;
    return true;
}

/* n numbers separated by `sep` into buf. */
static void format_numbers(const double *v, int n, const char *sep, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < n && used < size; i++)
        if (!append_number(buf, size, &used, i ? sep : "", v[i])) return;
}

void config_format_gauges(const void *target, const ini_key *k, char *buf, size_t size)
{
    (void)k;
    const config *cfg = target;
    format_numbers(cfg->gauges, cfg->n_gauges, ", ", buf, size);
}

/* No space before ';': in INI " ;" starts a comment. */
void config_format_point_list(const config *cfg, int coords, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < cfg->n_pressure_probes && used < size; i++) {
        const double *x = cfg->pressure_probes[i];
        for (int d = 0; d < coords && d < 3 && used < size; d++)
            if (!append_number(buf, size, &used, d ? " " : i ? "; " : "", x[d])) return;
        if (x[3] > 0.0 && used < size && !append_number(buf, size, &used, " d=", x[3])) return;
    }
}

void config_format_points(const void *target, const ini_key *k, char *buf, size_t size)
{
    (void)k;
    const config *cfg = target;
    config_format_point_list(cfg, cfg->dim, buf, size);
}

/* "x y[ z]": the rotation axis's point; z is filled in by resolve_defaults when absent. */
bool config_set_center(ini_session *ctx, const ini_key *k, const char *s, char *why, size_t n)
{
    double x[3] = {0.0, 0.0, NAN};
    int c = 0;
    for (const char *p = ini_skip_space(s); *p; c++) {
        if (c == 3) {
            snprintf(why, n, "more than 3 coordinates; must be %s", k->allowed);
            return false;
        }
        if (!list_number(k, &p, "", &x[c], why, n)) return false;
    }
    if (c < 2) {
        snprintf(why, n, "%d coordinate%s; must be %s", c, c == 1 ? "" : "s", k->allowed);
        return false;
    }
    memcpy(((config *)ini_target(ctx))->motion_center, x, sizeof x);
    return true;
}

void config_format_center(const void *target, const ini_key *k, char *buf, size_t size)
{
    (void)k;
    const config *cfg = target;
    format_numbers(cfg->motion_center, cfg->dim, " ", buf, size);
}

int config_wall_axis(const config *cfg, const double x[3])
{
    const double size[3] = {cfg->tank_length, cfg->tank_height, cfg->tank_width};
    int axis = -1;
    for (int d = 0; d < cfg->dim; d++) {
        /* on the wall to round-off of the tank's size, as a value typed in a case file is */
        double tolerance = 1e-12 * size[d];
        if (fabs(x[d]) > tolerance && fabs(x[d] - size[d]) > tolerance) continue;
        if (axis != -1) return -2;
        axis = d;
    }
    return axis;
}
