/* main: the vcsph command; the only place that decides exit statuses (design §2). */
#include "app/cli.h"
#include "app/simulation.h"
#include "boundary/motion.h"
#include "core/config.h"
#include "core/derived.h"

#include <stdio.h>
#include <string.h>

#define VCSPH_VERSION "0.1.0"

static int check_case(const config *cfg)
{
    motion mo;
    char err[1024];
    if (motion_init(&mo, cfg, err, sizeof err)) {
        fprintf(stderr, "vcsph: %s\n", err);
        return RUN_BAD_INPUT;
    }
    derived dv;
    derived_compute(cfg, &mo, &dv);
    motion_free(&mo);
    if (derived_check(cfg, &dv, err, sizeof err)) {
        fprintf(stderr, "vcsph: %s\n", err);
        return RUN_BAD_INPUT;
    }
    printf("%s: valid\n", cfg->name);
    derived_print(cfg, &dv, stdout);
    return RUN_OK;
}

int main(int argc, char **argv)
{
    cli_args args;
    char err[2048];
    if (cli_parse(argc, argv, &args, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return RUN_BAD_INPUT;
    }
    if (args.command == CLI_HELP) {
        cli_usage(stdout);
        return RUN_OK;
    }
    if (args.command == CLI_VERSION) {
        printf("vcsph %s\n", VCSPH_VERSION);
        return RUN_OK;
    }
    static config cfg;
    if (config_load(&cfg, args.case_path, args.overrides, args.n_overrides, err, sizeof err)) {
        fprintf(stderr, "vcsph: %s\n", err);
        return RUN_BAD_INPUT;
    }
    if (args.command == CLI_CHECK) return check_case(&cfg);
    if (args.output_dir) snprintf(cfg.output_dir, sizeof cfg.output_dir, "%s", args.output_dir);
    run_options opt = {cfg.output_dir, args.quiet};
    return simulation_run(&cfg, &opt);
}
