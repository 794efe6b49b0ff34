/* plot_command: reads the run's CSV files only far enough to know which plots and curves have
 * data (gnuplot stops a whole script at a plot without a single point), writes one gnuplot
 * script that refers to the data by column name, and runs gnuplot on it. */
#include "app/plot_command.h"
#include "app/gnuplot_run.h"
#include "core/config.h"
#include "io/csv_read.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#define PLOT_SCRIPT "plot.gp"
/* More marks than this would hide the curves of a plot (a chattering adaptive control). */
#define PLOT_MAX_SWITCH_MARKS 200

/* ---- what the plots are drawn from ---------------------------------------------------------- */

typedef struct {
    char title_name[CONFIG_NAME_MAX]; /* the case name, else the directory's name */
    bool has_case;
    config cfg; /* case.ini, when has_case */
    csv_summary series, dissipation, probes, loads;
    double switch_t[PLOT_MAX_SWITCH_MARKS]; /* times of the eta_switch events */
    int n_switch;
} plot_inputs;

static void record_switch(void *ctx, const csv_summary *s, char **fields, int n_fields)
{
    plot_inputs *in = ctx;
    int t = csv_summary_column(s, "t"), event = csv_summary_column(s, "event");
    if (t < 0 || event < 0 || t >= n_fields || event >= n_fields) return;
    if (strcmp(fields[event], "eta_switch") || in->n_switch == PLOT_MAX_SWITCH_MARKS) return;
    char *end;
    double v = strtod(fields[t], &end);
    if (end != fields[t] && !*end && isfinite(v)) in->switch_t[in->n_switch++] = v;
}

/* dir/name, without a doubled slash when dir ends in one */
static int path_join(char *buf, size_t size, const char *dir, const char *name, char *err,
                     size_t err_len)
{
    int len = (int)strlen(dir);
    while (len > 1 && dir[len - 1] == '/') len--;
    if ((size_t)snprintf(buf, size, "%.*s/%s", len, dir, name) < size) return PLOT_OK;
    snprintf(err, err_len, "vcsph plot: the path %s/%s is too long", dir, name);
    return PLOT_BAD_INPUT;
}

/* The last component of dir, for titles when case.ini is missing. */
static void plot_name_from_dir(const char *dir, char *name, size_t size)
{
    size_t len = strlen(dir);
    while (len > 1 && dir[len - 1] == '/') len--;
    size_t start = len;
    while (start > 0 && dir[start - 1] != '/') start--;
    snprintf(name, size, "%.*s", (int)(len - start), dir + start);
}

/* case.ini gives the name, motion.decay and the experiment; a run without it, or with one
 * that this vcsph no longer reads, is still plotted. */
static void plot_read_case(const char *dir, plot_inputs *in, plot_report *report)
{
    char path[4096], err[1024];
    plot_name_from_dir(dir, in->title_name, sizeof in->title_name);
    if (path_join(path, sizeof path, dir, "case.ini", err, sizeof err)) return;
    if (access(path, F_OK)) return;
    /* the tank motion is not plotted: dropping it spares looking for a motion table */
    const char *const no_motion[] = {"motion.type=none", "motion.file="};
    if (config_load(&in->cfg, path, no_motion, 2, err, sizeof err)) {
        snprintf(report->warning, sizeof report->warning,
                 "vcsph plot: plotting without the case: %s", err);
        return;
    }
    in->has_case = true;
    snprintf(in->title_name, sizeof in->title_name, "%s", in->cfg.name);
}

/* An optional file that is missing is simply not plotted. */
static int plot_read_optional(const char *dir, const char *name, csv_summary *s, row_hook *hook,
                              void *ctx, char *err, size_t err_len)
{
    char path[4096];
    int status = path_join(path, sizeof path, dir, name, err, err_len);
    if (status) return status;
    if (csv_summary_read(path, s, hook, ctx) && s->present) {
        snprintf(err, err_len, "vcsph plot: cannot read %s: %s", path, strerror(errno));
        return PLOT_FAILED;
    }
    return PLOT_OK;
}

/* The key columns of volume.png, energy.png, density.png and liquid.png: one is enough. */
static bool plot_series_drawable(const csv_summary *series)
{
    return csv_summary_values(series, "eps_v1") || csv_summary_values(series, "ekin") ||
           csv_summary_values(series, "rho_min") || csv_summary_values(series, "com_x");
}

