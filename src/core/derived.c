/* derived: numbers that follow from the case (theory §3, §7, §10). */
#include "core/derived.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>

/* The solver indexes particles with int32 (neighbour lists, ghost sources): a case whose
   liquid box lattice holds more points than that is refused (derived_check), and neither counted
   nor multiplied out in a long (derived_compute). */
#define PARTICLES_MAX INT32_MAX

static int check_sanity(const config *cfg, const derived *dv, const char **key, char *why,
                        size_t why_len);

static double min2(double a, double b) { return a < b ? a : b; }

bool derived_lattice_point(const config *cfg, const derived *dv, long c0, long c1, long c2,
                           double x[3])
{
    const long c[3] = {c0, c1, c2};
    const double origin[3] = {cfg->liquid_x0, cfg->liquid_y0, 0.0};
    int dim = cfg->dim;
    for (int d = 0; d < 3; d++) x[d] = d < dim ? origin[d] + (c[d] + 0.5) * dv->spacing[d] : 0.0;
    if (cfg->liquid_shape == LIQUID_BOX) return true;
    /* (x - xc) / a = ((c + 1/2) L / n - L / 2) / (L / 2) = (2 c + 1 - n) / n: the same test on
       the point's centre, computed from whole numbers, so that the kept set is exactly
       symmetric about the centre of the box and free of rounding in x0, y0 and the spacing. */
    double r2 = 0.0;
    for (int d = 0; d < dim; d++) {
        double n = (double)dv->n_axis[d];
        double u = (2.0 * (double)c[d] + 1.0 - n) / n;
        r2 += u * u;
    }
    return r2 <= 1.0;
}

/* Points of the liquid box lattice, in double: the product of the n_axis may overflow a long. */
static double box_points(const derived *dv)
{
    return (double)dv->n_axis[0] * (double)dv->n_axis[1] * (double)dv->n_axis[2];
}

/* The lattice points derived_lattice_point keeps for the ellipse (ellipsoid). Along a line of
   the lattice parallel to axis a, it keeps a run symmetric about the middle: its test is
   monotone in |2 c_a + 1 - n_a| (an exact integer, then a correctly rounded division, square
   and sums). So each line is counted by bisection on that same predicate, which gives the
   count of the point-by-point loop exactly, in O(lines log n) rather than O(points) (10^9
   points in a cube: 10^6 lines along the longest axis, 10^7 evaluations). */
static long ellipse_points(const config *cfg, const derived *dv)
{
    int a = 0;
    for (int d = 1; d < cfg->dim; d++)
        if (dv->n_axis[d] > dv->n_axis[a]) a = d;
    int b = (a + 1) % 3, e = (a + 2) % 3; /* in 2D, one of them is axis 2, with one point */
    long n = dv->n_axis[a], count = 0, c[3];
    double x[3];
    for (c[e] = 0; c[e] < dv->n_axis[e]; c[e]++) {
        for (c[b] = 0; c[b] < dv->n_axis[b]; c[b]++) {
            /* the run's first point is in [0, (n - 1) / 2]; the line has none if that is out */
            long lo = 0, hi = (n - 1) / 2;
            c[a] = hi;
            if (!derived_lattice_point(cfg, dv, c[0], c[1], c[2], x)) continue;
            while (lo < hi) {
                c[a] = lo + (hi - lo) / 2;
                if (derived_lattice_point(cfg, dv, c[0], c[1], c[2], x))
                    hi = c[a];
                else
                    lo = c[a] + 1;
            }
            count += n - 2 * lo;
        }
    }
    return count;
}

