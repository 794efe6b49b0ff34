/* csv: writers. */
#include "io/csv.h"
#include "io/atomic_file.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int csv_open(csv_file *c, const char *path, const char *header)
{
    c->column = 0;
    c->error = 0;
    c->f = fopen(path, "w");
    if (!c->f) return -1;
    fprintf(c->f, "%s\n", header);
    return fflush(c->f) == 0 ? 0 : -1;
}

int csv_reopen(csv_file *c, const char *path, long long size)
{
    struct stat st;
    c->column = 0;
    c->error = 0;
    c->f = NULL;
    if (size < 0 || stat(path, &st) || st.st_size < size || truncate(path, (off_t)size)) return -1;
    c->f = fopen(path, "a");
    /* the position csv_size reports is the end, where the appends go */
    return c->f && fseeko(c->f, 0, SEEK_END) == 0 ? 0 : -1;
}

/* The separators of the empty fields a row gains, as many as a reopen may add. */
static const char EMPTY_FIELDS[] = ",,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,";

/* Copies the first `size` bytes of `in` (its header line already read) to `out` under
 * `header`, each row ended by `added` empty fields. Returns the bytes written or -1. */
static long long copy_with_columns(FILE *in, FILE *out, long long size, long long header_len,
                                   const char *header, int added)
{
    long long read = header_len, written = fprintf(out, "%s\n", header);
    char *line = NULL;
    size_t cap = 0;
    ssize_t len;
    while (written > 0 && read < size && (len = getline(&line, &cap, in)) > 0) {
        read += len;
        if (read > size || line[len - 1] != '\n') break; /* a row cut at the checkpoint's size */
        line[len - 1] = '\0';
        int n = fprintf(out, "%s%.*s\n", line, added, EMPTY_FIELDS);
        written = n < 0 ? -1 : written + n;
    }
    free(line);
    return read == size && written > 0 ? written : -1;
}

int csv_reopen_with_header(csv_file *c, const char *path, long long size, const char *header)
{
    FILE *in = fopen(path, "r");
    if (!in) return -1;
    char *old = NULL;
    size_t cap = 0;
    ssize_t len = getline(&old, &cap, in);
    size_t old_len = len > 0 && old[len - 1] == '\n' ? (size_t)len - 1 : 0;
    if (old_len == strlen(header) && !strncmp(old, header, old_len)) {
        free(old);
        fclose(in);
        return csv_reopen(c, path, size);
    }
    int added = 0;
    bool prefix = old_len > 0 && old_len < strlen(header) && !strncmp(old, header, old_len) &&
                  header[old_len] == ',';
    for (const char *h = header + old_len; prefix && *h; h++) added += *h == ',';
    free(old);
    if (!prefix || added > (int)sizeof EMPTY_FIELDS - 1) {
        fclose(in);
        errno = EINVAL;
        return -2;
    }
    char *tmp = atomic_temp_path(path);
    FILE *out = tmp ? fopen(tmp, "w") : NULL;
    long long written = out ? copy_with_columns(in, out, size, (long long)len, header, added) : -1;
    fclose(in);
    int ok = out && fflush(out) == 0 && fsync(fileno(out)) == 0;
    if (out) ok = fclose(out) == 0 && ok;
    char err[256];
    if (!ok || written < 0 || atomic_commit("csv", tmp, path, err, sizeof err)) {
        if (tmp) remove(tmp);
        free(tmp);
        return -1;
    }
    free(tmp);
    return csv_reopen(c, path, written);
}

long long csv_size(const csv_file *c) { return c->f ? (long long)ftello(c->f) : -1; }

int csv_sync(csv_file *c)
{
    if (!c->f) return 0;
    return fflush(c->f) == 0 && fsync(fileno(c->f)) == 0 ? 0 : -1;
}

void csv_close(csv_file *c)
{
    if (c->f) fclose(c->f);
    c->f = NULL;
}

/* Whether the file is open, after the separator of a new field. A file that is not open (the
 * processes of an MPI run other than rank 0, which writes) takes no rows. */
static bool separator(csv_file *c)
{
    if (!c->f) return false;
    if (c->column++ > 0) fputc(',', c->f);
    return true;
}

void csv_put(csv_file *c, double value)
{
    if (separator(c)) fprintf(c->f, "%.10g", value);
}

void csv_put_long(csv_file *c, long value)
{
    if (separator(c)) fprintf(c->f, "%ld", value);
}

void csv_put_empty(csv_file *c) { separator(c); }

void csv_put_number(csv_file *c, double value)
{
    if (isnan(value))
        csv_put_empty(c);
    else
        csv_put(c, value);
}

void csv_put_text(csv_file *c, const char *text)
{
    if (!separator(c)) return;
    if (!strpbrk(text, ",\"\n")) {
        fputs(text, c->f);
        return;
    }
    fputc('"', c->f);
    for (const char *s = text; *s; s++) {
        if (*s == '"') fputc('"', c->f);
        fputc(*s == '\n' ? ' ' : *s, c->f);
    }
    fputc('"', c->f);
}

void csv_end_row(csv_file *c)
{
    if (!c->f) return;
    fputc('\n', c->f);
    if ((fflush(c->f) || ferror(c->f)) && !c->error) c->error = errno ? errno : EIO;
    c->column = 0;
}
