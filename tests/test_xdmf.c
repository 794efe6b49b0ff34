/* Unit tests of io/snapshot's XDMF index, checked against the snapshot files it points at
 * (the snapshots themselves: test_snapshot.c). */
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
#include "test_filter.h"

/* ---------------------------------------------------------------------------------------- */
/* snapshot_write_xdmf                                                                       */

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    const long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)len + 1);
    assert_non_null(text);
    assert_int_equal(fread(text, 1, (size_t)len, f), (size_t)len);
    text[len] = '\0';
    fclose(f);
    return text;
}

/* Balanced, properly nested tags (a small stand-in for an XML parser): skips the <?xml?>
 * declaration, treats <x/> as closed. Attribute values never hold '<' or '>' because the
 * writer escapes them. */
static bool xml_balanced(const char *s)
{
    const char *open_name[32];
    size_t open_len[32];
    int depth = 0;
    for (const char *p = strchr(s, '<'); p; p = strchr(p + 1, '<')) {
        const char *end = strchr(p, '>');
        if (!end) return false;
        if (p[1] == '?') continue;
        if (p[1] == '/') {
            const size_t len = strcspn(p + 2, " >");
            if (depth == 0 || open_len[depth - 1] != len ||
                strncmp(open_name[depth - 1], p + 2, len) != 0)
                return false;
            --depth;
        } else if (end[-1] != '/') {
            if (depth == 32) return false;
            open_name[depth] = p + 1;
            open_len[depth] = strcspn(p + 1, " />\n");
            ++depth;
        }
    }
    return depth == 0;
}

/* Value of attribute `name` inside the tag [tag, end), copied into out. */
static bool tag_attr(const char *tag, const char *end, const char *name, char *out, size_t len)
{
    char key[64];
    snprintf(key, sizeof key, " %s=\"", name);
    const char *v = strstr(tag, key);
    if (!v || v > end) return false;
    v += strlen(key);
    const size_t n = strcspn(v, "\"");
    if (n >= len) return false;
    memcpy(out, v, n);
    out[n] = '\0';
    return true;
}

/* Follows one <DataItem> to its HDF5 dataset and checks that the declared Dimensions,
 * NumberType and Precision are what the file holds: what ParaView relies on. */