void derived_compute(const config *cfg, const derived_inputs *in, derived *dv)
{
    double dr = cfg->liquid_height / cfg->resolution;
    dv->dr = dr;
    dv->h = cfg->h_over_dr * dr;
    /* The lattice fills the liquid box exactly (V0 = L H W, sec. 3): a whole number of
       particles along each axis, spaced dr along y and within dr / (2 n) of dr along x and z.
       A square lattice of spacing dr would leave a gap of up to dr/2 at one wall, where the
       kernel sums of Eq. (11) read a spurious +28 % volume at t = 0. */
    double extent[3] = {cfg->liquid_length, cfg->liquid_height, cfg->tank_width};
    dv->v0 = 1.0;
    for (int d = 0; d < 3; d++) {
        if (d == 2 && cfg->dim == 2) {
            dv->n_axis[d] = 1;
            dv->spacing[d] = 1.0;
            continue;
        }
        /* past the range of a long, lround's result is unspecified: such a length counts
           as more points than PARTICLES_MAX rather than as one */
        double q = extent[d] / dr;
        long n = d == 1 ? cfg->resolution : q < 0x1p62 ? lround(q) : LONG_MAX;
        dv->n_axis[d] = n < 1 ? 1 : n;
        dv->spacing[d] = extent[d] / (double)dv->n_axis[d];
        dv->v0 *= extent[d];
    }
    if (box_points(dv) > PARTICLES_MAX) {
        /* refused by derived_check; the box's volume stands, the count is left at 0 */
        dv->n_fluid = 0;
        dv->cell_volume = dv->spacing[0] * dv->spacing[1] * dv->spacing[2];
    } else if (cfg->liquid_shape == LIQUID_BOX) {
        dv->n_fluid = dv->n_axis[0] * dv->n_axis[1] * dv->n_axis[2];
        dv->cell_volume = dv->v0 / (double)dv->n_fluid;
    } else {
        /* the ellipse (ellipsoid) inscribed in the box: the lattice points lattice_fill keeps,
           each standing for one cell of the box lattice */
        dv->n_fluid = ellipse_points(cfg, dv);
        dv->cell_volume = dv->spacing[0] * dv->spacing[1] * dv->spacing[2];
        dv->v0 = (double)dv->n_fluid * dv->cell_volume;
    }

    dv->g_max = in->g_max;
    /* Eq. (6) with U_max the speed of a fall from H under g_max */
    dv->c0 = cfg->sound_speed > 0.0 ? cfg->sound_speed
                                    : 10.0 * sqrt(2.0 * dv->g_max * cfg->liquid_height);
    dv->k_c = in->k_c;
    /* Eq. (6): c0 >= 10 max(sqrt(dp_max / rho), U_max), with dp_max = rho g_max H, the column
       under the largest effective gravity, and U_max the speed the case itself sets, the
       tank's peak. The flow's own speeds (a fall from H, the `auto` rule's sqrt(2 g_max H))
       are what the paper's c0 (Table 5) is chosen against; a run reports them when they pass
       c0 / 10 (events.csv). */
    dv->u_tank_max = in->u_tank_max;
    double u_hydro = sqrt(dv->g_max * cfg->liquid_height);
    dv->c0_eq6 = 10.0 * (dv->u_tank_max > u_hydro ? dv->u_tank_max : u_hydro);
    for (int d = 0; d < 3; d++) dv->excursion[d] = in->excursion[d];

    double h = dv->h;
    dv->dt_v = 0.125 * h * h / cfg->viscosity;
    dv->dt_c = dv->k_c * h / dv->c0;
    dv->dt_a = dv->g_max > 0.0 ? 0.25 * sqrt(h / dv->g_max) : INFINITY;
    dv->dt_st = cfg->surface_tension > 0.0
                    ? 0.25 * sqrt(cfg->density * h * h * h / (2.0 * M_PI * cfg->surface_tension))
                    : INFINITY;
    dv->dt = min2(min2(dv->dt_v, dv->dt_c), min2(dv->dt_a, dv->dt_st));

    double width = cfg->dim == 3 ? cfg->tank_width : 1.0;
    if (cfg->liquid_shape == LIQUID_BOX)
        dv->mass_liquid = cfg->density * cfg->liquid_length * cfg->liquid_height * width;
    else
        dv->mass_liquid = cfg->density * dv->v0;
    int periodic = cfg->motion != MOTION_NONE && cfg->motion != MOTION_TABLE && cfg->period > 0;
    dv->omega = periodic ? 2.0 * M_PI / cfg->period : 0.0;
    bool translation = config_motion_translation_axis(cfg->motion) >= 0;
    bool rotation = config_motion_rotation(cfg->motion) >= 0;
    /* the tank's speed scale: A w of a translation; for a rotation g Theta / w, the speed
       amplitude of the sway whose acceleration g Theta equals the tilted gravity's pull along
       the tank, a rotation's main forcing (docs/case-file.md) */
    double aw = translation ? cfg->amplitude * dv->omega : 0.0;
    double turn = rotation && dv->omega > 0.0 ? cfg->gravity * cfg->angle / dv->omega : 0.0;
    dv->d_energy = 0.5 * dv->mass_liquid * (aw * aw + turn * turn);
    dv->d_power = periodic ? dv->d_energy / cfg->period : 0.0;
    dv->dissipation_norm = cfg->decay > 0.0 ? dv->mass_liquid * cfg->gravity * 2.0 * cfg->amplitude
                                            : (periodic ? dv->d_energy : 0.0);

    /* T1 = 2 pi / sqrt(g k tanh(k H)), k = pi / L: the first mode of linear sloshing */
    double k = M_PI / cfg->tank_length;
    double g = cfg->gravity > 0.0 ? cfg->gravity : dv->g_max;
    dv->t_sloshing1 = g > 0.0 ? 2.0 * M_PI / sqrt(g * k * tanh(k * cfg->liquid_height)) : 0.0;
    if (periodic)
        dv->response_period = cfg->motion == MOTION_HEAVE ? 2.0 * cfg->period : cfg->period;
    else
        dv->response_period = dv->t_sloshing1;
}

