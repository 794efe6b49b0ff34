/* csv_read: reading back the CSV files that io/csv.c writes (its quoting: a field holding a
 * comma or a quote is quoted, a quote doubled), far enough to summarise each column: how many
 * values, their range, whether any is not zero. `vcsph plot` decides from it which plots and
 * curves have data. */
#ifndef VCSPH_CSV_READ_H
#define VCSPH_CSV_READ_H

#include <stdbool.h>

typedef struct {
    char *name;
    long n_values; /* numeric cells (an empty cell is a quantity not computed) */
    bool nonzero;  /* some value differs from 0 */
    double first, min, max;
} column_summary;

typedef struct {
    bool present; /* the file could be opened */
    long n_rows;
    int n_cols;
    column_summary *cols;
} csv_summary;

/* Called with the fields of every data row, for what a summary does not keep. */
typedef void row_hook(void *ctx, const csv_summary *s, char **fields, int n_fields);

/* Splits one CSV line in place into at most max fields, removing the quotes of quoted fields
 * (events.csv quotes details that hold commas). Returns the number of fields. */
int csv_split_fields(char *line, char **fields, int max);
/* Reads the header row and summarises the data rows, calling hook (if not NULL) with the
 * fields of each. Returns 0; -1 with errno when the file cannot be opened or read
 * (s->present tells which). */
int csv_summary_read(const char *path, csv_summary *s, row_hook *hook, void *ctx);
void csv_summary_free(csv_summary *s);
/* The index of the column named `name`, -1 when there is none. */
int csv_summary_column(const csv_summary *s, const char *name);
/* The column named `name`, NULL when the file lacks it or has no value in it. */
const column_summary *csv_summary_values(const csv_summary *s, const char *name);

#endif
