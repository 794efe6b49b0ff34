/* temp_dir: a fresh temporary folder per test (under $TMPDIR, else /tmp) and its removal with
 * everything in it, for the cmocka fixtures. Needs _XOPEN_SOURCE >= 500 (CMake defines 700). */
#ifndef VCSPH_TEST_TEMP_DIR_H
#define VCSPH_TEST_TEMP_DIR_H

#include <errno.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#if !defined(_XOPEN_SOURCE) || (_XOPEN_SOURCE - 0) < 500
#error "temp_dir.h needs _XOPEN_SOURCE >= 500 for nftw"
#endif

/* Makes a new folder $TMPDIR/PREFIX-XXXXXX (/tmp when TMPDIR is unset or empty) and writes its
 * name to dir. Returns 0, or -1 with errno set when the name does not fit in size bytes or the
 * folder cannot be made. */
static inline int temp_dir_make(char *dir, size_t size, const char *prefix)
{
    const char *tmp = getenv("TMPDIR");
    int n = snprintf(dir, size, "%s/%s-XXXXXX", tmp && *tmp ? tmp : "/tmp", prefix);
    if (n < 0 || (size_t)n >= size) {
        errno = ENAMETOOLONG;
        return -1;
    }
    return mkdtemp(dir) ? 0 : -1;
}

static inline int temp_dir_remove_entry(const char *path, const struct stat *st, int flag,
                                        struct FTW *ftw)
{
    (void)st, (void)flag, (void)ftw;
    return remove(path);
}

/* Removes dir and everything under it, without following symbolic links. Returns 0, or nonzero
 * when something could not be removed. */
static inline int temp_dir_remove(const char *dir)
{
    return nftw(dir, temp_dir_remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

/* A test's temporary folder for cmocka's setup and teardown, with a scratch buffer for the
 * paths in it; `row` keeps what a table-driven test had in *state. */
typedef struct {
    char dir[256];
    char path[512]; /* scratch for temp_fixture_path */
    const void *row;
} temp_fixture;

/* Replaces *state by a new fixture whose folder is named after prefix. Returns 0 or -1. */
static inline int temp_fixture_setup(void **state, const char *prefix)
{
    temp_fixture *fx = calloc(1, sizeof *fx);
    if (!fx) return -1;
    fx->row = *state;
    if (temp_dir_make(fx->dir, sizeof fx->dir, prefix) != 0) {
        free(fx);
        return -1;
    }
    *state = fx;
    return 0;
}

/* Removes the fixture's folder with everything in it, and the fixture. */
static inline int temp_fixture_teardown(void **state)
{
    temp_fixture *fx = *state;
    int rc = temp_dir_remove(fx->dir);
    free(fx);
    return rc;
}

/* dir/name, in the fixture's scratch buffer (valid until the next call). */
static inline const char *temp_fixture_path(temp_fixture *fx, const char *name)
{
    snprintf(fx->path, sizeof fx->path, "%s/%s", fx->dir, name);
    return fx->path;
}

#endif
