/* case_numbers: the derived numbers of a case (core/derived.h), with what the scheme and the
 * tank's motion contribute to them: Table 1's CFL number, the motion's largest effective
 * gravity, tank speed and excursion up to t_end. */
#ifndef VCSPH_CASE_NUMBERS_H
#define VCSPH_CASE_NUMBERS_H

#include "boundary/motion.h"
#include "core/config.h"
#include "core/derived.h"

void case_numbers(const config *cfg, const motion *mo, derived *out);

#endif
