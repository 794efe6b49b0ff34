/* cli_fixture: the temporary folder, the file helpers and the tiny case of the tests of the
 * vcsph command (test_cli.c, test_cli_outputs.c). Include after <cmocka.h> and vcsph_child.h. */
#ifndef VCSPH_TEST_CLI_FIXTURE_H
#define VCSPH_TEST_CLI_FIXTURE_H

#include "temp_dir.h"

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

extern char **environ;

/* ---- fixture: one temporary folder per test, the child's working directory ----------------- */

typedef temp_fixture fixture;

static inline int setup(void **state) { return temp_fixture_setup(state, "vcsph-cli"); }

static inline int teardown(void **state) { return temp_fixture_teardown(state); }

/* ---- helpers -------------------------------------------------------------------------------- */

static inline void path_in(const fixture *fx, const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", fx->dir, name);
}

static inline void write_file(const fixture *fx, const char *name, const char *text)
{
    char path[512];
    path_in(fx, name, path, sizeof path);
    text_file_write(path, text);
}

/* The whole file as a string (empty if it cannot be read); free() it. */
/* not inline: inlined, gcc 12 takes the text open_memstream returns for a pointer to a local
 * (a false -Wdangling-pointer) */
static __attribute__((unused)) char *read_file(const fixture *fx, const char *name)
{
    char path[512];
    path_in(fx, name, path, sizeof path);
    return text_file_read(path);
}

static inline bool is_regular_file(const fixture *fx, const char *name)
{
    char path[512];
    struct stat st;
    path_in(fx, name, path, sizeof path);
    return stat(path, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0;
}

static inline bool exists(const fixture *fx, const char *name)
{
    char path[512];
    struct stat st;
    path_in(fx, name, path, sizeof path);
    return lstat(path, &st) == 0;
}

/* Runs vcsph with argv[1..] (NULL-terminated) in the fixture's folder (vcsph_child.h). */
static inline int run_vcsph(const fixture *fx, const char *const *args)
{
    return vcsph_child_run(fx->dir, args, environ);
}

/* The same with one more variable ("NAME=value") in the environment. */
static inline int run_vcsph_with(const fixture *fx, const char *const *args, const char *variable)
{
    size_t n = 0;
    while (environ[n]) n++;
    char **envp = calloc(n + 2, sizeof *envp);
    assert_non_null(envp);
    memcpy(envp, environ, n * sizeof *envp);
    envp[n] = (char *)variable;
    int rc = vcsph_child_run(fx->dir, args, envp);
    free(envp);
    return rc;
}

/* The line after `line`, NULL at the end of the text. */
static inline const char *next_line(const char *line)
{
    const char *nl = strchr(line, '\n');
    return nl && nl[1] ? nl + 1 : NULL;
}

/* Fails unless the fixture's folder holds exactly the entries in `expected` (NULL-ended):
 * "nothing written" means no output folder, no out/<name>, no stray file anywhere. */
static inline void assert_folder_holds(const fixture *fx, const char *const *expected)
{
    DIR *d = opendir(fx->dir);
    assert_non_null(d);
    int seen = 0, n_expected = 0;
    while (expected[n_expected]) n_expected++;
    struct dirent *e;
    char unexpected[1024] = "";
    while ((e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        bool known = false;
        for (int k = 0; k < n_expected; k++) known |= !strcmp(e->d_name, expected[k]);
        if (known)
            seen++;
        else
            snprintf(unexpected + strlen(unexpected), sizeof unexpected - strlen(unexpected), " %s",
                     e->d_name);
    }
    closedir(d);
    if (unexpected[0]) fail_msg("unexpected entries in the working folder:%s", unexpected);
    assert_int_equal(seen, n_expected);
}

/* The good case that the bad ones vary; line numbers in the comments on the right. */
#define BASE_CASE                                                                                  \
    "[case]\n"         /* 1 */                                                                     \
    "name = base\n"    /* 2 */                                                                     \
    "t_end = 0.05\n"   /* 3 */                                                                     \
    "[tank]\n"         /* 4 */                                                                     \
    "length = 0.2\n"   /* 5 */                                                                     \
    "height = 0.1\n"   /* 6 */                                                                     \
    "[liquid]\n"       /* 7 */                                                                     \
    "height = 0.05\n"  /* 8 */                                                                     \
    "[numerics]\n"     /* 9 */                                                                     \
    "resolution = 8\n" /* 10 */

/* A case of a few steps at N = 8 with a snapshot and a time series. */
#define TINY_CASE                                                                                  \
    "[case]\n"                                                                                     \
    "name = tiny\n"                                                                                \
    "t_end = 0.05\n"                                                                               \
    "[tank]\n"                                                                                     \
    "length = 0.2\n"                                                                               \
    "height = 0.1\n"                                                                               \
    "[liquid]\n"                                                                                   \
    "height = 0.05\n"                                                                              \
    "[numerics]\n"                                                                                 \
    "resolution = 8\n"                                                                             \
    "[output]\n"                                                                                   \
    "timeseries_every = 0.01\n"                                                                    \
    "snapshot_every = 0.02\n"

#endif
