/* gnuplot_run: `gnuplot SCRIPT` run in a directory, for `vcsph plot` (plot_command.h). */
#ifndef VCSPH_GNUPLOT_RUN_H
#define VCSPH_GNUPLOT_RUN_H

#include <stddef.h>

/* Runs `gnuplot script` in dir, without a shell. Returns PLOT_OK, or PLOT_FAILED with one
 * message in err: gnuplot not installed, not runnable in dir, failed or killed. */
int gnuplot_run(const char *dir, const char *script, char *err, size_t err_len);

#endif
