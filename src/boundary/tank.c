/* tank: ghost particles and bounce-back. */
#include "boundary/tank.h"
#include "physics/eos.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>

/* The reflection across a plane: a = I - 2 n n^T, b = 2 distance n (exact for the box's
 * axis-aligned planes: a = diag(+-1), b = 0 or 2 size_d). */
static ghost_map reflection(wall_plane w)
{
    ghost_map m;
    for (int r = 0; r < DIM; r++) {
        for (int c = 0; c < DIM; c++)
            m.a[r][c] = (r == c ? 1.0 : 0.0) - 2.0 * w.normal.c[r] * w.normal.c[c];
        m.b[r] = 2.0 * w.distance * w.normal.c[r];
    }
    return m;
}

/* outer after inner: x -> a_o (a_i x + b_i) + b_o */
static ghost_map compose(const ghost_map *outer, const ghost_map *inner)
{
    ghost_map m;
    vec b_inner;
    for (int r = 0; r < DIM; r++) {
        b_inner.c[r] = inner->b[r];
        for (int c = 0; c < DIM; c++) {
            m.a[r][c] = 0.0;
            for (int k = 0; k < DIM; k++) m.a[r][c] += outer->a[r][k] * inner->a[k][c];
        }
    }
    vec b = ghost_map_point(outer, b_inner);
    for (int r = 0; r < DIM; r++) m.b[r] = b.c[r];
    return m;
}

/* Entry `walls` of the table is the product of the reflections across the planes whose bits
 * are set: one wall, an edge (two) or a corner (three). */
static void box_ghost_maps(tank *t)
{
    for (unsigned walls = 0; walls < (1u << (2 * DIM)); walls++) {
        ghost_map m = {{{0}}, {0}};
        for (int d = 0; d < DIM; d++) m.a[d][d] = 1.0;
        for (int k = 0; k < TANK_PLANES; k++) {
            if (!(walls & (1u << k))) continue;
            ghost_map r = reflection(tank_plane(t, k));
            m = compose(&r, &m);
        }
        t->maps[walls] = m;
    }
}

tank tank_box(const double size[DIM], wall_kind wall)
{
    tank t = {.wall = wall};
    for (int d = 0; d < DIM; d++) {
        t.size[d] = size[d];
        t.planes[2 * d] = (wall_plane){vec_zero(), 0.0};
        t.planes[2 * d].normal.c[d] = 1.0;
        t.planes[2 * d + 1] = (wall_plane){vec_zero(), -size[d]};
        t.planes[2 * d + 1].normal.c[d] = -1.0;
    }
    box_ghost_maps(&t);
    return t;
}

/* Per axis, the walls particle i is within `reach` of, as bits of the ghost-map table: none,
 * low, high (a thin tank: both). Returns its images: every combination of one option per axis
 * but "none" everywhere, a wall, an edge (two walls) or a corner (three walls). */
static int wall_options(const tank *t, const particles *p, size_t i, double reach,
                        unsigned options[DIM][3], int n_options[DIM])
{
    int combinations = 1;
    for (int d = 0; d < DIM; d++) {
        n_options[d] = 0;
        options[d][n_options[d]++] = 0;
        if (p->x[d][i] < reach) options[d][n_options[d]++] = 1u << (2 * d);
        if (p->x[d][i] > t->size[d] - reach) options[d][n_options[d]++] = 2u << (2 * d);
        combinations *= n_options[d];
    }
    return combinations - 1;
}

/* Particle i's images (wall_options) into the slots from g on; returns the next free slot. */
static size_t add_images(particles *p, size_t i, size_t g, unsigned options[DIM][3],
                         const int n_options[DIM])
{
    int combo[DIM] = {0};
    for (;;) {
        unsigned walls = 0;
        for (int d = 0; d < DIM; d++) walls |= options[d][combo[d]];
        if (walls) {
            p->ghost_kind[g - p->n_fluid] = GHOST_WALL_IMAGE;
            p->ghost_source[g - p->n_fluid] = (int32_t)i;
            p->ghost_map[g - p->n_fluid] = (uint8_t)walls;
            g++;
        }
        int d = 0;
        while (d < DIM && ++combo[d] == n_options[d]) combo[d++] = 0;
        if (d == DIM) return g;
    }
}

