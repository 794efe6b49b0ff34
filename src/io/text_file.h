/* text_file: a whole small file (a motion table, a run's case.ini) read into memory. */
#ifndef VCSPH_TEXT_FILE_H
#define VCSPH_TEXT_FILE_H

#include <stddef.h>

/* The whole file as a NUL-terminated text (free() it), or NULL with a message in err that
 * names the file and calls it `what` ("motion table"). */
char *text_file_read(const char *path, const char *what, char *err, size_t err_len);

#endif
