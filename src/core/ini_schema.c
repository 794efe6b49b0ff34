/* ini_schema: typed INI keys read into a struct with inih (ini_schema.h). */
#include "core/ini_schema.h"
#include "core/suggest.h"
#include "core/ini_value.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include <ini.h>

/* Values longer than this are shortened in messages, so the message itself stays readable. */
#define SHOWN_VALUE_MAX 80
/* "file:line" of a message */
#define WHERE_MAX 1100

#if defined(__GNUC__)
#define PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PRINTF_LIKE(f, a)
#endif

struct ini_session {
    const ini_schema *schema;
    void *target, *user;
    const char *origin; /* names the input in messages */
    const char *path;   /* the file, NULL for a string */
    char *err;
    size_t err_len;
    bool failed;
    FILE *file;       /* the input is either a file ... */
    const char *text; /* ... or the rest of a string */
    int lineno;
    int *section_line;       /* first header line of each section, 0 if absent */
    int *key_line;           /* where each key was set: a line, INI_LINE_SET, or 0 (default) */
    char line[INI_LINE_MAX]; /* the current line as read, before inih cuts it up */
};

/* Only the first error is kept: later ones are usually consequences of it. */
PRINTF_LIKE(2, 3) static void fail(ini_session *ctx, const char *fmt, ...)
{
    if (ctx->failed) return;
    ctx->failed = true;
    if (!ctx->err || ctx->err_len == 0) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ctx->err, ctx->err_len, fmt, ap);
    va_end(ap);
}

/* "file:line", or "--set" for a value from the command line. */
static const char *where(const ini_session *ctx, int line, char *buf, size_t size)
{
    if (line == INI_LINE_SET) return "--set";
    if (line <= 0) return ctx->origin; /* what the file lacks has no line */
    snprintf(buf, size, "%s:%d", ctx->origin, line);
    return buf;
}

void ini_fail_value(ini_session *ctx, const ini_key *k, int line, const char *text, const char *why)
{
    char at[WHERE_MAX];
    int n = (int)strlen(text);
    bool cut = n > SHOWN_VALUE_MAX;
    fail(ctx, "%s: %s.%s = %.*s%s: %s", where(ctx, line, at, sizeof at), k->section, k->name,
         cut ? SHOWN_VALUE_MAX - 3 : n, text, cut ? "..." : "", why);
}

static int section_index(const ini_schema *schema, const char *name)
{
    for (size_t i = 0; i < schema->n_sections; i++)
        if (strcmp(schema->sections[i], name) == 0) return (int)i;
    return -1;
}

static const ini_key *find_key(const ini_schema *schema, const char *section, const char *name)
{
    for (size_t i = 0; i < schema->n_keys; i++)
        if (strcmp(schema->keys[i].section, section) == 0 &&
            strcmp(schema->keys[i].name, name) == 0)
            return &schema->keys[i];
    return NULL;
}

static size_t section_key_names(const ini_schema *schema, const char *section, const char **names)
{
    size_t n = 0;
    for (size_t i = 0; i < schema->n_keys; i++)
        if (strcmp(schema->keys[i].section, section) == 0) names[n++] = schema->keys[i].name;
    return n;
}

static void join_words(const char *const *words, size_t n, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < n && used < size; i++) {
        int w = snprintf(buf + used, size - used, "%s%s", i ? ", " : "", words[i]);
        if (w < 0) break;
        used += (size_t)w;
    }
}

static void fail_unknown_section(ini_session *ctx, const char *at, const char *name)
{
    const ini_schema *schema = ctx->schema;
    const char *hint = word_suggest(name, schema->sections, schema->n_sections);
    char list[256];
    join_words(schema->sections, schema->n_sections, list, sizeof list);
    if (hint)
        fail(ctx, "%s: unknown section [%s]; did you mean [%s]?", at, name, hint);
    else
        fail(ctx, "%s: unknown section [%s]; sections are: %s", at, name, list);
}

