/* snapshot: particle fields to HDF5 files (docs/outputs.md) and the XDMF index ParaView opens. */
#include "io/snapshot.h"
#include "io/atomic_file.h"
#include "core/version.h"
#include "io/hdf5_attr.h"
#include "io/hdf5_errors.h"
#include "io/io_error.h"

#include <errno.h>
#include <hdf5.h>
#ifdef VCSPH_PARALLEL_HDF5
#include <mpi.h>
#endif
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Vector fields are interleaved through a buffer of at most this many rows (192 KiB for
 * 3 doubles), so a snapshot never needs a second copy of a whole n x dim array. */
enum { INTERLEAVE_ROWS = 8192 };

/* The rows of the file that this process writes: first .. first + n - 1 of total (a whole
 * snapshot: 0, n, n), and the communicator of the processes that write the others (NULL: this
 * one writes them all). */
typedef struct {
    size_t n, first, total;
    const void *comm; /* an MPI_Comm, parallel HDF5 only */
} rows_part;

/* Where a failure of snapshot_write is reported: the caller's buffer, plus what HDF5 said
 * about the first failed call (caught when it happens: every later HDF5 call, even the
 * successful closes on the way out, clears the library's error stack). */
typedef struct {
    char *err;
    size_t err_len;
    hdf5_errors hdf5; /* HDF5 silenced while a snapshot is written; its first failure */
} report;

/* Fills err with what failed on which object, and HDF5's explanation when it gave one. */
static void fail_hdf5(const report *r, const char *what, const char *name)
{
    if (r->hdf5.detail[0])
        io_error(r->err, r->err_len, "snapshot: %s '%s': %s", what, name, r->hdf5.detail);
    else
        io_error(r->err, r->err_len, "snapshot: %s '%s'", what, name);
}

/* ---------------------------------------------------------------------------------------- */
/* Field types                                                                               */

static size_t field_elem_size(field_type t)
{
    return t == FIELD_UINT8 ? 1 : (t == FIELD_INT32 || t == FIELD_FLOAT ? 4 : 8);
}

static hid_t field_mem_type(field_type t)
{
    switch (t) {
    case FIELD_DOUBLE: return H5T_NATIVE_DOUBLE;
    case FIELD_FLOAT: return H5T_NATIVE_FLOAT;
    case FIELD_INT64: return H5T_NATIVE_INT64;
    case FIELD_INT32: return H5T_NATIVE_INT32;
    case FIELD_UINT8: return H5T_NATIVE_UINT8;
    }
    return H5I_INVALID_HID;
}

/* Fixed little-endian file types, so files are the same whatever machine wrote them. */
static hid_t field_file_type(field_type t)
{
    switch (t) {
    case FIELD_DOUBLE: return H5T_IEEE_F64LE;
    case FIELD_FLOAT: return H5T_IEEE_F32LE;
    case FIELD_INT64: return H5T_STD_I64LE;
    case FIELD_INT32: return H5T_STD_I32LE;
    case FIELD_UINT8: return H5T_STD_U8LE;
    }
    return H5I_INVALID_HID;
}

static bool field_type_valid(field_type t)
{
    return t == FIELD_DOUBLE || t == FIELD_FLOAT || t == FIELD_INT64 || t == FIELD_INT32 ||
           t == FIELD_UINT8;
}

static int check_fields(size_t n, const snapshot_field *fields, int n_fields, char *err,
                        size_t err_len)
{
    if (n_fields < 0 || (n_fields > 0 && !fields)) {
        io_error(err, err_len, "snapshot: bad field list (%d fields)", n_fields);
        return -1;
    }
    for (int i = 0; i < n_fields; ++i) {
        const snapshot_field *f = &fields[i];
        if (!f->name || !f->name[0] || strchr(f->name, '/') ||
            strcmp(f->name, SNAPSHOT_VERTICES_DATASET) == 0) {
            io_error(err, err_len, "snapshot: field %d has no usable name", i);
            return -1;
        }
        if (!field_type_valid(f->type) || f->ncomp < 1 || f->ncomp > 3) {
            io_error(err, err_len, "snapshot: field '%s' has a bad type or %d components", f->name,
                     f->ncomp);
            return -1;
        }
        for (int c = 0; c < f->ncomp && n > 0; ++c) {
            if (!f->component[c]) {
                io_error(err, err_len, "snapshot: field '%s' component %d is NULL", f->name, c);
                return -1;
            }
        }
    }
    return 0;
}

