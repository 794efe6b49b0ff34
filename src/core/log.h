/* log: messages to the terminal and to log.txt of the run (without the progress line). */
#ifndef VCSPH_LOG_H
#define VCSPH_LOG_H

#include <stdbool.h>

/* Starts copying messages to `path`, after what it holds when `append` (a restarted run);
 * returns 0 or -1. */
int log_open(const char *path, bool append);
void log_close(void);
/* Silences the terminal copy (tests); the file copy stays. */
void log_set_quiet(bool quiet);
/* One line to stdout (and the log file); a trailing newline is added. */
void log_info(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* One line to stderr (and the log file). */
void log_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

#endif
