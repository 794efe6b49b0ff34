/* particles: the SoA particle store. Fluid particles occupy [0, n_fluid), wall ghosts the
 * tail [n_fluid, n_total) (where MPI halo particles will also go, docs/architecture.md). */
#ifndef VCSPH_PARTICLES_H
#define VCSPH_PARTICLES_H

#include "core/dim.h"
#include "core/vec.h"

#include <stddef.h>
#include <stdint.h>

/* The field registry: every array of the store, one line each, in the order of the struct.
 * SCALAR(type, name, flags, snapshot, comment) is one value per particle, VECTOR(...) DIM
 * components. FIELD_STATE marks the persistent state of a fluid particle, reordered with it when
 * the fluid is sorted by cell (particles_permute_fluid); every other field is recomputed from it
 * every step or stage. FIELD_GHOST_COPY and FIELD_GHOST_MIRROR mark the per-step fields that a
 * wall ghost takes from its source once they are computed (tank_mirror_step_fields): as they
 * are (scalars), or mirrored across the ghost's walls (vectors). FIELD_SOURCES_ONLY marks the
 * fields that no wall image holds, read and written for the fluid and an MPI run's halo only:
 * they have room for `sources_capacity` slots, not the whole store's (the walls' images of a
 * narrow 3D tank are 40-45 % of its fluid). FIELD_GHOSTS_ONLY marks the fields of the tail
 * alone (an MPI run's halo and the walls' images), indexed g - n_fluid, with room for
 * `ghosts_capacity` ghosts (particles_reserve_ghosts). New slots start as zeros (shifting and
 * lambda are read before anything writes them). Adding a field is one line here: allocation,
 * growth, the bytes of a slot and the reordering follow from the table. */
enum {
    FIELD_STATE = 1,
    FIELD_GHOST_COPY = 2,
    FIELD_GHOST_MIRROR = 4,
    FIELD_SURFACE_TENSION = 8,
    FIELD_SOURCES_ONLY = 16, /* held by the fluid and an MPI run's halo, never by a wall image */
    FIELD_GHOSTS_ONLY = 32   /* held by the tail [n_fluid, n_total) only, indexed g - n_fluid */
};

/* The per-step fields that only weigh a correction term (the density gradient and the
 * diffusion coefficient of Eq. (5), the eddy viscosity, the shifting velocity of Eq. (7), the
 * volume correction's mismatch) are held in single precision: every wall image holds them too,
 * and in a narrow 3D tank the images outnumber the fluid. Each
 * is computed in double and rounded once when stored (a relative 6e-8, far below the
 * discretisation's error in these terms); the pair sums that read them stay in double, and
 * every pair form that reads them is symmetric in i and j as before, so the mass and momentum
 * stay conserved to round-off. The state, the pressure, the volumes and every quantity of the
 * run-time volume measures stay in double (docs/performance.md: how far eps_V1 moved). */
typedef float frozen_real;

/* The values of the field `surface` (Marrone et al. 2010; diag/freesurface.h writes it) */
enum { SURFACE_INTERIOR = 0, SURFACE_REGION = 1, SURFACE_FREE = 2 };