/* ---------------------------------------------------------------------------------------- */
/* HDF5 snapshot                                                                             */

static int write_attrs(hid_t file, const snapshot_attrs *a, const report *r)
{
    const long step = a->step;
    const int dim = a->dim;
    struct {
        const char *name;
        hid_t file_type, mem_type;
        const void *value;
    } scalars[] = {
        {"time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &a->time},
        {"step", H5T_STD_I64LE, H5T_NATIVE_LONG, &step},
        {"eta", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &a->eta},
        {"dim", H5T_STD_I32LE, H5T_NATIVE_INT, &dim},
        {"dr", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &a->dr},
        {"h", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &a->h},
    };
    for (size_t i = 0; i < sizeof scalars / sizeof scalars[0]; ++i) {
        if (hdf5_attr_write_scalar(file, scalars[i].name, scalars[i].file_type, scalars[i].mem_type,
                                   scalars[i].value) < 0) {
            fail_hdf5(r, "cannot write attribute", scalars[i].name);
            return -1;
        }
    }
    if (hdf5_attr_write_string(file, "case", a->case_text) < 0) {
        fail_hdf5(r, "cannot write attribute", "case");
        return -1;
    }
    /* the vcsph that wrote the file (core/version.h) */
    if (hdf5_attr_write_string(file, "vcsph_version", vcsph_version()) < 0) {
        fail_hdf5(r, "cannot write attribute", "vcsph_version");
        return -1;
    }
    return 0;
}

/* Copies `rows` elements of size es from a contiguous array into every `stride`-th slot of
 * dst. The constant-size memcpy compiles to plain loads/stores and copies the bits exactly
 * (NaN payloads included), without type-punning the caller's arrays. */
static void copy_strided(unsigned char *dst, size_t stride, const unsigned char *src, size_t rows,
                         size_t es)
{
    if (es == 8) {
        for (size_t i = 0; i < rows; ++i) memcpy(dst + i * stride * 8, src + i * 8, 8);
    } else if (es == 4) {
        for (size_t i = 0; i < rows; ++i) memcpy(dst + i * stride * 4, src + i * 4, 4);
    } else {
        for (size_t i = 0; i < rows; ++i) dst[i * stride] = src[i];
    }
}

/* Creates an n-row dataset: 1-D when ncomp == 1, n x ncomp otherwise (docs/outputs.md). */
static hid_t create_dataset(hid_t file, const char *name, field_type type, size_t n, int ncomp)
{
    hsize_t dims[2] = {n, (hsize_t)ncomp};
    hid_t space = H5Screate_simple(ncomp > 1 ? 2 : 1, dims, NULL);
    if (space < 0) return H5I_INVALID_HID;
    /* no modification times in the object headers: the same state gives the same bytes
       (runs are compared byte for byte, docs/architecture.md); the storage placed when the
       dataset is made and never filled before the rows arrive, as parallel HDF5 must, so that
       a file written by several processes is laid out as one written by one */
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_obj_track_times(dcpl, 0);
    H5Pset_alloc_time(dcpl, H5D_ALLOC_TIME_EARLY);
    H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER);
    hid_t dset =
        H5Dcreate2(file, name, field_file_type(type), space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Pclose(dcpl);
    H5Sclose(space);
    return dset;
}

/* Writes rows [row0, row0 + rows) of a dataset of `ncomp` columns from buf (rows x ncomp,
 * row-major), through a hyperslab of the file space. */
static int write_rows(hid_t dset, field_type type, int ncomp, size_t row0, size_t rows,
                      const void *buf)
{
    const int rank = ncomp > 1 ? 2 : 1;
    hsize_t start[2] = {row0, 0}, count[2] = {rows, (hsize_t)ncomp};
    hid_t file_space = H5Dget_space(dset);
    if (file_space < 0) return -1;
    hid_t mem_space = H5I_INVALID_HID;
    int rc = -1;
    if (H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, NULL, count, NULL) >= 0 &&
        (mem_space = H5Screate_simple(rank, count, NULL)) >= 0)
        rc = H5Dwrite(dset, field_mem_type(type), mem_space, file_space, H5P_DEFAULT, buf) < 0 ? -1
                                                                                               : 0;
    if (mem_space >= 0) H5Sclose(mem_space);
    H5Sclose(file_space);
    return rc;
}

