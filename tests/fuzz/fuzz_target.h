/* fuzz_target: what the fuzz targets share (tests/fuzz/fuzz_*.c). */
#ifndef VCSPH_FUZZ_TARGET_H
#define VCSPH_FUZZ_TARGET_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* libFuzzer's entry point; tests/fuzz/replay.c calls it on the committed corpus. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* A property broken: say which (the input is what libFuzzer saves), then abort so that the
 * fuzzer and the replay both report it. FUZZ_TARGET names the target in the message. */
static inline void broken(const char *what, const char *detail)
{
    fprintf(stderr, "%s: %s\n%s\n", FUZZ_TARGET, what, detail ? detail : "");
    abort();
}

#endif
