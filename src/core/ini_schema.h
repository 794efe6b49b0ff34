/* ini_schema: an INI file read into a C struct through a table of typed keys, with inih.
 * Every value is checked against its key's type and range as it is read; an unknown section
 * or key gets a "did you mean"; the first error is kept, with the file and line (or --set)
 * where it happened; overrides "section.key=value" apply after the file; the schema's checks
 * run once every key is known. The struct can be written back as a file that reads to the
 * same bits. The case file's vocabulary is core/config.c's table; this module knows no key. */
#ifndef VCSPH_INI_SCHEMA_H
#define VCSPH_INI_SCHEMA_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* inih's default line limit (200 bytes) is too short for 64 pressure probes in 3D or a long
 * path, and ini_write must produce lines that the reader takes back. */
#define INI_LINE_MAX 8192
/* Both start a comment, at the start of a line or after white space in a value: ';' is the
 * INI convention, '#' the shell's, which users write by habit. A '#' inside a word (a path
 * "run#2") is kept. */
#define INI_COMMENT_CHARS ";#"
/* The line of a key that came from --set rather than from a line of the file. */
#define INI_LINE_SET (-1)

typedef enum {
    INI_INT,       /* stored in an int */
    INI_REAL,      /* a finite double */
    INI_REAL_AUTO, /* a double, or "auto" stored as 0 */
    INI_BOOL,      /* words[0] false, words[1] true, stored in a bool */
    INI_WORD,      /* an enumeration spelled as in `words`, stored as the word's index (int) */
    INI_NAME,      /* letters, digits, '.', '_' and '-' starting with a letter or digit */
    INI_PATH,      /* a path that survives ini_write (no control character, no comment) */
    INI_CUSTOM     /* the key's own setter and formatter */
} ini_kind;

enum {
    INI_REQUIRED = 1,  /* no default: the file or --set must give it */
    INI_DERIVED = 2,   /* default computed from other keys once all are known (a check) */
    INI_NOT_EMPTY = 4, /* a path that may not be empty */
    INI_LIST = 8,      /* a list of numbers, which an inline comment would cut silently */
};

typedef struct {
    double lo, hi;
    bool lo_open, hi_open;
} ini_range;

typedef struct ini_session ini_session;
typedef struct ini_key ini_key;

/* Text -> field; false with the reason in `why` when the text is not allowed. */
typedef bool (*ini_setter)(ini_session *ctx, const ini_key *k, const char *s, char *why, size_t n);
/* Field -> text that the setter reads back to the same bits. */
typedef void (*ini_formatter)(const void *target, const ini_key *k, char *buf, size_t size);

struct ini_key {
    const char *section;
    const char *name;
    ini_kind kind;
    unsigned flags;
    /* Default spelled as in a file. Required keys have none; for derived keys it is the rule,
     * in words, that ini_write_keys shows (a check of the schema applies it). */
    const char *def;
    size_t offset, size;      /* of the field in the target struct */
    ini_range range;          /* numbers */
    const char *const *words; /* INI_WORD and INI_BOOL, NULL-terminated, in enum order */
    const char *allowed;      /* "must be <allowed>" in messages, the comment in ini_write */
    const char *meaning;      /* one line for ini_write_keys (no tab) */
    ini_setter set;           /* INI_CUSTOM only */
    ini_formatter format;     /* INI_CUSTOM only */
};

typedef struct {
    const char *const *sections;
    size_t n_sections;
    const ini_key *keys;
    size_t n_keys;
    /* run in order once the file and the overrides are read, until one fails */
    void (*const *checks)(ini_session *ctx);
    size_t n_checks;
} ini_schema;

/* Where the input comes from: a file (path) or a string (text, named `origin`). */
typedef struct {
    const char *path;
    const char *text;
    const char *origin;
} ini_input;

/* Zeroes the target (padding included, so that two loads compare equal with memcmp), applies
 * the defaults, reads the input and the overrides, runs the checks. `user` is for the
 * schema's setters and checks (ini_user). Returns 0, or 2 with the first error in err. */
int ini_load(const ini_schema *schema, void *target, size_t target_size, const ini_input *in,
             const char *const *overrides, int n_overrides, void *user, char *err, size_t err_len);
/* Every key, section by section, "name = value ; allowed", after the comment line `title`. */
void ini_write(const ini_schema *schema, const void *target, const char *title, FILE *out);
/* One line per key: section.key, default (or "required", or a derived default's rule),
 * allowed values, meaning; tab-separated. */
void ini_write_keys(const ini_schema *schema, FILE *out);

/* ---- for the schema's setters and checks ---- */
void *ini_target(const ini_session *ctx);
void *ini_user(const ini_session *ctx);
/* the file being read, NULL for a string */
const char *ini_path(const ini_session *ctx);
/* The key (section, name) of the schema; one that does not exist is a bug (abort). */
const ini_key *ini_key_of(const ini_session *ctx, const char *section, const char *name);
/* Whether the file or --set gave the key (rather than its default). */
bool ini_given(const ini_session *ctx, const ini_key *k);
/* The line that set it, INI_LINE_SET, or 0 (its default). */
int ini_key_line(const ini_session *ctx, const ini_key *k);
/* Sets a key from text as line `line` would (0: a default); false with the message kept. */
bool ini_apply(ini_session *ctx, const ini_key *k, const char *text, int line);
/* Blames a key, once every key is known, where it was set, or where it should have been
 * (its section's header, or line 0 when the section is absent too). */
void ini_fail_key(ini_session *ctx, const ini_key *k, const char *why);
/* "where: section.key = text: why" */
void ini_fail_value(ini_session *ctx, const ini_key *k, int line, const char *text,
                    const char *why);

/* ---- helpers of the formats ---- */
const char *ini_skip_space(const char *s);
bool ini_is_name_char(char c, bool first);
/* a string into a field of `size` bytes with the rest zeroed; false if it does not fit */
bool ini_store_string(char *dst, size_t size, const char *s);
/* no control characters, no ';' or '#' that INI would read as a comment */
bool ini_path_is_writable(const char *s);
/* the shortest of %.15g, %.16g, %.17g that reads back exactly */
void ini_format_double(double v, char *buf, size_t size);
/* words[i], "?" past the end */
const char *ini_word_at(const char *const *words, int i);

#endif