/* Interleaves the SoA components block by block, so memory stays bounded whatever n; this
 * process's rows of the file. */
static int write_vector_data(hid_t dset, const snapshot_field *f, const rows_part *part)
{
    const size_t es = field_elem_size(f->type), nc = (size_t)f->ncomp, n = part->n;
    const size_t block = n < INTERLEAVE_ROWS ? n : INTERLEAVE_ROWS;
    unsigned char *buf = malloc(block * nc * es);
    if (!buf) return -1;
    int rc = 0;
    for (size_t row0 = 0; rc == 0 && row0 < n; row0 += block) {
        const size_t rows = n - row0 < block ? n - row0 : block;
        for (size_t c = 0; c < nc; ++c)
            copy_strided(buf + c * es, nc, (const unsigned char *)f->component[c] + row0 * es, rows,
                         es);
        rc = write_rows(dset, f->type, f->ncomp, part->first + row0, rows, buf);
    }
    free(buf);
    return rc;
}

static int write_field(hid_t file, const snapshot_field *f, const rows_part *part)
{
    hid_t dset = create_dataset(file, f->name, f->type, part->total, f->ncomp);
    if (dset < 0) return -1;
    int rc = 0;
    if (part->n > 0) { /* no rows here: nothing to write, and no buffer to point at */
        if (f->ncomp == 1)
            rc = write_rows(dset, f->type, 1, part->first, part->n, f->component[0]);
        else
            rc = write_vector_data(dset, f, part);
    }
    if (H5Dclose(dset) < 0) rc = -1;
    return rc;
}

/* The connectivity's integer type: 4 bytes a particle unless n needs more. Shared by the
 * writer and the XDMF index, which must declare the same type. */
static field_type vertices_type(size_t n)
{
    return n <= (size_t)INT32_MAX ? FIELD_INT32 : FIELD_INT64;
}

static void fill_vertices(void *buf, field_type type, size_t row0, size_t rows)
{
    if (type == FIELD_INT32) {
        int32_t *v = buf;
        for (size_t i = 0; i < rows; ++i) v[i] = (int32_t)(row0 + i);
    } else {
        int64_t *v = buf;
        for (size_t i = 0; i < rows; ++i) v[i] = (int64_t)(row0 + i);
    }
}

/* SNAPSHOT_VERTICES_DATASET: 0 .. n-1, generated block by block (see snapshot.h for why);
 * this process's rows of it. */
static int write_vertices(hid_t file, const rows_part *part)
{
    const field_type type = vertices_type(part->total);
    hid_t dset = create_dataset(file, SNAPSHOT_VERTICES_DATASET, type, part->total, 1);
    if (dset < 0) return -1;
    const size_t n = part->n, block = n < INTERLEAVE_ROWS ? n : INTERLEAVE_ROWS;
    void *buf = n > 0 ? malloc(block * field_elem_size(type)) : NULL;
    int rc = (n > 0 && !buf) ? -1 : 0;
    for (size_t row0 = 0; rc == 0 && row0 < n; row0 += block) {
        const size_t rows = n - row0 < block ? n - row0 : block;
        fill_vertices(buf, type, part->first + row0, rows);
        rc = write_rows(dset, type, 1, part->first + row0, rows, buf);
    }
    free(buf);
    if (H5Dclose(dset) < 0) rc = -1;
    return rc;
}