static void fail_unknown_key(ini_session *ctx, const char *at, const char *section,
                             const char *name)
{
    const char **names = calloc(ctx->schema->n_keys + 1, sizeof *names);
    if (!names) {
        fail(ctx, "%s: unknown key '%s.%s' (and out of memory)", at, section, name);
        return;
    }
    size_t n = section_key_names(ctx->schema, section, names);
    const char *hint = word_suggest(name, names, n);
    if (hint) {
        fail(ctx, "%s: unknown key '%s.%s'; did you mean '%s.%s'?", at, section, name, section,
             hint);
        free(names);
        return;
    }
    /* The right key in the wrong section is a common slip. */
    for (size_t i = 0; i < ctx->schema->n_keys; i++) {
        if (strcmp(ctx->schema->keys[i].name, name) == 0) {
            fail(ctx, "%s: unknown key '%s.%s'; did you mean '%s.%s'?", at, section, name,
                 ctx->schema->keys[i].section, name);
            free(names);
            return;
        }
    }
    char list[512];
    join_words(names, n, list, sizeof list);
    fail(ctx, "%s: unknown key '%s.%s'; [%s] has: %s", at, section, name, section, list);
    free(names);
}

/* Sets a key from its text, recording where it came from; false (and the message) if the text
 * is not allowed. */
bool ini_apply(ini_session *ctx, const ini_key *k, const char *text, int line)
{
    char why[512];
    bool ok = k->kind == INI_CUSTOM ? k->set(ctx, k, text, why, sizeof why)
                                    : ini_value_set(ctx->target, k, text, why, sizeof why);
    if (!ok) {
        ini_fail_value(ctx, k, line, text, why);
        return false;
    }
    ctx->key_line[k - ctx->schema->keys] = line;
    return true;
}

/* Whether the file or --set gave the key (rather than its default). */
bool ini_given(const ini_session *ctx, const ini_key *k)
{
    return ctx->key_line[k - ctx->schema->keys] != 0;
}

/* For checks made once all keys are known: blames the key where it was set, or where it
 * should have been (its section's header, or line 0 when the section is absent too). */
void ini_fail_key(ini_session *ctx, const ini_key *k, const char *why)
{
    int line = ctx->key_line[k - ctx->schema->keys];
    if (line != 0) {
        char value[INI_LINE_MAX];
        ini_value_format(ctx->target, k, value, sizeof value);
        ini_fail_value(ctx, k, line, value, why);
        return;
    }
    int header = ctx->section_line[section_index(ctx->schema, k->section)];
    char at[WHERE_MAX];
    if (header)
        fail(ctx, "%s: %s.%s: missing in [%s]; %s", where(ctx, header, at, sizeof at), k->section,
             k->name, k->section, why);
    else
        fail(ctx, "%s: %s.%s: missing, and so is section [%s]; %s", where(ctx, 0, at, sizeof at),
             k->section, k->name, k->section, why);
}

static bool next_text_line(ini_session *ctx, char *buf, size_t size, bool *complete)
{
    if (!*ctx->text) return false;
    size_t len = strcspn(ctx->text, "\n");
    size_t take = len + (ctx->text[len] == '\n');
    *complete = take < size;
    if (!*complete) take = size - 1;
    memcpy(buf, ctx->text, take);
    buf[take] = '\0';
    ctx->text += take;
    return true;
}

static bool next_file_line(ini_session *ctx, char *buf, size_t size, bool *complete)
{
    if (!fgets(buf, (int)size, ctx->file)) return false;
    size_t len = strlen(buf);
    *complete = len > 0 && buf[len - 1] == '\n';
    if (!*complete) {
        int c = getc(ctx->file);
        *complete = c == EOF; /* the last line need not end in '\n' */
        if (c != EOF) ungetc(c, ctx->file);
    }
    return true;
}

/* inih does not tell the handler about section headers, so they are checked here, where each
 * line passes anyway: this catches unknown sections that hold no keys, and records each
 * header's line for messages about missing keys. */
