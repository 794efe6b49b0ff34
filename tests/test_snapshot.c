/* Unit tests of io/snapshot: HDF5 snapshots read back through the HDF5 library (the XDMF
 * index: test_xdmf.c). */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* mkdtemp (temp_dir.h), dup, dup2 */
#endif

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <fcntl.h>
#include <float.h>
#include <hdf5.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/version.h"
#include "io/hdf5_attr.h"
#include "io/snapshot.h"

#include "snapshot_sample.h"

/* ---------------------------------------------------------------------------------------- */
/* Reading back                                                                              */

static size_t elem_size(field_type t) { return t == FIELD_INT32 ? 4 : 8; }

static hid_t expected_file_type(field_type t)
{
    return t == FIELD_DOUBLE ? H5T_IEEE_F64LE : t == FIELD_INT64 ? H5T_STD_I64LE : H5T_STD_I32LE;
}

static hid_t mem_type(field_type t)
{
    return t == FIELD_DOUBLE  ? H5T_NATIVE_DOUBLE
           : t == FIELD_INT64 ? H5T_NATIVE_INT64
                              : H5T_NATIVE_INT32;
}

/* Opens a dataset and checks its shape (n, or n x ncomp) and stored type. */
static hid_t open_checked(hid_t file, const char *name, field_type type, size_t n, int ncomp)
{
    hid_t dset = H5Dopen2(file, name, H5P_DEFAULT);
    assert_true(dset >= 0);
    hid_t space = H5Dget_space(dset);
    hsize_t dims[2] = {0, 0};
    const int rank = H5Sget_simple_extent_dims(space, dims, NULL);
    H5Sclose(space);
    assert_int_equal(rank, ncomp > 1 ? 2 : 1);
    assert_int_equal(dims[0], n);
    if (ncomp > 1) assert_int_equal(dims[1], ncomp);
    hid_t ftype = H5Dget_type(dset);
    assert_true(H5Tequal(ftype, expected_file_type(type)) > 0);
    H5Tclose(ftype);
    return dset;
}

/* Reads a field back and compares every element bit for bit with the SoA input. */
static void check_field(hid_t file, const snapshot_field *f, size_t n)
{
    hid_t dset = open_checked(file, f->name, f->type, n, f->ncomp);
    const size_t es = elem_size(f->type), nc = (size_t)f->ncomp;
    unsigned char *buf = malloc(n * nc * es + 1);
    assert_non_null(buf);
    if (n > 0)
        assert_true(H5Dread(dset, mem_type(f->type), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) >= 0);
    for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < nc; ++c)
            assert_memory_equal(buf + (i * nc + c) * es,
                                (const unsigned char *)f->component[c] + i * es, es);
    free(buf);
    H5Dclose(dset);
}

/* The connectivity the XDMF index uses: 0 .. n-1 as int32. */
static void check_vertices(hid_t file, size_t n)
{
    hid_t dset = open_checked(file, SNAPSHOT_VERTICES_DATASET, FIELD_INT32, n, 1);
    int32_t *v = malloc((n + 1) * sizeof *v);
    assert_non_null(v);
    if (n > 0) assert_true(H5Dread(dset, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) >= 0);
    for (size_t i = 0; i < n; ++i) assert_int_equal(v[i], (int32_t)i);
    free(v);
    H5Dclose(dset);
}

static void read_attr(hid_t file, const char *name, hid_t file_type, hid_t mtype, void *out)
{
    hid_t attr = H5Aopen(file, name, H5P_DEFAULT);
    assert_true(attr >= 0);
    hid_t t = H5Aget_type(attr);
    assert_true(H5Tequal(t, file_type) > 0);
    H5Tclose(t);
    assert_true(H5Aread(attr, mtype, out) >= 0);
    H5Aclose(attr);
}

