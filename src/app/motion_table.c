/* motion_table: the run's copy of its motion table (motion_table.h). */
#include "app/motion_table.h"
#include "io/atomic_file.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int motion_table_store(const char *dir, const char *text, char *copy_path, size_t copy_size,
                       char *err, size_t err_len)
{
    char absolute[PATH_MAX];
    if (!realpath(dir, absolute)) {
        snprintf(err, err_len, "%s: %s", dir, strerror(errno));
        return -1;
    }
    if ((size_t)snprintf(copy_path, copy_size, "%s/%s", absolute, MOTION_TABLE_COPY) >= copy_size) {
        snprintf(err, err_len, "%s: the path of the motion table's copy is too long", absolute);
        return -1;
    }
    char *tmp = atomic_temp_path(copy_path);
    FILE *f = tmp ? fopen(tmp, "wb") : NULL;
    if (!f) {
        snprintf(err, err_len, "%s: %s", tmp ? tmp : copy_path, strerror(errno));
        free(tmp);
        return -1;
    }
    size_t len = strlen(text);
    int failed = fwrite(text, 1, len, f) != len;
    if (fclose(f) || failed) {
        snprintf(err, err_len, "%s: %s", tmp, strerror(errno));
        remove(tmp);
        free(tmp);
        return -1;
    }
    int status = atomic_commit("motion table", tmp, copy_path, err, err_len);
    free(tmp);
    return status;
}
