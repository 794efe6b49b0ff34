/* plot_command: `vcsph plot OUTDIR`, PNG plots of a run's CSV outputs (README.md and
 * docs/outputs.md) drawn by gnuplot from a script left in OUTDIR/images/plot.gp, so that a user can
 * edit and rerun it
 * (`cd OUTDIR/images && gnuplot plot.gp`). */
#ifndef VCSPH_PLOT_COMMAND_H
#define VCSPH_PLOT_COMMAND_H

#include <stddef.h>

/* Statuses, the exit statuses of docs/architecture.md */
enum { PLOT_OK = 0, PLOT_FAILED = 1, PLOT_BAD_INPUT = 2 };

typedef struct {
    char images_dir[4096]; /* OUTDIR/images */
    char written[256];     /* the PNG files written there, separated by spaces */
    char warning[1536];    /* empty, or why case.ini could not be used (plots go on without it) */
} plot_report;

/* Plots the run in `dir`. Returns PLOT_OK; PLOT_BAD_INPUT when dir, its timeseries.csv or
 * that file's rows are missing; PLOT_FAILED when gnuplot is not installed, fails, or leaves a
 * plot unwritten. On failure err holds one message. Prints nothing. */
int plot_command_run(const char *dir, plot_report *report, char *err, size_t err_len);

#endif
