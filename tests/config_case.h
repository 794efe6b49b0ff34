/* config_case: the minimal case text and helpers shared by the case-file parser's tests
 * (test_config.c, test_config_errors.c). Include after <cmocka.h>. */
#ifndef VCSPH_TEST_CONFIG_CASE_H
#define VCSPH_TEST_CONFIG_CASE_H

#include "core/config.h"

#include <string.h>

#ifndef VCSPH_SOURCE_DIR
#error "VCSPH_SOURCE_DIR must name the source tree (CMake defines it)"
#endif
#define DATA_DIR VCSPH_SOURCE_DIR "/tests/data/config"
#define ERR_LEN  1024

/* Lines: 1 [case], 2 t_end, 3 [tank], 4 length, 5 height, 6 [liquid], 7 height, 8 [numerics],
 * 9 resolution. The bad cases below are variations of it. */
#define MINIMAL                                                                                    \
    "[case]\nt_end = 1.0\n[tank]\nlength = 1.0\nheight = 0.5\n[liquid]\nheight = 0.2\n"            \
    "[numerics]\nresolution = 20\n"

static inline int load_text(config *cfg, const char *text, const char *const *ov, int n, char *err)
{
    return config_load_string(cfg, text, "bad.ini", ov, n, err, ERR_LEN);
}

static inline void assert_contains(const char *msg, const char *part)
{
    if (!strstr(msg, part)) {
        print_error("message: %s\nlacks:   %s\n", msg, part);
        fail();
    }
}

#endif
