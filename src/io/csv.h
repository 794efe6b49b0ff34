/* csv: row-by-row CSV writers (timeseries.csv, events.csv), flushed after every row so a
 * crash loses nothing already computed. */
#ifndef VCSPH_CSV_H
#define VCSPH_CSV_H

#include <stdio.h>

typedef struct {
    FILE *f;
    int column; /* columns written in the current row */
    int error;  /* errno of the first row that could not be written (a full disk), or 0 */
} csv_file;

/* Creates the file and writes the header line. Returns 0 or -1. */
int csv_open(csv_file *c, const char *path, const char *header);
/* Opens an existing file to append after its first `size` bytes, dropping the rest (the rows
 * a restart rewinds). Returns 0, or -1 (the file is missing or shorter than size). */
int csv_reopen(csv_file *c, const char *path, long long size);
/* csv_reopen for a run that writes `header`. A file from an older vcsph whose header is this
 * one less columns added since at its end is first rewritten (under a temporary name, then
 * renamed) with this header and those columns empty in its rows ("not computed"). Returns 0,
 * -1 (as csv_reopen) or -2 (a header that is neither; errno EINVAL). */
int csv_reopen_with_header(csv_file *c, const char *path, long long size, const char *header);
void csv_close(csv_file *c);
/* Bytes written so far (every row is flushed), or -1 for a file that is not open. */
long long csv_size(const csv_file *c);
/* fsync: the rows so far reach the disk (before a checkpoint records csv_size). 0 or -1. */
int csv_sync(csv_file *c);
/* The writers of a row; on a file that is not open (f NULL: another process writes it) they
 * do nothing. */
void csv_put(csv_file *c, double value); /* %.10g */
void csv_put_long(csv_file *c, long value);
void csv_put_empty(csv_file *c);                  /* a quantity not computed in this run */
void csv_put_number(csv_file *c, double value);   /* csv_put, or empty for NaN (none to count) */
void csv_put_text(csv_file *c, const char *text); /* quoted when it holds , or " */
/* Ends the row and flushes it; a failure is kept in c->error (csv_error). */
void csv_end_row(csv_file *c);
/* errno of the first row that did not reach the file, or 0: the caller stops the run rather
 * than go on without its record. */
static inline int csv_error(const csv_file *c) { return c->f ? c->error : 0; }

#endif
