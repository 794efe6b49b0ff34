/* case_numbers: derived_compute with the scheme's and the motion's inputs. */
#include "scheme/case_numbers.h"
#include "scheme/models.h"

void case_numbers(const config *cfg, const motion *mo, derived *out)
{
    derived_inputs in = {
        .k_c = cfg->cfl > 0.0 ? cfg->cfl : models_params(cfg->scheme).k_c,
        .g_max = motion_max_effective_gravity(mo, cfg->gravity, cfg->t_end),
        .u_tank_max = motion_max_speed(mo, cfg->t_end),
    };
    motion_max_excursion(mo, cfg->t_end, in.excursion);
    derived_compute(cfg, &in, out);
}
