/* models: the five SPH models of Table 1 as parameter presets of the one system, Eq. (3). */
#ifndef VCSPH_MODELS_H
#define VCSPH_MODELS_H

#include "core/config.h"

typedef struct {
    double delta;   /* delta of D^m, Eq. (5); also sets the cap delta l c0 of delta_ij */
    double c_delta; /* C_delta of nu^delta, Eq. (5) */
    double xi;      /* 1: particle shifting on, Eq. (7) */
    int eta;        /* 1: variable masses; -1: the dynamical switch of delta-plus-ALE */
    double k_c;     /* CFL number of Eq. (8) */
} model_params;

model_params models_params(scheme_kind scheme);

#endif
