/* run_summary: the end-of-run summary (run_summary.h). */
#include "app/run_summary.h"
#include "core/config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_KINDS = 16, LINE_MAX_BYTES = 16384 };

typedef struct {
    char name[48];
    long count;
} event_kind;

/* The index of `name` among the comma-separated fields of a header line, or -1. */
static int column_of(const char *header, const char *name)
{
    size_t len = strlen(name);
    int k = 0;
    for (const char *s = header; s; k++) {
        if (!strncmp(s, name, len) && (s[len] == ',' || s[len] == '\n' || s[len] == '\0')) return k;
        s = strchr(s, ',');
        if (s) s++;
    }
    return -1;
}

/* Field k of a CSV line as a number (NAN where empty or missing). */
static double field_number(const char *line, int k)
{
    for (int i = 0; i < k && line; i++) {
        line = strchr(line, ',');
        if (line) line++;
    }
    if (!line || *line == ',' || *line == '\n' || *line == '\0') return NAN;
    return strtod(line, NULL);
}

/* The final and the largest |eps_v1| of timeseries.csv, with the time of the largest. */
static int volume_extremes(const char *dir, double *last, double *worst, double *t_worst)
{
    char path[CONFIG_PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/timeseries.csv", dir);
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    static char line[LINE_MAX_BYTES];
    int column = fgets(line, sizeof line, f) ? column_of(line, "eps_v1") : -1;
    *last = *worst = NAN;
    *t_worst = 0.0;
    while (column >= 0 && fgets(line, sizeof line, f)) {
        double e = field_number(line, column);
        if (isnan(e)) continue;
        *last = e;
        if (isnan(*worst) || fabs(e) > fabs(*worst)) {
            *worst = e;
            *t_worst = field_number(line, 0);
        }
    }
    fclose(f);
    return column >= 0 ? 0 : -1;
}

/* How many rows of events.csv name each event (its second field). */
static int count_events(const char *dir, event_kind *kinds, int *n_kinds)
{
    char path[CONFIG_PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/events.csv", dir);
    FILE *f = fopen(path, "r");
    *n_kinds = 0;
    if (!f) return -1;
    static char line[LINE_MAX_BYTES];
    for (int row = 0; fgets(line, sizeof line, f); row++) {
        char *name = strchr(line, ',');
        if (row == 0 || !name) continue; /* the header */
        name++;
        size_t len = strcspn(name, ",\n");
        int k = 0;
        while (k < *n_kinds && (strlen(kinds[k].name) != len || strncmp(kinds[k].name, name, len)))
            k++;
        if (k == *n_kinds) {
            if (k == MAX_KINDS || len >= sizeof kinds[k].name) continue;
            snprintf(kinds[k].name, sizeof kinds[k].name, "%.*s", (int)len, name);
            kinds[k].count = 0;
            ++*n_kinds;
        }
        kinds[k].count++;
    }
    fclose(f);
    return 0;
}

void run_summary(const char *dir, char *text, size_t size)
{
    size_t used = 0;
    text[0] = '\0';
    double last, worst, t_worst;
    if (volume_extremes(dir, &last, &worst, &t_worst) == 0 && !isnan(last))
        used += (size_t)snprintf(text, size,
                                 "vcsph: eps_v1 (Eq. 12): %+.3f %% at the end, largest %+.3f %% "
                                 "at t = %.4g s\n",
                                 100.0 * last, 100.0 * worst, t_worst);
    event_kind kinds[MAX_KINDS];
    int n_kinds;
    if (count_events(dir, kinds, &n_kinds) || used >= size) return;
    long switches = 0;
    for (int k = 0; k < n_kinds; k++)
        if (!strcmp(kinds[k].name, "eta_switch")) switches = kinds[k].count;
    used +=
        (size_t)snprintf(text + used, size - used, "vcsph: eta switches: %ld; events:", switches);
    for (int k = 0; k < n_kinds && used < size; k++)
        used += (size_t)snprintf(text + used, size - used, "%s %s x %ld", k ? "," : "",
                                 kinds[k].name, kinds[k].count);
    if (used < size)
        snprintf(text + used, size - used, "%s (events.csv)\n", n_kinds ? "" : " none");
}
