/* cli: argument parsing. */
#include "app/cli.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

void cli_usage(FILE *out)
{
    fputs("usage: vcsph run CASE [--set section.key=value]... [-o DIR] [--overwrite] [--insist]\n"
          "                 [--quiet]\n"
          "       vcsph run --restart OUTDIR/checkpoint.h5 [--set case.t_end=T]\n"
          "                 [--set output.KEY=VALUE]... [--quiet]\n"
          "       vcsph check [--print] CASE [--set section.key=value]... [-o DIR] [--insist]\n"
          "       vcsph volume SNAPSHOT...\n"
          "       vcsph plot OUTDIR\n"
          "       vcsph keys\n"
          "       vcsph --help | --version\n"
          "\n"
          "  run     run the case; outputs go to output.dir of the case (default out/<name>)\n"
          "  check   validate the case and print the derived numbers; runs nothing\n"
          "          --print: print the fully resolved case instead, the text a run writes\n"
          "          as OUTDIR/case.ini (it loads back to the same case)\n"
          "  volume  print t, eps_v1 (Eq. 12), eps_gm (Eq. 15), the free surface's count and\n"
          "          nearest-neighbour spacings and eps_fs of saved snapshots (CSV)\n"
          "  plot    PNG plots of a run's output directory with gnuplot, into OUTDIR/images\n"
          "          (volume error and eta, energy, density, liquid, dissipation, probes,\n"
          "          loads; the script OUTDIR/images/plot.gp can be edited and rerun)\n"
          "  keys    list every key of the case file, one line each, four fields separated\n"
          "          by tabs: section.key, default ('required' if none, '<...>' if computed,\n"
          "          empty if empty), allowed values, meaning (docs/case-file.md)\n"
          "  --set   override any key of the case file (repeatable)\n"
          "  -o DIR  output directory; one run at a time (a second is refused, exit 2), and a\n"
          "          folder with another run's outputs is refused (exit 2) unless\n"
          "  --overwrite\n"
          "          removes that run's files (only the files a run writes) first\n"
          "  --restart OUTDIR/checkpoint.h5\n"
          "          continue the run of a checkpoint (written every output.checkpoint_every\n"
          "          wall-clock seconds, and when SIGTERM or SIGINT stops a run) in its folder,\n"
          "          as if it had never stopped; only case.t_end and output.* (not output.dir)\n"
          "          may change\n"
          "  --insist\n"
          "          run a case that looks absurd all the same: a motion period of fewer than\n"
          "          20 time steps, or more than a day's estimated run for a tank acceleration\n"
          "          above 100 g or a sound speed above 100 times Eq. (6)'s (docs/checks.md)\n"
          "  --quiet no terminal output (log.txt is still written)\n"
          "Threads: OMP_NUM_THREADS. Exit status: 0 done, 1 I/O failure, 2 bad input,\n"
          "3 numerical breakdown, 4 stopped by SIGTERM or SIGINT (checkpoint written).\n",
          out);
}

static int take_value(int argc, char **argv, int *k, const char **value, char *err, int err_len)
{
    const char *opt = argv[*k];
    const char *eq = strchr(opt, '=');
    if (strncmp(opt, "--", 2) == 0 && eq) { /* --set=a.b=c */
        *value = eq + 1;
        return 0;
    }
    if (*k + 1 >= argc) {
        snprintf(err, (size_t)err_len, "vcsph: option %s needs a value", opt);
        return 2;
    }
    *value = argv[++*k];
    return 0;
}

/* Whether --set `o` ("section.key=value") may change a restarted run: its end time and how
 * it writes its outputs, not its physics, which the checkpoint's state depends on. The
 * output folder is the checkpoint's, whatever output.dir says. */
static int restart_may_set(const char *o)
{
    while (isspace((unsigned char)*o)) o++;
    size_t len = strcspn(o, "=");
    while (len > 0 && isspace((unsigned char)o[len - 1])) len--;
    if (len == strlen("case.t_end") && !strncmp(o, "case.t_end", len)) return 1;
    if (len == strlen("output.dir") && !strncmp(o, "output.dir", len)) return 0;
    return len > 7 && !strncmp(o, "output.", 7);
}

static int check_restart(const cli_args *args, char *err, int err_len)
{
    const char *why = NULL;
    if (args->command != CLI_RUN)
        why = "only `vcsph run` takes --restart";
    else if (args->case_path)
        why = "give no case file with --restart: the run continues the checkpoint's case";
    else if (args->output_dir)
        why = "give no -o with --restart: the run continues in the checkpoint's folder";
    else if (args->overwrite)
        why = "give no --overwrite with --restart: the run continues the files of its folder";
    if (why) {
        snprintf(err, (size_t)err_len, "vcsph: %s", why);
        return 2;
    }
    for (int k = 0; k < args->n_overrides; k++) {
        if (restart_may_set(args->overrides[k])) continue;
        snprintf(err, (size_t)err_len,
                 "vcsph: --set %s: a restarted run keeps the checkpoint's case; only case.t_end "
                 "and the output.* keys (except output.dir) may change",
                 args->overrides[k]);
        return 2;
    }
    return 0;
}

