/* particles: allocation and reordering of the SoA store. */
#include "core/particles.h"
#include "core/arrays.h"

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

/* Grows *ptr from `old` to `count` elements of `size` bytes, the new ones zero (core/arrays.h:
 * each field's array at its own offset in its pages). */
static int grow(void **ptr, size_t old, size_t count, size_t size, int array)
{
    return array_grow(ptr, old * size, old * size, count * size, array);
}

/* The array number (core/arrays.h) of component d of a field (d = 0: a scalar). */
#define FIELD_ARRAY(name, d) ((int)FIELD_BIT_##name * DIM + (d)) /* as particles_field_copy's */

/* The fields' room classes: the whole store, the fluid and halo (FIELD_SOURCES_ONLY), the
 * tail's ghosts (FIELD_GHOSTS_ONLY). */
#define ROOM_CLASS(flags) ((flags) & (FIELD_SOURCES_ONLY | FIELD_GHOSTS_ONLY))

/* Grows the fields of room class `room` (ROOM_CLASS) from `old` to `capacity` slots. */
static int grow_fields(particles *p, unsigned room, size_t old, size_t capacity)
{
#define SELECTED(flags) (ROOM_CLASS(flags) == room)
#define GROW_SCALAR(type, name, flags, snapshot, comment)                                          \
    if (SELECTED(flags) &&                                                                         \
        grow((void **)&p->name, old, capacity, sizeof(type), FIELD_ARRAY(name, 0)))                \
        return -1;
#define GROW_VECTOR(type, name, flags, snapshot, comment)                                          \
    for (int d = 0; d < DIM && SELECTED(flags); d++)                                               \
        if (grow((void **)&p->name[d], old, capacity, sizeof(type), FIELD_ARRAY(name, d)))         \
            return -1;
    PARTICLE_FIELDS(GROW_SCALAR, GROW_VECTOR)
    return 0;
}

void *particles_field_copy(int field, int d, const void *from, size_t n, size_t size)
{
    void *a = NULL;
    if (!from || array_grow(&a, 0, 0, n * size, field * DIM + d)) return NULL;
    memcpy(a, from, n * size);
    return a;
}

/* At least `capacity`, and at least particles_grown of `old` when it grows. */
static size_t grown_to(size_t old, size_t capacity)
{
    return capacity < particles_grown(old) ? particles_grown(old) : capacity;
}

int particles_reserve_images(particles *p, size_t capacity)
{
    if (capacity <= p->capacity) return 0;
    capacity = grown_to(p->capacity, capacity);
    if (grow_fields(p, 0, p->capacity, capacity)) return -1;
    p->capacity = capacity;
    return 0;
}

int particles_reserve(particles *p, size_t capacity)
{
    if (capacity > p->sources_capacity) {
        size_t sources = grown_to(p->sources_capacity, capacity);
        if (grow_fields(p, FIELD_SOURCES_ONLY, p->sources_capacity, sources)) return -1;
        p->sources_capacity = sources;
    }
    return particles_reserve_images(p, p->sources_capacity);
}

int particles_reserve_ghosts(particles *p, size_t n_ghosts)
{
    if (n_ghosts <= p->ghosts_capacity) return 0;
    /* at least the store's tail: ghosts appended one at a time grow the arrays in the store's
       steps, not from a handful of slots */
    size_t tail = p->capacity > p->n_fluid ? p->capacity - p->n_fluid : 0;
    size_t room = grown_to(p->ghosts_capacity, n_ghosts > tail ? n_ghosts : tail);
    if (grow_fields(p, FIELD_GHOSTS_ONLY, p->ghosts_capacity, room)) return -1;
    p->ghosts_capacity = room;
    return 0;
}

int particles_init(particles *p, size_t capacity)
{
    memset(p, 0, sizeof *p);
    return particles_reserve(p, capacity < 16 ? 16 : capacity);
}

/* The slots the fields of room class `room` (ROOM_CLASS) have. */
static size_t room_capacity(const particles *p, unsigned room)
{
    return room == FIELD_SOURCES_ONLY  ? p->sources_capacity
           : room == FIELD_GHOSTS_ONLY ? p->ghosts_capacity
                                       : p->capacity;
}

void particles_free(particles *p)
{
#define FIELD_BYTES(type, flags) (room_capacity(p, ROOM_CLASS(flags)) * sizeof(type))
#define FREE_SCALAR(type, name, flags, snapshot, comment)                                          \
    array_free(p->name, FIELD_BYTES(type, flags), FIELD_ARRAY(name, 0));
#define FREE_VECTOR(type, name, flags, snapshot, comment)                                          \
    for (int d = 0; d < DIM; d++)                                                                  \
        array_free(p->name[d], FIELD_BYTES(type, flags), FIELD_ARRAY(name, d));
    PARTICLE_FIELDS(FREE_SCALAR, FREE_VECTOR)
    memset(p, 0, sizeof *p);
}

