/* test_filter: `--only PATTERN` runs only the tests whose names match, `--except PATTERN` leaves
 * them out (cmocka's wildcards * and ?). ctest runs a test that may skip (a missing tool, a
 * processor without the wider lanes) as an entry of its own that reports "skipped", apart from
 * the tests that must pass. Include after <cmocka.h>. */
#ifndef VCSPH_TEST_FILTER_H
#define VCSPH_TEST_FILTER_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static inline void test_filter_args(int argc, char **argv)
{
    if (argc == 1) return;
    if (argc == 3 && !strcmp(argv[1], "--only")) {
        cmocka_set_test_filter(argv[2]);
        return;
    }
    if (argc == 3 && !strcmp(argv[1], "--except")) {
        cmocka_set_skip_filter(argv[2]);
        return;
    }
    fprintf(stderr, "usage: %s [--only PATTERN | --except PATTERN]\n", argv[0]);
    exit(2);
}

#endif
