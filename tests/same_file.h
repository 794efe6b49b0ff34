/* same_file: whether two files hold the same bytes, for the tests of byte-identical runs. */
#ifndef VCSPH_TEST_SAME_FILE_H
#define VCSPH_TEST_SAME_FILE_H

#include <stdio.h>

/* 1 when both files open and hold the same bytes, 0 otherwise. */
static inline int same_file(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    int same = fa && fb;
    while (same) {
        int ca = fgetc(fa), cb = fgetc(fb);
        if (ca != cb) same = 0;
        if (ca == EOF || cb == EOF) break;
    }
    if (fa) fclose(fa);
    if (fb) fclose(fb);
    return same;
}

#endif