/* The bytes of one slot of the fields whose flags include all of `flags` (0: every field). */
static size_t slot_bytes(unsigned flags)
{
#define HAS(field_flags) (((unsigned)(field_flags)&flags) == flags)
#define BYTES_SCALAR(type, name, field_flags, snapshot, comment)                                   \
    +(HAS(field_flags) ? sizeof(type) : 0)
#define BYTES_VECTOR(type, name, field_flags, snapshot, comment)                                   \
    +(HAS(field_flags) ? DIM * sizeof(type) : 0)
    return 0 PARTICLE_FIELDS(BYTES_SCALAR, BYTES_VECTOR);
}

size_t particles_bytes_per_slot(void) { return slot_bytes(0); }

size_t particles_bytes_sources_only(void) { return slot_bytes(FIELD_SOURCES_ONLY); }

size_t particles_bytes_ghosts_only(void) { return slot_bytes(FIELD_GHOSTS_ONLY); }

/* The state is reordered through a scratch array of doubles, eight bytes an element. */
#define FITS_SCALAR(type, name, flags, snapshot, comment)                                          \
    _Static_assert(!((flags)&FIELD_STATE) || sizeof(type) == sizeof(double), #name);
#define FITS_VECTOR FITS_SCALAR
PARTICLE_FIELDS(FITS_SCALAR, FITS_VECTOR)
/* A ghost mirrors vectors and copies scalars. */
#define GHOST_RULE_SCALAR(type, name, flags, snapshot, comment)                                    \
    _Static_assert(!((flags)&FIELD_GHOST_MIRROR), #name " is a scalar: copy it");
#define GHOST_RULE_VECTOR(type, name, flags, snapshot, comment)                                    \
    _Static_assert(!((flags)&FIELD_GHOST_COPY), #name " is a vector: mirror it");
PARTICLE_FIELDS(GHOST_RULE_SCALAR, GHOST_RULE_VECTOR)

/* a[k] = a[order[k]] for elements of eight bytes, through scratch. Both loops split the
 * particles as the passes do, so each thread writes the share it goes on to compute. */
static void permute(void *a, const uint32_t *order, size_t n, double *scratch)
{
    enum { SIZE = sizeof(double) };
    char *bytes = a, *tmp = (char *)scratch;
#pragma omp parallel for schedule(static)
    for (size_t k = 0; k < n; k++) memcpy(tmp + k * SIZE, bytes + (size_t)order[k] * SIZE, SIZE);
#pragma omp parallel for schedule(static)
    for (size_t k = 0; k < n; k++) memcpy(bytes + k * SIZE, tmp + k * SIZE, SIZE);
}

void particles_permute_fluid(particles *p, const uint32_t *order, double *scratch)
{
    size_t n = p->n_fluid;
#define PERMUTE_SCALAR(type, name, flags, snapshot, comment)                                       \
    if ((flags)&FIELD_STATE) permute(p->name, order, n, scratch);
#define PERMUTE_VECTOR(type, name, flags, snapshot, comment)                                       \
    if ((flags)&FIELD_STATE)                                                                       \
        for (int d = 0; d < DIM; d++) permute(p->name[d], order, n, scratch);
    PARTICLE_FIELDS(PERMUTE_SCALAR, PERMUTE_VECTOR)
}

/* A hash of n bytes continuing from h: FNV-1a's step over 8-byte words, then the tail's bytes */
static uint64_t bytes_hash(uint64_t h, const void *bytes, size_t n)
{
    const unsigned char *b = bytes;
    size_t k = 0;
    for (; k + 8 <= n; k += 8) {
        uint64_t word;
        memcpy(&word, b + k, sizeof word);
        h = (h ^ word) * UINT64_C(1099511628211);
        h ^= h >> 29;
    }
    for (; k < n; k++) h = (h ^ b[k]) * UINT64_C(1099511628211);
    return h;
}

void particles_field_hashes(const particles *p, size_t n, uint64_t hash[FIELD_BITS])
{
#define HELD(flags, a) (!((flags)&FIELD_GHOSTS_ONLY) && (a))
#define HASH_SCALAR(type, name, flags, snapshot, comment)                                          \
    hash[FIELD_BIT_##name] = HELD(flags, p->name) ? bytes_hash(UINT64_C(14695981039346656037),     \
                                                               p->name, n * sizeof(type))          \
                                                  : 0;
#define HASH_VECTOR(type, name, flags, snapshot, comment)                                          \
    hash[FIELD_BIT_##name] = 0;                                                                    \
    for (int d = 0; d < DIM; d++)                                                                  \
        if (HELD(flags, p->name[d]))                                                               \
            hash[FIELD_BIT_##name] =                                                               \
                bytes_hash(hash[FIELD_BIT_##name] ^ (uint64_t)d, p->name[d], n * sizeof(type));
    PARTICLE_FIELDS(HASH_SCALAR, HASH_VECTOR)
#undef HELD
}

const char *particles_field_name(int field)
{
    static const char *const names[FIELD_BITS] = {
#define FIELD_NAME(type, name, flags, snapshot, comment) #name,
        PARTICLE_FIELDS(FIELD_NAME, FIELD_NAME)};
    return field >= 0 && field < FIELD_BITS ? names[field] : "?";
}