/* timeseries.csv is the one file a plot needs: without it, or its rows, the input is bad. */
static int plot_read_inputs(const char *dir, plot_inputs *in, plot_report *report, char *err,
                            size_t err_len)
{
    char path[4096];
    int status = path_join(path, sizeof path, dir, "timeseries.csv", err, err_len);
    if (status) return status;
    if (csv_summary_read(path, &in->series, NULL, NULL)) {
        snprintf(err, err_len, "vcsph plot: cannot read %s: %s", path, strerror(errno));
        return in->series.present ? PLOT_FAILED : PLOT_BAD_INPUT;
    }
    if (in->series.n_rows == 0 || csv_summary_column(&in->series, "t") < 0) {
        snprintf(err, err_len, "vcsph plot: %s has %s", path,
                 in->series.n_rows ? "no column 't'" : "no rows to plot");
        return PLOT_BAD_INPUT;
    }
    if (!plot_series_drawable(&in->series)) {
        snprintf(err, err_len,
                 "vcsph plot: %s has none of the columns eps_v1, ekin, rho_min, com_x with a value",
                 path);
        return PLOT_BAD_INPUT;
    }
    plot_read_case(dir, in, report);
    csv_summary events;
    status = plot_read_optional(dir, "events.csv", &events, record_switch, in, err, err_len);
    csv_summary_free(&events);
    if (!status)
        status =
            plot_read_optional(dir, "dissipation.csv", &in->dissipation, NULL, NULL, err, err_len);
    if (!status)
        status = plot_read_optional(dir, "probes.csv", &in->probes, NULL, NULL, err, err_len);
    if (!status)
        status = plot_read_optional(dir, "loads.csv", &in->loads, NULL, NULL, err, err_len);
    return status;
}

static void plot_inputs_free(plot_inputs *in)
{
    csv_summary_free(&in->series);
    csv_summary_free(&in->dissipation);
    csv_summary_free(&in->probes);
    csv_summary_free(&in->loads);
}

/* ---- the gnuplot script --------------------------------------------------------------------- */

/* A gnuplot single-quoted string: nothing is special inside it but the quote, written twice. */
static void gp_put_quoted(FILE *f, const char *s)
{
    fputc('\'', f);
    for (; *s; s++) {
        if (*s == '\'') fputc('\'', f);
        if (*s != '\n' && *s != '\r') fputc(*s, f);
    }
    fputc('\'', f);
}

/* Each plot starts from gnuplot's defaults, so that a block can be edited or moved alone. */
static void gp_begin_plot(FILE *f, const plot_inputs *in, const char *png, int height,
                          const char *what, const char *ylabel)
{
    fprintf(f, "\n# ---- %s\nreset\n", png);
    fprintf(f, "set terminal pngcairo size 1000,%d font ',11'\n", height);
    fputs("set encoding utf8\n" /* the Greek letters of the labels */
          "set datafile separator ','\n"
          "set datafile columnheaders\n"
          "set datafile missing ''\n"
          "set grid\n"
          "set key outside top center horizontal\n" /* never over a curve, clear of the x label */
          "set xlabel 't (s)'\n",
          f);
    fprintf(f, "set output '%s'\nset title ", png);
    char title[CONFIG_NAME_MAX + 256];
    snprintf(title, sizeof title, "%s: %s", in->title_name, what);
    gp_put_quoted(f, title);
    fputs(" noenhanced\nset ylabel ", f);
    gp_put_quoted(f, ylabel);
    fputc('\n', f);
}

typedef struct {
    const char *column;
    const char *prefix, *suffix; /* around column(NAME), e.g. "100*" for percent */
    const char *style;           /* after "with" */
    const char *title;           /* enhanced text */
} curve;

/* Starts or continues a plot command with one curve of `data` against its column t. */
static void gp_put_curve(FILE *f, int *n_plotted, const char *data, const curve *c)
{
    fputs(*n_plotted ? ", \\\n     " : "plot ", f);
    if (*n_plotted) data = "";
    gp_put_quoted(f, data);
    fprintf(f, " using 't':(%scolumn('%s')%s) with %s title ", c->prefix, c->column, c->suffix,
            c->style);
    gp_put_quoted(f, c->title);
    ++*n_plotted;
}

