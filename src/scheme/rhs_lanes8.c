/* rhs_lanes8: the right-hand side in 8 lanes (AVX-512, x86-64-v4; scheme/rhs_lanes.h). */
#define LANES             8
#define RHS_COMPUTE_LANES rhs_compute_lanes8
#include "scheme/rhs_lanes.h"
