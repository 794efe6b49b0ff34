/* probes: wave gauges and pressure probes (docs/case-file.md [probes]), SPH interpolations of the
 * particle state at fixed points of the tank frame, for probes.csv. */
#ifndef VCSPH_PROBES_H
#define VCSPH_PROBES_H

#include "core/kernel.h"
#include "core/particles.h"

/* the projected kernel is tabulated at this many intervals over [0, 2h] */
#define PROBES_TABLE 1024

typedef struct {
    kernel k;
    kernel colour;                      /* the colour function's, h_c = dr (probes_level) */
    double cell_volume;                 /* V0 / N, each particle's share of the colour */
    double centre_z;                    /* 3D: the gauges' line is at mid-width */
    double projected[PROBES_TABLE + 2]; /* P(s) = integral of W(sqrt(s^2 + y^2)) over y */
} probes;

#define probes_init     DIM_NAME(probes_init)
#define probes_gauge    DIM_NAME(probes_gauge)
#define probes_level    DIM_NAME(probes_level)
#define probes_pressure DIM_NAME(probes_pressure)
#define probes_sensor   DIM_NAME(probes_sensor)

/* h the run's smoothing length, dr its particle spacing, cell_volume V0 / N */
void probes_init(probes *pr, double h, double dr, double cell_volume, double tank_width);

/* Liquid depth at x (m): the integral, along the vertical line at x (3D: at mid-width), of
 * the SPH liquid fraction sum_j W V_j over the tank height. The kernel's integral along y is
 * the projected kernel P, so the depth is sum_j V_j P(distance of j to the line) over the
 * fluid and the ghosts of the side walls (those of the bottom and the roof lie outside the
 * tank's height). For a single-valued surface this is its height above the bottom; drops and
 * overhangs on the line add their thickness, as on a capacitance gauge. Needs the ghosts. */
double probes_gauge(const probes *pr, const particles *p, double x);

/* The height (m) of the liquid's surface on the vertical line at x (3D: at mid-width): the
 * highest point of the line where the colour function C = sum_j W(r, h_c = dr) V0/N, over the
 * fluid and every wall image, reaches 1/2 (the graphical method's colour,
 * docs/graphical-method.md), to 1e-3 dr; 0 where it nowhere does. On a flat lattice surface
 * it reads the cell edge dr/2 above the top row: the liquid's height. Unlike probes_gauge it
 * counts every particle at the lattice cell's volume, so a surface layer packed tighter than
 * the liquid reads where its particles are, not where their SPH volumes would put it; a drop
 * on the line whose colour reaches 1/2 (a lone particle's peaks at 0.56 in 2D, 0.42 in 3D)
 * reads as the surface. Needs the ghosts. */
double probes_level(const probes *pr, const particles *p, double x);

/* Pressure at the point x (Pa): the Shepard-normalised SPH interpolation
 * sum_j p_j W_j V_j / sum_j W_j V_j over the fluid and all ghosts (so a probe on a wall
 * reads the hydrostatic continuation of the ghosts); 0 where no particle is within 2h. */
double probes_pressure(const probes *pr, const particles *p, const double x[3]);

/* Pressure read by a transducer of the given diameter (m) flush with the wall whose normal is
 * the axis `wall_axis`, centred at x: the mean of probes_pressure over its face, a segment of
 * the wall (2D, the face's trace in the plane) or a disc on it (3D), as a transducer
 * integrates the load on its membrane. Gauss-Legendre quadrature: 8 points along the
 * segment; in 3D 4 radii (weighted by r) x 8 angles, exact for polynomials of degree 7 over
 * the disc. */
double probes_sensor(const probes *pr, const particles *p, const double x[3], double diameter,
                     int wall_axis);

#endif