/* The curves whose columns have values; returns how many were plotted (0: no plot command). */
static int gp_put_curves(FILE *f, const char *data, const csv_summary *s, const curve *curves,
                         int n)
{
    int n_plotted = 0;
    for (int k = 0; k < n; k++)
        if (csv_summary_values(s, curves[k].column)) gp_put_curve(f, &n_plotted, data, &curves[k]);
    return n_plotted;
}

static const char series_data[] = "../timeseries.csv";

/* The paper's Fig. 9: eps_V in percent, with eta on a second axis and its switches marked. */
static bool gp_plot_volume(FILE *f, const plot_inputs *in)
{
    if (!csv_summary_values(&in->series, "eps_v1")) return false;
    gp_begin_plot(f, in, "volume.png", 600, "volume error (Eq. 12) and the ALE switch η",
                  "volume error (%)");
    const curve curves[] = {
        {"eps_v1", "100*", "", "lines lw 2", "ε_V^{(1)}"},
        {"eps_gm", "100*", "", "linespoints lw 2 pt 7 ps 0.6", "ε_{GM} (Eq. 15)"},
        /* the free surface's own layer measured too (docs/volume.md) */
        {"eps_fs", "100*(column('eps_v1') + ", ")", "lines lw 1", "ε_V^{(1)} + ε_{fs}"},
        {"eta", "", "", "lines lw 1 lc rgb 'black' axes x1y2", "η"},
    };
    bool has_eta = csv_summary_values(&in->series, "eta") != NULL;
    if (has_eta)
        fputs("set ytics nomirror\nset y2tics 0, 0.25, 1\nset y2range [-0.05:1.05]\n"
              "set y2label 'η'\n",
              f);
    for (int k = 0; k < in->n_switch; k++)
        fprintf(f, "set arrow from %.10g, graph 0 to %.10g, graph 1 nohead dt 2 lc rgb 'gray40'\n",
                in->switch_t[k], in->switch_t[k]);
    gp_put_curves(f, series_data, &in->series, curves, has_eta ? 4 : 3);
    if (in->n_switch)
        fputs(", \\\n     keyentry with lines dt 2 lc rgb 'gray40' title 'η switch'", f);
    fputc('\n', f);
    return true;
}

static bool gp_plot_energy(FILE *f, const plot_inputs *in)
{
    const column_summary *epot = csv_summary_values(&in->series, "epot");
    if (!csv_summary_values(&in->series, "ekin")) return false;
    const char *unit = !in->has_case      ? "energy (J; per unit width in 2D)"
                       : in->cfg.dim == 2 ? "energy per unit width (J/m)"
                                          : "energy (J)";
    gp_begin_plot(f, in, "energy.png", 600, "energy budget, E_pot from its initial value", unit);
    /* E_pot(0) of the run, so that all curves start near 0 */
    fprintf(f, "EPOT0 = %.15g\n", epot ? epot->first : 0.0);
    const curve curves[] = {
        {"ekin", "", "", "lines lw 2", "E_{kin}"},
        {"epot", "", " - EPOT0", "lines lw 2", "E_{pot} - E_{pot}(0)"},
        {"eint", "", "", "lines lw 2", "E_{int}"},
        {"work_in", "", "", "lines lw 2", "W_{in}"},
        {"ediss", "", "", "lines lw 2", "E_{diss}"},
        {"esurf", "", "", "lines lw 2", "E_{surf}"},
    };
    const column_summary *esurf = csv_summary_values(&in->series, "esurf");
    /* esurf is 0 throughout without surface tension: no flat line in the key then */
    gp_put_curves(f, series_data, &in->series, curves, esurf && esurf->nonzero ? 6 : 5);
    fputc('\n', f);
    return true;
}

static bool gp_plot_density(FILE *f, const plot_inputs *in)
{
    if (!csv_summary_values(&in->series, "rho_min")) return false;
    gp_begin_plot(f, in, "density.png", 600, "density extremes", "density (kg/m^3)");
    const curve curves[] = {
        {"rho_min", "", "", "lines lw 2", "ρ_{min}"},
        {"rho_max", "", "", "lines lw 2", "ρ_{max}"},
    };
    gp_put_curves(f, series_data, &in->series, curves, 2);
    fputc('\n', f);
    return true;
}