#define PARTICLE_FIELDS(SCALAR, VECTOR)                                                            \
    /* state of every particle (ghosts: mirrored from their source each RK stage) */               \
    SCALAR(int64_t, id, FIELD_STATE | FIELD_SOURCES_ONLY, "id", "global id of the fluid particle") \
    VECTOR(double, x, FIELD_STATE, "position", "position, tank frame")                             \
    VECTOR(double, u, FIELD_STATE, "velocity", "velocity, tank frame; ghosts: free-slip image")    \
    SCALAR(double, rho, FIELD_STATE, "density", "density")                                         \
    SCALAR(double, p, 0, "pressure", "pressure (EOS)")                                             \
    SCALAR(double, m, FIELD_STATE | FIELD_SOURCES_ONLY, "mass",                                    \
           "mass (a wall's image has its source's)")                                               \
    SCALAR(double, vol, 0, "volume", "SPH volume m/rho")                                           \
    /* per-step fields, frozen over the RK stages (sec. 2.4); ghosts copy their source's */        \
    VECTOR(frozen_real, grad_rho, 0, NULL, "renormalized density gradient <grad rho>^L")           \
    SCALAR(frozen_real, nu_t, FIELD_GHOST_COPY, NULL,                                              \
           "Smagorinsky eddy viscosity with van Driest damping, m^2/s")                            \
    SCALAR(frozen_real, nu_delta, FIELD_GHOST_COPY, NULL,                                          \
           "diffusion coefficient nu^delta of Eq. (5), m^2/s")                                     \
    SCALAR(double, lambda, FIELD_SOURCES_ONLY, "lambda",                                           \
           "smallest eigenvalue of L, Eq. (10) (fluid)")                                           \
    VECTOR(double, normal, FIELD_SOURCES_ONLY, NULL,                                               \
           "unit normal -L^-1 sum grad W V out of the fluid (theory §4; unnormalised until the "  \
           "free-surface test); in S_F below the free surface, the nearest free-surface "          \
           "neighbour's (equidistant ones averaged)")                                              \
    SCALAR(double, kernel_sum, FIELD_SOURCES_ONLY, NULL,                                           \
           "sum_j W_ij, self included: 1 / geometric volume, Eq. (11)")                            \
    SCALAR(double, gamma, FIELD_SOURCES_ONLY, NULL,                                                \
           "Gamma_i = sum_j W_ij V_j, self included, Eq. (A.2)")                                   \
    SCALAR(frozen_real, volume_mismatch, 0, NULL,                                                  \
           "e_i = V_i sum_j W_ij / kappa - 1: SPH over geometric volume, with the geometric "      \
           "correction only (volume_correction.h)")                                                \
    SCALAR(uint8_t, surface, FIELD_GHOST_COPY, "surface",                                          \
           "0 interior, 1 in S_F, 2 free surface (Marrone et al. 2010)")                           \
    SCALAR(uint8_t, is_free, FIELD_SOURCES_ONLY, NULL,                                             \
           "the free-surface test alone, read while `surface` is written")                         \
    SCALAR(double, eps_vi, FIELD_SOURCES_ONLY, "eps_vi",                                           \
           "the local volume error eps_Vi^(1) of Eq. (12), computed for the snapshots")            \
    SCALAR(double, diff_m, FIELD_SOURCES_ONLY, NULL, "mass diffusion D^m of Eq. (5) (fluid)")      \
    VECTOR(frozen_real, shift, FIELD_GHOST_MIRROR, "shifting",                                     \
           "shifting velocity delta-u, Eq. (7)")                                                   \
    VECTOR(double, correction, FIELD_SOURCES_ONLY, NULL,                                           \
           "the geometric volume correction's velocity (zero without it), "                        \
           "scheme/volume_correction.h")                                                           \
    SCALAR(double, diff_rho, FIELD_SOURCES_ONLY, NULL,                                             \
           "density diffusion D^rho of Eq. (5) (fluid)")                                           \
    /* surface tension, with fluid.surface_tension > 0 only (scheme/surface_tension.h) */          \
    SCALAR(double, interface, FIELD_SOURCES_ONLY, NULL, "interface function delta_Sigma, 1/m")     \
    SCALAR(double, curvature, FIELD_SURFACE_TENSION | FIELD_SOURCES_ONLY, "curvature",             \
           "kappa, 1/m (fluid)")                                                                   \
    VECTOR(double, st_force, FIELD_SOURCES_ONLY, NULL,                                             \
           "F^st V_i, the surface-tension force on the particle at the current RK stage, N")       \
    /* ghosts only, indexed g - n_fluid */                                                         \
    SCALAR(uint8_t, ghost_kind, FIELD_GHOSTS_ONLY, NULL,                                           \
           "what the ghost is (ghost_kind): a wall's image")                                       \
    SCALAR(int32_t, ghost_source, FIELD_GHOSTS_ONLY, NULL, "fluid index it mirrors")               \
    SCALAR(uint8_t, ghost_map, FIELD_GHOSTS_ONLY, NULL,                                            \
           "its map from the source: an index into ghost_maps")

/* The fields the RK4 integrator advances (scheme/integrate.c): the persistent state less the
 * id. The right-hand side stores the rate d<name>/dt of each but the position (scheme/rhs.h),
 * whose rate, the transport velocity, follows from the state and the frozen fields. */
#define PARTICLE_INTEGRATED(SCALAR, VECTOR) VECTOR(x) PARTICLE_RATED(SCALAR, VECTOR)
#define PARTICLE_RATED(SCALAR, VECTOR)      VECTOR(u) SCALAR(rho) SCALAR(m)
#define PARTICLE_COUNT_SCALAR(name)         +1
#define PARTICLE_COUNT_VECTOR(name)         +DIM
/* integrated variables per particle, components counted */
#define PARTICLE_N_INTEGRATED (0 PARTICLE_INTEGRATED(PARTICLE_COUNT_SCALAR, PARTICLE_COUNT_VECTOR))
/* the stored rates per particle, components counted */
#define PARTICLE_N_RATED (0 PARTICLE_RATED(PARTICLE_COUNT_SCALAR, PARTICLE_COUNT_VECTOR))

