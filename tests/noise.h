/* noise: a fixed sequence of numbers uniform in [-1, 1), the same on every machine (64-bit LCG,
 * Knuth's MMIX constants), for the tests that perturb particles. */
#ifndef VCSPH_TEST_NOISE_H
#define VCSPH_TEST_NOISE_H

#include <stdint.h>

static inline double noise(uint64_t *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) / 4503599627370496.0 - 1.0;
}

#endif
