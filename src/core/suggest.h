/* suggest: the "did you mean" of a mistyped word among the words a file may hold (case keys,
 * allowed values, a motion table's column names). */
#ifndef VCSPH_SUGGEST_H
#define VCSPH_SUGGEST_H

#include <stddef.h>

/* The candidate closest to `given` (case-insensitive edit distance <= 2 and shorter than the
 * word), else one that `given` starts or ends a prefix of; NULL when nothing is close. */
const char *word_suggest(const char *given, const char *const *cands, size_t n);

#endif
