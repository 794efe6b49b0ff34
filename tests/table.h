/* table: reads a CSV file with a header row into columns of doubles (empty cells: NaN), for
 * the integration tests. */
#ifndef VCSPH_TEST_TABLE_H
#define VCSPH_TEST_TABLE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TABLE_MAX_COLUMNS 64

typedef struct {
    int n_columns;
    size_t n_rows;
    char names[TABLE_MAX_COLUMNS][32];
    double *column[TABLE_MAX_COLUMNS];
} table;

static inline int table_read(table *t, const char *path)
{
    memset(t, 0, sizeof *t);
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    char line[8192];
    if (!fgets(line, sizeof line, f)) {
        fclose(f);
        return -1;
    }
    line[strcspn(line, "\r\n")] = '\0';
    for (char *tok = line, *next; tok && t->n_columns < TABLE_MAX_COLUMNS; tok = next) {
        next = strchr(tok, ',');
        if (next) *next++ = '\0';
        size_t len = strlen(tok) < sizeof t->names[0] ? strlen(tok) : sizeof t->names[0] - 1;
        memcpy(t->names[t->n_columns], tok, len);
        t->names[t->n_columns++][len] = '\0';
    }
    size_t cap = 0;
    while (fgets(line, sizeof line, f)) {
        if (t->n_rows == cap) {
            cap = cap ? 2 * cap : 256;
            for (int c = 0; c < t->n_columns; c++)
                t->column[c] = realloc(t->column[c], cap * sizeof(double));
        }
        char *s = line;
        for (int c = 0; c < t->n_columns; c++) {
            char *end;
            double v = strtod(s, &end);
            t->column[c][t->n_rows] = end == s ? NAN : v;
            s = strchr(s, ',');
            s = s ? s + 1 : (char *)"";
        }
        t->n_rows++;
    }
    fclose(f);
    return 0;
}

/* The column named `name`, or NULL. */
static inline const double *table_column(const table *t, const char *name)
{
    for (int c = 0; c < t->n_columns; c++)
        if (!strcmp(t->names[c], name)) return t->column[c];
    return NULL;
}

static inline void table_free(table *t)
{
    for (int c = 0; c < t->n_columns; c++) free(t->column[c]);
    memset(t, 0, sizeof *t);
}

#endif
