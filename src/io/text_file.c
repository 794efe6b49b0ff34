/* text_file: a whole small file read into memory (text_file.h). */
#include "io/text_file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

char *text_file_read(const char *path, const char *what, char *err, size_t err_len)
{
    FILE *f = fopen(path, "rb");
    char *text = NULL;
    size_t len = 0;
    FILE *out = f ? open_memstream(&text, &len) : NULL;
    if (!out) {
        snprintf(err, err_len, "%s: cannot read the %s: %s", path, what, strerror(errno));
        if (f) fclose(f);
        return NULL;
    }
    char buf[65536];
    for (size_t n; (n = fread(buf, 1, sizeof buf, f)) > 0;) fwrite(buf, 1, n, out);
    int failed = ferror(f);
    fclose(f);
    if (fclose(out) || failed) {
        snprintf(err, err_len, "%s: cannot read the %s", path, what);
        free(text);
        return NULL;
    }
    return text;
}
