/* cli: the command line (README.md). */
#ifndef VCSPH_CLI_H
#define VCSPH_CLI_H

#include <stdbool.h>
#include <stdio.h>

#define CLI_MAX_OVERRIDES 64

typedef enum {
    CLI_RUN,
    CLI_CHECK,
    CLI_VOLUME,
    CLI_PLOT,
    CLI_KEYS,
    CLI_HELP,
    CLI_VERSION
} cli_command;

typedef struct {
    cli_command command;
    const char *case_path; /* run, check */
    char **snapshots;      /* volume: the snapshot files */
    int n_snapshots;
    const char *plot_dir;                     /* plot: a run's output directory */
    const char *overrides[CLI_MAX_OVERRIDES]; /* "section.key=value" from --set */
    int n_overrides;
    const char *output_dir;   /* -o, NULL: output.dir of the case */
    const char *restart_path; /* run --restart: the checkpoint to continue */
    bool quiet;
    bool overwrite; /* run: replace an earlier run's outputs in the folder */
    bool print;     /* check --print: the resolved case instead of the derived numbers */
    bool insist;    /* run, check: take a case that looks absurd (case_checks.h) */
} cli_args;

/* Parses argv; returns 0, or 2 with a message in err. */
int cli_parse(int argc, char **argv, cli_args *args, char *err, int err_len);
void cli_usage(FILE *out);

#endif