/* A ghost's affine map from its source: position x_g = a x_i + b, a vector v_g = a v_i (a wall's
 * image: a reflection, or the product of the reflections of an edge or a corner; a halo copy:
 * the identity or a period's translation). The provider that makes the ghosts owns the table
 * (the tank's walls: boundary/tank.c, computed once from its planes) and points the store at
 * it; each ghost names its entry. */
typedef struct {
    double a[DIM][DIM];
    double b[DIM];
} ghost_map;
#define GHOST_MAPS_MAX 64 /* the box: one entry per set of walls, bits 2d (low) and 2d+1 (high) */

#define PARTICLE_SCALAR_MEMBER(type, name, flags, snapshot, comment) type *name;
#define PARTICLE_VECTOR_MEMBER(type, name, flags, snapshot, comment) type *name[DIM];

/* One bit per field of the registry, for the sets of fields a pass reads or writes
 * (scheme/passes.c) and that a halo refresh sends (parallel/slabs.h). */
enum {
#define FIELD_BIT_ENUM(type, name, flags, snapshot, comment) FIELD_BIT_##name,
    PARTICLE_FIELDS(FIELD_BIT_ENUM, FIELD_BIT_ENUM) FIELD_BITS
};
_Static_assert(FIELD_BITS <= 64, "the field masks are 64 bits");
#define FIELD_MASK(name) (UINT64_C(1) << FIELD_BIT_##name)

/* The tail [n_fluid, n_total) holds first the n_halo halo particles of an MPI run (none on one
 * process), then the walls' images of the fluid and halo particles. */
typedef struct {
    size_t n_fluid, n_halo, n_total, capacity;
    size_t sources_capacity; /* the slots of the FIELD_SOURCES_ONLY fields, at most capacity */
    size_t ghosts_capacity;  /* the slots of the FIELD_GHOSTS_ONLY fields */
    PARTICLE_FIELDS(PARTICLE_SCALAR_MEMBER, PARTICLE_VECTOR_MEMBER)
    const ghost_map *ghost_maps; /* the table of the provider that made the ghosts */
    bool no_slip_images; /* the walls' images are no-slip ones (particle_viscous_velocity) */
} particles;

/* What a particle of the tail [n_fluid, n_total) stands for. A loop that treats walls apart
 * asks this, never the index alone: a halo particle copied from another process (MPI) will sit
 * in the same tail and is fluid. */
typedef enum {
    GHOST_WALL_IMAGE = 0,
    GHOST_HALO = 1 /* a fluid particle of another MPI process (parallel/slabs.h); map 0 */
} ghost_kind;

/* The first wall image of the tail; the fluid particles and the halo before it are the images'
 * sources. */
static inline size_t particles_images_begin(const particles *p) { return p->n_fluid + p->n_halo; }

/* The map of ghost g (n_fluid <= g < n_total). */
static inline const ghost_map *particle_ghost_map(const particles *p, size_t g)
{
    return &p->ghost_maps[p->ghost_map[g - p->n_fluid]];
}

/* a v, the sum in the order of the columns (a reflection reverses components exactly) */
static inline vec ghost_map_vector(const ghost_map *m, vec v)
{
    vec r;
    for (int d = 0; d < DIM; d++) {
        r.c[d] = 0.0;
        for (int k = 0; k < DIM; k++) r.c[d] += m->a[d][k] * v.c[k];
    }
    return r;
}

/* a x + b */
static inline vec ghost_map_point(const ghost_map *m, vec x)
{
    vec r = ghost_map_vector(m, x);
    for (int d = 0; d < DIM; d++) r.c[d] += m->b[d];
    return r;
}

/* The particle whose entry of a FIELD_SOURCES_ONLY field stands for particle j: j itself (the
 * fluid, an MPI run's halo), or a wall image's source. */
static inline size_t particle_source_of(const particles *p, size_t j)
{
    return j < particles_images_begin(p) ? j : (size_t)p->ghost_source[j - p->n_fluid];
}

/* The velocity the viscous term and the velocity gradient see at particle j: a fluid or halo
 * particle's own; a wall image's no-slip image, its source's velocity reversed (the walls are
 * at rest in the tank frame), or its free-slip image, the mirrored velocity the image holds.
 * Read through the source rather than held by each image: 24 bytes an image less in 3D, and
 * only the rows that reach a wall ask. */
static inline vec particle_viscous_velocity(const particles *p, size_t j)
{
    if (j < particles_images_begin(p) || !p->no_slip_images) return vec_load(p->u, j);
    return vec_scale(vec_load(p->u, particle_source_of(p, j)), -1.0);
}

/* A field that no wall image holds, at particle j as an image would hold it: a scalar is its
 * source's, a vector its source's mirrored by the image's map (what tank_mirror_step_fields
 * copies into the fields the images do hold). */