/* The sources a chunk of tank_make_ghosts: a few dozen chunks a thread at 1e5 particles */
#define GHOST_CHUNK 1024

/* The end of chunk c of n sources */
static inline size_t chunk_end(size_t c, size_t n)
{
    return (c + 1) * GHOST_CHUNK < n ? (c + 1) * GHOST_CHUNK : n;
}

int tank_make_ghosts(const tank *t, particles *p, double reach)
{
    p->ghost_maps = t->maps;
    p->no_slip_images = t->wall == WALL_NO_SLIP;
    size_t n_fluid = p->n_fluid, n_sources = particles_images_begin(p);
    size_t chunks = (n_sources + GHOST_CHUNK - 1) / GHOST_CHUNK;
    /* in the sources' order (the fluid, then an MPI run's halo), whatever the thread count,
       so that a cell's images come in the order of one process: each chunk's images counted,
       then written from the slot that the counts of the chunks before it give */
    size_t *first = malloc((chunks + 1) * sizeof *first);
    if (!first) return -1;
    first[0] = n_sources;
#pragma omp parallel for schedule(static)
    for (size_t c = 0; c < chunks; c++) {
        size_t images = 0, end = chunk_end(c, n_sources);
        for (size_t i = c * GHOST_CHUNK; i < end; i++) {
            unsigned options[DIM][3];
            int n_options[DIM];
            images += (size_t)wall_options(t, p, i, reach, options, n_options);
        }
        first[c + 1] = images;
    }
    for (size_t c = 0; c < chunks; c++) first[c + 1] += first[c];
    size_t n_total = first[chunks];
    /* the neighbour lists index fluid and ghosts with int32 (derived.c bounds the fluid
       alone) */
    bool room = n_total <= (size_t)INT32_MAX &&
                (n_total <= p->capacity || !particles_reserve_images(p, n_total)) &&
                (n_total - n_fluid <= p->ghosts_capacity ||
                 !particles_reserve_ghosts(p, n_total - n_fluid));
    if (room) {
#pragma omp parallel for schedule(static)
        for (size_t c = 0; c < chunks; c++) {
            size_t g = first[c], end = chunk_end(c, n_sources);
            for (size_t i = c * GHOST_CHUNK; i < end; i++) {
                unsigned options[DIM][3];
                int n_options[DIM];
                if (wall_options(t, p, i, reach, options, n_options))
                    g = add_images(p, i, g, options, n_options);
            }
        }
        p->n_total = n_total;
    }
    free(first);
    return room ? 0 : -1;
}

void tank_refresh_ghosts(particles *p, const tank_frame *frame, double rho0, double c0)
{
    size_t n_fluid = p->n_fluid;
#pragma omp parallel for schedule(static)
    for (size_t g = particles_images_begin(p); g < p->n_total; g++) {
        size_t i = (size_t)p->ghost_source[g - n_fluid];
        const ghost_map *map = particle_ghost_map(p, g);
        vec xi = vec_load(p->x, i), ui = vec_load(p->u, i);
        vec xg = ghost_map_point(map, xi);
        vec ug = ghost_map_vector(map, ui);
        vec_store(p->x, g, xg);
        vec_store(p->u, g, ug);
        /* the hydrostatic continuation under the source's body force */
        vec force = frame_body_force(frame, xi, ui);
        double pg = p->p[i] + p->rho[i] * vec_dot(force, vec_sub(xg, xi));
        p->p[g] = pg;
        p->rho[g] = eos_density(pg, rho0, c0);
        p->vol[g] = p->m[i] / p->rho[g]; /* an image has the mass of its source */
    }
}

/* Image g's density gradient from its source i's: the dynamic part mirrored, the hydrostatic
 * part rho f_i / c0^2 kept (tank_mirror_step_fields). */