int derived_problem(const config *cfg, const derived *dv, const char **key, char *why,
                    size_t why_len)
{
    if (box_points(dv) > PARTICLES_MAX) {
        char axes[64];
        if (cfg->dim == 2)
            snprintf(axes, sizeof axes, "%ld x %ld", dv->n_axis[0], dv->n_axis[1]);
        else
            snprintf(axes, sizeof axes, "%ld x %ld x %ld", dv->n_axis[0], dv->n_axis[1],
                     dv->n_axis[2]);
        *key = "numerics.resolution";
        snprintf(why, why_len,
                 "the liquid box's lattice would have %.3g points (%s), more than the %d "
                 "particles the solver can index; lower the resolution",
                 box_points(dv), axes, PARTICLES_MAX);
        return 2;
    }
    if (dv->c0 <= 0.0) {
        *key = "numerics.sound_speed";
        snprintf(why, why_len,
                 "10 sqrt(2 g_max H) is 0 without gravity or tank motion; give a sound speed > "
                 "0 (m/s; Eq. 6: at least 10 times the largest speed)");
        return 2;
    }
    if (cfg->scheme == SCHEME_DELTA_PLUS_ALE && cfg->eta_control == ETA_CONTROL_ADAPTIVE &&
        !(dv->response_period > 0.0)) {
        *key = "model.eta_control";
        snprintf(why, why_len,
                 "adaptive averages eps_V1 over the period of the flow's response, which needs "
                 "periodic motion or gravity; use eta_control = threshold");
        return 2;
    }
    return check_sanity(cfg, dv, key, why, why_len);
}

int derived_check(const config *cfg, const derived *dv, char *err, size_t err_len)
{
    const char *key = "";
    char why[1024];
    int status = derived_problem(cfg, dv, &key, why, sizeof why);
    if (status) snprintf(err, err_len, "%s: %s", key, why);
    return status;
}

/* The liquid's extent along axis d, and the keys that set it and its particle count. */
static const char *const axis_name[3] = {"x", "y", "z"};
static const char *const axis_keys[3] = {"liquid.length or numerics.resolution",
                                         "numerics.resolution",
                                         "tank.width (the liquid fills it) or numerics.resolution"};
static const char *const axis_key[3] = {"numerics.resolution", "numerics.resolution", "tank.width"};

static double liquid_extent(const config *cfg, int d)
{
    return d == 0 ? cfg->liquid_length : d == 1 ? cfg->liquid_height : cfg->tank_width;
}

/* The limit of Eq. (8) that sets dt, and the keys that set that limit. */
static void dt_limit(const derived *dv, const char **name, const char **keys)
{
    if (dv->dt == dv->dt_c) {
        *name = "dt_c = K_c h / c0";
        *keys = "numerics.sound_speed (auto: from g_max, i.e. motion.amplitude and motion.period)";
    } else if (dv->dt == dv->dt_a) {
        *name = "dt_a = 0.25 sqrt(h / g_max)";
        *keys = "motion.amplitude or motion.period (g_max)";
    } else if (dv->dt == dv->dt_v) {
        *name = "dt_v = 0.125 h^2 / nu";
        *keys = "fluid.viscosity";
    } else {
        *name = "dt_st = 0.25 sqrt(rho0 h^3 / (2 pi sigma))";
        *keys = "fluid.surface_tension";
    }
}