static bool gp_plot_liquid(FILE *f, const plot_inputs *in)
{
    if (!csv_summary_values(&in->series, "com_x")) return false;
    gp_begin_plot(f, in, "liquid.png", 600, "liquid centre of mass and extent", "position (m)");
    const curve curves[] = {
        {"com_x", "", "", "lines lw 2", "x_{com}"},
        {"com_y", "", "", "lines lw 2", "y_{com}"},
        {"ymax", "", "", "lines lw 2", "y_{max}"},
    };
    gp_put_curves(f, series_data, &in->series, curves, 3);
    fputc('\n', f);
    return true;
}

/* From 0, so that periods compare by their size; never an empty range (one period, or all of
 * them equal to the experiment). */
static void gp_dissipation_yrange(FILE *f, const column_summary *power, double experiment)
{
    double lo = power->min < 0.0 ? power->min : 0.0;
    double hi = power->max > experiment ? power->max : experiment;
    double pad = hi > lo ? 0.1 * (hi - lo) : 1.0;
    fprintf(f, "set yrange [%.10g:%.10g]\n", lo < 0.0 ? lo - pad : 0.0, hi + pad);
}

/* power_norm per excitation period, against the measured value when the case gives one. */
static bool gp_plot_dissipation(FILE *f, const plot_inputs *in)
{
    const column_summary *period = csv_summary_values(&in->dissipation, "period");
    const column_summary *power = csv_summary_values(&in->dissipation, "power_norm");
    if (!period || !power) return false;
    bool decaying = in->has_case && in->cfg.decay > 0.0;
    double experiment = in->has_case ? in->cfg.experiment_dissipation : 0.0;
    gp_begin_plot(f, in, "dissipation.png", 600, "slosh dissipation per excitation period",
                  decaying ? "P / dE_P" : "P / dW");
    fputs("set xlabel 'excitation period'\n", f);
    /* half a period of margin, so that a single period is not an empty x range */
    fprintf(f, "set xrange [%.10g:%.10g]\n", period->min - 0.5, period->max + 0.5);
    if (period->max - period->min < 20) fputs("set xtics 1\n", f);
    gp_dissipation_yrange(f, power, experiment);
    fputs("plot '../dissipation.csv' using 'period':(column('power_norm')) "
          "with linespoints lw 2 pt 7 title 'vcsph'",
          f);
    if (experiment > 0.0)
        fprintf(f, ", \\\n     %.10g with lines dt 2 lw 2 lc rgb 'black' title 'experiment'",
                experiment);
    fputc('\n', f);
    return true;
}

/* "x = 0.1 m" for gauge_1, "(x, y) = (0.5, 0.1) m" for pressure_1, from case.ini */
static void probe_title(const plot_inputs *in, const char *column, char *buf, size_t size)
{
    int k = 0;
    bool gauge = sscanf(column, "gauge_%d", &k) == 1;
    bool pressure =
        !gauge && (sscanf(column, "pressure_%d", &k) == 1 || sscanf(column, "sensor_%d", &k) == 1);
    const config *c = &in->cfg;
    if (in->has_case && gauge && k >= 1 && k <= c->n_gauges)
        snprintf(buf, size, "gauge %d: x = %g m", k, c->gauges[k - 1]);
    else if (in->has_case && pressure && k >= 1 && k <= c->n_pressure_probes) {
        const double *x = c->pressure_probes[k - 1];
        char size_of[48] = "";
        if (x[3] > 0.0) snprintf(size_of, sizeof size_of, ", d = %g m", x[3]);
        if (c->dim == 2)
            snprintf(buf, size, "p %d: (x, y) = (%g, %g) m%s", k, x[0], x[1], size_of);
        else
            snprintf(buf, size, "p %d: (x, y, z) = (%g, %g, %g) m%s", k, x[0], x[1], x[2], size_of);
    } else
        snprintf(buf, size, "%s %d", gauge ? "gauge" : "p", k);
}

/* One panel: the columns of probes.csv whose names start with `prefix`. */
static void gp_probe_panel(FILE *f, const plot_inputs *in, const char *prefix, const char *ylabel)
{
    fputs("set ylabel ", f);
    gp_put_quoted(f, ylabel);
    fputc('\n', f);
    int n_plotted = 0;
    for (int k = 0; k < in->probes.n_cols; k++) {
        const column_summary *c = &in->probes.cols[k];
        if (strncmp(c->name, prefix, strlen(prefix)) || !c->n_values) continue;
        char title[256];
        probe_title(in, c->name, title, sizeof title);
        /* column names come from the file: quoted like any other string */
        fputs(n_plotted++ ? ", \\\n     '' using 't':(column("
                          : "plot '../probes.csv' using 't':(column(",
              f);
        gp_put_quoted(f, c->name);
        fputs(")) with lines lw 2 title ", f);
        gp_put_quoted(f, title);
    }
    fputc('\n', f);
}