static inline double particle_source_scalar(const particles *p, const double *a, size_t j)
{
    return a[particle_source_of(p, j)];
}

static inline vec particle_source_vector(const particles *p, double *const a[DIM], size_t j)
{
    vec v = vec_load(a, particle_source_of(p, j));
    return j < particles_images_begin(p) ? v : ghost_map_vector(particle_ghost_map(p, j), v);
}

/* Whether particle j is the image of a fluid particle across a wall. */
static inline int particle_is_wall_image(const particles *p, size_t j)
{
    return j >= p->n_fluid && p->ghost_kind[j - p->n_fluid] == GHOST_WALL_IMAGE;
}

#define particles_init               DIM_NAME(particles_init)
#define particles_free               DIM_NAME(particles_free)
#define particles_reserve            DIM_NAME(particles_reserve)
#define particles_reserve_images     DIM_NAME(particles_reserve_images)
#define particles_reserve_ghosts     DIM_NAME(particles_reserve_ghosts)
#define particles_bytes_ghosts_only  DIM_NAME(particles_bytes_ghosts_only)
#define particles_bytes_sources_only DIM_NAME(particles_bytes_sources_only)
#define particles_permute_fluid      DIM_NAME(particles_permute_fluid)
#define particles_bytes_per_slot     DIM_NAME(particles_bytes_per_slot)
#define particles_field_copy         DIM_NAME(particles_field_copy)
#define particles_field_hashes       DIM_NAME(particles_field_hashes)
#define particles_field_name         DIM_NAME(particles_field_name)

/* Allocates room for `capacity` particles (fluid + ghosts); all counts 0. Returns 0 or -1. */
int particles_init(particles *p, size_t capacity);
void particles_free(particles *p);
/* The store's head-room: the lattice reserves its particles and a sixteenth more for the
 * walls' images (about 5 % of the fluid in the 2D benchmarks of 1e5 particles and more); past
 * that it grows by a sixteenth at a time, so that a store growing a few slots at a time (the
 * images as they are made, a slab's halo from step to step) is copied a few times at the start,
 * not at every slot, and ends within a sixteenth of what it holds (a narrow 3D tank's images
 * are 40-45 % of its fluid: grown by quarters, its store held 1.76 times the fluid for 1.44
 * used). estimate.c follows the same two rules. */
static inline size_t particles_initial_room(size_t n) { return n + n / 16 + 64; }
static inline size_t particles_grown(size_t capacity) { return capacity + capacity / 16; }
/* Grows the store to hold at least `capacity` particles, fluid, halo or wall images, and at
 * least particles_grown of what it held, keeping the contents. */
int particles_reserve(particles *p, size_t capacity);
/* A copy of the n elements of `size` bytes at `from` laid out as the store lays out component
 * d of the field of bit `field` (FIELD_BIT_*; core/arrays.h): an array that particles_free and
 * particles_reserve can take, in a store of capacity n. NULL when `from` is, or out of memory. */
void *particles_field_copy(int field, int d, const void *from, size_t n, size_t size);
/* particles_reserve for slots that only wall images will take (from particles_images_begin
 * on): the FIELD_SOURCES_ONLY fields keep their room. */
int particles_reserve_images(particles *p, size_t capacity);
/* Room in the FIELD_GHOSTS_ONLY fields for n_ghosts ghosts (the tail's halo and images), at
 * least the store's tail (capacity - n_fluid) and particles_grown of what they held, keeping
 * the contents: the ghosts' makers call it as they append (tank_make_ghosts, an MPI run's
 * halo_build). Returns 0 or -1. */
int particles_reserve_ghosts(particles *p, size_t n_ghosts);
/* The bytes one particle slot takes in the store (every array of it), and of those the
 * FIELD_SOURCES_ONLY fields' and the FIELD_GHOSTS_ONLY fields'. */
size_t particles_bytes_per_slot(void);
size_t particles_bytes_sources_only(void);
size_t particles_bytes_ghosts_only(void);
/* For the debug build's checks (core/invariant.h): a hash of the bytes of each field over the
 * particles [0, n), per field bit (0 for the FIELD_GHOSTS_ONLY fields and a field not held),
 * and a field's name. */
void particles_field_hashes(const particles *p, size_t n, uint64_t hash[FIELD_BITS]);
const char *particles_field_name(int field);
/* Reorders the persistent fluid state (the fields marked FIELD_STATE: id, x, u, rho, m) so
 * that new slot k holds old particle order[k]; scratch needs n_fluid doubles. */
void particles_permute_fluid(particles *p, const uint32_t *order, double *scratch);

#endif