static void check_section_header(ini_session *ctx)
{
    const char *p = ctx->line;
    if (ctx->lineno == 1 && strncmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;
    p = ini_skip_space(p);
    if (*p != '[') return;
    const char *end = strchr(p + 1, ']');
    if (!end) return; /* inih reports the syntax error */
    char name[128];
    int len = (int)(end - p - 1);
    snprintf(name, sizeof name, "%.*s", len, p + 1);
    char at[WHERE_MAX];
    where(ctx, ctx->lineno, at, sizeof at);
    const char *rest = ini_skip_space(end + 1);
    if (*rest && !strchr(INI_COMMENT_CHARS, *rest)) {
        fail(ctx, "%s: unexpected text after [%s]; only a comment may follow a section header", at,
             name);
        return;
    }
    int i = section_index(ctx->schema, name);
    if (i < 0)
        fail_unknown_section(ctx, at, name);
    else if (!ctx->section_line[i])
        ctx->section_line[i] = ctx->lineno;
}

/* inih's reader: one line per call, so ctx->lineno is the line of the key that the handler
 * sees next (Debian's inih has no INI_HANDLER_LINENO). */
static char *read_line(char *str, int num, void *stream)
{
    ini_session *ctx = stream;
    bool complete = true;
    if (ctx->failed || num < 2) return NULL;
    bool got = ctx->file ? next_file_line(ctx, str, (size_t)num, &complete)
                         : next_text_line(ctx, str, (size_t)num, &complete);
    if (!got) return NULL;
    ctx->lineno++;
    if (!complete) {
        char at[WHERE_MAX];
        if (strlen(str) + 1 < (size_t)num)
            fail(ctx, "%s: the line holds a NUL character", where(ctx, ctx->lineno, at, sizeof at));
        else
            fail(ctx, "%s: line longer than %d characters", where(ctx, ctx->lineno, at, sizeof at),
                 num - 2);
        return NULL;
    }
    snprintf(ctx->line, sizeof ctx->line, "%s", str);
    check_section_header(ctx);
    return ctx->failed ? NULL : str;
}

/* True when the raw line's value holds an inline comment that starts like a number: inih cuts
 * "0.1 0.2 ; 0.3 0.4" at " ;" (and "0.1 # 0.3" at " #"), which would silently drop probes. */
static bool list_cut_by_comment(const char *raw)
{
    const char *p = raw + strcspn(raw, "=:");
    if (!*p) return false;
    for (p++; *p; p++) {
        if (strchr(INI_COMMENT_CHARS, *p) && isspace((unsigned char)p[-1])) {
            const char *q = ini_skip_space(p + 1);
            return isdigit((unsigned char)*q) || (*q && strchr("+-.", *q));
        }
    }
    return false;
}

static int on_key(void *user, const char *section, const char *name, const char *value)
{
    ini_session *ctx = user;
    char at[WHERE_MAX];
    where(ctx, ctx->lineno, at, sizeof at);
    if (ctx->failed) return 0;
    if (!*section) {
        fail(ctx, "%s: key '%s' comes before any [section]", at, name);
        return 0;
    }
    const ini_key *k = find_key(ctx->schema, section, name);
    if (!k) {
        fail_unknown_key(ctx, at, section, name);
        return 0;
    }
    int first = ctx->key_line[k - ctx->schema->keys];
    if (first > 0) {
        fail(ctx, "%s: %s.%s: set twice (first on line %d); give each key once", at, section, name,
             first);
        return 0;
    }
    if ((k->flags & INI_LIST) && list_cut_by_comment(ctx->line)) {
        ini_fail_value(ctx, k, ctx->lineno, value,
                       "' ;' or ' #' starts a comment in INI and would drop the numbers after it; "
                       "write ';' right after a number, as in '0.1 0.2; 0.3 0.4'");
        return 0;
    }
    return ini_apply(ctx, k, value, ctx->lineno);
}

/* inih's options are globals of the library: set ours for the parse, then put back what was
 * there, so that other users of inih are not surprised. */
typedef struct {
    bool multiline, bom, inline_comments, use_stack, stop_on_first_error, no_value;
    char *start_prefixes, *inline_prefixes;
    int max_line;
} ini_options;

static ini_options ini_options_get(void)
{
    return (ini_options){ini_allow_multiline,
                         ini_allow_bom,
                         ini_allow_inline_comments,
                         ini_use_stack,
                         ini_stop_on_first_error,
                         ini_allow_no_value,
                         ini_start_comment_prefixes,
                         ini_inline_comment_prefixes,
                         ini_max_line};
}

static void ini_options_set(const ini_options *o)
{
    ini_allow_multiline = o->multiline;
    ini_allow_bom = o->bom;
    ini_allow_inline_comments = o->inline_comments;
    ini_use_stack = o->use_stack;
    ini_stop_on_first_error = o->stop_on_first_error;
    ini_allow_no_value = o->no_value;
    ini_start_comment_prefixes = o->start_prefixes;
    ini_inline_comment_prefixes = o->inline_prefixes;
    ini_max_line = o->max_line;
}

static void parse_input(ini_session *ctx)
{
    /* No multi-line values: an indented line must not be glued to the previous value. */
    static const ini_options ours = {
        false, true, true, true, true, false, INI_COMMENT_CHARS, INI_COMMENT_CHARS, INI_LINE_MAX};
    ini_options saved = ini_options_get();
    ini_options_set(&ours);
    int rc = ini_parse_stream(read_line, ctx, on_key, ctx);
    int read_errno = errno;
    ini_options_set(&saved);
    if (ctx->failed) return;
    char at[WHERE_MAX];
    if (ctx->file && ferror(ctx->file)) {
        fail(ctx, "%s: cannot read: %s", ctx->origin, strerror(read_errno));
    } else if (rc > 0) {
        const char *text = ini_skip_space(ctx->line);
        int len = (int)strcspn(text, "\r\n");
        where(ctx, rc, at, sizeof at);
        if (*text == '[')
            fail(ctx, "%s: '%.*s': a section header needs a closing ']'", at, len, text);
        else
            fail(ctx, "%s: '%.*s': expected [section], key = value, or a comment", at,
                 len > SHOWN_VALUE_MAX ? SHOWN_VALUE_MAX : len, text);
    } else if (rc < 0) {
        fail(ctx, "%s: cannot parse (inih error %d)", ctx->origin, rc);
    }
}

/* Copies [s, s+n) without surrounding white space; false if it had to be cut to fit. */
static bool copy_trimmed(char *dst, size_t size, const char *s, size_t n)
{
    while (n > 0 && isspace((unsigned char)*s)) s++, n--;
    while (n > 0 && isspace((unsigned char)s[n - 1])) n--;
    snprintf(dst, size, "%.*s", (int)n, s);
    return n < size;
}

static void apply_override(ini_session *ctx, const char *arg)
{
    const char *eq = strchr(arg, '=');
    const char *dot = eq ? memchr(arg, '.', (size_t)(eq - arg)) : NULL;
    if (!dot) {
        fail(ctx, "--set %s: expected section.key=value, as in --set numerics.resolution=50", arg);
        return;
    }
    char section[128], name[128];
    copy_trimmed(section, sizeof section, arg, (size_t)(dot - arg));
    copy_trimmed(name, sizeof name, dot + 1, (size_t)(eq - dot - 1));
    if (section_index(ctx->schema, section) < 0) {
        fail_unknown_section(ctx, "--set", section);
        return;
    }
    const ini_key *k = find_key(ctx->schema, section, name);
    if (!k) {
        fail_unknown_key(ctx, "--set", section, name);
        return;
    }
    if (!copy_trimmed(ctx->line, sizeof ctx->line, eq + 1, strlen(eq + 1))) {
        fail(ctx, "--set: %s.%s: value longer than %zu characters", section, name,
             sizeof ctx->line - 1);
        return;
    }
    ini_apply(ctx, k, ctx->line, INI_LINE_SET);
}

/* Appends to buf what a missing key is and where it belongs, "; " between two. */
static void describe_missing(const ini_session *ctx, const ini_key *k, char *buf, size_t size)
{
    size_t used = strlen(buf);
    int header = ctx->section_line[section_index(ctx->schema, k->section)];
    char place[64];
    if (header)
        snprintf(place, sizeof place, "in [%s], line %d", k->section, header);
    else
        snprintf(place, sizeof place, "section [%s] missing too", k->section);
    snprintf(buf + used, size - used, "%s%s.%s (%s: %s)", used ? "; " : "", k->section, k->name,
             place, k->allowed);
}

/* All the missing required keys in one message, so that a user fixes them in one go. One
 * missing key is blamed where it belongs (fail_key); several at the first one's place. */
static void check_required(ini_session *ctx)
{
    const ini_schema *schema = ctx->schema;
    const ini_key *first = NULL;
    size_t n = 0;
    char why[1024] = "";
    for (size_t i = 0; i < schema->n_keys; i++) {
        const ini_key *k = &schema->keys[i];
        if (!(k->flags & INI_REQUIRED) || ini_given(ctx, k)) continue;
        if (!first) first = k;
        n++;
        describe_missing(ctx, k, why, sizeof why);
    }
    if (n == 0) return;
    if (n == 1) {
        snprintf(why, sizeof why, "required: %s", first->allowed);
        ini_fail_key(ctx, first, why);
        return;
    }
    char at[WHERE_MAX];
    fail(ctx, "%s: %zu required keys missing: %s",
         where(ctx, ctx->section_line[section_index(schema, first->section)], at, sizeof at), n,
         why);
}

static void apply_defaults(ini_session *ctx)
{
    for (size_t i = 0; i < ctx->schema->n_keys; i++) {
        const ini_key *k = &ctx->schema->keys[i];
        bool has_default = !(k->flags & (INI_REQUIRED | INI_DERIVED));
        if (has_default && !ini_apply(ctx, k, k->def, 0))
            abort(); /* a default that its own key rejects is a bug of the table */
    }
}

int ini_load(const ini_schema *schema, void *target, size_t target_size, const ini_input *in,
             const char *const *overrides, int n_overrides, void *user, char *err, size_t err_len)
{
    const char *origin = in->path ? in->path : in->origin ? in->origin : "(string)";
    ini_session *ctx = calloc(1, sizeof *ctx);
    int *lines = calloc(schema->n_keys + schema->n_sections + 1, sizeof *lines);
    if (!ctx || !lines) {
        free(ctx);
        free(lines);
        if (err && err_len) snprintf(err, err_len, "%s: out of memory", origin);
        return 2;
    }
    /* Zero first, padding included, so that two loads of one case compare equal with memcmp. */
    memset(target, 0, target_size);
    ctx->schema = schema;
    ctx->target = target;
    ctx->user = user;
    ctx->origin = origin;
    ctx->path = in->path;
    ctx->err = err;
    ctx->err_len = err_len;
    ctx->key_line = lines;
    ctx->section_line = lines + schema->n_keys;
    ctx->text = in->text ? in->text : "";
    if (in->path && !(ctx->file = fopen(in->path, "r")))
        fail(ctx, "%s: cannot open: %s", in->path, strerror(errno));
    if (!ctx->failed) {
        apply_defaults(ctx);
        parse_input(ctx);
        for (int i = 0; i < n_overrides && !ctx->failed; i++) apply_override(ctx, overrides[i]);
        if (!ctx->failed) check_required(ctx);
        for (size_t i = 0; i < schema->n_checks && !ctx->failed; i++) schema->checks[i](ctx);
    }
    if (ctx->file) fclose(ctx->file);
    int rc = ctx->failed ? 2 : 0;
    if (!rc && err && err_len) err[0] = '\0';
    free(lines);
    free(ctx);
    return rc;
}

void ini_write(const ini_schema *schema, const void *target, const char *title, FILE *out)
{
    char value[INI_LINE_MAX];
    fprintf(out, "; %s\n", title);
    const char *section = NULL;
    for (size_t i = 0; i < schema->n_keys; i++) {
        const ini_key *k = &schema->keys[i];
        if (!section || strcmp(section, k->section) != 0) {
            fprintf(out, "%s[%s]\n", section ? "\n" : "", k->section);
            section = k->section;
        }
        ini_value_format(target, k, value, sizeof value);
        fprintf(out, "%-16s = %s ; %s\n", k->name, value, k->allowed);
    }
}

void ini_write_keys(const ini_schema *schema, FILE *out)
{
    for (size_t i = 0; i < schema->n_keys; i++) {
        const ini_key *k = &schema->keys[i];
        /* the default as a file spells it, the rule of a derived default, or "required" */
        const char *def = (k->flags & INI_REQUIRED) ? "required" : k->def;
        fprintf(out, "%s.%s\t%s\t%s\t%s\n", k->section, k->name, def, k->allowed, k->meaning);
    }
}

void *ini_target(const ini_session *ctx) { return ctx->target; }
void *ini_user(const ini_session *ctx) { return ctx->user; }
const char *ini_path(const ini_session *ctx) { return ctx->path; }
int ini_key_line(const ini_session *ctx, const ini_key *k)
{
    return ctx->key_line[k - ctx->schema->keys];
}

const ini_key *ini_key_of(const ini_session *ctx, const char *section, const char *name)
{
    const ini_key *k = find_key(ctx->schema, section, name);
    if (!k) abort(); /* a key of the schema's own checks: exists by construction */
    return k;
}
