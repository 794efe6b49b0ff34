/* Fuzz target of the case parser (libFuzzer's entry point; tests/fuzz/replay.c calls the same
 * function on the committed corpus in the normal build, tools/fuzz runs libFuzzer on it).
 *
 * An input is a case file, optionally followed by a line "---" and up to MAX_OVERRIDES lines
 * "section.key=value", which go the way of --set. Besides "no crash, hang or sanitizer report",
 * it checks the properties the parser promises (core/config.h):
 * - a failed load says why (a message in err);
 * - what config_write writes, config_load reads back to the same struct, which writes the
 *   same text again;
 * and it computes and checks the derived numbers of every case that loads (case_numbers,
 * derived_check and derived_print, as `vcsph check` does), without running the solver. */
#define FUZZ_TARGET "fuzz_config"
#include "fuzz_target.h"
#include "scheme/case_numbers.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "boundary/motion.h"
#include "core/config.h"
#include "core/derived.h"

#define MAX_OVERRIDES 4
#define ERR_LEN       1024

/* The case as config_write writes it, in a malloc'd string. */
static char *written(const config *cfg, size_t *len)
{
    char *text = NULL;
    FILE *out = open_memstream(&text, len);
    if (!out) broken("open_memstream failed", NULL);
    config_write(cfg, out);
    if (fclose(out) != 0 || !text) broken("writing to a memory stream failed", NULL);
    return text;
}

static void check_round_trip(const config *cfg)
{
    size_t len1, len2;
    char *text1 = written(cfg, &len1);
    static config again; /* static: a config holds ~6 kB of paths */
    char err[ERR_LEN];
    if (config_load_string(&again, text1, "written", NULL, 0, err, sizeof err) != 0)
        broken("config_load rejects what config_write wrote", err);
    /* config_load zeroes the struct, padding and unused string bytes included, so that two
       loads of one case compare equal byte for byte */
    if (memcmp(cfg, &again, sizeof again) != 0)
        broken("config_write -> config_load gives another struct", text1);
    char *text2 = written(&again, &len2);
    if (len1 != len2 || memcmp(text1, text2, len1) != 0)
        broken("config_write -> config_load -> config_write gives another text", text1);
    free(text1);
    free(text2);
}

/* The numbers `vcsph check` prints, for a case that loaded. */
static void check_derived(const config *loaded)
{
    static config cfg;
    cfg = *loaded;
    /* motion_init would read the table file the case names (any file of this machine): the
       derived numbers are fuzzed without tank motion instead */
    if (cfg.motion == MOTION_TABLE) cfg.motion = MOTION_NONE;
    motion mo;
    char err[ERR_LEN];
    if (motion_init(&mo, &cfg, err, sizeof err) != 0)
        broken("motion_init failed without a table", err);
    derived dv;
    case_numbers(&cfg, &mo, &dv);
    motion_free(&mo);
    err[0] = '\0';
    int rc = derived_check(&cfg, &dv, err, sizeof err);
    if (rc != 0 && (rc != 2 || !err[0])) broken("derived_check failed without a message", NULL);
    if (rc != 0) return;
    char *text = NULL;
    size_t len;
    FILE *out = open_memstream(&text, &len);
    if (!out) broken("open_memstream failed", NULL);
    derived_print(&cfg, &dv, out);
    fclose(out);
    free(text);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* config_load_string takes a C string: the input up to its first NUL, if any */
    char *text = malloc(size + 1);
    if (!text) return 0;
    memcpy(text, data, size);
    text[size] = '\0';

    const char *overrides[MAX_OVERRIDES];
    int n_overrides = 0;
    char *marker = strstr(text, "\n---\n");
    if (marker) {
        marker[1] = '\0'; /* the case keeps its last '\n' */
        char *line = marker + 5;
        while (*line && n_overrides < MAX_OVERRIDES) {
            overrides[n_overrides++] = line;
            char *end = strchr(line, '\n');
            if (!end) break;
            *end = '\0';
            line = end + 1;
        }
    }

    static config cfg;
    char err[ERR_LEN];
    err[0] = '\0';
    int rc = config_load_string(&cfg, text, "fuzz", overrides, n_overrides, err, sizeof err);
    if (rc != 0 && (rc != 2 || !err[0])) broken("config_load failed without a message", NULL);
    if (rc == 0) {
        check_round_trip(&cfg);
        check_derived(&cfg);
    }
    free(text);
    return 0;
}
