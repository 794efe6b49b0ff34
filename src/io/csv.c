/* csv: writers. */
#include "io/csv.h"

#include <errno.h>
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

static void separator(csv_file *c)
{
    if (c->column++ > 0) fputc(',', c->f);
}

void csv_put(csv_file *c, double value)
{
    separator(c);
    fprintf(c->f, "%.10g", value);
}

void csv_put_long(csv_file *c, long value)
{
    separator(c);
    fprintf(c->f, "%ld", value);
}

void csv_put_empty(csv_file *c) { separator(c); }

void csv_put_text(csv_file *c, const char *text)
{
    separator(c);
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
    fputc('\n', c->f);
    if ((fflush(c->f) || ferror(c->f)) && !c->error) c->error = errno ? errno : EIO;
    c->column = 0;
}
