/* models: Table 1. */
#include "scheme/models.h"

model_params models_params(scheme_kind scheme)
{
    /*                                delta C_delta xi  eta  K_c      (Table 1) */
    static const model_params table[] = {
        [SCHEME_STANDARD] = {0.0, 0.0, 0.0, 0, 1.0},
        [SCHEME_DELTA] = {0.1, 6.0, 0.0, 0, 1.2},
        [SCHEME_DELTA_PLUS] = {0.1, 6.0, 1.0, 0, 1.3},
        [SCHEME_DELTA_ALE] = {0.1, 6.0, 1.0, 1, 1.3},
        [SCHEME_DELTA_PLUS_ALE] = {0.1, 6.0, 1.0, -1, 1.3},
    };
    return table[scheme];
}