int cli_parse(int argc, char **argv, cli_args *args, char *err, int err_len)
{
    memset(args, 0, sizeof *args);
    if (argc < 2) {
        snprintf(err, (size_t)err_len,
                 "vcsph: missing command (run, check, volume, plot or keys); try vcsph --help");
        return 2;
    }
    const char *cmd = argv[1];
    if (!strcmp(cmd, "--help") || !strcmp(cmd, "-h") || !strcmp(cmd, "help")) {
        args->command = CLI_HELP;
        return 0;
    }
    /* `vcsph run --help` and the like: the help, whatever else the line holds */
    for (int k = 2; k < argc; k++)
        if (!strcmp(argv[k], "--help") || !strcmp(argv[k], "-h")) {
            args->command = CLI_HELP;
            return 0;
        }
    if (!strcmp(cmd, "--version")) {
        args->command = CLI_VERSION;
        return 0;
    }
    if (!strcmp(cmd, "volume")) {
        args->command = CLI_VOLUME;
        args->snapshots = argv + 2;
        args->n_snapshots = argc - 2;
        if (args->n_snapshots > 0) return 0;
        snprintf(err, (size_t)err_len, "vcsph volume: give one or more snapshot files");
        return 2;
    }
    if (!strcmp(cmd, "plot")) {
        args->command = CLI_PLOT;
        args->plot_dir = argc == 3 ? argv[2] : NULL;
        if (args->plot_dir && args->plot_dir[0]) return 0;
        snprintf(err, (size_t)err_len, "vcsph plot: give one output directory (vcsph plot OUTDIR)");
        return 2;
    }
    if (!strcmp(cmd, "keys")) {
        args->command = CLI_KEYS;
        if (argc == 2) return 0;
        snprintf(err, (size_t)err_len, "vcsph keys: takes no arguments ('%s')", argv[2]);
        return 2;
    }
    if (!strcmp(cmd, "run"))
        args->command = CLI_RUN;
    else if (!strcmp(cmd, "check"))
        args->command = CLI_CHECK;
    else {
        snprintf(err, (size_t)err_len,
                 "vcsph: unknown command '%s' (allowed: run, check, volume, plot, keys)", cmd);
        return 2;
    }
    for (int k = 2; k < argc; k++) {
        const char *a = argv[k], *value;
        if (!strncmp(a, "--set", 5) && (a[5] == '\0' || a[5] == '=')) {
            if (take_value(argc, argv, &k, &value, err, err_len)) return 2;
            if (args->n_overrides == CLI_MAX_OVERRIDES) {
                snprintf(err, (size_t)err_len, "vcsph: at most %d --set options",
                         CLI_MAX_OVERRIDES);
                return 2;
            }
            args->overrides[args->n_overrides++] = value;
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output") || !strncmp(a, "--output=", 9)) {
            if (take_value(argc, argv, &k, &value, err, err_len)) return 2;
            if (value[0] == '-' || value[0] == '\0') {
                snprintf(err, (size_t)err_len, "vcsph: %s needs a directory, not '%s'", a, value);
                return 2;
            }
            args->output_dir = value;
        } else if (!strcmp(a, "--restart") || !strncmp(a, "--restart=", 10)) {
            if (take_value(argc, argv, &k, &value, err, err_len)) return 2;
            args->restart_path = value;
        } else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) {
            args->quiet = true;
        } else if (!strcmp(a, "--overwrite") && args->command == CLI_RUN) {
            args->overwrite = true;
        } else if (!strcmp(a, "--insist") &&
                   (args->command == CLI_RUN || args->command == CLI_CHECK)) {
            args->insist = true;
        } else if (!strcmp(a, "--print")) {
            if (args->command != CLI_CHECK) {
                snprintf(err, (size_t)err_len, "vcsph: only `vcsph check` takes --print");
                return 2;
            }
            args->print = true;
        } else if (a[0] == '-') {
            snprintf(err, (size_t)err_len,
                     "vcsph: unknown option '%s' (allowed: --set, -o, --overwrite, --restart, "
                     "--quiet, --print, --insist)",
                     a);
            return 2;
        } else if (!args->case_path) {
            args->case_path = a;
        } else {
            snprintf(err, (size_t)err_len, "vcsph: more than one case file ('%s' and '%s')",
                     args->case_path, a);
            return 2;
        }
    }
    if (args->restart_path) return check_restart(args, err, err_len);
    if (!args->case_path) {
        snprintf(err, (size_t)err_len, "vcsph %s: missing the case file", cmd);
        return 2;
    }
    return 0;
}