static bool probes_have(const plot_inputs *in, const char *prefix)
{
    for (int k = 0; k < in->probes.n_cols; k++)
        if (!strncmp(in->probes.cols[k].name, prefix, strlen(prefix)) &&
            in->probes.cols[k].n_values)
            return true;
    return false;
}

/* Gauges and pressures have different units: one panel each, and one for the filtered
 * sensors (probes.filter). */
static bool gp_plot_probes(FILE *f, const plot_inputs *in)
{
    bool gauges = probes_have(in, "gauge_"), pressures = probes_have(in, "pressure_");
    bool sensors = probes_have(in, "sensor_");
    if ((!gauges && !pressures) || csv_summary_column(&in->probes, "t") < 0) return false;
    gp_begin_plot(f, in, "probes.png", 300 + 300 * (gauges + pressures + sensors), "probes", "");
    /* the panels share the title of the page */
    fprintf(f, "set multiplot layout %d,1 title ", gauges + pressures + sensors);
    char title[CONFIG_NAME_MAX + 16];
    snprintf(title, sizeof title, "%s: probes", in->title_name);
    gp_put_quoted(f, title);
    fputs(" noenhanced\nunset title\n", f);
    if (gauges) gp_probe_panel(f, in, "gauge_", "liquid height (m)");
    if (pressures) gp_probe_panel(f, in, "pressure_", "pressure (Pa)");
    if (sensors) gp_probe_panel(f, in, "sensor_", "pressure through the sensor's filter (Pa)");
    fputs("unset multiplot\n", f);
    return true;
}

/* The force and the moment the liquid exerts on the tank (docs/loads.md), tank axes: one panel
 * each; a 2D run's moment is mz alone. */
static bool gp_plot_loads(FILE *f, const plot_inputs *in)
{
    if (!csv_summary_values(&in->loads, "fx") || csv_summary_column(&in->loads, "t") < 0)
        return false;
    static const char data[] = "../loads.csv";
    bool three_d = csv_summary_values(&in->loads, "fz") != NULL;
    gp_begin_plot(f, in, "loads.png", 900, "loads", "");
    fputs("set multiplot layout 2,1 title ", f);
    char title[CONFIG_NAME_MAX + 64];
    snprintf(title, sizeof title, "%s: the liquid's force and moment on the tank (tank axes)",
             in->title_name);
    gp_put_quoted(f, title);
    fputs(" noenhanced\nunset title\n", f);
    const curve forces[] = {
        {"fx", "", "", "lines lw 2", "F_x"},
        {"fy", "", "", "lines lw 2", "F_y"},
        {"fz", "", "", "lines lw 2", "F_z"},
    };
    const curve moments[] = {
        {"mz", "", "", "lines lw 2", "M_z"},
        {"mx", "", "", "lines lw 2", "M_x"},
        {"my", "", "", "lines lw 2", "M_y"},
    };
    fputs(three_d ? "set ylabel 'force (N)'\n" : "set ylabel 'force per unit width (N/m)'\n", f);
    gp_put_curves(f, data, &in->loads, forces, three_d ? 3 : 2);
    fputs(three_d ? "\nset ylabel 'moment about motion.center (N m)'\n"
                  : "\nset ylabel 'moment about motion.center per unit width (N m/m)'\n",
          f);
    gp_put_curves(f, data, &in->loads, moments, three_d ? 3 : 1);
    fputs("\nunset multiplot\n", f);
    return true;
}

typedef bool plot_writer(FILE *f, const plot_inputs *in);

static const struct {
    const char *png;
    plot_writer *write;
} plots[] = {
    {"volume.png", gp_plot_volume},
    {"energy.png", gp_plot_energy},
    {"density.png", gp_plot_density},
    {"liquid.png", gp_plot_liquid},
    {"dissipation.png", gp_plot_dissipation},
    {"probes.png", gp_plot_probes},
    {"loads.png", gp_plot_loads},
};
#define N_PLOTS (int)(sizeof plots / sizeof plots[0])

