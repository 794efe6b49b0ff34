/* tank: ghost particles and bounce-back. */
#include "boundary/tank.h"
#include "physics/eos.h"

#include <stdint.h>

int tank_make_ghosts(const tank *t, particles *p, double reach)
{
    size_t n_fluid = p->n_fluid, g = n_fluid;
    /* serial and in fluid order: the ghost list is the same for any thread count */
    for (size_t i = 0; i < n_fluid; i++) {
        /* per axis, the walls this particle is near: none, low, high (a thin tank: both) */
        unsigned options[DIM][3];
        int n_options[DIM];
        int near_any = 0;
        for (int d = 0; d < DIM; d++) {
            n_options[d] = 0;
            options[d][n_options[d]++] = 0;
            if (p->x[d][i] < reach) options[d][n_options[d]++] = 1u << (2 * d);
            if (p->x[d][i] > t->size[d] - reach) options[d][n_options[d]++] = 2u << (2 * d);
            near_any |= n_options[d] > 1;
        }
        if (!near_any) continue;
        /* every combination of one option per axis but "none" everywhere: a wall, an edge
           (two walls) or a corner (three walls) */
        int combo[DIM] = {0};
        for (;;) {
            unsigned walls = 0;
            for (int d = 0; d < DIM; d++) walls |= options[d][combo[d]];
            if (walls) {
                /* the neighbour lists index fluid and ghosts with int32 (derived.c bounds the
                   fluid alone) */
                if (g == (size_t)INT32_MAX) return -1;
                if (g + 1 > p->capacity && particles_reserve(p, 2 * p->capacity)) return -1;
                p->ghost_kind[g - n_fluid] = GHOST_WALL_IMAGE;
                p->ghost_source[g - n_fluid] = (int32_t)i;
                p->ghost_walls[g - n_fluid] = (uint8_t)walls;
                p->id[g] = p->id[i];
                g++;
            }
            int d = 0;
            while (d < DIM && ++combo[d] == n_options[d]) combo[d++] = 0;
            if (d == DIM) break;
        }
    }
    p->n_total = g;
    return 0;
}

void tank_refresh_ghosts(const tank *t, particles *p, const tank_frame *frame, double rho0,
                         double c0)
{
    size_t n_fluid = p->n_fluid;
    int no_slip = t->wall == WALL_NO_SLIP;
#pragma omp parallel for schedule(static)
    for (size_t g = n_fluid; g < p->n_total; g++) {
        size_t i = (size_t)p->ghost_source[g - n_fluid];
        unsigned walls = p->ghost_walls[g - n_fluid];
        vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
        vec xg = tank_mirror_position(t, xi, walls);
        vec ug = tank_mirror_vector(ui, walls);
        vec_store(p->x, g, xg);
        vec_store(p->u, g, ug);
        vec_store(p->u_wall, g, no_slip ? vec_scale(ui, -1.0) : ug);
        /* the hydrostatic continuation under the source's body force */
        vec force = frame_body_force(frame, xi, ui);
        double pg = p->p[i] + p->rho[i] * vec_dot(force, vec_sub(xg, xi));
        p->p[g] = pg;
        p->rho[g] = eos_density(pg, rho0, c0);
        p->m[g] = p->m[i];
        p->vol[g] = p->m[g] / p->rho[g];
    }
}

void tank_mirror_step_fields(particles *p, const tank_frame *frame, double c0)
{
    size_t n_fluid = p->n_fluid;
#pragma omp parallel for schedule(static)
    for (size_t g = n_fluid; g < p->n_total; g++) {
        size_t i = (size_t)p->ghost_source[g - n_fluid];
        unsigned walls = p->ghost_walls[g - n_fluid];
        vec force = frame_body_force(frame, vec_load(p->x, i), vec_load(p->u, i));
        vec grad_hydro = vec_scale(force, p->rho[i] / (c0 * c0));
        vec dynamic = vec_sub(vec_load(p->grad_rho, i), grad_hydro);
        vec_store(p->grad_rho, g, vec_add(tank_mirror_vector(dynamic, walls), grad_hydro));
#define GHOST_COPY(type, name, flags, comment)                                                     \
    if ((flags)&FIELD_GHOST_COPY) p->name[g] = p->name[i];
#define GHOST_MIRROR(type, name, flags, comment)                                                   \
    if ((flags)&FIELD_GHOST_MIRROR)                                                                \
        vec_store(p->name, g, tank_mirror_vector(vec_load(p->name, i), walls));
        PARTICLE_FIELDS(GHOST_COPY, GHOST_MIRROR)
    }
}

void tank_copy_to_ghosts(const particles *p, double *field)
{
    size_t n_fluid = p->n_fluid;
#pragma omp parallel for schedule(static)
    for (size_t g = n_fluid; g < p->n_total; g++) field[g] = field[p->ghost_source[g - n_fluid]];
}

/* Reverses v when it points towards the wall on the `side` (-1: low wall, +1: high wall). */
static inline double away_from_wall(double v, int side) { return v * side > 0.0 ? -v : v; }

size_t tank_bounce_back(const tank *t, particles *p, double dr, double dt)
{
    double near = 0.25 * dr;
    size_t bounced = 0;
#pragma omp parallel for schedule(static) reduction(+ : bounced)
    for (size_t i = 0; i < p->n_fluid; i++) {
        int hit = 0;
        for (int d = 0; d < DIM; d++) {
            double transport = p->u[d][i] + p->shift[d][i] + p->correction[d][i];
            double ahead = p->x[d][i] + transport * dt;
            int side = ahead < near && transport < 0.0                ? -1
                       : t->size[d] - ahead < near && transport > 0.0 ? 1
                                                                      : 0;
            if (!side) continue;
            p->u[d][i] = away_from_wall(p->u[d][i], side);
            p->shift[d][i] = away_from_wall(p->shift[d][i], side);
            p->correction[d][i] = away_from_wall(p->correction[d][i], side);
            hit = 1;
        }
        bounced += (size_t)hit;
    }
    return bounced;
}