/* Writes everything into an already created file; the caller closes and commits it. */
static int write_contents(hid_t file, const rows_part *part, const snapshot_field *fields,
                          int n_fields, const snapshot_attrs *attrs, const report *r)
{
    if (write_attrs(file, attrs, r) < 0) return -1;
    for (int i = 0; i < n_fields; ++i) {
        if (write_field(file, &fields[i], part) < 0) {
            fail_hdf5(r, "cannot write dataset", fields[i].name);
            return -1;
        }
    }
    if (write_vertices(file, part) < 0) {
        fail_hdf5(r, "cannot write dataset", SNAPSHOT_VERTICES_DATASET);
        return -1;
    }
    return 0;
}

#ifdef VCSPH_PARALLEL_HDF5
/* The file access of a part: every process of its communicator opens the file together
 * (MPI-IO); H5P_DEFAULT for a whole snapshot. */
static hid_t file_access(const rows_part *part)
{
    if (!part->comm) return H5P_DEFAULT;
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl >= 0 && H5Pset_fapl_mpio(fapl, *(const MPI_Comm *)part->comm, MPI_INFO_NULL) < 0) {
        H5Pclose(fapl);
        return H5I_INVALID_HID;
    }
    return fapl;
}

/* Whether every process of the part's communicator succeeded (rc 0). */
static int all_succeeded(const rows_part *part, int rc)
{
    int failed = rc != 0, any;
    if (!part->comm) return !failed;
    MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_LOR, *(const MPI_Comm *)part->comm);
    return !any;
}

/* Whether this process publishes the file: rank 0 of the part's communicator. */
static int publishes(const rows_part *part)
{
    int rank = 0;
    if (part->comm) MPI_Comm_rank(*(const MPI_Comm *)part->comm, &rank);
    return rank == 0;
}

/* Rank 0's rename, its status shared. */
static int shared_status(const rows_part *part, int rc)
{
    if (part->comm) MPI_Bcast(&rc, 1, MPI_INT, 0, *(const MPI_Comm *)part->comm);
    return rc;
}
#else
static hid_t file_access(const rows_part *part)
{
    return part->comm ? H5I_INVALID_HID : H5P_DEFAULT;
}
static int all_succeeded(const rows_part *part, int rc)
{
    (void)part;
    return rc == 0;
}
static int publishes(const rows_part *part)
{
    (void)part;
    return 1;
}
static int shared_status(const rows_part *part, int rc)
{
    (void)part;
    return rc;
}
#endif

/* Writes this process's part of the file under tmp and renames it to path; with a
 * communicator every process of it calls this, and the file is published once all wrote. */
static int write_h5_file(const char *path, const char *tmp, const rows_part *part,
                         const snapshot_field *fields, int n_fields, const snapshot_attrs *attrs,
                         const report *r)
{
    hid_t fapl = file_access(part);
    hid_t file = fapl < 0 ? H5I_INVALID_HID : H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    if (fapl >= 0 && fapl != H5P_DEFAULT) H5Pclose(fapl);
    if (file < 0) {
        fail_hdf5(r, "cannot create", tmp);
        if (publishes(part)) remove(tmp); /* in case the create got as far as making the file */
        return -1;
    }
    int rc = write_contents(file, part, fields, n_fields, attrs, r);
    if (rc == 0 && H5Fflush(file, H5F_SCOPE_LOCAL) < 0) {
        fail_hdf5(r, "cannot flush", tmp);
        rc = -1;
    }
    if (H5Fclose(file) < 0 && rc == 0) {
        fail_hdf5(r, "cannot close", tmp);
        rc = -1;
    }
    if (!all_succeeded(part, rc)) {
        if (publishes(part)) remove(tmp);
        return -1;
    }
    rc = publishes(part) ? atomic_commit("snapshot", tmp, path, r->err, r->err_len) : 0;
    return shared_status(part, rc);
}