/* Writes the script; drawn[k] tells whether plots[k] is in it. */
static int plot_write_script(const char *path, const plot_inputs *in, bool drawn[N_PLOTS],
                             char *err, size_t err_len)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, err_len, "vcsph plot: cannot write %s: %s", path, strerror(errno));
        return PLOT_FAILED;
    }
    fputs("# Plots of a vcsph run, written by `vcsph plot`; rerun with: gnuplot plot.gp\n"
          "# in this folder: the data files are referred to as ../NAME.csv\n",
          f);
    for (int k = 0; k < N_PLOTS; k++) drawn[k] = plots[k].write(f, in);
    if (fclose(f)) {
        snprintf(err, err_len, "vcsph plot: cannot write %s: %s", path, strerror(errno));
        return PLOT_FAILED;
    }
    return PLOT_OK;
}

/* ---- the command ---------------------------------------------------------------------------- */

static int plot_check_dir(const char *dir, char *err, size_t err_len)
{
    struct stat st;
    if (stat(dir, &st)) {
        snprintf(err, err_len, "vcsph plot: no run directory %s: %s", dir, strerror(errno));
        return PLOT_BAD_INPUT;
    }
    if (!S_ISDIR(st.st_mode)) {
        snprintf(err, err_len, "vcsph plot: %s is not a directory (give a run's output directory)",
                 dir);
        return PLOT_BAD_INPUT;
    }
    return PLOT_OK;
}

static int plot_make_images_dir(const char *dir, plot_report *report, char *err, size_t err_len)
{
    int status =
        path_join(report->images_dir, sizeof report->images_dir, dir, "images", err, err_len);
    if (status) return status;
    if (mkdir(report->images_dir, 0777) && errno != EEXIST) {
        snprintf(err, err_len, "vcsph plot: cannot create %s: %s", report->images_dir,
                 strerror(errno));
        return PLOT_FAILED;
    }
    return PLOT_OK;
}

/* Old plots are removed first, so that a plot gnuplot did not draw is noticed. */
static int plot_remove_old(const plot_report *report, const bool drawn[N_PLOTS], char *err,
                           size_t err_len)
{
    for (int k = 0; k < N_PLOTS; k++) {
        char path[4200];
        if (!drawn[k]) continue;
        if (path_join(path, sizeof path, report->images_dir, plots[k].png, err, err_len))
            return PLOT_BAD_INPUT;
        if (remove(path) && errno != ENOENT) {
            snprintf(err, err_len, "vcsph plot: cannot replace %s: %s", path, strerror(errno));
            return PLOT_FAILED;
        }
    }
    return PLOT_OK;
}

static int plot_check_written(plot_report *report, const bool drawn[N_PLOTS], char *err,
                              size_t err_len)
{
    report->written[0] = '\0';
    for (int k = 0; k < N_PLOTS; k++) {
        char path[4200];
        struct stat st;
        if (!drawn[k]) continue;
        snprintf(path, sizeof path, "%s/%s", report->images_dir, plots[k].png);
        if (stat(path, &st) || st.st_size == 0) {
            snprintf(err, err_len, "vcsph plot: gnuplot did not write %s (script %s/%s)", path,
                     report->images_dir, PLOT_SCRIPT);
            return PLOT_FAILED;
        }
        size_t used = strlen(report->written);
        snprintf(report->written + used, sizeof report->written - used, "%s%s", used ? " " : "",
                 plots[k].png);
    }
    return PLOT_OK;
}

int plot_command_run(const char *dir, plot_report *report, char *err, size_t err_len)
{
    memset(report, 0, sizeof *report);
    int status = plot_check_dir(dir, err, err_len);
    if (status) return status;
    plot_inputs *in = calloc(1, sizeof *in);
    if (!in) {
        snprintf(err, err_len, "vcsph plot: out of memory");
        return PLOT_FAILED;
    }
    bool drawn[N_PLOTS];
    char script[4200];
    /* bad input is found before anything is written */
    status = plot_read_inputs(dir, in, report, err, err_len);
    if (!status) status = plot_make_images_dir(dir, report, err, err_len);
    if (!status)
        status = path_join(script, sizeof script, report->images_dir, PLOT_SCRIPT, err, err_len);
    if (!status) status = plot_write_script(script, in, drawn, err, err_len);
    plot_inputs_free(in);
    free(in);
    if (!status) status = plot_remove_old(report, drawn, err, err_len);
    if (!status) status = gnuplot_run(report->images_dir, PLOT_SCRIPT, err, err_len);
    if (!status) status = plot_check_written(report, drawn, err, err_len);
    return status;
}
