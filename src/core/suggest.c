/* suggest: the "did you mean" of a mistyped word among the words a file may hold. */
#include "core/suggest.h"

#include <ctype.h>
#include <limits.h>
#include <string.h>

static int same_letter(char a, char b)
{
    return tolower((unsigned char)a) == tolower((unsigned char)b);
}

/* Case-insensitive edit distance counting a swap of two neighbouring letters as one edit (the
 * optimal string alignment distance: "heigth" is 1 from "height", 2 from "length"); long
 * strings are never close. */
static int edit_distance(const char *a, const char *b)
{
    enum { CAP = 64 };
    size_t la = strlen(a), lb = strlen(b);
    if (la >= CAP || lb >= CAP) return INT_MAX;
    int before[CAP], prev[CAP], cur[CAP];
    for (size_t j = 0; j <= lb; j++) prev[j] = (int)j;
    for (size_t i = 1; i <= la; i++) {
        cur[0] = (int)i;
        for (size_t j = 1; j <= lb; j++) {
            int best = prev[j - 1] + !same_letter(a[i - 1], b[j - 1]);
            if (prev[j] + 1 < best) best = prev[j] + 1;
            if (cur[j - 1] + 1 < best) best = cur[j - 1] + 1;
            if (i > 1 && j > 1 && same_letter(a[i - 1], b[j - 2]) &&
                same_letter(a[i - 2], b[j - 1]) && before[j - 2] + 1 < best)
                best = before[j - 2] + 1;
            cur[j] = best;
        }
        memcpy(before, prev, sizeof before);
        memcpy(prev, cur, sizeof prev);
    }
    return prev[lb];
}

/* The candidate closest to `given` (edit distance <= 2 and shorter than the word), else one
 * that `given` starts or ends a prefix of; NULL when nothing is close. */
const char *word_suggest(const char *given, const char *const *cands, size_t n)
{
    const char *best = NULL;
    int best_d = 3;
    int len = (int)strlen(given);
    for (size_t i = 0; i < n; i++) {
        int d = edit_distance(given, cands[i]);
        if (d < best_d && d < len) {
            best = cands[i];
            best_d = d;
        }
    }
    if (best || len < 2) return best;
    for (size_t i = 0; i < n; i++) {
        size_t lc = strlen(cands[i]);
        if (strncmp(cands[i], given, (size_t)len) == 0 ||
            (lc >= 2 && strncmp(given, cands[i], lc) == 0))
            return cands[i];
    }
    return NULL;
}