static int write_part(const char *path, const rows_part *part, const snapshot_field *fields,
                      int n_fields, const snapshot_attrs *attrs, char *err, size_t err_len)
{
    if (!path || !path[0] || !attrs) {
        io_error(err, err_len, "snapshot: no path or attributes given");
        return -1;
    }
    if (check_fields(part->n, fields, n_fields, err, err_len) < 0) return -1;
    char *tmp = atomic_temp_path(path);
    if (!tmp) {
        io_error(err, err_len, "snapshot: out of memory");
        return -1;
    }
    report r = {.err = err, .err_len = err_len};
    hdf5_errors_begin(&r.hdf5);
    int rc = write_h5_file(path, tmp, part, fields, n_fields, attrs, &r);
    hdf5_errors_end(&r.hdf5);
    free(tmp);
    return rc;
}

int snapshot_write(const char *path, size_t n, const snapshot_field *fields, int n_fields,
                   const snapshot_attrs *attrs, char *err, size_t err_len)
{
    rows_part whole = {n, 0, n, NULL};
    return write_part(path, &whole, fields, n_fields, attrs, err, err_len);
}

int snapshot_write_part(const char *path, size_t n, size_t first, size_t total, const void *comm,
                        const snapshot_field *fields, int n_fields, const snapshot_attrs *attrs,
                        char *err, size_t err_len)
{
    rows_part part = {n, first, total, comm};
    return write_part(path, &part, fields, n_fields, attrs, err, err_len);
}

/* ---------------------------------------------------------------------------------------- */
/* XDMF index                                                                                */

/* Writes text with the five XML special characters escaped, so any file or field name
 * gives well-formed XML (valid in both attribute values and element content). */
static void xml_puts(FILE *out, const char *s)
{
    for (; *s; ++s) {
        switch (*s) {
        case '&': fputs("&amp;", out); break;
        case '<': fputs("&lt;", out); break;
        case '>': fputs("&gt;", out); break;
        case '"': fputs("&quot;", out); break;
        case '\'': fputs("&apos;", out); break;
        default: fputc(*s, out);
        }
    }
}

/* One HDF DataItem: `file:/name`, typed from the field so ParaView reads the right bytes. */
static void xdmf_data_item(FILE *out, const char *indent, const char *file, const snapshot_field *f,
                           size_t n)
{
    const char *number_type = f->type == FIELD_DOUBLE || f->type == FIELD_FLOAT
                                  ? "Float"
                                  : (f->type == FIELD_UINT8 ? "UChar" : "Int");
    fprintf(out, "%s<DataItem Format=\"HDF\" NumberType=\"%s\" Precision=\"%zu\" Dimensions=\"%zu",
            indent, number_type, field_elem_size(f->type), n);
    if (f->ncomp > 1) fprintf(out, " %d", f->ncomp);
    fputs("\">", out);
    xml_puts(out, file);
    fputs(":/", out);
    xml_puts(out, f->name);
    fputs("</DataItem>\n", out);
}

/* 2-component vectors (dim 2) are declared Vector too. XDMF has no 2-D vector type, and
 * ParaView accepts it: its Xdmf3 reader loads an attribute as an array of n_values/n
 * components whatever its AttributeType, and only skips making a non-3-component one the
 * active vectors; the legacy XDMF reader pads it to 3 components (checked with 5.11). */
static void xdmf_attribute(FILE *out, const char *file, const snapshot_field *f, size_t n)
{
    fputs("        <Attribute Name=\"", out);
    xml_puts(out, f->name);
    fprintf(out, "\" AttributeType=\"%s\" Center=\"Node\">\n", f->ncomp > 1 ? "Vector" : "Scalar");
    xdmf_data_item(out, "          ", file, f, n);
    fputs("        </Attribute>\n", out);
}

/* One time step. The Topology points at the explicit 0 .. n-1 connectivity, without which
 * ParaView's Xdmf3 reader makes no cells (see SNAPSHOT_VERTICES_DATASET in snapshot.h). */
