/* motion_table: a run's own copy of its motion table (motion.type = table). The table is read
 * once, copied into the output folder as motion_table.csv, named by the folder's case.ini and
 * stored in every checkpoint, so that an edit of the original, or of the copy, never changes a
 * run that is under way or restarted. */
#ifndef VCSPH_MOTION_TABLE_H
#define VCSPH_MOTION_TABLE_H

#include <stddef.h>

#define MOTION_TABLE_COPY "motion_table.csv"

/* Writes text as dir/motion_table.csv (whole or not at all) and puts the copy's absolute path
 * in copy_path, for case.ini. Returns 0, or -1 with a message in err. */
int motion_table_store(const char *dir, const char *text, char *copy_path, size_t copy_size,
                       char *err, size_t err_len);

#endif
