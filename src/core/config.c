/* config: reads a case file (docs/case-file.md) with inih, checks every value, resolves the
 * defaults that depend on other keys, and writes the resolved case back out. */
#include "core/config.h"

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <ini.h>

/* inih's default line limit (200 bytes) is too short for 64 pressure probes in 3D or a long
 * path, and config_write must produce lines that config_load reads back. */
#define CASE_LINE_MAX 8192
/* key_line[] value of a key that came from --set rather than from a line of the file. */
#define LINE_SET (-1)
/* Values longer than this are shortened in messages, so the message itself stays readable. */
#define SHOWN_VALUE_MAX 80
/* Both start a comment, at the start of a line or after white space in a value: ';' is the
 * INI convention, '#' the shell's, which users write by habit. A '#' inside a word (a path
 * "run#2") is kept. */
#define COMMENT_CHARS ";#"
/* Relative slack of the liquid-inside-the-tank checks: 0.1 + 0.2 must fit in a tank 0.3 high. */
#define FIT_SLACK 1e-12

#if defined(__GNUC__)
#define PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PRINTF_LIKE(f, a)
#endif

/* Enumerations are stored through memcpy of an int (see set_word), which needs this. */
_Static_assert(sizeof(scheme_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(motion_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(edbc_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(volume_correction_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(eta_control_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(wall_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(liquid_shape_kind) == sizeof(int), "enum size");

/* ---- the schema --------------------------------------------------------------------------- */

typedef enum {
    KIND_INT,
    KIND_REAL,
    KIND_REAL_AUTO, /* "auto" is stored as 0 */
    KIND_BOOL,
    KIND_WORD, /* an enumeration, spelled as in `words`, stored as the word's index */
    KIND_NAME,
    KIND_PATH,
    KIND_GAUGES,
    KIND_POINTS
} key_kind;

enum {
    KEY_REQUIRED = 1,  /* no default: the file or --set must give it */
    KEY_DERIVED = 2,   /* default computed from other keys once all are known */
    KEY_NOT_EMPTY = 4, /* a path that may not be empty */
};

typedef struct {
    double lo, hi;
    bool lo_open, hi_open;
} range;

typedef struct {
    const char *section;
    const char *name;
    key_kind kind;
    unsigned flags;
    /* Default spelled as in a file. Required keys have none; for derived keys it is the rule,
     * in words, that `vcsph keys` shows (resolve_defaults applies it). */
    const char *def;
    size_t offset, size;
    range range;              /* numbers */
    const char *const *words; /* KIND_WORD and KIND_BOOL, NULL-terminated, in enum order */
    const char *allowed;      /* "must be <allowed>" in messages, the comment in config_write */
    const char *meaning;      /* one line for `vcsph keys` and docs/case-file.md (no tab) */
} key_spec;

#define ANY                                                                                        \
    {                                                                                              \
        -DBL_MAX, DBL_MAX, false, false                                                            \
    }
#define POSITIVE                                                                                   \
    {                                                                                              \
        0.0, DBL_MAX, true, false                                                                  \
    }
#define NON_NEGATIVE                                                                               \
    {                                                                                              \
        0.0, DBL_MAX, false, false                                                                 \
    }
#define CLOSED(lo, hi)                                                                             \
    {                                                                                              \
        lo, hi, false, false                                                                       \
    }
#define OPEN(lo, hi)                                                                               \
    {                                                                                              \
        lo, hi, true, true                                                                         \
    }
#define LEFT_OPEN(lo, hi)                                                                          \
    {                                                                                              \
        lo, hi, true, false                                                                        \
    }
#define KEY(sec, nam, kind, flags, def, field, rng, words, allowed, meaning)                       \
    {                                                                                              \
        sec, nam, kind, flags, def, offsetof(config, field), sizeof(((config *)0)->field), rng,    \
            words, allowed, meaning                                                                \
    }

static const char *const bool_words[] = {"false", "true", NULL};
static const char *const motion_words[] = {"none", "sway", "heave", "table", NULL};
static const char *const scheme_words[] = {"standard",  "delta",          "delta-plus",
                                           "delta-ale", "delta-plus-ale", NULL};
static const char *const edbc_words[] = {"false", "true", "with-eta0", "auto", NULL};
static const char *const volume_correction_words[] = {"none", "geometric", "auto", NULL};
static const char *const eta_control_words[] = {"threshold", "adaptive", NULL};
static const char *const wall_words[] = {"no-slip", "free-slip", NULL};
static const char *const liquid_shape_words[] = {"box", "ellipse", NULL};

static const char *const sections[] = {"case",  "tank",     "liquid", "fluid", "motion",
                                       "model", "numerics", "probes", "output"};
#define N_SECTIONS (sizeof sections / sizeof sections[0])

/* The case file, section by section (docs/case-file.md; config_write follows this table). */
static const key_spec keys[] = {
    KEY("case", "name", KIND_NAME, KEY_DERIVED, "<file base name>", name, ANY, NULL,
        "a name of letters, digits, '.', '_' and '-' starting with a letter or digit",
        "name of the case: titles, and <name> in output.dir"),
    KEY("case", "dim", KIND_INT, 0, "2", dim, CLOSED(2, 3), NULL, "2 or 3",
        "number of space dimensions"),
    KEY("case", "t_end", KIND_REAL, KEY_REQUIRED, NULL, t_end, POSITIVE, NULL, "a time > 0 (s)",
        "simulated time at which the run ends"),
    KEY("case", "experiment_dissipation", KIND_REAL, 0, "0.0", experiment_dissipation, NON_NEGATIVE,
        NULL, "a number >= 0: the measured P/dW (P/dE_P with motion.decay > 0); 0 = none",
        "measured dissipation per period, drawn as a line by vcsph plot"),

    KEY("tank", "length", KIND_REAL, KEY_REQUIRED, NULL, tank_length, POSITIVE, NULL,
        "a length > 0 (m)", "L: the tank's inner length along x"),
    KEY("tank", "height", KIND_REAL, KEY_REQUIRED, NULL, tank_height, POSITIVE, NULL,
        "a length > 0 (m)", "D: the tank's inner height along y"),
    KEY("tank", "width", KIND_REAL, 0, "1.0", tank_width, POSITIVE, NULL,
        "a length > 0 (m; 3D only)",
        "W: the tank's inner width along z (2D results are per unit width)"),

    KEY("liquid", "height", KIND_REAL, KEY_REQUIRED, NULL, liquid_height, POSITIVE, NULL,
        "a length > 0 (m)",
        "H: the filling height; numerics.resolution counts particles across it"),
    KEY("liquid", "length", KIND_REAL, KEY_DERIVED, "<tank.length>", liquid_length, POSITIVE, NULL,
        "a length > 0 (m); default: the tank length", "length along x of the liquid box at t = 0"),
    KEY("liquid", "x0", KIND_REAL, 0, "0.0", liquid_x0, NON_NEGATIVE, NULL, "a position >= 0 (m)",
        "x of the liquid box's left side at t = 0"),
    KEY("liquid", "y0", KIND_REAL, 0, "0.0", liquid_y0, NON_NEGATIVE, NULL, "a position >= 0 (m)",
        "y of the liquid box's bottom at t = 0 (> 0 lifts it off the floor)"),
    KEY("liquid", "shape", KIND_WORD, 0, "box", liquid_shape, ANY, liquid_shape_words,
        "one of box | ellipse (the ellipse, or ellipsoid, inscribed in the box)",
        "the liquid at t = 0: the whole box, or the ellipse inscribed in it"),

    KEY("fluid", "density", KIND_REAL, 0, "1000.0", density, POSITIVE, NULL,
        "a density > 0 (kg/m^3)", "rho0: reference density of the liquid"),
    KEY("fluid", "viscosity", KIND_REAL, 0, "1.0e-6", viscosity, POSITIVE, NULL,
        "a kinematic viscosity > 0 (m^2/s)", "nu: kinematic viscosity of the liquid"),
    KEY("fluid", "surface_tension", KIND_REAL, 0, "0.0", surface_tension, NON_NEGATIVE, NULL,
        "a surface tension >= 0 (N/m; 0 = off)",
        "sigma: surface tension coefficient of the free surface"),
    KEY("fluid", "gravity", KIND_REAL, 0, "9.81", gravity, NON_NEGATIVE, NULL,
        "an acceleration >= 0 (m/s^2, along -y)", "g: magnitude of gravity, pointing along -y"),

    KEY("motion", "type", KIND_WORD, 0, "none", motion, ANY, motion_words,
        "one of none | sway | heave | table",
        "prescribed tank motion: none, sway (x), heave (y) or a table"),
    KEY("motion", "amplitude", KIND_REAL, 0, "0.0", amplitude, NON_NEGATIVE, NULL,
        "a length >= 0 (m)", "A: amplitude of the sway or heave displacement"),
    KEY("motion", "period", KIND_REAL, 0, "0.0", period, NON_NEGATIVE, NULL,
        "a time >= 0 (s), > 0 when type is sway or heave", "T: period of the sway or heave motion"),
    KEY("motion", "decay", KIND_REAL, 0, "0.0", decay, NON_NEGATIVE, NULL, "a rate >= 0 (1/s)",
        "l: the amplitude decays as A exp(-l t)"),
    KEY("motion", "phase", KIND_REAL, 0, "0.0", phase, ANY, NULL, "an angle (rad)",
        "phi: phase of the motion at t = 0, added to 2 pi t / T"),
    KEY("motion", "duration", KIND_REAL, 0, "0.0", duration, NON_NEGATIVE, NULL,
        "a time >= 0 (s; 0 = whole run)",
        "time after which the tank stops accelerating (keeps its velocity)"),
    KEY("motion", "file", KIND_PATH, 0, "", motion_file, ANY, NULL,
        "a readable CSV file t,x,y[,z] (required when type = table)",
        "CSV of the tank displacement t,x,y[,z] for type = table"),

    KEY("model", "scheme", KIND_WORD, 0, "delta-plus-ale", scheme, ANY, scheme_words,
        "one of standard | delta | delta-plus | delta-ale | delta-plus-ale",
        "SPH model of the paper's Table 1"),
    KEY("model", "edbc", KIND_WORD, 0, "auto", edbc, ANY, edbc_words,
        "one of auto | true | false | with-eta0 (auto: with-eta0 for delta-plus-ale, else false)",
        "EdBC of Eq. (9): p = 0, rho = rho0 on thin jets and drops"),
    KEY("model", "volume_correction", KIND_WORD, 0, "auto", volume_correction, ANY,
        volume_correction_words,
        "one of auto | none | geometric (auto: geometric for delta-plus-ale, else none)",
        "vcsph's geometric volume correction (moves particles)"),
    KEY("model", "eta_threshold", KIND_REAL, 0, "0.01", eta_threshold, OPEN(0.0, 1.0), NULL,
        "a number in (0, 1)", "|eps_v1| at which delta-plus-ALE switches eta"),
    KEY("model", "eta_control", KIND_WORD, 0, "threshold", eta_control, ANY, eta_control_words,
        "one of threshold | adaptive",
        "how delta-plus-ALE sets eta: the paper's switch or vcsph's adaptive control"),
    KEY("model", "les", KIND_BOOL, 0, "true", les, ANY, bool_words, "true or false",
        "Smagorinsky eddy viscosity (Eq. 4) with van Driest wall damping"),
    KEY("model", "wall", KIND_WORD, 0, "no-slip", wall, ANY, wall_words,
        "one of no-slip | free-slip", "velocity condition of the walls for the viscous term"),

    KEY("numerics", "resolution", KIND_INT, KEY_REQUIRED, NULL, resolution, CLOSED(4, INT_MAX),
        NULL, "an integer >= 4 (particles across liquid.height)",
        "N = H / dr: particles across the filling height"),
    KEY("numerics", "h_over_dr", KIND_REAL, KEY_DERIVED, "2.0 in 2D, 1.5 in 3D", h_over_dr,
        CLOSED(1.0, 4.0), NULL, "a number in [1, 4]; default 2.0 in 2D, 1.5 in 3D",
        "smoothing length over particle spacing (support radius 2h)"),
    KEY("numerics", "sound_speed", KIND_REAL_AUTO, 0, "auto", sound_speed, POSITIVE, NULL,
        "auto or a speed > 0 (m/s)",
        "c0 of the equation of state; auto: 10 sqrt(2 g_max H) (Eq. 6)"),
    KEY("numerics", "cfl", KIND_REAL_AUTO, 0, "auto", cfl, LEFT_OPEN(0.0, 2.0), NULL,
        "auto or a number in (0, 2]",
        "K_c of the acoustic time step dt = K_c h / c0 (Eq. 8); auto: Table 1"),
    KEY("numerics", "density_bound", KIND_REAL, 0, "0.2", density_bound, OPEN(0.0, 1.0), NULL,
        "a fraction in (0, 1): a density outside rho0 (1 +- bound) is a breakdown",
        "how far a density may stray from rho0 before the run stops (exit 3)"),

    KEY("probes", "gauges", KIND_GAUGES, 0, "", gauges, ANY, NULL,
        "x positions (m) inside the tank, separated by commas or spaces",
        "x of wave gauges: liquid depth on a vertical line, into probes.csv"),
    KEY("probes", "pressure", KIND_POINTS, 0, "", pressure_probes, ANY, NULL,
        "points 'x y[ z]' (m) inside the tank, separated by ';'",
        "points where the SPH pressure is sampled, into probes.csv"),

    KEY("output", "dir", KIND_PATH, KEY_NOT_EMPTY, "out/<name>", output_dir, ANY, NULL,
        "a directory path ('<name>' stands for case.name)",
        "output directory of the run (-o overrides it)"),
    KEY("output", "timeseries_every", KIND_REAL, 0, "0.0", timeseries_every, NON_NEGATIVE, NULL,
        "a time >= 0 (s; 0 = every step)",
        "simulated time between rows of timeseries.csv and probes.csv"),
    KEY("output", "snapshot_every", KIND_REAL, 0, "0.0", snapshot_every, NON_NEGATIVE, NULL,
        "a time >= 0 (s; 0 = none)", "simulated time between HDF5 snapshots"),
    KEY("output", "image_every", KIND_REAL, 0, "0.0", image_every, NON_NEGATIVE, NULL,
        "a time >= 0 (s; 0 = none)", "simulated time between particle images"),
    KEY("output", "checkpoint_every", KIND_REAL, 0, "600", checkpoint_every, NON_NEGATIVE, NULL,
        "a wall-clock time >= 0 (s; 0 = none)", "wall-clock time between checkpoints"),
    KEY("output", "graphical", KIND_BOOL, 0, "false", graphical, ANY, bool_words, "true or false",
        "also compute eps_gm (Eq. 15) at every time-series row (costly)"),
};
#define N_KEYS (sizeof keys / sizeof keys[0])

/* ---- parse state -------------------------------------------------------------------------- */

typedef struct {
    config *cfg;
    const char *origin;    /* names the input in messages */
    const char *case_path; /* the case file, to find motion.file beside it; NULL for a string */
    char *err;
    size_t err_len;
    bool failed;
    FILE *file;       /* the input is either a file ... */
    const char *text; /* ... or the rest of a string */
    int lineno;
    int section_line[N_SECTIONS]; /* first header line of each section, 0 if absent */
    int key_line[N_KEYS];         /* where each key was set: a line, LINE_SET, or 0 (default) */
    int point_coords;             /* coordinates per pressure point as given, 0 if none */
    char line[CASE_LINE_MAX];     /* the current line as read, before inih cuts it up */
} parse_ctx;

/* Only the first error is kept: later ones are usually consequences of it. */
PRINTF_LIKE(2, 3) static void fail(parse_ctx *ctx, const char *fmt, ...)
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
static const char *where(const parse_ctx *ctx, int line, char *buf, size_t size)
{
    if (line == LINE_SET) return "--set";
    snprintf(buf, size, "%s:%d", ctx->origin, line);
    return buf;
}

static void fail_value(parse_ctx *ctx, const key_spec *k, int line, const char *text,
                       const char *why)
{
    char at[CONFIG_PATH_MAX + 32];
    int n = (int)strlen(text);
    bool cut = n > SHOWN_VALUE_MAX;
    fail(ctx, "%s: %s.%s = %.*s%s: %s", where(ctx, line, at, sizeof at), k->section, k->name,
         cut ? SHOWN_VALUE_MAX - 3 : n, text, cut ? "..." : "", why);
}

/* ---- small helpers ------------------------------------------------------------------------ */

static const char *skip_space(const char *s)
{
    while (isspace((unsigned char)*s)) s++;
    return s;
}

static bool is_ascii_alnum(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

static void *field(config *cfg, const key_spec *k) { return (char *)cfg + k->offset; }

static const void *field_c(const config *cfg, const key_spec *k)
{
    return (const char *)cfg + k->offset;
}

static int section_index(const char *name)
{
    for (size_t i = 0; i < N_SECTIONS; i++)
        if (strcmp(sections[i], name) == 0) return (int)i;
    return -1;
}

static const key_spec *find_key(const char *section, const char *name)
{
    for (size_t i = 0; i < N_KEYS; i++)
        if (strcmp(keys[i].section, section) == 0 && strcmp(keys[i].name, name) == 0)
            return &keys[i];
    return NULL;
}

/* For internal look-ups of keys that exist by construction. */
static const key_spec *key_of(const char *section, const char *name)
{
    const key_spec *k = find_key(section, name);
    if (!k) abort();
    return k;
}

static int word_index(const char *const *words, const char *s)
{
    for (int i = 0; words[i]; i++)
        if (strcmp(words[i], s) == 0) return i;
    return -1;
}

static const char *word_at(const char *const *words, int i)
{
    for (int j = 0; words[j]; j++)
        if (j == i) return words[j];
    return "?";
}

static bool in_range(double v, const range *r)
{
    bool above = r->lo_open ? v > r->lo : v >= r->lo;
    bool below = r->hi_open ? v < r->hi : v <= r->hi;
    return above && below;
}

/* A whole string that is one finite number: "1.0abc", "", "inf" and "nan" are not. */
static bool parse_real(const char *s, double *out)
{
    if (!*s || isspace((unsigned char)*s)) return false;
    char *end;
    double v = strtod(s, &end);
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
static bool store_string(char *dst, size_t size, const char *s)
{
    size_t n = strlen(s);
    if (n >= size) return false;
    memset(dst, 0, size);
    memcpy(dst, s, n);
    return true;
}

/* ---- did you mean ------------------------------------------------------------------------- */

/* Case-insensitive Levenshtein distance; long strings are never close. */
static int edit_distance(const char *a, const char *b)
{
    enum { CAP = 64 };
    size_t la = strlen(a), lb = strlen(b);
    if (la >= CAP || lb >= CAP) return INT_MAX;
    int prev[CAP], cur[CAP];
    for (size_t j = 0; j <= lb; j++) prev[j] = (int)j;
    for (size_t i = 1; i <= la; i++) {
        cur[0] = (int)i;
        for (size_t j = 1; j <= lb; j++) {
            int same = tolower((unsigned char)a[i - 1]) == tolower((unsigned char)b[j - 1]);
            int best = prev[j - 1] + !same;
            if (prev[j] + 1 < best) best = prev[j] + 1;
            if (cur[j - 1] + 1 < best) best = cur[j - 1] + 1;
            cur[j] = best;
        }
        memcpy(prev, cur, sizeof prev);
    }
    return prev[lb];
}

/* The candidate closest to `given` (edit distance <= 2 and shorter than the word), else one
 * that `given` starts or ends a prefix of; NULL when nothing is close. */
static const char *suggest(const char *given, const char *const *cands, size_t n)
{
    const char *best = NULL;
    int best_d = 3;
    int len = (int)strlen(given);
    for (size_t i = 0; i < n; i++) {
        int d = edit_distance(given, cands[i]);
        if (d < best_d && d < len) {
            best = cands[i];
            best_d = d;
        }
    }
    if (best || len < 2) return best;
    for (size_t i = 0; i < n; i++) {
        size_t lc = strlen(cands[i]);
        if (strncmp(cands[i], given, (size_t)len) == 0 ||
            (lc >= 2 && strncmp(given, cands[i], lc) == 0))
            return cands[i];
    }
    return NULL;
}

static size_t section_key_names(const char *section, const char **names)
{
    size_t n = 0;
    for (size_t i = 0; i < N_KEYS; i++)
        if (strcmp(keys[i].section, section) == 0) names[n++] = keys[i].name;
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

static void fail_unknown_section(parse_ctx *ctx, const char *at, const char *name)
{
    const char *hint = suggest(name, sections, N_SECTIONS);
    char list[256];
    join_words(sections, N_SECTIONS, list, sizeof list);
    if (hint)
        fail(ctx, "%s: unknown section [%s]; did you mean [%s]?", at, name, hint);
    else
        fail(ctx, "%s: unknown section [%s]; sections are: %s", at, name, list);
}

static void fail_unknown_key(parse_ctx *ctx, const char *at, const char *section, const char *name)
{
    const char *names[N_KEYS];
    size_t n = section_key_names(section, names);
    const char *hint = suggest(name, names, n);
    if (hint) {
        fail(ctx, "%s: unknown key '%s.%s'; did you mean '%s.%s'?", at, section, name, section,
             hint);
        return;
    }
    /* The right key in the wrong section is a common slip. */
    for (size_t i = 0; i < N_KEYS; i++) {
        if (strcmp(keys[i].name, name) == 0) {
            fail(ctx, "%s: unknown key '%s.%s'; did you mean '%s.%s'?", at, section, name,
                 keys[i].section, name);
            return;
        }
    }
    char list[512];
    join_words(names, n, list, sizeof list);
    fail(ctx, "%s: unknown key '%s.%s'; [%s] has: %s", at, section, name, section, list);
}

/* ---- setters: text -> field, with the range check ------------------------------------------ */

typedef bool (*setter)(parse_ctx *ctx, const key_spec *k, const char *s, char *why, size_t n);
typedef void (*formatter)(const config *cfg, const key_spec *k, char *buf, size_t size);

static bool set_int(parse_ctx *ctx, const key_spec *k, const char *s, char *why, size_t n)
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
    *(int *)field(ctx->cfg, k) = (int)v;
    return true;
}

static bool set_real_checked(parse_ctx *ctx, const key_spec *k, const char *s, char *why, size_t n)
{
    double v;
    if (!parse_real(s, &v)) {
        snprintf(why, n, "not a finite number; must be %s", k->allowed);
        return false;
    }
    if (!in_range(v, &k->range)) {
        snprintf(why, n, "must be %s", k->allowed);
        return false;
    }
    *(double *)field(ctx->cfg, k) = v;
    return true;
}

static bool set_real_auto(parse_ctx *ctx, const key_spec *k, const char *s, char *why, size_t n)
{
    if (strcmp(s, "auto") == 0) {
        *(double *)field(ctx->cfg, k) = 0.0;
        return true;
    }
    return set_real_checked(ctx, k, s, why, n);
}

static bool set_word(parse_ctx *ctx, const key_spec *k, const char *s, char *why, size_t n)
{
    int i = word_index(k->words, s);
    if (i < 0) {
        size_t count = 0;
        while (k->words[count]) count++;
        const char *hint = suggest(s, k->words, count);
        if (hint)
            snprintf(why, n, "did you mean '%s'? must be %s", hint, k->allowed);
        else
            snprintf(why, n, "must be %s", k->allowed);
        return false;
    }
    if (k->kind == KIND_BOOL)
        *(bool *)field(ctx->cfg, k) = i != 0;
    else
        memcpy(field(ctx->cfg, k), &i, sizeof i);
    return true;
}

static bool set_name(parse_ctx *ctx, const key_spec *k, const char *s, char *why, size_t n)
{
    bool ok = is_ascii_alnum(s[0]);
    for (const char *p = s; ok && *p; p++) ok = is_ascii_alnum(*p) || strchr("._-", *p);
    if (!ok || !store_string(field(ctx->cfg, k), k->size, s)) {
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
    return strchr(COMMENT_CHARS, *p) && (p == s || isspace((unsigned char)p[-1]));
}

/* A path must survive config_write and config_load: no control characters, and no ';' or '#'
 * that INI would take for the start of a comment. */
static bool path_is_writable(const char *s)
{
    for (const char *p = s; *p; p++) {
        if (iscntrl((unsigned char)*p)) return false;
        if (starts_comment(s, p)) return false;
    }
    return true;
}

static bool set_path(parse_ctx *ctx, const key_spec *k, const char *s, char *why, size_t n)
{
    if ((k->flags & KEY_NOT_EMPTY) && !*s) {
        snprintf(why, n, "empty; must be %s", k->allowed);
        return false;
    }
    if (!path_is_writable(s)) {
        snprintf(why, n,
                 "control characters, and ';' or '#' first or after a space (INI reads a "
                 "comment there), are not allowed in a path");
        return false;
    }
    if (!store_string(field(ctx->cfg, k), k->size, s)) {
        snprintf(why, n, "longer than %zu characters", k->size - 1);
        return false;
    }
    return true;
}

/* Reads one number of a list; `seps` are the characters that may follow it. */
static bool list_number(const key_spec *k, const char **p, const char *seps, double *v, char *why,
                        size_t n)
{
    char *end;
    *v = strtod(*p, &end);
    if (end == *p || !isfinite(*v) ||
        (*end && !isspace((unsigned char)*end) && !strchr(seps, *end))) {
        char stop[16];
        snprintf(stop, sizeof stop, " \t%s", seps);
        int len = (int)strcspn(*p, stop);
        if (len == 0)
            snprintf(why, n, "unexpected '%c'; must be %s", **p, k->allowed);
        else
            snprintf(why, n, "'%.*s' is not a finite number; must be %s", len > 40 ? 40 : len, *p,
                     k->allowed);
        return false;
    }
    *p = skip_space(end);
    return true;
}

static bool set_gauges(parse_ctx *ctx, const key_spec *k, const char *s, char *why, size_t n)
{
    double x[CONFIG_PROBES_MAX];
    int count = 0;
    for (const char *p = skip_space(s); *p;) {
        if (count == CONFIG_PROBES_MAX) {
            snprintf(why, n, "more than %d gauges", CONFIG_PROBES_MAX);
            return false;
        }
        if (!list_number(k, &p, ",", &x[count++], why, n)) return false;
        if (*p == ',') {
            p = skip_space(p + 1);
            if (!*p) {
                snprintf(why, n, "a ',' must be followed by a position; must be %s", k->allowed);
                return false;
            }
        }
    }
    config *cfg = ctx->cfg;
    memset(cfg->gauges, 0, sizeof cfg->gauges);
    memcpy(cfg->gauges, x, (size_t)count * sizeof x[0]);
    cfg->n_gauges = count;
    return true;
}

/* Points "x y[ z]; x y[ z]": 2 or 3 coordinates each, the same number for all; whether that
 * number matches case.dim is checked once dim is final. */
static bool set_points(parse_ctx *ctx, const key_spec *k, const char *s, char *why, size_t n)
{
    double pts[CONFIG_PROBES_MAX][3] = {{0}};
    int count = 0, coords = 0;
    const char *p = skip_space(s);
    while (*p) {
        if (count == CONFIG_PROBES_MAX) {
            snprintf(why, n, "more than %d pressure probes", CONFIG_PROBES_MAX);
            return false;
        }
        int c = 0;
        while (*p && *p != ';') {
            if (c == 3) {
                snprintf(why, n, "point %d has more than 3 coordinates; must be %s", count + 1,
                         k->allowed);
                return false;
            }
            if (!list_number(k, &p, ";", &pts[count][c++], why, n)) return false;
        }
        if (c < 2 || (coords && c != coords)) {
            snprintf(why, n, "point %d has %d coordinates%s; must be %s", count + 1, c,
                     coords && c != coords ? ", unlike point 1" : "", k->allowed);
            return false;
        }
        coords = c;
        count++;
        if (*p == ';') {
            p = skip_space(p + 1);
            if (!*p) {
                snprintf(why, n, "a ';' must be followed by a point; must be %s", k->allowed);
                return false;
            }
        }
    }
    config *cfg = ctx->cfg;
    memcpy(cfg->pressure_probes, pts, sizeof pts);
    cfg->n_pressure_probes = count;
    ctx->point_coords = coords;
    return true;
}

/* ---- formatters: field -> text that the setters read back to the same bits ---------------- */

/* The shortest of %.15g, %.16g, %.17g that reads back exactly (%.17g always does). */
static void format_double(double v, char *buf, size_t size)
{
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, size, "%.*g", prec, v);
        if (strtod(buf, NULL) == v) return;
    }
}

static void format_int(const config *cfg, const key_spec *k, char *buf, size_t size)
{
    snprintf(buf, size, "%d", *(const int *)field_c(cfg, k));
}

static void format_real(const config *cfg, const key_spec *k, char *buf, size_t size)
{
    format_double(*(const double *)field_c(cfg, k), buf, size);
}

static void format_real_auto(const config *cfg, const key_spec *k, char *buf, size_t size)
{
    double v = *(const double *)field_c(cfg, k);
    if (v == 0.0)
        snprintf(buf, size, "auto");
    else
        format_double(v, buf, size);
}

static void format_word(const config *cfg, const key_spec *k, char *buf, size_t size)
{
    int i;
    if (k->kind == KIND_BOOL)
        i = *(const bool *)field_c(cfg, k);
    else
        memcpy(&i, field_c(cfg, k), sizeof i);
    snprintf(buf, size, "%s", word_at(k->words, i));
}

static void format_string(const config *cfg, const key_spec *k, char *buf, size_t size)
{
    snprintf(buf, size, "%s", (const char *)field_c(cfg, k));
}

static void format_gauges(const config *cfg, const key_spec *k, char *buf, size_t size)
{
    (void)k;
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < cfg->n_gauges && used < size; i++) {
        char num[32];
        format_double(cfg->gauges[i], num, sizeof num);
        int w = snprintf(buf + used, size - used, "%s%s", i ? ", " : "", num);
        if (w < 0) break;
        used += (size_t)w;
    }
}

/* No space before ';': in INI " ;" starts a comment. */
static void format_point_list(const config *cfg, int coords, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < cfg->n_pressure_probes && used < size; i++) {
        for (int d = 0; d < coords && d < 3 && used < size; d++) {
            char num[32];
            format_double(cfg->pressure_probes[i][d], num, sizeof num);
            const char *sep = d ? " " : i ? "; " : "";
            int w = snprintf(buf + used, size - used, "%s%s", sep, num);
            if (w < 0) return;
            used += (size_t)w;
        }
    }
}

static void format_points(const config *cfg, const key_spec *k, char *buf, size_t size)
{
    (void)k;
    format_point_list(cfg, cfg->dim, buf, size);
}

static const struct {
    setter set;
    formatter format;
} kinds[] = {
    [KIND_INT] = {set_int, format_int},
    [KIND_REAL] = {set_real_checked, format_real},
    [KIND_REAL_AUTO] = {set_real_auto, format_real_auto},
    [KIND_BOOL] = {set_word, format_word},
    [KIND_WORD] = {set_word, format_word},
    [KIND_NAME] = {set_name, format_string},
    [KIND_PATH] = {set_path, format_string},
    [KIND_GAUGES] = {set_gauges, format_gauges},
    [KIND_POINTS] = {set_points, format_points},
};

/* Sets a key from its text, recording where it came from; false (and the message) if the text
 * is not allowed. */
static bool apply(parse_ctx *ctx, const key_spec *k, const char *text, int line)
{
    char why[512];
    if (!kinds[k->kind].set(ctx, k, text, why, sizeof why)) {
        fail_value(ctx, k, line, text, why);
        return false;
    }
    ctx->key_line[k - keys] = line;
    return true;
}

/* Whether the file or --set gave the key (rather than its default). */
static bool given(const parse_ctx *ctx, const key_spec *k) { return ctx->key_line[k - keys] != 0; }

/* For checks made once all keys are known: blames the key where it was set, or where it
 * should have been (its section's header, or line 0 when the section is absent too). */
static void fail_key(parse_ctx *ctx, const key_spec *k, const char *why)
{
    int line = ctx->key_line[k - keys];
    if (line != 0) {
        char value[CASE_LINE_MAX];
        kinds[k->kind].format(ctx->cfg, k, value, sizeof value);
        fail_value(ctx, k, line, value, why);
        return;
    }
    int header = ctx->section_line[section_index(k->section)];
    char at[CONFIG_PATH_MAX + 32];
    if (header)
        fail(ctx, "%s: %s.%s: missing in [%s]; %s", where(ctx, header, at, sizeof at), k->section,
             k->name, k->section, why);
    else
        fail(ctx, "%s: %s.%s: missing, and so is section [%s]; %s", where(ctx, 0, at, sizeof at),
             k->section, k->name, k->section, why);
}

/* ---- reading the file --------------------------------------------------------------------- */

static bool next_text_line(parse_ctx *ctx, char *buf, size_t size, bool *complete)
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

static bool next_file_line(parse_ctx *ctx, char *buf, size_t size, bool *complete)
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
static void check_section_header(parse_ctx *ctx)
{
    const char *p = ctx->line;
    if (ctx->lineno == 1 && strncmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;
    p = skip_space(p);
    if (*p != '[') return;
    const char *end = strchr(p + 1, ']');
    if (!end) return; /* inih reports the syntax error */
    char name[128];
    int len = (int)(end - p - 1);
    snprintf(name, sizeof name, "%.*s", len, p + 1);
    char at[CONFIG_PATH_MAX + 32];
    where(ctx, ctx->lineno, at, sizeof at);
    const char *rest = skip_space(end + 1);
    if (*rest && !strchr(COMMENT_CHARS, *rest)) {
        fail(ctx, "%s: unexpected text after [%s]; only a comment may follow a section header", at,
             name);
        return;
    }
    int i = section_index(name);
    if (i < 0)
        fail_unknown_section(ctx, at, name);
    else if (!ctx->section_line[i])
        ctx->section_line[i] = ctx->lineno;
}

/* inih's reader: one line per call, so ctx->lineno is the line of the key that the handler
 * sees next (Debian's inih has no INI_HANDLER_LINENO). */
static char *read_line(char *str, int num, void *stream)
{
    parse_ctx *ctx = stream;
    bool complete = true;
    if (ctx->failed || num < 2) return NULL;
    bool got = ctx->file ? next_file_line(ctx, str, (size_t)num, &complete)
                         : next_text_line(ctx, str, (size_t)num, &complete);
    if (!got) return NULL;
    ctx->lineno++;
    if (!complete) {
        char at[CONFIG_PATH_MAX + 32];
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
        if (strchr(COMMENT_CHARS, *p) && isspace((unsigned char)p[-1])) {
            const char *q = skip_space(p + 1);
            return isdigit((unsigned char)*q) || (*q && strchr("+-.", *q));
        }
    }
    return false;
}

static int on_key(void *user, const char *section, const char *name, const char *value)
{
    parse_ctx *ctx = user;
    char at[CONFIG_PATH_MAX + 32];
    where(ctx, ctx->lineno, at, sizeof at);
    if (ctx->failed) return 0;
    if (!*section) {
        fail(ctx, "%s: key '%s' comes before any [section]", at, name);
        return 0;
    }
    const key_spec *k = find_key(section, name);
    if (!k) {
        fail_unknown_key(ctx, at, section, name);
        return 0;
    }
    int first = ctx->key_line[k - keys];
    if (first > 0) {
        fail(ctx, "%s: %s.%s: set twice (first on line %d); give each key once", at, section, name,
             first);
        return 0;
    }
    if ((k->kind == KIND_GAUGES || k->kind == KIND_POINTS) && list_cut_by_comment(ctx->line)) {
        fail_value(ctx, k, ctx->lineno, value,
                   "' ;' or ' #' starts a comment in INI and would drop the numbers after it; "
                   "write ';' right after a number, as in '0.1 0.2; 0.3 0.4'");
        return 0;
    }
    return apply(ctx, k, value, ctx->lineno);
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

static void parse_input(parse_ctx *ctx)
{
    /* No multi-line values: an indented line must not be glued to the previous value. */
    static const ini_options ours = {false, true,          true,          true,         true,
                                     false, COMMENT_CHARS, COMMENT_CHARS, CASE_LINE_MAX};
    ini_options saved = ini_options_get();
    ini_options_set(&ours);
    int rc = ini_parse_stream(read_line, ctx, on_key, ctx);
    int read_errno = errno;
    ini_options_set(&saved);
    if (ctx->failed) return;
    char at[CONFIG_PATH_MAX + 32];
    if (ctx->file && ferror(ctx->file)) {
        fail(ctx, "%s: cannot read: %s", ctx->origin, strerror(read_errno));
    } else if (rc > 0) {
        const char *text = skip_space(ctx->line);
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

/* ---- overrides ---------------------------------------------------------------------------- */

/* Copies [s, s+n) without surrounding white space; false if it had to be cut to fit. */
static bool copy_trimmed(char *dst, size_t size, const char *s, size_t n)
{
    while (n > 0 && isspace((unsigned char)*s)) s++, n--;
    while (n > 0 && isspace((unsigned char)s[n - 1])) n--;
    snprintf(dst, size, "%.*s", (int)n, s);
    return n < size;
}

static void apply_override(parse_ctx *ctx, const char *arg)
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
    if (section_index(section) < 0) {
        fail_unknown_section(ctx, "--set", section);
        return;
    }
    const key_spec *k = find_key(section, name);
    if (!k) {
        fail_unknown_key(ctx, "--set", section, name);
        return;
    }
    if (!copy_trimmed(ctx->line, sizeof ctx->line, eq + 1, strlen(eq + 1))) {
        fail(ctx, "--set: %s.%s: value longer than %zu characters", section, name,
             sizeof ctx->line - 1);
        return;
    }
    apply(ctx, k, ctx->line, LINE_SET);
}

/* ---- checks and defaults once every key is known ------------------------------------------- */

/* Appends to buf what a missing key is and where it belongs, "; " between two. */
static void describe_missing(const parse_ctx *ctx, const key_spec *k, char *buf, size_t size)
{
    size_t used = strlen(buf);
    int header = ctx->section_line[section_index(k->section)];
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
static void check_required(parse_ctx *ctx)
{
    const key_spec *missing[N_KEYS];
    size_t n = 0;
    for (size_t i = 0; i < N_KEYS; i++)
        if ((keys[i].flags & KEY_REQUIRED) && !given(ctx, &keys[i])) missing[n++] = &keys[i];
    if (n == 0) return;
    char why[1024] = "";
    if (n == 1) {
        snprintf(why, sizeof why, "required: %s", missing[0]->allowed);
        fail_key(ctx, missing[0], why);
        return;
    }
    for (size_t i = 0; i < n; i++) describe_missing(ctx, missing[i], why, sizeof why);
    char at[CONFIG_PATH_MAX + 32];
    fail(ctx, "%s: %zu required keys missing: %s",
         where(ctx, ctx->section_line[section_index(missing[0]->section)], at, sizeof at), n, why);
}

/* Replaces every "<name>" in the output directory by the case name. */
static bool expand_name(char *dir, size_t size, const char *name)
{
    static const char token[] = "<name>";
    char out[CONFIG_PATH_MAX];
    size_t used = 0;
    for (const char *p = dir; *p;) {
        const char *hit = strstr(p, token);
        size_t take = hit ? (size_t)(hit - p) : strlen(p);
        const char *ins = hit ? name : "";
        if (used + take + strlen(ins) >= sizeof out) return false;
        memcpy(out + used, p, take);
        used += take;
        memcpy(out + used, ins, strlen(ins));
        used += strlen(ins);
        p += take + (hit ? sizeof token - 1 : 0);
    }
    out[used] = '\0';
    return store_string(dir, size, out);
}

/* case.name by default: the case file's base name without its extension, so that a case
 * without a name writes into out/<its file name>. Characters a name may not hold become '_',
 * and "case-" goes in front of one that does not start with a letter or digit; a case read
 * from a string (no file) is "case". */
static void default_name(const char *path, char *name, size_t size)
{
    const char *base = path ? strrchr(path, '/') : NULL;
    base = base ? base + 1 : path;
    if (!base || !*base) {
        snprintf(name, size, "case");
        return;
    }
    const char *dot = strrchr(base, '.');
    size_t len = dot && dot > base ? (size_t)(dot - base) : strlen(base);
    size_t used = is_ascii_alnum(base[0]) ? 0 : (size_t)snprintf(name, size, "case-");
    for (size_t i = 0; i < len && used + 1 < size; i++) {
        char c = base[i];
        name[used++] = is_ascii_alnum(c) || strchr("._-", c) ? c : '_';
    }
    name[used] = '\0';
}

static void resolve_defaults(parse_ctx *ctx)
{
    config *cfg = ctx->cfg;
    const key_spec *name = key_of("case", "name");
    if (!given(ctx, name)) {
        char text[CONFIG_NAME_MAX];
        default_name(ctx->case_path, text, sizeof text);
        if (!apply(ctx, name, text, 0)) return; /* cannot happen: default_name makes a name */
    }
    if (!given(ctx, key_of("liquid", "length"))) cfg->liquid_length = cfg->tank_length;
    if (!given(ctx, key_of("numerics", "h_over_dr"))) cfg->h_over_dr = cfg->dim == 3 ? 1.5 : 2.0;
    /* the scheme-dependent defaults (docs/volume-correction.md, "Defaults") */
    bool plus_ale = cfg->scheme == SCHEME_DELTA_PLUS_ALE;
    if (cfg->edbc == EDBC_AUTO) cfg->edbc = plus_ale ? EDBC_WITH_ETA0 : EDBC_OFF;
    if (cfg->volume_correction == VOLUME_CORRECTION_AUTO)
        cfg->volume_correction = plus_ale ? VOLUME_CORRECTION_GEOMETRIC : VOLUME_CORRECTION_NONE;
    if (!expand_name(cfg->output_dir, sizeof cfg->output_dir, cfg->name))
        fail_key(ctx, key_of("output", "dir"), "too long once '<name>' is replaced");
}

static bool exceeds(double a, double b) { return a > b + FIT_SLACK * fabs(b); }

static void check_liquid(parse_ctx *ctx)
{
    const config *cfg = ctx->cfg;
    char why[256];
    if (exceeds(cfg->liquid_y0 + cfg->liquid_height, cfg->tank_height)) {
        snprintf(why, sizeof why,
                 "liquid higher than the tank: "
                 "liquid.y0 + liquid.height = %g m > tank.height = %g m",
                 cfg->liquid_y0 + cfg->liquid_height, cfg->tank_height);
        fail_key(ctx, key_of("liquid", "height"), why);
        return;
    }
    if (exceeds(cfg->liquid_x0 + cfg->liquid_length, cfg->tank_length)) {
        const key_spec *length = key_of("liquid", "length");
        const key_spec *blamed = given(ctx, length) ? length : key_of("liquid", "x0");
        snprintf(why, sizeof why,
                 "liquid longer than the tank: "
                 "liquid.x0 + liquid.length = %g m > tank.length = %g m",
                 cfg->liquid_x0 + cfg->liquid_length, cfg->tank_length);
        fail_key(ctx, blamed, why);
    }
}

static bool readable_file(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) return false;
    FILE *f = fopen(path, "r");
    if (!f) return false;
    fclose(f);
    return true;
}

/* The motion table as given when it opens from the current directory (a path typed with
 * --set), else beside the case file (a path written in the case file). */
static bool locate_table(const char *file, const char *case_path, char *out, size_t size)
{
    if (readable_file(file)) return store_string(out, size, file);
    const char *slash = case_path ? strrchr(case_path, '/') : NULL;
    if (!slash || file[0] == '/') return false;
    char joined[CONFIG_PATH_MAX];
    int n = snprintf(joined, sizeof joined, "%.*s/%s", (int)(slash - case_path), case_path, file);
    return n > 0 && (size_t)n < sizeof joined && readable_file(joined) &&
           path_is_writable(joined) && store_string(out, size, joined);
}

static void check_motion(parse_ctx *ctx)
{
    config *cfg = ctx->cfg;
    char why[CONFIG_PATH_MAX + 256];
    const char *type = config_motion_name(cfg->motion);
    if ((cfg->motion == MOTION_SWAY || cfg->motion == MOTION_HEAVE) && !(cfg->period > 0.0)) {
        snprintf(why, sizeof why, "must be a time > 0 (s) when motion.type = %s", type);
        fail_key(ctx, key_of("motion", "period"), why);
        return;
    }
    if (cfg->motion != MOTION_TABLE) return;
    const key_spec *file = key_of("motion", "file");
    if (!cfg->motion_file[0]) {
        fail_key(ctx, file, "required when motion.type = table: a CSV file t,x,y[,z]");
        return;
    }
    char as_given[CONFIG_PATH_MAX];
    snprintf(as_given, sizeof as_given, "%s", cfg->motion_file);
    if (!locate_table(as_given, ctx->case_path, cfg->motion_file, sizeof cfg->motion_file)) {
        snprintf(why, sizeof why,
                 "cannot read '%s' (looked from the current directory%s); must be %s", as_given,
                 ctx->case_path ? " and beside the case file" : "", file->allowed);
        fail_key(ctx, file, why);
    }
}

static void check_probes(parse_ctx *ctx)
{
    const config *cfg = ctx->cfg;
    const key_spec *gauges = key_of("probes", "gauges"), *pressure = key_of("probes", "pressure");
    char why[256];
    for (int i = 0; i < cfg->n_gauges; i++) {
        if (cfg->gauges[i] < 0.0 || exceeds(cfg->gauges[i], cfg->tank_length)) {
            snprintf(why, sizeof why, "gauge %d at x = %g m is outside the tank, x in [0, %g] m",
                     i + 1, cfg->gauges[i], cfg->tank_length);
            fail_key(ctx, gauges, why);
            return;
        }
    }
    if (ctx->point_coords && ctx->point_coords != cfg->dim) {
        /* Shown with the coordinates as given: formatting for dim would drop or invent some. */
        char as_given[CASE_LINE_MAX];
        format_point_list(cfg, ctx->point_coords, as_given, sizeof as_given);
        snprintf(why, sizeof why, "points have %d coordinates but case.dim = %d; write %s",
                 ctx->point_coords, cfg->dim, cfg->dim == 3 ? "'x y z'" : "'x y'");
        fail_value(ctx, pressure, ctx->key_line[pressure - keys], as_given, why);
        return;
    }
    const double size[3] = {cfg->tank_length, cfg->tank_height, cfg->tank_width};
    for (int i = 0; i < cfg->n_pressure_probes; i++) {
        for (int d = 0; d < cfg->dim; d++) {
            double v = cfg->pressure_probes[i][d];
            if (v < 0.0 || exceeds(v, size[d])) {
                snprintf(why, sizeof why,
                         "pressure point %d: %c = %g m is outside the tank, %c in [0, %g] m", i + 1,
                         "xyz"[d], v, "xyz"[d], size[d]);
                fail_key(ctx, pressure, why);
                return;
            }
        }
    }
}

/* In this order: defaults that depend on other keys need those keys first. */
static void (*const checks[])(parse_ctx *ctx) = {check_required, resolve_defaults, check_liquid,
                                                 check_motion, check_probes};

/* ---- public ------------------------------------------------------------------------------- */

static void apply_defaults(parse_ctx *ctx)
{
    for (size_t i = 0; i < N_KEYS; i++) {
        bool has_default = !(keys[i].flags & (KEY_REQUIRED | KEY_DERIVED));
        if (has_default && !apply(ctx, &keys[i], keys[i].def, 0))
            abort(); /* a default that its own key rejects is a bug of this table */
    }
}

static int load(parse_ctx *ctx, const char *const *overrides, int n_overrides)
{
    apply_defaults(ctx);
    parse_input(ctx);
    for (int i = 0; i < n_overrides && !ctx->failed; i++) apply_override(ctx, overrides[i]);
    for (size_t i = 0; i < sizeof checks / sizeof checks[0] && !ctx->failed; i++) checks[i](ctx);
    if (ctx->failed) return 2;
    if (ctx->err && ctx->err_len) ctx->err[0] = '\0';
    return 0;
}

static void ctx_init(parse_ctx *ctx, config *cfg, const char *origin, char *err, size_t err_len)
{
    /* Zero first, padding included, so that two loads of one case compare equal with memcmp. */
    memset(cfg, 0, sizeof *cfg);
    memset(ctx, 0, sizeof *ctx);
    ctx->cfg = cfg;
    ctx->origin = origin ? origin : "(string)";
    ctx->err = err;
    ctx->err_len = err_len;
}

int config_load(config *cfg, const char *path, const char *const *overrides, int n_overrides,
                char *err, size_t err_len)
{
    parse_ctx *ctx = malloc(sizeof *ctx);
    if (!ctx) {
        if (err && err_len) snprintf(err, err_len, "%s: out of memory", path);
        return 2;
    }
    ctx_init(ctx, cfg, path, err, err_len);
    ctx->case_path = path;
    ctx->file = fopen(path, "r");
    int rc;
    if (!ctx->file) {
        fail(ctx, "%s: cannot open: %s", path, strerror(errno));
        rc = 2;
    } else {
        rc = load(ctx, overrides, n_overrides);
        fclose(ctx->file);
    }
    free(ctx);
    return rc;
}

int config_load_string(config *cfg, const char *text, const char *origin,
                       const char *const *overrides, int n_overrides, char *err, size_t err_len)
{
    parse_ctx *ctx = malloc(sizeof *ctx);
    if (!ctx) {
        if (err && err_len) snprintf(err, err_len, "%s: out of memory", origin ? origin : "");
        return 2;
    }
    ctx_init(ctx, cfg, origin, err, err_len);
    ctx->text = text ? text : "";
    int rc = load(ctx, overrides, n_overrides);
    free(ctx);
    return rc;
}

void config_write(const config *cfg, FILE *out)
{
    char value[CASE_LINE_MAX];
    fputs("; vcsph case, fully resolved: every key, with defaults and --set applied\n", out);
    const char *section = NULL;
    for (size_t i = 0; i < N_KEYS; i++) {
        const key_spec *k = &keys[i];
        if (!section || strcmp(section, k->section) != 0) {
            fprintf(out, "%s[%s]\n", section ? "\n" : "", k->section);
            section = k->section;
        }
        kinds[k->kind].format(cfg, k, value, sizeof value);
        fprintf(out, "%-16s = %s ; %s\n", k->name, value, k->allowed);
    }
}

char *config_text(const config *cfg)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f) return NULL;
    config_write(cfg, f);
    return fclose(f) == 0 ? text : (free(text), NULL);
}

/* The default column of `vcsph keys`: the default as a file spells it, the rule of a derived
 * default, or "required". */
static const char *key_default_text(const key_spec *k)
{
    return (k->flags & KEY_REQUIRED) ? "required" : k->def;
}

void config_write_keys(FILE *out)
{
    for (size_t i = 0; i < N_KEYS; i++) {
        const key_spec *k = &keys[i];
        fprintf(out, "%s.%s\t%s\t%s\t%s\n", k->section, k->name, key_default_text(k), k->allowed,
                k->meaning);
    }
}

const char *config_scheme_name(scheme_kind s) { return word_at(scheme_words, (int)s); }
const char *config_motion_name(motion_kind m) { return word_at(motion_words, (int)m); }
const char *config_edbc_name(edbc_mode e) { return word_at(edbc_words, (int)e); }
const char *config_volume_correction_name(volume_correction_kind v)
{
    return word_at(volume_correction_words, (int)v);
}
const char *config_eta_control_name(eta_control_kind e)
{
    return word_at(eta_control_words, (int)e);
}
const char *config_wall_name(wall_kind w) { return word_at(wall_words, (int)w); }
const char *config_liquid_shape_name(liquid_shape_kind s)
{
    return word_at(liquid_shape_words, (int)s);
}