static void check_attrs(hid_t file, const snapshot_attrs *a)
{
    double time, eta, dr, h;
    long step;
    int dim;
    read_attr(file, "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &time);
    read_attr(file, "step", H5T_STD_I64LE, H5T_NATIVE_LONG, &step);
    read_attr(file, "eta", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &eta);
    read_attr(file, "dim", H5T_STD_I32LE, H5T_NATIVE_INT, &dim);
    read_attr(file, "dr", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &dr);
    read_attr(file, "h", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &h);
    assert_memory_equal(&time, &a->time, sizeof time);
    assert_int_equal(step, a->step);
    assert_memory_equal(&eta, &a->eta, sizeof eta);
    assert_int_equal(dim, a->dim);
    assert_memory_equal(&dr, &a->dr, sizeof dr);
    assert_memory_equal(&h, &a->h, sizeof h);

    hid_t attr = H5Aopen(file, "case", H5P_DEFAULT);
    assert_true(attr >= 0);
    hid_t t = H5Aget_type(attr);
    assert_int_equal(H5Tget_class(t), H5T_STRING);
    assert_false(H5Tis_variable_str(t));
    const size_t size = H5Tget_size(t);
    char *text = calloc(size + 1, 1);
    assert_non_null(text);
    assert_true(H5Aread(attr, t, text) >= 0);
    assert_string_equal(text, a->case_text ? a->case_text : "");
    free(text);
    H5Tclose(t);
    H5Aclose(attr);

    /* the vcsph that wrote it */
    char *version = hdf5_attr_read_string(file, "vcsph_version");
    assert_non_null(version);
    assert_true(version[0] != '\0');
    assert_string_equal(version, vcsph_version());
    free(version);
}

/* Reads a whole snapshot back and checks it against the sample. */
static void check_sample_file(const char *path, const sample *s)
{
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(file >= 0);
    check_attrs(file, &s->attrs);
    for (int i = 0; i < N_SAMPLE_FIELDS; ++i) check_field(file, &s->fields[i], s->n);
    check_vertices(file, s->n);
    H5Fclose(file);
}

/* Every identifier the writer opened must be closed again: a leak would keep the file open
 * (and unflushed) behind our back. */
static void assert_no_open_hdf5_objects(void)
{
    assert_int_equal(H5Fget_obj_count((hid_t)H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

/* ---------------------------------------------------------------------------------------- */
/* snapshot_write                                                                            */

static void roundtrip(fixture *fx, int dim)
{
    sample s;
    sample_fill(&s, dim, SMALL, 0.0);
    char err[256] = "";
    const char *path = path_in(fx, "000000.h5");
    assert_int_equal(sample_write(&s, path, err, sizeof err), 0);
    assert_no_open_hdf5_objects();
    check_sample_file(path, &s);
    assert_false(exists(path_in(fx, "000000.h5.tmp")));
    assert_int_equal(count_entries(fx->dir), 1);
}

static void test_write_2d_roundtrip(void **state) { roundtrip(*state, 2); }

static void test_write_3d_roundtrip(void **state) { roundtrip(*state, 3); }

/* More rows than one interleaving block holds (8192), with a partial last block, so the
 * block boundaries are covered too. */
static void test_write_many_rows(void **state)
{
    fixture *fx = *state;
    const size_t n = 2 * 8192 + 17;
    double *x[3];
    int32_t *k[2];
    for (int c = 0; c < 3; ++c) {
        x[c] = malloc(n * sizeof *x[c]);
        assert_non_null(x[c]);
    }
    for (int c = 0; c < 2; ++c) {
        k[c] = malloc(n * sizeof *k[c]);
        assert_non_null(k[c]);
    }
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) x[c][i] = (double)i * 0.001 + c;
        for (int c = 0; c < 2; ++c) k[c][i] = (int32_t)i * (c ? -1 : 1);
    }
    const snapshot_field f[] = {
        {"position", FIELD_DOUBLE, 3, {x[0], x[1], x[2]}},
        {"pair", FIELD_INT32, 2, {k[0], k[1]}},
    };
    const snapshot_attrs a = {.dim = 3, .case_text = ""};
    char err[256] = "";
    const char *path = path_in(fx, "big.h5");
    assert_int_equal(snapshot_write(path, n, f, 2, &a, err, sizeof err), 0);
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(file >= 0);
    check_field(file, &f[0], n);
    check_field(file, &f[1], n);
    check_vertices(file, n);
    H5Fclose(file);
    for (int c = 0; c < 3; ++c) free(x[c]);
    for (int c = 0; c < 2; ++c) free(k[c]);
}

/* n = 0: every dataset exists with zero rows; the component pointers are never read. */
static void test_write_empty(void **state)
{
    fixture *fx = *state;
    const snapshot_field f[] = {
        {"id", FIELD_INT64, 1, {NULL}},
        {"position", FIELD_DOUBLE, 2, {NULL, NULL}},
        {"surface", FIELD_INT32, 1, {NULL}},
    };
    const snapshot_attrs a = {.time = 1.5, .step = 3, .dim = 2, .case_text = NULL};
    char err[256] = "";
    const char *path = path_in(fx, "empty.h5");
    assert_int_equal(snapshot_write(path, 0, f, 3, &a, err, sizeof err), 0);
    assert_no_open_hdf5_objects();
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(file >= 0);
    check_attrs(file, &a); /* a NULL case text is stored as "" */
    for (int i = 0; i < 3; ++i) check_field(file, &f[i], 0);
    check_vertices(file, 0);
    H5Fclose(file);
}

/* A second write to the same path replaces the file whole. */
static void test_write_replaces_existing(void **state)
{
    fixture *fx = *state;
    sample a, b;
    sample_fill(&a, 2, SMALL, 0.0);
    sample_fill(&b, 2, 3, 7.0);
    char err[256] = "";
    const char *path = path_in(fx, "s.h5");
    assert_int_equal(sample_write(&a, path, err, sizeof err), 0);
    assert_int_equal(sample_write(&b, path, err, sizeof err), 0);
    check_sample_file(path, &b);
    assert_int_equal(count_entries(fx->dir), 1);
}

static void test_unwritable_path(void **state)
{
    fixture *fx = *state;
    sample s;
    sample_fill(&s, 2, SMALL, 0.0);
    char err[256] = "";
    const char *path = path_in(fx, "no/such/dir/s.h5");
    assert_int_equal(sample_write(&s, path, err, sizeof err), -1);
    assert_true(strlen(err) > 0);
    assert_non_null(strstr(err, "no/such/dir/s.h5.tmp"));
    assert_int_equal(count_entries(fx->dir), 0);
    assert_no_open_hdf5_objects();
}

/* A full disk gives the system's reason, not the file driver's whole description (the
 * buffer's address, offsets and sizes). A 64 kB tmpfs holds it; mounting one needs root (CI
 * runs as root), so the test is skipped elsewhere. */
static void test_full_disk_named(void **state)
{
    fixture *fx = *state;
    if (geteuid() != 0) skip();
    const char *mnt = path_in(fx, "full");
    assert_int_equal(mkdir(mnt, 0700), 0);
    char command[600];
    snprintf(command, sizeof command, "mount -t tmpfs -o size=64k tmpfs '%s' 2>/dev/null", mnt);
    if (system(command) != 0) {
        rmdir(mnt);
        skip();
    }
    const size_t n = 16384; /* 384 kB of positions */
    double *x = calloc(n, sizeof *x);
    assert_non_null(x);
    const snapshot_field f[] = {{"position", FIELD_DOUBLE, 3, {x, x, x}}};
    const snapshot_attrs a = {.dim = 3, .case_text = ""};
    char err[512] = "", path[600];
    snprintf(path, sizeof path, "%s/s.h5", mnt);
    int rc = snapshot_write(path, n, f, 1, &a, err, sizeof err);
    free(x);
    snprintf(command, sizeof command, "umount '%s'", mnt);
    assert_int_equal(system(command), 0);
    rmdir(mnt);
    assert_int_equal(rc, -1);
    if (!strstr(err, "No space left on device") || strstr(err, "buf ="))
        fail_msg("full disk: \"%s\"", err);
}

/* A failure after the temporary file exists (here: two fields with the same name) removes
 * the temporary file and leaves the previous snapshot untouched. */
static void test_failure_keeps_previous_file(void **state)
{
    fixture *fx = *state;
    sample good, bad;
    sample_fill(&good, 3, SMALL, 0.0);
    sample_fill(&bad, 3, SMALL, 1.0);
    bad.fields[2].name = "position";
    char err[256] = "";
    const char *path = path_in(fx, "s.h5");
    assert_int_equal(sample_write(&good, path, err, sizeof err), 0);
    assert_int_equal(sample_write(&bad, path, err, sizeof err), -1);
    assert_non_null(strstr(err, "'position': ")); /* with HDF5's reason after the colon */
    assert_no_open_hdf5_objects();
    check_sample_file(path_in(fx, "s.h5"), &good);
    assert_false(exists(path_in(fx, "s.h5.tmp")));
    assert_int_equal(count_entries(fx->dir), 1);
}

/* The rename is the last step: when it fails (target is a directory) nothing is left but
 * what was there before. */
static void test_rename_failure_cleans_up(void **state)
{
    fixture *fx = *state;
    assert_int_equal(mkdir(path_in(fx, "taken.h5"), 0700), 0);
    sample s;
    sample_fill(&s, 2, SMALL, 0.0);
    char err[256] = "";
    assert_int_equal(sample_write(&s, path_in(fx, "taken.h5"), err, sizeof err), -1);
    assert_non_null(strstr(err, "rename"));
    assert_false(exists(path_in(fx, "taken.h5.tmp")));
    assert_int_equal(count_entries(fx->dir), 1);
}

static void test_bad_fields_rejected(void **state)
{
    fixture *fx = *state;
    const double x[2] = {0, 1};
    const snapshot_attrs a = {.dim = 2};
    const snapshot_field null_component[] = {{"density", FIELD_DOUBLE, 2, {x, NULL}}};
    const snapshot_field bad_ncomp[] = {{"density", FIELD_DOUBLE, 4, {x, x, x}}};
    const snapshot_field reserved[] = {{SNAPSHOT_VERTICES_DATASET, FIELD_INT32, 1, {x}}};
    const snapshot_field no_name[] = {{"", FIELD_DOUBLE, 1, {x}}};
    const snapshot_field *cases[] = {null_component, bad_ncomp, reserved, no_name};
    const char *path = path_in(fx, "s.h5");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        char err[256] = "";
        assert_int_equal(snapshot_write(path, 2, cases[i], 1, &a, err, sizeof err), -1);
        assert_true(strlen(err) > 0);
    }
    assert_int_equal(count_entries(fx->dir), 0);
}

/* HDF5's automatic error printing is off during the call (errors go to err) and restored
 * afterwards. */
static void test_hdf5_errors_not_printed(void **state)
{
    fixture *fx = *state;
    H5E_auto2_t func_before = NULL, func_after = NULL;
    void *data_before = NULL, *data_after = NULL;
    H5Eget_auto2(H5E_DEFAULT, &func_before, &data_before);

    char capture[512];
    snprintf(capture, sizeof capture, "%s/stderr.txt", fx->dir);
    fflush(stderr);
    const int saved = dup(STDERR_FILENO);
    const int fd = open(capture, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    assert_true(saved >= 0 && fd >= 0);
    dup2(fd, STDERR_FILENO);
    close(fd);

    sample s;
    sample_fill(&s, 2, SMALL, 0.0);
    char err[256] = "";
    const int rc = sample_write(&s, path_in(fx, "missing/s.h5"), err, sizeof err);

    fflush(stderr);
    dup2(saved, STDERR_FILENO);
    close(saved);
    assert_int_equal(rc, -1);
    struct stat st;
    assert_int_equal(stat(capture, &st), 0);
    assert_int_equal(st.st_size, 0);

    H5Eget_auto2(H5E_DEFAULT, &func_after, &data_after);
    assert_true(func_before == func_after);
    assert_true(data_before == data_after);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_write_2d_roundtrip, setup, teardown),
        cmocka_unit_test_setup_teardown(test_write_3d_roundtrip, setup, teardown),
        cmocka_unit_test_setup_teardown(test_write_many_rows, setup, teardown),
        cmocka_unit_test_setup_teardown(test_write_empty, setup, teardown),
        cmocka_unit_test_setup_teardown(test_write_replaces_existing, setup, teardown),
        cmocka_unit_test_setup_teardown(test_unwritable_path, setup, teardown),
        cmocka_unit_test_setup_teardown(test_failure_keeps_previous_file, setup, teardown),
        cmocka_unit_test_setup_teardown(test_rename_failure_cleans_up, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bad_fields_rejected, setup, teardown),
        cmocka_unit_test_setup_teardown(test_hdf5_errors_not_printed, setup, teardown),
        cmocka_unit_test_setup_teardown(test_full_disk_named, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
