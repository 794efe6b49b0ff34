/* decimal: the numbers a case file or a motion table holds, written in decimal (3, -0.5, .25,
 * 2e-3): strtod less what it also reads, hex floats (0x1p-4), inf and nan, which in such a
 * file are typos. */
#ifndef VCSPH_DECIMAL_H
#define VCSPH_DECIMAL_H

#include <ctype.h>
#include <stdlib.h>

/* strtod on a decimal number; *end == s (nothing read) for anything else. */
static inline double decimal_strtod(const char *s, char **end)
{
    const char *p = s;
    while (isspace((unsigned char)*p)) p++;
    if (*p == '+' || *p == '-') p++;
    int starts_decimal = isdigit((unsigned char)*p) || (*p == '.' && isdigit((unsigned char)p[1]));
    int hex = p[0] == '0' && (p[1] == 'x' || p[1] == 'X');
    if (!starts_decimal || hex) {
        *end = (char *)s;
        return 0.0;
    }
    return strtod(s, end);
}

#endif
