/* ini_value: the values of the built-in key kinds, text to field and back, and the helpers of
 * the formats (ini_schema.h, ini_value.h). */
#include "core/ini_value.h"
#include "core/decimal.h"
#include "core/suggest.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *ini_skip_space(const char *s)
{
    while (isspace((unsigned char)*s)) s++;
    return s;
}

static bool is_ascii_alnum(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

bool ini_is_name_char(char c, bool first)
{
    return is_ascii_alnum(c) || (!first && strchr("._-", c));
}

static void *field(void *target, const ini_key *k) { return (char *)target + k->offset; }

static const void *field_c(const void *target, const ini_key *k)
{
    return (const char *)target + k->offset;
}

static int word_index(const char *const *words, const char *s)
{
    for (int i = 0; words[i]; i++)
        if (strcmp(words[i], s) == 0) return i;
    return -1;
}

const char *ini_word_at(const char *const *words, int i)
{
    for (int j = 0; words[j]; j++)
        if (j == i) return words[j];
    return "?";
}

static bool in_range(double v, const ini_range *r)
{
    bool above = r->lo_open ? v > r->lo : v >= r->lo;
    bool below = r->hi_open ? v < r->hi : v <= r->hi;
    return above && below;
}

/* A whole string that is one finite decimal number: "1.0abc", "", "inf", "nan" and "0x1p-4"
 * are not. */
static bool parse_real(const char *s, double *out)
{
    if (!*s || isspace((unsigned char)*s)) return false;
    char *end;
    double v = decimal_strtod(s, &end);
    if (end == s || *end != '\0' || !isfinite(v)) return false;
    *out = v;
    return true;
}

static bool parse_long(const char *s, long *out)
{
    if (!*s || isspace((unsigned char)*s)) return false;
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE) return false;
    *out = v;
    return true;
}

/* Stores a string with the rest of the field zeroed, so that config structs compare with
 * memcmp whatever was stored there before. */
bool ini_store_string(char *dst, size_t size, const char *s)
{
    size_t n = strlen(s);
    if (n >= size) return false;
    memset(dst, 0, size);
    memcpy(dst, s, n);
    return true;
}

static bool set_int(void *target, const ini_key *k, const char *s, char *why, size_t n)
{
    long v;
    if (!parse_long(s, &v)) {
        snprintf(why, n, "not an integer; must be %s", k->allowed);
        return false;
    }
    if (!in_range((double)v, &k->range)) {
        snprintf(why, n, "must be %s", k->allowed);
        return false;
    }
    *(int *)field(target, k) = (int)v;
    return true;
}

static bool set_real_checked(void *target, const ini_key *k, const char *s, char *why, size_t n)
{
    double v;
    if (!parse_real(s, &v)) {
        snprintf(why, n, "not a finite decimal number; must be %s", k->allowed);
        return false;
    }
    if (!in_range(v, &k->range)) {
        snprintf(why, n, "must be %s", k->allowed);
        return false;
    }
    *(double *)field(target, k) = v;
    return true;
}

static bool set_real_auto(void *target, const ini_key *k, const char *s, char *why, size_t n)
{
    if (strcmp(s, "auto") == 0) {
        *(double *)field(target, k) = 0.0;
        return true;
    }
    return set_real_checked(target, k, s, why, n);
}

static bool set_word(void *target, const ini_key *k, const char *s, char *why, size_t n)
{
    int i = word_index(k->words, s);
    if (i < 0) {
        size_t count = 0;
        while (k->words[count]) count++;
        const char *hint = word_suggest(s, k->words, count);
        if (hint)
            snprintf(why, n, "did you mean '%s'? must be %s", hint, k->allowed);
        else
            snprintf(why, n, "must be %s", k->allowed);
        return false;
    }
    if (k->kind == INI_BOOL)
        *(bool *)field(target, k) = i != 0;
    else
        memcpy(field(target, k), &i, sizeof i);
    return true;
}

