/* csv_read: the reader of io/csv.c's files, column summaries. */
#include "io/csv_read.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Splits one CSV line in place into at most max fields, removing the quotes of quoted fields
 * (events.csv quotes details that hold commas). Returns the number of fields. */
int csv_split_fields(char *line, char **fields, int max)
{
    line[strcspn(line, "\r\n")] = '\0';
    int n = 0;
    char *p = line;
    for (;;) {
        char *out = p, *field = p;
        bool quoted = *p == '"';
        if (quoted) p++;
        while (*p && (quoted || *p != ',')) {
            if (quoted && *p == '"') {
                if (p[1] != '"') { /* closing quote */
                    quoted = false;
                    p++;
                    continue;
                }
                p++; /* "" stands for one quote */
            }
            *out++ = *p++;
        }
        bool more = *p == ',';
        *out = '\0';
        if (n < max) fields[n++] = field;
        if (!more) return n;
        p++;
    }
}

void csv_summary_free(csv_summary *s)
{
    for (int k = 0; k < s->n_cols; k++) free(s->cols[k].name);
    free(s->cols);
    memset(s, 0, sizeof *s);
}

int csv_summary_column(const csv_summary *s, const char *name)
{
    for (int k = 0; k < s->n_cols; k++)
        if (!strcmp(s->cols[k].name, name)) return k;
    return -1;
}

/* The column named `name`, NULL when the file lacks it or has no value in it. */
const column_summary *csv_summary_values(const csv_summary *s, const char *name)
{
    int k = csv_summary_column(s, name);
    return k >= 0 && s->cols[k].n_values > 0 ? &s->cols[k] : NULL;
}

static int csv_summary_header(csv_summary *s, char *line)
{
    int max = (int)strlen(line) + 1; /* no more fields than characters */
    char **fields = malloc((size_t)max * sizeof *fields);
    if (!fields) return -1;
    int n = csv_split_fields(line, fields, max);
    s->cols = calloc((size_t)n + 1, sizeof *s->cols); /* + 1: never calloc(0) */
    int status = s->cols ? 0 : -1;
    for (int k = 0; k < n && !status; k++) {
        s->cols[k].name = strdup(fields[k]);
        if (!s->cols[k].name) status = -1;
        s->n_cols = k + 1;
    }
    free(fields);
    return status;
}

static void csv_summary_add(csv_summary *s, char **fields, int n_fields)
{
    for (int k = 0; k < n_fields && k < s->n_cols; k++) {
        char *end;
        double v = strtod(fields[k], &end);
        /* empty, text, or nan/inf that gnuplot would not draw either */
        if (end == fields[k] || *end || !isfinite(v)) continue;
        column_summary *c = &s->cols[k];
        if (c->n_values++ == 0) c->first = c->min = c->max = v;
        c->min = v < c->min ? v : c->min;
        c->max = v > c->max ? v : c->max;
        c->nonzero |= v != 0.0;
    }
    s->n_rows++;
}

/* Reads the header row and summarises the data rows. Returns 0; -1 with errno when the file
 * cannot be opened or read (s->present tells which). */
int csv_summary_read(const char *path, csv_summary *s, row_hook *hook, void *ctx)
{
    memset(s, 0, sizeof *s);
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    s->present = true;
    char *line = NULL, **fields = NULL;
    size_t cap = 0;
    int status = 0;
    if (getline(&line, &cap, f) > 0) status = csv_summary_header(s, line);
    if (!status) fields = malloc((size_t)(s->n_cols + 1) * sizeof *fields);
    if (!fields) status = -1;
    while (!status && getline(&line, &cap, f) > 0) {
        if (line[strspn(line, "\r\n")] == '\0') continue; /* blank line */
        int n = csv_split_fields(line, fields, s->n_cols + 1);
        csv_summary_add(s, fields, n);
        if (hook) hook(ctx, s, fields, n);
    }
    if (ferror(f)) status = -1;
    int saved = errno;
    free(fields);
    free(line);
    fclose(f);
    errno = saved;
    return status;
}
