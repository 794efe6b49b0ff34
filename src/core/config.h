/* config: the case file (docs/case-file.md) read with inih, validated, immutable afterwards. */
#ifndef VCSPH_CONFIG_H
#define VCSPH_CONFIG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#define CONFIG_PATH_MAX   1024
#define CONFIG_NAME_MAX   128
#define CONFIG_PROBES_MAX 64

typedef enum {
    SCHEME_STANDARD,
    SCHEME_DELTA,
    SCHEME_DELTA_PLUS,
    SCHEME_DELTA_ALE,
    SCHEME_DELTA_PLUS_ALE
} scheme_kind;

/* The tank's prescribed motion: a translation (sway along x, heave along y), a rotation (roll
 * about z, pitch about x, yaw about y, through motion.center), the two superposed, or a table. */
typedef enum {
    MOTION_NONE,
    MOTION_SWAY,
    MOTION_HEAVE,
    MOTION_TABLE,
    MOTION_ROLL,
    MOTION_PITCH,
    MOTION_YAW,
    MOTION_SWAY_ROLL,
    MOTION_HEAVE_ROLL
} motion_kind;
/* EDBC_AUTO is resolved by config_load (with-eta0 for delta-plus-ALE, false otherwise) and
 * never reaches the solver. */
typedef enum { EDBC_OFF, EDBC_ON, EDBC_WITH_ETA0, EDBC_AUTO } edbc_mode;
/* The geometric volume correction (docs/volume-correction.md); VOLUME_CORRECTION_AUTO is
 * resolved by config_load and never reaches the solver. */
typedef enum {
    VOLUME_CORRECTION_NONE,
    VOLUME_CORRECTION_GEOMETRIC,
    VOLUME_CORRECTION_AUTO
} volume_correction_kind;
typedef enum { ETA_CONTROL_THRESHOLD, ETA_CONTROL_ADAPTIVE } eta_control_kind;
typedef enum { WALL_NO_SLIP, WALL_FREE_SLIP } wall_kind;
/* The liquid at t = 0: the whole box, or the ellipse (ellipsoid) inscribed in it. */
typedef enum { LIQUID_BOX, LIQUID_ELLIPSE } liquid_shape_kind;
/* the bandwidth of the pressure sensors (probes.filter; diag/sensor_filter.h) */
typedef enum { PROBES_RAW, PROBES_FIRST_ORDER, PROBES_BUTTERWORTH } probes_filter_kind;

typedef struct {
    /* [case] */
    char name[CONFIG_NAME_MAX];
    int dim;
    double t_end;
    double experiment_dissipation; /* measured dissipation per period, normalised as in
                                      dissipation.csv's power_norm (0 = none); for plots */
    /* [tank] */
    double tank_length, tank_height, tank_width;
    /* [liquid] */
    double liquid_height, liquid_length, liquid_x0, liquid_y0;
    liquid_shape_kind liquid_shape;
    /* [fluid] */
    double density, viscosity, surface_tension, gravity;
    /* [motion] */
    motion_kind motion;
    double amplitude, period, decay, phase, duration;
    double settling;           /* 1/s: -settling u after `duration` (0: none) */
    double angle, angle_phase; /* rotation amplitude (rad) and its phase beyond `phase` */
    double motion_center[3];   /* the rotation axis's point, tank coordinates (m) */
    char motion_file[CONFIG_PATH_MAX];
    /* not a key: the table's text when a run holds it (read once at the start, or stored in
       the checkpoint), parsed instead of motion_file, which an edit could change under a
       restart; NULL: read motion_file */
    const char *motion_table;
    /* [model] */
    scheme_kind scheme;
    edbc_mode edbc;
    volume_correction_kind volume_correction;
    double eta_threshold;
    eta_control_kind eta_control;
    bool les;
    wall_kind wall;
    bool surface_unpacking;
    /* [numerics] */
    int resolution;
    double h_over_dr;
    double sound_speed;   /* 0 = auto */
    double cfl;           /* 0 = auto (Table 1) */
    double density_bound; /* breakdown when a density leaves rho0 (1 +- this) */
    /* [probes] */
    int n_gauges;
    double gauges[CONFIG_PROBES_MAX];
    int n_pressure_probes;
    /* x, y, z and the sensor's diameter (0: a point; > 0: a transducer flush with a wall,
       which reads the mean pressure over its face) */
    double pressure_probes[CONFIG_PROBES_MAX][4];
    double probes_every; /* s between rows of probes.csv, 0 = every step */
    probes_filter_kind probes_filter;
    double probes_cutoff; /* Hz, the filter's -3 dB frequency */
    /* [output] */
    char output_dir[CONFIG_PATH_MAX];
    double timeseries_every, snapshot_every, image_every, checkpoint_every;
    bool graphical;
} config;

