/* io_error: the one way the io modules write a message into their caller's error buffer. */
#ifndef VCSPH_IO_ERROR_H
#define VCSPH_IO_ERROR_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

/* printf into err (err_len bytes, truncated); nothing when err is NULL or err_len is 0. */
static inline void io_error(char *err, size_t err_len, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static inline void io_error(char *err, size_t err_len, const char *fmt, ...)
{
    if (!err || err_len == 0) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, err_len, fmt, ap);
    va_end(ap);
}

#endif