static bool set_name(void *target, const ini_key *k, const char *s, char *why, size_t n)
{
    bool ok = ini_is_name_char(s[0], true);
    for (const char *p = s; ok && *p; p++) ok = ini_is_name_char(*p, false);
    if (!ok || !ini_store_string(field(target, k), k->size, s)) {
        snprintf(why, n, "must be %s, at most %zu characters", k->allowed, k->size - 1);
        return false;
    }
    return true;
}

/* Whether INI reads p, a character of the value s, as the start of an inline comment: a
 * comment character after white space. config_write puts a space after '=', so a value that
 * starts with one would read back as a comment too. */
static bool starts_comment(const char *s, const char *p)
{
    return strchr(INI_COMMENT_CHARS, *p) && (p == s || isspace((unsigned char)p[-1]));
}

/* A path must survive config_write and config_load: no control characters, and no ';' or '#'
 * that INI would take for the start of a comment. */
bool ini_path_is_writable(const char *s)
{
    for (const char *p = s; *p; p++) {
        if (iscntrl((unsigned char)*p)) return false;
        if (starts_comment(s, p)) return false;
    }
    return true;
}

static bool set_path(void *target, const ini_key *k, const char *s, char *why, size_t n)
{
    if ((k->flags & INI_NOT_EMPTY) && !*s) {
        snprintf(why, n, "empty; must be %s", k->allowed);
        return false;
    }
    if (!ini_path_is_writable(s)) {
        snprintf(why, n,
                 "control characters, and ';' or '#' first or after a space (INI reads a "
                 "comment there), are not allowed in a path");
        return false;
    }
    if (!ini_store_string(field(target, k), k->size, s)) {
        snprintf(why, n, "longer than %zu characters", k->size - 1);
        return false;
    }
    return true;
}

/* The shortest of %.15g, %.16g, %.17g that reads back exactly (%.17g always does). */
void ini_format_double(double v, char *buf, size_t size)
{
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, size, "%.*g", prec, v);
        if (strtod(buf, NULL) == v) return;
    }
}

static void format_int(const void *target, const ini_key *k, char *buf, size_t size)
{
    snprintf(buf, size, "%d", *(const int *)field_c(target, k));
}

static void format_real(const void *target, const ini_key *k, char *buf, size_t size)
{
    ini_format_double(*(const double *)field_c(target, k), buf, size);
}

static void format_real_auto(const void *target, const ini_key *k, char *buf, size_t size)
{
    double v = *(const double *)field_c(target, k);
    if (v == 0.0)
        snprintf(buf, size, "auto");
    else
        ini_format_double(v, buf, size);
}

static void format_word(const void *target, const ini_key *k, char *buf, size_t size)
{
    int i;
    if (k->kind == INI_BOOL)
        i = *(const bool *)field_c(target, k);
    else
        memcpy(&i, field_c(target, k), sizeof i);
    snprintf(buf, size, "%s", ini_word_at(k->words, i));
}

static void format_string(const void *target, const ini_key *k, char *buf, size_t size)
{
    snprintf(buf, size, "%s", (const char *)field_c(target, k));
}

typedef bool (*value_setter)(void *target, const ini_key *k, const char *s, char *why, size_t n);

static const struct {
    value_setter set;
    ini_formatter format;
} kinds[] = {
    [INI_INT] = {set_int, format_int},
    [INI_REAL] = {set_real_checked, format_real},
    [INI_REAL_AUTO] = {set_real_auto, format_real_auto},
    [INI_BOOL] = {set_word, format_word},
    [INI_WORD] = {set_word, format_word},
    [INI_NAME] = {set_name, format_string},
    [INI_PATH] = {set_path, format_string},
};

bool ini_value_set(void *target, const ini_key *k, const char *s, char *why, size_t n)
{
    return kinds[k->kind].set(target, k, s, why, n);
}

void ini_value_format(const void *target, const ini_key *k, char *buf, size_t size)
{
    (k->kind == INI_CUSTOM ? k->format : kinds[k->kind].format)(target, k, buf, size);
}