/* Loads and validates a case file, then applies overrides "section.key=value" (from --set)
 * in order. On failure returns 2 and writes one message into err naming file, line, key and
 * what is allowed (every missing required key at once); cfg is then unspecified. Returns 0 on
 * success. case.name defaults to the file's base name without its extension. Both ';' and '#'
 * start a comment (docs/case-file.md). */
int config_load(config *cfg, const char *path, const char *const *overrides, int n_overrides,
                char *err, size_t err_len);

/* A check of the whole case once its keys are read and checked (the numbers derived from it,
 * its motion, its cost): 0, or nonzero with the key to blame ("section.name", a key of the
 * case file) in *key and the reason in why. */
typedef int (*config_case_check)(const config *cfg, void *user, const char **key, char *why,
                                 size_t why_len);
/* config_load, then `check` (with `user`) within the load, so that its message names the file
 * and line of the key it blames as every other error does. */
int config_load_checked(config *cfg, const char *path, const char *const *overrides,
                        int n_overrides, config_case_check check, void *check_user, char *err,
                        size_t err_len);

/* Same, from a string (tests, fuzzing, a checkpoint's case); `origin` names it in messages.
 * Without a file to name it, case.name defaults to "case". */
int config_load_string(config *cfg, const char *text, const char *origin,
                       const char *const *overrides, int n_overrides, char *err, size_t err_len);

/* Writes the fully resolved case (every key, defaults and overrides applied) as an INI file
 * that config_load reads back to the same struct. */
void config_write(const config *cfg, FILE *out);
/* config_write's text in malloc'd memory (free() it; NULL when out of memory): case.ini, the
 * checkpoint's case. */
char *config_text(const config *cfg);

/* Writes every key of the case file, one line each, in the order of config_write, as four
 * fields separated by tabs: section.key, default (as a file spells it; "<...>" for a default
 * computed from something else, "required" for a key without one, empty for an empty
 * default), what is allowed, and its meaning. `vcsph keys` prints it. */
void config_write_keys(FILE *out);

/* The spellings of the case file (docs/case-file.md), e.g. "delta-plus-ale", "with-eta0". */
const char *config_scheme_name(scheme_kind s);
const char *config_motion_name(motion_kind m);
/* The harmonic motions' parts: the axis a sway (0) or heave (1) translates along, and the angle
 * a rotation turns, 0 roll, 1 pitch, 2 yaw; -1 when the motion has none (and for a table). */
int config_motion_translation_axis(motion_kind m);
int config_motion_rotation(motion_kind m);
const char *config_edbc_name(edbc_mode e);
const char *config_volume_correction_name(volume_correction_kind v);
const char *config_eta_control_name(eta_control_kind e);
const char *config_wall_name(wall_kind w);
const char *config_liquid_shape_name(liquid_shape_kind s);

/* Whether the case has probes (gauges or pressure points), so probes.csv and its rows. */
static inline bool config_has_probes(const config *cfg)
{
    return cfg->n_gauges + cfg->n_pressure_probes > 0;
}

/* The intervals (s) on whose multiples the steps land, 0 where there is none: the rows of
 * timeseries.csv, the snapshots, the rows of probes.csv and, with a periodic motion (omega,
 * rad/s, > 0), its period. */
#define CONFIG_LANDINGS 4
static inline void config_landing_intervals(const config *cfg, double omega,
                                            double every[CONFIG_LANDINGS])
{
    every[0] = cfg->timeseries_every;
    every[1] = cfg->snapshot_every;
    every[2] = config_has_probes(cfg) ? cfg->probes_every : 0.0;
    every[3] = omega > 0.0 ? cfg->period : 0.0;
}

/* The axis (0, 1, 2) of the tank wall that the point x (m) lies on, -1 when it lies on none,
 * -2 when on more than one (an edge or a corner). */
int config_wall_axis(const config *cfg, const double x[3]);

#endif
