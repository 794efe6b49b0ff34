/* atomic_file: a file written under a temporary name and renamed over its real name, so that a
 * reader (or a crash) finds the previous complete file or the new complete one, never half a
 * file: snapshots, the XDMF index, images and checkpoints. */
#ifndef VCSPH_ATOMIC_FILE_H
#define VCSPH_ATOMIC_FILE_H

#include <stddef.h>

/* path + ".tmp", the name a file is written under (malloc'd; NULL when out of memory). */
char *atomic_temp_path(const char *path);

/* Renames tmp over path: rename() replaces the target in one step (POSIX). On failure removes
 * tmp and writes "MODULE: cannot rename 'tmp' to 'path': why" into err. Returns 0 or -1. */
int atomic_commit(const char *module, const char *tmp, const char *path, char *err, size_t err_len);

#endif
