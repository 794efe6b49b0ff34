/* log: one place that knows where messages go. */
#include "core/log.h"

#include <stdarg.h>
#include <stdio.h>

static FILE *log_file;
static bool log_quiet;

int log_open(const char *path, bool append)
{
    log_close();
    log_file = fopen(path, append ? "a" : "w");
    return log_file ? 0 : -1;
}

void log_close(void)
{
    if (log_file) fclose(log_file);
    log_file = NULL;
}

void log_set_quiet(bool quiet) { log_quiet = quiet; }

static void emit(FILE *terminal, const char *fmt, va_list args)
{
    if (log_file) {
        va_list copy;
        va_copy(copy, args);
        vfprintf(log_file, fmt, copy);
        fputc('\n', log_file);
        fflush(log_file);
        va_end(copy);
    }
    if (!log_quiet || terminal == stderr) {
        vfprintf(terminal, fmt, args);
        fputc('\n', terminal);
        fflush(terminal);
    }
}

void log_info(const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    emit(stdout, fmt, args);
    va_end(args);
}

void log_error(const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    emit(stderr, fmt, args);
    va_end(args);
}