static void check_data_item(fixture *fx, const char *tag, const char *end)
{
    char dims[64], number_type[16], precision[8], format[8];
    assert_true(tag_attr(tag, end, "Dimensions", dims, sizeof dims));
    assert_true(tag_attr(tag, end, "NumberType", number_type, sizeof number_type));
    assert_true(tag_attr(tag, end, "Precision", precision, sizeof precision));
    assert_true(tag_attr(tag, end, "Format", format, sizeof format));
    assert_string_equal(format, "HDF");

    const char *ref = end + 1;
    const char *sep = strstr(ref, ":/");
    assert_non_null(sep);
    char file_name[128], dset_name[64];
    const size_t flen = (size_t)(sep - ref), dlen = strcspn(sep + 2, "<");
    assert_true(flen < sizeof file_name && dlen < sizeof dset_name);
    memcpy(file_name, ref, flen);
    file_name[flen] = '\0';
    memcpy(dset_name, sep + 2, dlen);
    dset_name[dlen] = '\0';

    hid_t file = H5Fopen(path_in(fx, file_name), H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(file >= 0);
    hid_t dset = H5Dopen2(file, dset_name, H5P_DEFAULT);
    assert_true(dset >= 0);
    hid_t space = H5Dget_space(dset);
    hsize_t d[2] = {0, 0};
    const int rank = H5Sget_simple_extent_dims(space, d, NULL);
    char actual[64];
    if (rank == 1)
        snprintf(actual, sizeof actual, "%llu", (unsigned long long)d[0]);
    else
        snprintf(actual, sizeof actual, "%llu %llu", (unsigned long long)d[0],
                 (unsigned long long)d[1]);
    assert_string_equal(dims, actual);
    hid_t type = H5Dget_type(dset);
    assert_string_equal(number_type, H5Tget_class(type) == H5T_FLOAT ? "Float" : "Int");
    assert_int_equal(atoi(precision), H5Tget_size(type));
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(dset);
    H5Fclose(file);
}

static int check_all_data_items(fixture *fx, const char *xml)
{
    int count = 0;
    for (const char *p = strstr(xml, "<DataItem "); p; p = strstr(p + 1, "<DataItem ")) {
        const char *end = strchr(p, '>');
        assert_non_null(end);
        check_data_item(fx, p, end);
        ++count;
    }
    return count;
}

static void check_times(const char *xml, const double *times, int n)
{
    const char *p = xml;
    for (int k = 0; k < n; ++k) {
        p = strstr(p, "<Time Value=\"");
        assert_non_null(p);
        p += strlen("<Time Value=\"");
        const double t = strtod(p, NULL);
        assert_memory_equal(&t, &times[k], sizeof t); /* %.17g round-trips exactly */
    }
    assert_null(strstr(p, "<Time "));
}

/* Writes snapshots with the sample fields and the XDMF index over them. */
static char *write_series(fixture *fx, int dim, const double *times, const size_t *counts,
                          const char *const *files, int n)
{
    sample s;
    char err[256] = "";
    for (int k = 0; k < n; ++k) {
        sample_fill(&s, dim, counts[k], times[k]);
        assert_int_equal(sample_write(&s, path_in(fx, files[k]), err, sizeof err), 0);
    }
    sample_fill(&s, dim, SMALL, 0.0);
    const char *xmf = path_in(fx, "snapshots.xmf");
    assert_int_equal(snapshot_write_xdmf(xmf, n, files, times, counts, s.fields, N_SAMPLE_FIELDS,
                                         dim, err, sizeof err),
                     0);
    assert_false(exists(path_in(fx, "snapshots.xmf.tmp")));
    return slurp(path_in(fx, "snapshots.xmf"));
}

static void test_xdmf_2d(void **state)
{
    fixture *fx = *state;
    const char *files[] = {"000000.h5", "000001.h5", "000002.h5"};
    const double times[] = {0.0, 0.1, 0.30000000000000004};
    const size_t counts[] = {SMALL, 5, 0};
    char *xml = write_series(fx, 2, times, counts, files, 3);

    assert_non_null(strstr(xml, "<Xdmf Version=\"3.0\">"));
    assert_non_null(strstr(xml, "GridType=\"Collection\" CollectionType=\"Temporal\""));
    assert_non_null(strstr(xml, "<Time Value=\"0.10000000000000001\"/>"));
    assert_non_null(strstr(xml, "<Time Value=\"0.30000000000000004\"/>"));
    assert_non_null(strstr(xml, "TopologyType=\"Polyvertex\" NumberOfElements=\"5\""
                                " NodesPerElement=\"1\""));
    assert_non_null(strstr(xml, "<Geometry GeometryType=\"XY\">"));
    assert_null(strstr(xml, "\"XYZ\""));
    assert_non_null(strstr(xml, "Precision=\"8\" Dimensions=\"5 2\">000001.h5:/position<"));
    assert_non_null(strstr(xml, "<Attribute Name=\"velocity\" AttributeType=\"Vector\""
                                " Center=\"Node\">"));
    assert_non_null(strstr(xml, "<Attribute Name=\"density\" AttributeType=\"Scalar\""
                                " Center=\"Node\">"));
    assert_non_null(strstr(xml, "NumberType=\"Int\" Precision=\"8\" Dimensions=\"7\">"
                                "000000.h5:/id<"));
    assert_non_null(strstr(xml, "NumberType=\"Int\" Precision=\"4\" Dimensions=\"5\">"
                                "000001.h5:/surface<"));
    assert_non_null(strstr(xml, "NumberType=\"Float\" Precision=\"8\" Dimensions=\"7 2\">"
                                "000000.h5:/velocity<"));
    assert_non_null(strstr(xml, "Dimensions=\"0\">000002.h5:/" SNAPSHOT_VERTICES_DATASET "<"));
    assert_null(strstr(xml, "Attribute Name=\"position\""));
    assert_true(xml_balanced(xml));
    check_times(xml, times, 3);
    /* per snapshot: topology + geometry + one attribute per non-position field */
    assert_int_equal(check_all_data_items(fx, xml), 3 * (1 + N_SAMPLE_FIELDS));
    free(xml);
}

static void test_xdmf_3d(void **state)
{
    fixture *fx = *state;
    const char *files[] = {"a.h5", "b.h5"};
    const double times[] = {1e-3, 2.5};
    const size_t counts[] = {4, SMALL};
    char *xml = write_series(fx, 3, times, counts, files, 2);

    assert_non_null(strstr(xml, "<Geometry GeometryType=\"XYZ\">"));
    assert_non_null(strstr(xml, "Dimensions=\"4 3\">a.h5:/position<"));
    assert_non_null(strstr(xml, "Dimensions=\"7 3\">b.h5:/velocity<"));
    assert_non_null(strstr(xml, "NumberType=\"Int\" Precision=\"4\" Dimensions=\"7 3\">"
                                "b.h5:/flags<"));
    assert_non_null(strstr(xml, "<Time Value=\"0.001\"/>"));
    assert_non_null(strstr(xml, "<Time Value=\"2.5\"/>"));
    assert_true(xml_balanced(xml));
    check_times(xml, times, 2);
    assert_int_equal(check_all_data_items(fx, xml), 2 * (1 + N_SAMPLE_FIELDS));
    free(xml);
}

/* Rewriting the index (as a run does after each snapshot) replaces it whole; names with XML
 * special characters are escaped. */
static void test_xdmf_rewrite_and_escaping(void **state)
{
    fixture *fx = *state;
    sample s;
    sample_fill(&s, 2, SMALL, 0.0);
    const char *files[] = {"a&b.h5", "<c>.h5"};
    const double times[] = {0.0, 1.0};
    const size_t counts[] = {SMALL, SMALL};
    char err[256] = "";
    const char *xmf = path_in(fx, "s.xmf");
    assert_int_equal(snapshot_write_xdmf(xmf, 1, files, times, counts, s.fields, N_SAMPLE_FIELDS, 2,
                                         err, sizeof err),
                     0);
    xmf = path_in(fx, "s.xmf");
    assert_int_equal(snapshot_write_xdmf(xmf, 2, files, times, counts, s.fields, N_SAMPLE_FIELDS, 2,
                                         err, sizeof err),
                     0);
    char *xml = slurp(path_in(fx, "s.xmf"));
    assert_non_null(strstr(xml, ">a&amp;b.h5:/density<"));
    assert_non_null(strstr(xml, ">&lt;c&gt;.h5:/density<"));
    assert_null(strstr(xml, "a&b"));
    assert_true(xml_balanced(xml));
    check_times(xml, times, 2);
    assert_int_equal(count_entries(fx->dir), 1);
    free(xml);
}

/* An empty series is still a valid document ParaView can open (no time steps). */
static void test_xdmf_no_snapshots(void **state)
{
    fixture *fx = *state;
    sample s;
    sample_fill(&s, 3, SMALL, 0.0);
    char err[256] = "";
    const char *xmf = path_in(fx, "s.xmf");
    assert_int_equal(snapshot_write_xdmf(xmf, 0, NULL, NULL, NULL, s.fields, N_SAMPLE_FIELDS, 3,
                                         err, sizeof err),
                     0);
    char *xml = slurp(path_in(fx, "s.xmf"));
    assert_true(xml_balanced(xml));
    assert_null(strstr(xml, "<Time "));
    free(xml);
}

static void test_xdmf_errors(void **state)
{
    fixture *fx = *state;
    sample s;
    sample_fill(&s, 2, SMALL, 0.0);
    const char *files[] = {"a.h5"};
    const double times[] = {0.0};
    const size_t counts[] = {SMALL};
    char err[256] = "";

    /* no position field */
    assert_int_equal(snapshot_write_xdmf(path_in(fx, "s.xmf"), 1, files, times, counts,
                                         s.fields + 2, N_SAMPLE_FIELDS - 2, 2, err, sizeof err),
                     -1);
    assert_non_null(strstr(err, "position"));
    /* position has 2 components, not 3 */
    err[0] = '\0';
    assert_int_equal(snapshot_write_xdmf(path_in(fx, "s.xmf"), 1, files, times, counts, s.fields,
                                         N_SAMPLE_FIELDS, 3, err, sizeof err),
                     -1);
    assert_true(strlen(err) > 0);
    err[0] = '\0';
    assert_int_equal(snapshot_write_xdmf(path_in(fx, "s.xmf"), 1, files, times, counts, s.fields,
                                         N_SAMPLE_FIELDS, 4, err, sizeof err),
                     -1);
    assert_true(strlen(err) > 0);
    /* unwritable place */
    err[0] = '\0';
    assert_int_equal(snapshot_write_xdmf(path_in(fx, "none/s.xmf"), 1, files, times, counts,
                                         s.fields, N_SAMPLE_FIELDS, 2, err, sizeof err),
                     -1);
    assert_non_null(strstr(err, "none/s.xmf.tmp"));
    assert_int_equal(count_entries(fx->dir), 0);
}

/* The index of 2D and 3D series is well-formed XML by xmllint (libxml2-utils, which
 * tools/install-deps installs): without it the test is reported as skipped, not passed. */
static void test_xdmf_well_formed(void **state)
{
    if (access("/usr/bin/xmllint", X_OK) != 0) skip();
    fixture *fx = *state;
    const char *files[] = {"000000.h5", "000001.h5"};
    const double times[] = {0.0, 0.1};
    const size_t counts[] = {SMALL, 5};
    for (int dim = 2; dim <= 3; dim++) {
        free(write_series(fx, dim, times, counts, files, 2));
        char cmd[640];
        snprintf(cmd, sizeof cmd, "/usr/bin/xmllint --noout '%s'", path_in(fx, "snapshots.xmf"));
        assert_int_equal(system(cmd), 0);
    }
}

int main(int argc, char **argv)
{
    test_filter_args(argc, argv);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_xdmf_2d, setup, teardown),
        cmocka_unit_test_setup_teardown(test_xdmf_3d, setup, teardown),
        cmocka_unit_test_setup_teardown(test_xdmf_rewrite_and_escaping, setup, teardown),
        cmocka_unit_test_setup_teardown(test_xdmf_no_snapshots, setup, teardown),
        cmocka_unit_test_setup_teardown(test_xdmf_errors, setup, teardown),
        cmocka_unit_test_setup_teardown(test_xdmf_well_formed, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