static void xdmf_grid(FILE *out, int k, const char *file, double time, size_t n,
                      const snapshot_field *fields, int n_fields, const snapshot_field *position,
                      int dim)
{
    fprintf(out, "      <Grid Name=\"snapshot_%d\" GridType=\"Uniform\">\n", k);
    fprintf(out, "        <Time Value=\"%.17g\"/>\n", time);
    fprintf(out,
            "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%zu\""
            " NodesPerElement=\"1\">\n",
            n);
    const snapshot_field vertices = {SNAPSHOT_VERTICES_DATASET, vertices_type(n), 1, {NULL}};
    xdmf_data_item(out, "          ", file, &vertices, n);
    fputs("        </Topology>\n", out);
    fprintf(out, "        <Geometry GeometryType=\"%s\">\n", dim == 2 ? "XY" : "XYZ");
    xdmf_data_item(out, "          ", file, position, n);
    fputs("        </Geometry>\n", out);
    for (int i = 0; i < n_fields; ++i)
        if (&fields[i] != position) xdmf_attribute(out, file, &fields[i], n);
    fputs("      </Grid>\n", out);
}

static const snapshot_field *find_position(const snapshot_field *fields, int n_fields, int dim)
{
    for (int i = 0; i < n_fields; ++i)
        if (strcmp(fields[i].name, "position") == 0 && fields[i].ncomp == dim) return &fields[i];
    return NULL;
}

static void xdmf_document(FILE *out, int n_snapshots, const char *const *files, const double *times,
                          const size_t *counts, const snapshot_field *fields, int n_fields,
                          const snapshot_field *position, int dim)
{
    fputs("<?xml version=\"1.0\" ?>\n"
          "<Xdmf Version=\"3.0\">\n"
          "  <Domain>\n"
          "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
          out);
    for (int k = 0; k < n_snapshots; ++k)
        xdmf_grid(out, k, files[k], times[k], counts[k], fields, n_fields, position, dim);
    fputs("    </Grid>\n"
          "  </Domain>\n"
          "</Xdmf>\n",
          out);
}

static int check_xdmf_args(const char *xmf_path, int n_snapshots, const char *const *files,
                           const double *times, const size_t *counts, int dim, char *err,
                           size_t err_len)
{
    if (!xmf_path || !xmf_path[0] || n_snapshots < 0 ||
        (n_snapshots > 0 && (!files || !times || !counts))) {
        io_error(err, err_len, "xdmf: bad arguments");
        return -1;
    }
    if (dim != 2 && dim != 3) {
        io_error(err, err_len, "xdmf: dimension %d is not 2 or 3", dim);
        return -1;
    }
    for (int k = 0; k < n_snapshots; ++k) {
        if (!files[k] || !files[k][0]) {
            io_error(err, err_len, "xdmf: snapshot %d has no file name", k);
            return -1;
        }
    }
    return 0;
}

int snapshot_write_xdmf(const char *xmf_path, int n_snapshots, const char *const *files,
                        const double *times, const size_t *counts, const snapshot_field *fields,
                        int n_fields, int dim, char *err, size_t err_len)
{
    if (check_xdmf_args(xmf_path, n_snapshots, files, times, counts, dim, err, err_len) < 0 ||
        check_fields(0, fields, n_fields, err, err_len) < 0)
        return -1;
    const snapshot_field *position = find_position(fields, n_fields, dim);
    if (!position) {
        io_error(err, err_len, "xdmf: no 'position' field with %d components", dim);
        return -1;
    }
    char *tmp = atomic_temp_path(xmf_path);
    if (!tmp) {
        io_error(err, err_len, "xdmf: out of memory");
        return -1;
    }
    int rc = -1;
    FILE *out = fopen(tmp, "w");
    if (!out) {
        io_error(err, err_len, "xdmf: cannot create '%s': %s", tmp, strerror(errno));
    } else {
        xdmf_document(out, n_snapshots, files, times, counts, fields, n_fields, position, dim);
        /* ferror catches a failed write anywhere above; fclose catches a failed flush. */
        bool failed = ferror(out) != 0;
        if (fclose(out) != 0 || failed) {
            io_error(err, err_len, "xdmf: cannot write '%s'", tmp);
            remove(tmp);
        } else {
            rc = atomic_commit("xdmf", tmp, xmf_path, err, err_len);
        }
    }
    free(tmp);
    return rc;
}
