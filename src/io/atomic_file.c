/* atomic_file: write under path.tmp, then rename over path. */
#include "io/atomic_file.h"
#include "io/io_error.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char temp_suffix[] = ".tmp";

char *atomic_temp_path(const char *path)
{
    size_t len = strlen(path);
    char *tmp = malloc(len + sizeof temp_suffix);
    if (tmp) {
        memcpy(tmp, path, len);
        memcpy(tmp + len, temp_suffix, sizeof temp_suffix);
    }
    return tmp;
}

int atomic_commit(const char *module, const char *tmp, const char *path, char *err, size_t err_len)
{
    if (rename(tmp, path) == 0) return 0;
    io_error(err, err_len, "%s: cannot rename '%s' to '%s': %s", module, tmp, path,
             strerror(errno));
    remove(tmp);
    return -1;
}
