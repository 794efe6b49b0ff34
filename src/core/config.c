/* config: the case file's vocabulary (docs/case-file.md): its sections and keys, the defaults
 * that depend on other keys and the checks of the whole case (the list-valued keys' readers:
 * core/config_lists.c). The INI engine that reads it, checks each value and writes it back is
 * core/ini_schema.c. */
#include "core/config.h"
#include "core/config_lists.h"
#include "core/ini_schema.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Relative slack of the liquid-inside-the-tank checks: 0.1 + 0.2 must fit in a tank 0.3 high. */
#define FIT_SLACK 1e-12

/* Enumerations are stored through memcpy of an int (INI_WORD), which needs this. */
_Static_assert(sizeof(scheme_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(motion_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(edbc_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(volume_correction_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(eta_control_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(wall_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(liquid_shape_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(probes_filter_kind) == sizeof(int), "enum size");

/* ---- the schema --------------------------------------------------------------------------- */

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
            words, allowed, meaning, NULL, NULL                                                    \
    }
/* a list of numbers, read and written by its own functions */
#define LIST_KEY_FLAGS(sec, nam, flags, def, field, set, format, allowed, meaning)                 \
    {                                                                                              \
        sec, nam, INI_CUSTOM, INI_LIST | (flags), def, offsetof(config, field),                    \
            sizeof(((config *)0)->field), ANY, NULL, allowed, meaning, set, format                 \
    }
#define LIST_KEY(sec, nam, def, field, set, format, allowed, meaning)                              \
    LIST_KEY_FLAGS(sec, nam, 0, def, field, set, format, allowed, meaning)

static const char *const bool_words[] = {"false", "true", NULL};
static const char *const motion_words[] = {"none",  "sway", "heave",     "table",      "roll",
                                           "pitch", "yaw",  "sway+roll", "heave+roll", NULL};
static const char *const scheme_words[] = {"standard",  "delta",          "delta-plus",
                                           "delta-ale", "delta-plus-ale", NULL};
static const char *const edbc_words[] = {"false", "true", "with-eta0", "auto", NULL};
static const char *const volume_correction_words[] = {"none", "geometric", "auto", NULL};
static const char *const eta_control_words[] = {"threshold", "adaptive", NULL};
static const char *const wall_words[] = {"no-slip", "free-slip", NULL};
static const char *const liquid_shape_words[] = {"box", "ellipse", NULL};
static const char *const probes_filter_words[] = {"raw", "first-order", "butterworth", NULL};

static const char *const sections[] = {"case",  "tank",     "liquid", "fluid", "motion",
                                       "model", "numerics", "probes", "output"};
#define N_SECTIONS (sizeof sections / sizeof sections[0])

/* The case file, section by section (docs/case-file.md; config_write follows this table). */
static const ini_key keys[] = {
    KEY("case", "name", INI_NAME, INI_DERIVED, "<file base name>", name, ANY, NULL,
        "a name of letters, digits, '.', '_' and '-' starting with a letter or digit",
        "name of the case: titles, and <name> in output.dir"),
    KEY("case", "dim", INI_INT, 0, "2", dim, CLOSED(2, 3), NULL, "2 or 3",
        "number of space dimensions"),
    KEY("case", "t_end", INI_REAL, INI_REQUIRED, NULL, t_end, POSITIVE, NULL, "a time > 0 (s)",
        "simulated time at which the run ends"),
    KEY("case", "experiment_dissipation", INI_REAL, 0, "0.0", experiment_dissipation, NON_NEGATIVE,
        NULL, "a number >= 0: the measured P/dW (P/dE_P with motion.decay > 0); 0 = none",
        "measured dissipation per period, drawn as a line by vcsph plot"),

    KEY("tank", "length", INI_REAL, INI_REQUIRED, NULL, tank_length, POSITIVE, NULL,
        "a length > 0 (m)", "L: the tank's inner length along x"),
    KEY("tank", "height", INI_REAL, INI_REQUIRED, NULL, tank_height, POSITIVE, NULL,
        "a length > 0 (m)", "D: the tank's inner height along y"),
    KEY("tank", "width", INI_REAL, 0, "1.0", tank_width, POSITIVE, NULL,
        "a length > 0 (m; 3D only)",
        "W: the tank's inner width along z (2D results are per unit width)"),

    KEY("liquid", "height", INI_REAL, INI_REQUIRED, NULL, liquid_height, POSITIVE, NULL,
        "a length > 0 (m)",
        "H: the filling height; numerics.resolution counts particles across it"),
    KEY("liquid", "length", INI_REAL, INI_DERIVED, "<tank.length>", liquid_length, POSITIVE, NULL,
        "a length > 0 (m); default: the tank length", "length along x of the liquid box at t = 0"),
    KEY("liquid", "x0", INI_REAL, 0, "0.0", liquid_x0, NON_NEGATIVE, NULL, "a position >= 0 (m)",
        "x of the liquid box's left side at t = 0"),
    KEY("liquid", "y0", INI_REAL, 0, "0.0", liquid_y0, NON_NEGATIVE, NULL, "a position >= 0 (m)",
        "y of the liquid box's bottom at t = 0 (> 0 lifts it off the floor)"),
    KEY("liquid", "shape", INI_WORD, 0, "box", liquid_shape, ANY, liquid_shape_words,
        "one of box | ellipse (the ellipse, or ellipsoid, inscribed in the box)",
        "the liquid at t = 0: the whole box, or the ellipse inscribed in it"),

    KEY("fluid", "density", INI_REAL, 0, "1000.0", density, POSITIVE, NULL,
        "a density > 0 (kg/m^3)", "rho0: reference density of the liquid"),
    KEY("fluid", "viscosity", INI_REAL, 0, "1.0e-6", viscosity, POSITIVE, NULL,
        "a kinematic viscosity > 0 (m^2/s)", "nu: kinematic viscosity of the liquid"),
    KEY("fluid", "surface_tension", INI_REAL, 0, "0.0", surface_tension, NON_NEGATIVE, NULL,
        "a surface tension >= 0 (N/m; 0 = off)",
        "sigma: surface tension coefficient of the free surface"),
    KEY("fluid", "gravity", INI_REAL, 0, "9.81", gravity, NON_NEGATIVE, NULL,
        "an acceleration >= 0 (m/s^2, along -y)", "g: magnitude of gravity, pointing along -y"),

    KEY("motion", "type", INI_WORD, 0, "none", motion, ANY, motion_words,
        "one of none | sway | heave | table | roll | pitch | yaw | sway+roll | heave+roll",
        "prescribed tank motion: sway (x), heave (y), roll (about z), pitch (about x), yaw "
        "(about y), a translation and roll together, or a table"),
    KEY("motion", "amplitude", INI_REAL, 0, "0.0", amplitude, NON_NEGATIVE, NULL,
        "a length >= 0 (m)", "A: amplitude of the sway or heave displacement"),
    KEY("motion", "angle", INI_REAL, 0, "0.0", angle, NON_NEGATIVE, NULL, "an angle >= 0 (rad)",
        "Theta: amplitude of the roll, pitch or yaw angle"),
    KEY("motion", "period", INI_REAL, 0, "0.0", period, NON_NEGATIVE, NULL,
        "a time >= 0 (s), > 0 when the motion is periodic (every type but none and table)",
        "T: period of the motion"),
    KEY("motion", "decay", INI_REAL, 0, "0.0", decay, NON_NEGATIVE, NULL, "a rate >= 0 (1/s)",
        "l: the amplitude decays as A exp(-l t)"),
    KEY("motion", "phase", INI_REAL, 0, "0.0", phase, ANY, NULL, "an angle (rad)",
        "phi: phase of the motion at t = 0, added to 2 pi t / T"),
    KEY("motion", "angle_phase", INI_REAL, 0, "0.0", angle_phase, ANY, NULL, "an angle (rad)",
        "phase of the rotation beyond phi: the angle's phase is phi + angle_phase"),
    LIST_KEY_FLAGS("motion", "center", INI_DERIVED, "<tank bottom centre>", motion_center,
                   config_set_center, config_format_center,
                   "a point 'x y[ z]' (m) in tank coordinates",
                   "point of the rotation axis (roll, pitch, yaw, table angles); in 3D a "
                   "missing z is the tank's mid-width"),
    KEY("motion", "duration", INI_REAL, 0, "0.0", duration, NON_NEGATIVE, NULL,
        "a time >= 0 (s; 0 = whole run)",
        "time after which the tank stops accelerating (keeps its velocity)"),
    KEY("motion", "settling", INI_REAL, 0, "0.0", settling, NON_NEGATIVE, NULL,
        "a rate >= 0 (1/s; 0 = none); > 0 needs motion.duration > 0",
        "after motion.duration, a body force -rate u that settles the liquid"),
    KEY("motion", "file", INI_PATH, 0, "", motion_file, ANY, NULL,
        "a readable CSV file, header t then any of x,y,z,roll,pitch,yaw; only for type = table",
        "CSV of the tank displacement and angles against time for type = table"),

    KEY("model", "scheme", INI_WORD, 0, "delta-plus-ale", scheme, ANY, scheme_words,
        "one of standard | delta | delta-plus | delta-ale | delta-plus-ale",
        "SPH model of the paper's Table 1"),
    KEY("model", "edbc", INI_WORD, 0, "auto", edbc, ANY, edbc_words,
        "one of auto | true | false | with-eta0 (auto: with-eta0 for delta-plus-ale, else false)",
        "EdBC of Eq. (9): p = 0, rho = rho0 on thin jets and drops"),
    KEY("model", "volume_correction", INI_WORD, 0, "auto", volume_correction, ANY,
        volume_correction_words,
        "one of auto | none | geometric (auto: geometric for delta-plus-ale, else none)",
        "vcsph's geometric volume correction (moves particles)"),
    KEY("model", "eta_threshold", INI_REAL, 0, "0.01", eta_threshold, OPEN(0.0, 1.0), NULL,
        "a number in (0, 1)", "|eps_v1| at which delta-plus-ALE switches eta"),
    KEY("model", "eta_control", INI_WORD, 0, "threshold", eta_control, ANY, eta_control_words,
        "one of threshold | adaptive",
        "how delta-plus-ALE sets eta: the paper's switch or vcsph's adaptive control"),
    KEY("model", "les", INI_BOOL, 0, "true", les, ANY, bool_words, "true or false",
        "Smagorinsky eddy viscosity (Eq. 4) with van Driest wall damping"),
    KEY("model", "wall", INI_WORD, 0, "no-slip", wall, ANY, wall_words,
        "one of no-slip | free-slip", "velocity condition of the walls for the viscous term"),
    KEY("model", "surface_unpacking", INI_BOOL, 0, "false", surface_unpacking, ANY, bool_words,
        "true or false", "vcsph's inward shift of a free surface packed tighter than a flat one"),

    KEY("numerics", "resolution", INI_INT, INI_REQUIRED, NULL, resolution, CLOSED(4, INT_MAX), NULL,
        "an integer >= 4 (particles across liquid.height)",
        "N = H / dr: particles across the filling height"),
    KEY("numerics", "h_over_dr", INI_REAL, INI_DERIVED, "2.0 in 2D, 1.5 in 3D", h_over_dr,
        CLOSED(1.0, 4.0), NULL, "a number in [1, 4]; default 2.0 in 2D, 1.5 in 3D",
        "smoothing length over particle spacing (support radius 2h)"),
    KEY("numerics", "sound_speed", INI_REAL_AUTO, 0, "auto", sound_speed, POSITIVE, NULL,
        "auto or a speed > 0 (m/s)",
        "c0 of the equation of state; auto: 10 sqrt(2 g_max H) (Eq. 6)"),
    KEY("numerics", "cfl", INI_REAL_AUTO, 0, "auto", cfl, LEFT_OPEN(0.0, 2.0), NULL,
        "auto or a number in (0, 2]",
        "K_c of the acoustic time step dt = K_c h / c0 (Eq. 8); auto: Table 1"),
    KEY("numerics", "density_bound", INI_REAL, 0, "0.2", density_bound, OPEN(0.0, 1.0), NULL,
        "a fraction in (0, 1): a density outside rho0 (1 +- bound) is a breakdown",
        "how far a density may stray from rho0 before the run stops (exit 3)"),

    LIST_KEY("probes", "gauges", "", gauges, config_set_gauges, config_format_gauges,
             "x positions (m) inside the tank, separated by commas or spaces",
             "x of wave gauges: liquid depth on a vertical line, into probes.csv"),
    LIST_KEY("probes", "pressure", "", pressure_probes, config_set_points, config_format_points,
             "points 'x y[ z][ d=D]' (m) inside the tank, separated by ';'; with a diameter "
             "D > 0, on one wall with the face inside it",
             "points where the SPH pressure is sampled, or sensors of diameter D on a wall that "
             "read its mean over their face, into probes.csv"),
    KEY("probes", "every", INI_REAL, INI_DERIVED, "output.timeseries_every", probes_every,
        NON_NEGATIVE, NULL, "a time >= 0 (s; 0 = every step)",
        "simulated time between rows of probes.csv: the sensors' sampling interval"),
    KEY("probes", "filter", INI_WORD, 0, "raw", probes_filter, ANY, probes_filter_words,
        "one of raw | first-order | butterworth",
        "the pressure sensors' bandwidth: a low-pass of probes.cutoff on their samples, "
        "written beside the raw signal as sensor_k"),
    KEY("probes", "cutoff", INI_REAL, 0, "0.0", probes_cutoff, NON_NEGATIVE, NULL,
        "a frequency > 0 (Hz) below half the sampling rate 1 / probes.every; needed by "
        "probes.filter",
        "the filter's cut-off (-3 dB) frequency"),

    KEY("output", "dir", INI_PATH, INI_NOT_EMPTY, "out/<name>", output_dir, ANY, NULL,
        "a directory path ('<name>' stands for case.name)",
        "output directory of the run (-o overrides it)"),
    KEY("output", "timeseries_every", INI_REAL, 0, "0.0", timeseries_every, NON_NEGATIVE, NULL,
        "a time >= 0 (s; 0 = every step)",
        "simulated time between rows of timeseries.csv and loads.csv (probes.csv: probes.every)"),
    KEY("output", "snapshot_every", INI_REAL, 0, "0.0", snapshot_every, NON_NEGATIVE, NULL,
        "a time >= 0 (s; 0 = none)", "simulated time between HDF5 snapshots"),
    KEY("output", "image_every", INI_REAL, 0, "0.0", image_every, NON_NEGATIVE, NULL,
        "a time >= 0 (s; 0 = none)", "simulated time between particle images"),
    KEY("output", "checkpoint_every", INI_REAL, 0, "600", checkpoint_every, NON_NEGATIVE, NULL,
        "a wall-clock time >= 0 (s; 0 = none)", "wall-clock time between checkpoints"),
    KEY("output", "graphical", INI_BOOL, 0, "false", graphical, ANY, bool_words, "true or false",
        "also compute eps_gm (Eq. 15) at every time-series row (costly)"),
};
#define N_KEYS (sizeof keys / sizeof keys[0])

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
    return ini_store_string(dir, size, out);
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
    size_t used = ini_is_name_char(base[0], true) ? 0 : (size_t)snprintf(name, size, "case-");
    for (size_t i = 0; i < len && used + 1 < size; i++) {
        char c = base[i];
        name[used++] = ini_is_name_char(c, false) ? c : '_';
    }
    name[used] = '\0';
}

static void resolve_defaults(ini_session *ctx)
{
    config *cfg = ini_target(ctx);
    const ini_key *name = ini_key_of(ctx, "case", "name");
    if (!ini_given(ctx, name)) {
        char text[CONFIG_NAME_MAX];
        default_name(ini_path(ctx), text, sizeof text);
        if (!ini_apply(ctx, name, text, 0)) return; /* cannot happen: default_name makes a name */
    }
    if (!ini_given(ctx, ini_key_of(ctx, "liquid", "length"))) cfg->liquid_length = cfg->tank_length;
    double *center = cfg->motion_center;
    if (!ini_given(ctx, ini_key_of(ctx, "motion", "center"))) { /* the bottom centre */
        center[0] = 0.5 * cfg->tank_length;
        center[1] = 0.0;
        center[2] = NAN;
    }
    if (isnan(center[2])) center[2] = cfg->dim == 3 ? 0.5 * cfg->tank_width : 0.0;
    if (!ini_given(ctx, ini_key_of(ctx, "numerics", "h_over_dr")))
        cfg->h_over_dr = cfg->dim == 3 ? 1.5 : 2.0;
    if (!ini_given(ctx, ini_key_of(ctx, "probes", "every")))
        cfg->probes_every = cfg->timeseries_every;
    /* the scheme-dependent defaults (docs/volume-correction.md, "Defaults") */
    bool plus_ale = cfg->scheme == SCHEME_DELTA_PLUS_ALE;
    if (cfg->edbc == EDBC_AUTO) cfg->edbc = plus_ale ? EDBC_WITH_ETA0 : EDBC_OFF;
    if (cfg->volume_correction == VOLUME_CORRECTION_AUTO)
        cfg->volume_correction = plus_ale ? VOLUME_CORRECTION_GEOMETRIC : VOLUME_CORRECTION_NONE;
    if (cfg->settling > 0.0 && cfg->duration <= 0.0)
        ini_fail_key(ctx, ini_key_of(ctx, "motion", "settling"),
                     "settles the liquid after the motion stops: set motion.duration > 0");
    if (cfg->surface_unpacking && (cfg->scheme == SCHEME_STANDARD || cfg->scheme == SCHEME_DELTA))
        ini_fail_key(ctx, ini_key_of(ctx, "model", "surface_unpacking"),
                     "needs particle shifting: model.scheme = delta-plus, delta-ale or "
                     "delta-plus-ale");
    if (!expand_name(cfg->output_dir, sizeof cfg->output_dir, cfg->name))
        ini_fail_key(ctx, ini_key_of(ctx, "output", "dir"), "too long once '<name>' is replaced");
}

static bool exceeds(double a, double b) { return a > b + FIT_SLACK * fabs(b); }

static void check_liquid(ini_session *ctx)
{
    const config *cfg = ini_target(ctx);
    char why[256];
    if (exceeds(cfg->liquid_y0 + cfg->liquid_height, cfg->tank_height)) {
        snprintf(why, sizeof why,
                 "liquid higher than the tank: "
                 "liquid.y0 + liquid.height = %g m > tank.height = %g m",
                 cfg->liquid_y0 + cfg->liquid_height, cfg->tank_height);
        ini_fail_key(ctx, ini_key_of(ctx, "liquid", "height"), why);
        return;
    }
    if (exceeds(cfg->liquid_x0 + cfg->liquid_length, cfg->tank_length)) {
        const ini_key *length = ini_key_of(ctx, "liquid", "length");
        const ini_key *blamed = ini_given(ctx, length) ? length : ini_key_of(ctx, "liquid", "x0");
        snprintf(why, sizeof why,
                 "liquid longer than the tank: "
                 "liquid.x0 + liquid.length = %g m > tank.length = %g m",
                 cfg->liquid_x0 + cfg->liquid_length, cfg->tank_length);
        ini_fail_key(ctx, blamed, why);
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
    if (readable_file(file)) return ini_store_string(out, size, file);
    const char *slash = case_path ? strrchr(case_path, '/') : NULL;
    if (!slash || file[0] == '/') return false;
    char joined[CONFIG_PATH_MAX];
    int n = snprintf(joined, sizeof joined, "%.*s/%s", (int)(slash - case_path), case_path, file);
    return n > 0 && (size_t)n < sizeof joined && readable_file(joined) &&
           ini_path_is_writable(joined) && ini_store_string(out, size, joined);
}

static void check_motion(ini_session *ctx)
{
    config *cfg = ini_target(ctx);
    char why[CONFIG_PATH_MAX + 256];
    const char *type = config_motion_name(cfg->motion);
    bool periodic = cfg->motion != MOTION_NONE && cfg->motion != MOTION_TABLE;
    if (cfg->dim == 2 && (cfg->motion == MOTION_PITCH || cfg->motion == MOTION_YAW)) {
        snprintf(why, sizeof why,
                 "%s turns the tank out of the x-y plane: 3D only (case.dim = 3); a 2D tank rolls",
                 type);
        ini_fail_key(ctx, ini_key_of(ctx, "motion", "type"), why);
        return;
    }
    if (periodic && !(cfg->period > 0.0)) {
        snprintf(why, sizeof why, "must be a time > 0 (s) when motion.type = %s", type);
        ini_fail_key(ctx, ini_key_of(ctx, "motion", "period"), why);
        return;
    }
    const ini_key *file = ini_key_of(ctx, "motion", "file");
    if (cfg->motion != MOTION_TABLE && cfg->motion_file[0]) {
        snprintf(why, sizeof why,
                 "applies only to motion.type = table, and the type is %s: set motion.type = "
                 "table to follow the file, or remove motion.file",
                 type);
        ini_fail_key(ctx, file, why);
        return;
    }
    if (cfg->motion != MOTION_TABLE) return;
    if (!cfg->motion_file[0]) {
        ini_fail_key(ctx, file, "required when motion.type = table: a CSV file t,x,y[,z]");
        return;
    }
    char as_given[CONFIG_PATH_MAX];
    snprintf(as_given, sizeof as_given, "%s", cfg->motion_file);
    if (!locate_table(as_given, ini_path(ctx), cfg->motion_file, sizeof cfg->motion_file)) {
        snprintf(why, sizeof why,
                 "cannot read '%s' (looked from the current directory%s); must be %s", as_given,
                 ini_path(ctx) ? " and beside the case file" : "", file->allowed);
        ini_fail_key(ctx, file, why);
    }
}

static void check_probes(ini_session *ctx)
{
    const config *cfg = ini_target(ctx);
    const ini_key *gauges = ini_key_of(ctx, "probes", "gauges"),
                  *pressure = ini_key_of(ctx, "probes", "pressure");
    char why[256];
    for (int i = 0; i < cfg->n_gauges; i++) {
        if (cfg->gauges[i] < 0.0 || exceeds(cfg->gauges[i], cfg->tank_length)) {
            snprintf(why, sizeof why, "gauge %d at x = %g m is outside the tank, x in [0, %g] m",
                     i + 1, cfg->gauges[i], cfg->tank_length);
            ini_fail_key(ctx, gauges, why);
            return;
        }
    }
    int coords = ((const case_reading *)ini_user(ctx))->point_coords;
    if (coords && coords != cfg->dim) {
        /* Shown with the coordinates as given: formatting for dim would drop or invent some. */
        char as_given[INI_LINE_MAX];
        config_format_point_list(cfg, coords, as_given, sizeof as_given);
        snprintf(why, sizeof why, "points have %d coordinates but case.dim = %d; write %s", coords,
                 cfg->dim, cfg->dim == 3 ? "'x y z'" : "'x y'");
        ini_fail_value(ctx, pressure, ini_key_line(ctx, pressure), as_given, why);
        return;
    }
    const double size[3] = {cfg->tank_length, cfg->tank_height, cfg->tank_width};
    for (int i = 0; i < cfg->n_pressure_probes; i++) {
        const double *x = cfg->pressure_probes[i];
        for (int d = 0; d < cfg->dim; d++) {
            if (x[d] < 0.0 || exceeds(x[d], size[d])) {
                snprintf(why, sizeof why,
                         "pressure point %d: %c = %g m is outside the tank, %c in [0, %g] m", i + 1,
                         "xyz"[d], x[d], "xyz"[d], size[d]);
                ini_fail_key(ctx, pressure, why);
                return;
            }
        }
        if (!(x[3] > 0.0)) continue;
        /* a transducer is flush with one wall, and its face lies inside that wall */
        int axis = config_wall_axis(cfg, x);
        if (axis < 0) {
            snprintf(why, sizeof why, "pressure sensor %d (d = %g m) must lie on one wall%s", i + 1,
                     x[3], axis == -2 ? ", not on an edge or corner" : "");
            ini_fail_key(ctx, pressure, why);
            return;
        }
        for (int d = 0; d < cfg->dim; d++) {
            if (d == axis || (x[d] >= 0.5 * x[3] && !exceeds(x[d] + 0.5 * x[3], size[d]))) continue;
            snprintf(why, sizeof why,
                     "pressure sensor %d: its face (d = %g m) reaches past the wall's edge at "
                     "%c = %g m",
                     i + 1, x[3], "xyz"[d], x[d] < 0.5 * x[3] ? 0.0 : size[d]);
            ini_fail_key(ctx, pressure, why);
            return;
        }
    }
}

/* A filter needs sensors, a cut-off, and samples at least twice per period of its cut-off
 * (Nyquist): a low-pass cannot model a bandwidth its sampling aliases. */
static void check_probes_filter(ini_session *ctx)
{
    const config *cfg = ini_target(ctx);
    if (cfg->probes_filter == PROBES_RAW) return;
    const ini_key *filter = ini_key_of(ctx, "probes", "filter"),
                  *cutoff = ini_key_of(ctx, "probes", "cutoff");
    char why[256];
    if (cfg->n_pressure_probes == 0)
        ini_fail_key(ctx, filter, "filters the pressure sensors: set probes.pressure");
    else if (!(cfg->probes_cutoff > 0.0))
        ini_fail_key(ctx, cutoff, "probes.filter needs its cut-off frequency (Hz) > 0");
    else if (cfg->probes_every > 0.0 && cfg->probes_cutoff >= 0.5 / cfg->probes_every) {
        snprintf(why, sizeof why,
                 "%g Hz is not below half the sampling rate 1 / probes.every = %g Hz; sample "
                 "faster (probes.every < %g s, 0 = every step) or lower the cut-off",
                 cfg->probes_cutoff, 1.0 / cfg->probes_every, 0.5 / cfg->probes_cutoff);
        ini_fail_key(ctx, cutoff, why);
    }
}

/* The caller's check of the whole case, last, blaming the key it names where it was set. */
static void check_whole_case(ini_session *ctx)
{
    const case_reading *reading = ini_user(ctx);
    if (!reading->check) return;
    const char *key = NULL;
    char why[2048], section[32];
    if (!reading->check(ini_target(ctx), reading->check_user, &key, why, sizeof why)) return;
    size_t dot = strcspn(key, ".");
    snprintf(section, sizeof section, "%.*s", (int)dot, key);
    ini_fail_key(ctx, ini_key_of(ctx, section, key + dot + 1), why);
}

/* In this order, after the required keys: defaults that depend on other keys need those keys
 * first, and the whole case's check needs every key. */
static void (*const checks[])(ini_session *ctx) = {resolve_defaults,    check_liquid,
                                                   check_motion,        check_probes,
                                                   check_probes_filter, check_whole_case};

static const ini_schema case_schema = {sections, N_SECTIONS, keys,
                                       N_KEYS,   checks,     sizeof checks / sizeof checks[0]};

/* ---- public ------------------------------------------------------------------------------- */

int config_load(config *cfg, const char *path, const char *const *overrides, int n_overrides,
                char *err, size_t err_len)
{
    return config_load_checked(cfg, path, overrides, n_overrides, NULL, NULL, err, err_len);
}

int config_load_checked(config *cfg, const char *path, const char *const *overrides,
                        int n_overrides, config_case_check check, void *check_user, char *err,
                        size_t err_len)
{
    case_reading reading = {0, check, check_user};
    ini_input in = {path, NULL, path};
    return ini_load(&case_schema, cfg, sizeof *cfg, &in, overrides, n_overrides, &reading, err,
                    err_len);
}

int config_load_string(config *cfg, const char *text, const char *origin,
                       const char *const *overrides, int n_overrides, char *err, size_t err_len)
{
    case_reading reading = {0};
    ini_input in = {NULL, text, origin};
    return ini_load(&case_schema, cfg, sizeof *cfg, &in, overrides, n_overrides, &reading, err,
                    err_len);
}

void config_write(const config *cfg, FILE *out)
{
    ini_write(&case_schema, cfg,
              "vcsph case, fully resolved: every key, with defaults and --set applied", out);
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

void config_write_keys(FILE *out) { ini_write_keys(&case_schema, out); }

const char *config_scheme_name(scheme_kind s) { return ini_word_at(scheme_words, (int)s); }
const char *config_motion_name(motion_kind m) { return ini_word_at(motion_words, (int)m); }

int config_motion_translation_axis(motion_kind m)
{
    switch (m) {
    case MOTION_SWAY:
    case MOTION_SWAY_ROLL: return 0;
    case MOTION_HEAVE:
    case MOTION_HEAVE_ROLL: return 1;
    default: return -1;
    }
}

int config_motion_rotation(motion_kind m)
{
    switch (m) {
    case MOTION_ROLL:
    case MOTION_SWAY_ROLL:
    case MOTION_HEAVE_ROLL: return 0;
    case MOTION_PITCH: return 1;
    case MOTION_YAW: return 2;
    default: return -1;
    }
}
const char *config_edbc_name(edbc_mode e) { return ini_word_at(edbc_words, (int)e); }
const char *config_volume_correction_name(volume_correction_kind v)
{
    return ini_word_at(volume_correction_words, (int)v);
}
const char *config_eta_control_name(eta_control_kind e)
{
    return ini_word_at(eta_control_words, (int)e);
}
const char *config_wall_name(wall_kind w) { return ini_word_at(wall_words, (int)w); }
const char *config_liquid_shape_name(liquid_shape_kind s)
{
    return ini_word_at(liquid_shape_words, (int)s);
}