/* A case whose first step already breaks a bound, or that would never end. */
static int check_sanity(const config *cfg, const derived *dv, const char **key, char *why,
                        size_t why_len)
{
    /* fewer than 2 particles across: no pair of particles along that axis, no gradient */
    for (int d = 0; d < cfg->dim; d++)
        if (dv->n_axis[d] < DERIVED_MIN_ACROSS) {
            *key = axis_key[d];
            snprintf(why, why_len,
                     "the liquid is %ld particle(s) across %s (%.6g m at dr = H/N = %.6g m); at "
                     "least %d are needed: raise %s",
                     dv->n_axis[d], axis_name[d], liquid_extent(cfg, d), dv->dr, DERIVED_MIN_ACROSS,
                     axis_keys[d]);
            return 2;
        }
    /* more steps than any run on this kind of machine can make (1e10 steps of even 100
       particles at a microsecond each are 11 days): a unit error, or a case that never ends */
    double steps = cfg->t_end / dv->dt;
    if (!(steps <= DERIVED_MAX_STEPS)) {
        const char *name, *keys;
        dt_limit(dv, &name, &keys);
        *key = "case.t_end";
        snprintf(why, why_len,
                 "at dt = %.3g s (Eq. 8: %s, c0 = %.3g m/s, g_max = %.3g m/s^2) it is %.3g "
                 "steps, more than %.0e; lower case.t_end or check %s",
                 dv->dt, name, dv->c0, dv->g_max, steps, DERIVED_MAX_STEPS, keys);
        return 2;
    }
    /* the linear EOS (Eq. 3) at the bottom of a column H under g_max at rest: the lattice
       starts hydrostatic (under g), and the health check stops a run whose density leaves
       rho0 (1 +- density_bound) (diag/health.c) */
    double rho0 = cfg->density;
    double rho_bottom = rho0 * (1.0 + dv->g_max * cfg->liquid_height / (dv->c0 * dv->c0));
    if (!(rho_bottom <= rho0 * (1.0 + cfg->density_bound))) {
        *key = "numerics.sound_speed";
        snprintf(why, why_len,
                 "the hydrostatic density at the bottom, rho0 (1 + g_max H / c0^2) = %.6g kg/m^3 "
                 "(g_max = %.4g m/s^2, H = %g m, c0 = %.4g m/s), is outside rho0 (1 +- %g) "
                 "(numerics.density_bound) before the first step; raise numerics.sound_speed to "
                 "at least %.3g m/s (Eq. 6 asks %.3g m/s) or numerics.density_bound",
                 rho_bottom, dv->g_max, cfg->liquid_height, dv->c0, cfg->density_bound,
                 sqrt(dv->g_max * cfg->liquid_height / cfg->density_bound), dv->c0_eq6);
        return 2;
    }
    return 0;
}

int derived_warnings(const config *cfg, const derived *dv, void (*emit)(const char *msg, void *ctx),
                     void *ctx)
{
    char msg[1024];
    int n = 0;
    /* Eq. (6): density variations within 1 % need c0 >= 10 U_max */
    if (dv->c0 < dv->c0_eq6) {
        snprintf(msg, sizeof msg,
                 "numerics.sound_speed: c0 = %.4g m/s%s is below Eq. (6)'s 10 max(sqrt(g_max H), "
                 "U_max) = %.4g m/s (g_max = %.4g m/s^2, H = %.4g m, U_max = %.4g m/s the tank's "
                 "peak speed); expect density errors above 1 %%",
                 dv->c0, cfg->sound_speed > 0.0 ? "" : " (auto)", dv->c0_eq6, dv->g_max,
                 cfg->liquid_height, dv->u_tank_max);
        emit(msg, ctx);
        n++;
    }
    /* a kernel of h = 2 dr reaches 4 particles: with fewer than 8 across there is no
       particle that both walls or surfaces leave alone */
    for (int d = 0; d < cfg->dim; d++)
        if (dv->n_axis[d] < DERIVED_FEW_ACROSS) {
            snprintf(msg, sizeof msg,
                     "the liquid is %ld particles across %s (%.6g m at dr = %.6g m), fewer than "
                     "%d: the kernel (2h = %.3g m) spans it; raise %s",
                     dv->n_axis[d], axis_name[d], liquid_extent(cfg, d), dv->dr, DERIVED_FEW_ACROSS,
                     2.0 * dv->h, axis_keys[d]);
            emit(msg, ctx);
            n++;
        }
    /* The tank moves as a whole and the particles live in the tank frame, so no amplitude
       takes the liquid out of the tank; only the effective gravity g - a_tank reaches it.
       But a driven displacement larger than the tank itself along the same axis (sway: x,
       heave: y) is no sloshing experiment: almost certainly a unit error (mm written as m). */
    const double size[3] = {cfg->tank_length, cfg->tank_height, cfg->tank_width};
    for (int d = 0; d < 3; d++)
        if (dv->excursion[d] > size[d]) {
            snprintf(msg, sizeof msg,
                     "%s: the tank's displacement along %s reaches +-%.4g m, more than the "
                     "tank's own %.4g m along that axis: a unit error? (motion amplitudes are "
                     "in m)",
                     cfg->motion == MOTION_TABLE ? "motion.file" : "motion.amplitude", axis_name[d],
                     dv->excursion[d], size[d]);
            emit(msg, ctx);
            n++;
        }
    /* A roll of more than 45 degrees is no tank's motion; 1 to 45 "degrees" written as
       radians is (angles are in rad, like motion.phase) */
    if (config_motion_rotation(cfg->motion) >= 0 && cfg->angle > 0.25 * M_PI) {
        snprintf(msg, sizeof msg,
                 "motion.angle = %.4g rad is %.4g degrees: a unit error? (angles are in rad)",
                 cfg->angle, cfg->angle * 180.0 / M_PI);
        emit(msg, ctx);
        n++;
    }
    return n;
}