static inline void mirror_grad_rho(particles *p, const tank_frame *frame, double c0, size_t g,
                                   size_t i, const ghost_map *map)
{
    vec force = frame_body_force(frame, vec_load(p->x, i), vec_load(p->u, i));
    vec grad_hydro = vec_scale(force, p->rho[i] / (c0 * c0));
    vec dynamic = vec_sub(vec_load(p->grad_rho, i), grad_hydro);
    vec_store(p->grad_rho, g, vec_add(ghost_map_vector(map, dynamic), grad_hydro));
}

void tank_mirror_diffusion_fields(particles *p, const tank_frame *frame, double c0)
{
    size_t n_fluid = p->n_fluid;
#pragma omp parallel for schedule(static)
    for (size_t g = particles_images_begin(p); g < p->n_total; g++) {
        size_t i = (size_t)p->ghost_source[g - n_fluid];
        mirror_grad_rho(p, frame, c0, g, i, particle_ghost_map(p, g));
        p->nu_delta[g] = p->nu_delta[i];
    }
}

void tank_mirror_step_fields(particles *p, const tank_frame *frame, double c0)
{
    size_t n_fluid = p->n_fluid;
#pragma omp parallel for schedule(static)
    for (size_t g = particles_images_begin(p); g < p->n_total; g++) {
        size_t i = (size_t)p->ghost_source[g - n_fluid];
        const ghost_map *map = particle_ghost_map(p, g);
        mirror_grad_rho(p, frame, c0, g, i, map);
#define GHOST_COPY(type, name, flags, snapshot, comment)                                           \
    if ((flags)&FIELD_GHOST_COPY) p->name[g] = p->name[i];
#define GHOST_MIRROR(type, name, flags, snapshot, comment)                                         \
    if ((flags)&FIELD_GHOST_MIRROR)                                                                \
        vec_store(p->name, g, ghost_map_vector(map, vec_load(p->name, i)));
        PARTICLE_FIELDS(GHOST_COPY, GHOST_MIRROR)
    }
}

void tank_copy_to_ghosts(const particles *p, frozen_real *field)
{
    size_t n_fluid = p->n_fluid;
#pragma omp parallel for schedule(static)
    for (size_t g = particles_images_begin(p); g < p->n_total; g++)
        field[g] = field[p->ghost_source[g - n_fluid]];
}

/* v reflected across the plane when it points at it (v . n < 0), as it is otherwise: the
 * normal component reversed, the tangential ones kept. */
static inline vec away_from_wall(vec v, vec n)
{
    double vn = vec_dot(v, n);
    return vn < 0.0 ? vec_axpy(v, -2.0 * vn, n) : v;
}

size_t tank_bounce_back(const tank *t, particles *p, double dr, double dt)
{
    double near = 0.25 * dr;
    size_t bounced = 0;
#pragma omp parallel for schedule(static) reduction(+ : bounced)
    for (size_t i = 0; i < p->n_fluid; i++) {
        vec u = vec_load(p->u, i), shift = vec_load(p->shift, i), dv = vec_load(p->correction, i);
        vec transport = vec_add(vec_add(u, shift), dv);
        vec ahead = vec_axpy(vec_load(p->x, i), dt, transport);
        /* the walls it reaches, all judged from the velocities before any reversal (two
           opposite walls cannot both be within dr/4: the tank holds at least two particles
           across, derived_check) */
        unsigned hit = 0;
        for (int k = 0; k < TANK_PLANES; k++) {
            wall_plane w = tank_plane(t, k);
            if (vec_dot(w.normal, ahead) - w.distance < near && vec_dot(w.normal, transport) < 0.0)
                hit |= 1u << k;
        }
        if (!hit) continue;
        for (int k = 0; k < TANK_PLANES; k++) {
            if (!(hit & (1u << k))) continue;
            vec n = tank_plane(t, k).normal;
            u = away_from_wall(u, n);
            shift = away_from_wall(shift, n);
            dv = away_from_wall(dv, n);
        }
        vec_store(p->u, i, u);
        vec_store(p->shift, i, shift);
        vec_store(p->correction, i, dv);
        bounced++;
    }
    return bounced;
}
