/* tank: the rectangular tank in its own frame: ghost particles of its walls (Colagrossi &
 * Landrini 2003), wall distance and bounce-back (sec. 2.5; theory §5). */
#ifndef VCSPH_TANK_H
#define VCSPH_TANK_H

#include "boundary/frame.h"
#include "core/config.h"
#include "core/particles.h"
#include "core/vec.h"

/* A wall: the plane n . x = distance, n pointing into the liquid. */
typedef struct {
    vec normal;
    double distance;
} wall_plane;

/* The walls' planes. The box's: plane 2d is the low wall of axis d (e_d, 0), plane 2d + 1 the
 * high one (-e_d, -size_d); wall distance, bounce-back and the ghosts' maps loop over them, so a
 * wall that is not a box face is one more plane (the ghost list of tank_make_ghosts is still
 * the box's: images across the walls of each axis and their edges and corners). */
#define TANK_PLANES (2 * DIM)

typedef struct {
    double size[DIM]; /* L, D[, W]: walls at x_d = 0 and x_d = size[d] */
    wall_kind wall;
    wall_plane planes[TANK_PLANES];
    ghost_map maps[GHOST_MAPS_MAX]; /* the ghosts' maps, entry `walls` (tank_make_ghosts) */
} tank;

#define tank_box DIM_NAME(tank_box)

/* The rectangular tank of inner size `size` with its walls' planes and the ghosts' maps. */
tank tank_box(const double size[DIM], wall_kind wall);

static inline wall_plane tank_plane(const tank *t, int k) { return t->planes[k]; }

#define tank_make_ghosts             DIM_NAME(tank_make_ghosts)
#define tank_refresh_ghosts          DIM_NAME(tank_refresh_ghosts)
#define tank_mirror_step_fields      DIM_NAME(tank_mirror_step_fields)
#define tank_mirror_diffusion_fields DIM_NAME(tank_mirror_diffusion_fields)
#define tank_bounce_back             DIM_NAME(tank_bounce_back)
#define tank_copy_to_ghosts          DIM_NAME(tank_copy_to_ghosts)

/* Rebuilds the ghost list: every fluid particle within `reach` of a wall gets an image across
 * it, and across each pair (and triple) of walls near an edge or corner. Only the list
 * (source, walls) is made here; tank_refresh_ghosts fills the state. Returns 0, or -1 when
 * out of memory or past INT32_MAX particles in all (the neighbour lists index them in int32). */
int tank_make_ghosts(const tank *t, particles *p, double reach);

/* Ghost state from the current fluid state (every RK stage): mirrored position; velocity
 * with the normal components reversed (free slip; the viscous term's no-slip image, reversed
 * whole, is read through the source: particle_viscous_velocity); mass of the source; pressure
 * continued hydrostatically, p_g = p_i + rho_i f_i . (r_g - r_i) with f_i the body force of the
 * tank frame at the source (frame.h; g - a_tank today), and density from the EOS. Needs fluid p. */
void tank_refresh_ghosts(particles *p, const tank_frame *frame, double rho0, double c0);

/* Per-step fields of the ghosts from their sources: eddy viscosity, diffusion coefficient and
 * S_F flag copied, the shifting velocity mirrored (free slip): the fields marked
 * FIELD_GHOST_COPY and FIELD_GHOST_MIRROR in core/particles.h (the volume correction's velocity
 * no image holds: particle_source_vector reads it through the image); density gradient
 * = mirror of the source's dynamic part plus the hydrostatic gradient rho f_i / c0^2, consistent
 * with the hydrostatic continuation above. */
void tank_mirror_step_fields(particles *p, const tank_frame *frame, double c0);

/* Of those, what the density diffusion (Eq. 5) reads at an image: the density gradient and
 * the diffusion coefficient. In a frame that does not rotate they are final once the step's
 * geometry and EdBC have run (the body force does not depend on the velocity), so the
 * diffusion of a row at a wall can be summed before bounce-back (scheme/passes.c). */
void tank_mirror_diffusion_fields(particles *p, const tank_frame *frame, double c0);

/* A per-particle scalar of the fluid copied to its ghosts (a field that is even across the
 * walls: the ghost carries its source's value). */
void tank_copy_to_ghosts(const particles *p, frozen_real *field);

/* Bounce-back (sec. 2.5), at the start of a step once its shifting velocity du is known:
 * a particle that its transport velocity u + du (+ the volume correction's) takes closer than
 * dr/4 to a wall within the step `dt` (or past it) has the normal components of these
 * velocities that point at the wall reversed, tangential ones kept. Looking a step ahead matters:
 * during a roof impact a particle moves half a spacing per step. Reversing u alone fails with ALE,
 * where du may carry a particle into the wall that u takes away from it. Returns the particles
 * bounced. */
size_t tank_bounce_back(const tank *t, particles *p, double dr, double dt);

/* Distance to the nearest wall (sec. 2.5) and that wall's normal (into the liquid). */
static inline double tank_wall_distance(const tank *t, vec x, vec *normal)
{
    double best = INFINITY;
    for (int k = 0; k < TANK_PLANES; k++) {
        wall_plane w = tank_plane(t, k);
        double m = vec_dot(w.normal, x) - w.distance;
        if (m < best) {
            best = m;
            *normal = w.normal;
        }
    }
    return best;
}

static inline int tank_contains(const tank *t, vec x)
{
    for (int d = 0; d < DIM; d++)
        if (!(x.c[d] >= 0.0 && x.c[d] <= t->size[d])) return 0;
    return 1;
}

#endif