void derived_print(const config *cfg, const derived *dv, FILE *out)
{
    const char *per = cfg->dim == 2 ? " (per unit width)" : "";
    fprintf(out, "dim              %d\n", cfg->dim);
    fprintf(out, "scheme           %s\n", config_scheme_name(cfg->scheme));
    fprintf(out, "volume controls  edbc = %s, eta_control = %s, volume_correction = %s\n",
            config_edbc_name(cfg->edbc), config_eta_control_name(cfg->eta_control),
            config_volume_correction_name(cfg->volume_correction));
    fprintf(out, "dr               %.6g m (N = %d)\n", dv->dr, cfg->resolution);
    fprintf(out, "h                %.6g m (h/dr = %g, support 2h = %.6g m)\n", dv->h,
            cfg->h_over_dr, 2.0 * dv->h);
    bool box = cfg->liquid_shape == LIQUID_BOX;
    const char *inscribed = box             ? ""
                            : cfg->dim == 2 ? "the ellipse inscribed in "
                                            : "the ellipsoid inscribed in ";
    if (cfg->dim == 2)
        fprintf(out, "fluid particles  %ld (%s%ld x %ld)\n", dv->n_fluid, inscribed, dv->n_axis[0],
                dv->n_axis[1]);
    else
        fprintf(out, "fluid particles  %ld (%s%ld x %ld x %ld)\n", dv->n_fluid, inscribed,
                dv->n_axis[0], dv->n_axis[1], dv->n_axis[2]);
    if (dv->spacing[0] != dv->dr || (cfg->dim == 3 && dv->spacing[2] != dv->dr)) {
        fprintf(out, "lattice spacing  %.6g x %.6g", dv->spacing[0], dv->spacing[1]);
        if (cfg->dim == 3) fprintf(out, " x %.6g", dv->spacing[2]);
        fprintf(out, " m (%s)\n",
                box ? "fills the liquid box exactly" : "the liquid box's lattice");
    }
    fprintf(out, "V0               %.6g m^%d\n", dv->v0, cfg->dim);
    fprintf(out, "g_max            %.6g m/s^2\n", dv->g_max);
    fprintf(out, "c0               %.6g m/s%s\n", dv->c0, cfg->sound_speed > 0 ? "" : " (auto)");
    fprintf(out,
            "Eq. (6) c0 >=    %.4g m/s (10 max(sqrt(g_max H), U_max), U_max the tank's peak "
            "speed %.4g m/s)\n",
            dv->c0_eq6, dv->u_tank_max);
    fprintf(out, "K_c              %g\n", dv->k_c);
    fprintf(out, "dt_c             %.4g s\n", dv->dt_c);
    fprintf(out, "dt_v             %.4g s\n", dv->dt_v);
    fprintf(out, "dt_a (g_max)     %.4g s\n", dv->dt_a);
    if (isfinite(dv->dt_st)) fprintf(out, "dt_st            %.4g s\n", dv->dt_st);
    fprintf(out, "dt estimate      %.4g s (%.3g steps to t_end = %g s)\n", dv->dt,
            cfg->t_end / dv->dt, cfg->t_end);
    fprintf(out, "M_L              %.6g kg%s\n", dv->mass_liquid, per);
    if (dv->d_power > 0.0) {
        fprintf(out, "dE               %.6g J%s\n", dv->d_energy, per);
        fprintf(out, "dW               %.6g W%s\n", dv->d_power, per);
    }
    if (cfg->decay > 0.0 && dv->dissipation_norm > 0.0)
        fprintf(out, "dE_P = M_L g 2A  %.6g J%s (normalises dissipation.csv)\n",
                dv->dissipation_norm, per);
    fprintf(out, "T1 (sloshing)    %.6g s\n", dv->t_sloshing1);
    fprintf(out, "response period  %.6g s (the adaptive eta control's average)\n",
            dv->response_period);
}
