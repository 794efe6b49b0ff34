/* snapshot_read: reading back a snapshot written by snapshot_write (for `vcsph volume`). */
#ifndef VCSPH_SNAPSHOT_READ_H
#define VCSPH_SNAPSHOT_READ_H

#include <stddef.h>

typedef struct snapshot_info {
    double time;
    long step;
    int dim;
    size_t n;        /* particles */
    char *case_text; /* the resolved case (malloc'd) */
} snapshot_info;

/* Opens `path` and reads its attributes and particle count. Returns 0, or -1 with a message. */
int snapshot_read_info(const char *path, snapshot_info *info, char *err, size_t err_len);
void snapshot_info_free(snapshot_info *info);
/* Reads the double dataset `name` (n rows of ncomp) into the SoA arrays out[0..ncomp). */
int snapshot_read_doubles(const char *path, const char *name, int ncomp, double *const *out,
                          size_t n, char *err, size_t err_len);

#endif
