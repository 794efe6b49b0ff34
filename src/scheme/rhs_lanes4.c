/* rhs_lanes4: the right-hand side in 4 lanes (AVX2, x86-64-v3; scheme/rhs_lanes.h). */
#define LANES             4
#define RHS_COMPUTE_LANES rhs_compute_lanes4
#include "scheme/rhs_lanes.h"
