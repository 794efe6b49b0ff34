/* snapshot_sample: the fixture and the sample particle data of io/snapshot's tests
 * (test_snapshot.c, test_xdmf.c). Include after <cmocka.h>, <hdf5.h> and the headers the
 * tests use. */
#ifndef VCSPH_TEST_SNAPSHOT_SAMPLE_H
#define VCSPH_TEST_SNAPSHOT_SAMPLE_H

#include "io/snapshot.h"
#include "temp_dir.h"

#include <stdbool.h>
#include <string.h>
#include <unistd.h>

/* ---------------------------------------------------------------------------------------- */
/* Fixture: a fresh directory under $TMPDIR (else /tmp) per test, removed afterwards          */

typedef temp_fixture fixture;

static inline int setup(void **state) { return temp_fixture_setup(state, "vcsph-snapshot"); }

static inline int teardown(void **state) { return temp_fixture_teardown(state); }

static inline const char *path_in(fixture *fx, const char *name)
{
    return temp_fixture_path(fx, name);
}

static inline bool exists(const char *path) { return access(path, F_OK) == 0; }

static inline int count_entries(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d) closedir(d);
    return n;
}

/* ---------------------------------------------------------------------------------------- */
/* Sample particle data: every field type, scalar and vector                                  */

enum { SMALL = 7, N_SAMPLE_FIELDS = 7 };

typedef struct {
    size_t n;
    int dim;
    double pos[3][SMALL], vel[3][SMALL], rho[SMALL];
    int64_t id[SMALL], cell[3][SMALL];
    int32_t surface[SMALL], flags[3][SMALL];
    snapshot_field fields[N_SAMPLE_FIELDS];
    snapshot_attrs attrs;
} sample;

static inline void sample_fill(sample *s, int dim, size_t n, double shift)
{
    memset(s, 0, sizeof *s);
    s->n = n;
    s->dim = dim;
    /* Edge values, so "exact" means bit for bit: signed zero, subnormal, extremes, NaN, inf. */
    const double special[SMALL] = {
        -0.0, 4.9406564584124654e-324, DBL_MAX, -DBL_MAX, NAN, INFINITY, 1.0 / 3.0};
    const int64_t special64[SMALL] = {INT64_MIN, INT64_MAX, -1, 0, 1, 1LL << 40, 42};
    const int32_t special32[SMALL] = {INT32_MIN, INT32_MAX, -1, 0, 1, 2, 1 << 20};
    for (size_t i = 0; i < SMALL; ++i) {
        for (int c = 0; c < 3; ++c) {
            s->pos[c][i] = shift + (double)i + 0.125 * c;
            s->vel[c][i] = -0.5 * (double)i + 10.0 * c + shift;
            s->cell[c][i] = (int64_t)(100 * i + (size_t)c) - 300;
            s->flags[c][i] = (int32_t)(c * 10 + (int)i) - 20;
        }
        s->rho[i] = special[i];
        s->id[i] = special64[i];
        s->surface[i] = special32[i];
    }
    const snapshot_field f[N_SAMPLE_FIELDS] = {
        {"id", FIELD_INT64, 1, {s->id}},
        {"position", FIELD_DOUBLE, dim, {s->pos[0], s->pos[1], s->pos[2]}},
        {"velocity", FIELD_DOUBLE, dim, {s->vel[0], s->vel[1], s->vel[2]}},
        {"density", FIELD_DOUBLE, 1, {s->rho}},
        {"surface", FIELD_INT32, 1, {s->surface}},
        {"cell", FIELD_INT64, dim, {s->cell[0], s->cell[1], s->cell[2]}},
        {"flags", FIELD_INT32, dim, {s->flags[0], s->flags[1], s->flags[2]}},
    };
    memcpy(s->fields, f, sizeof f);
    s->attrs =
        (snapshot_attrs){.time = 0.1 + shift,
                         .step = 123456789012L,
                         .eta = 0.015625,
                         .dim = dim,
                         .dr = 1.0 / 30.0,
                         .h = 2.0 / 30.0,
                         .case_text = "[case]\nname = \"sap\"\n[numerics]\nresolution = 30\n"};
}

static inline int sample_write(const sample *s, const char *path, char *err, size_t err_len)
{
    return snapshot_write(path, s->n, s->fields, N_SAMPLE_FIELDS, &s->attrs, err, err_len);
}

#endif
