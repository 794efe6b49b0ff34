/* checkpoint: named arrays in one verified HDF5 file (checkpoint.h). */
#include "io/checkpoint.h"
#include "core/version.h"
#include "io/atomic_file.h"
#include "io/hdf5_attr.h"
#include "io/hdf5_errors.h"
#include "io/io_error.h"

#include <errno.h>
#include <fcntl.h>
#include <hdf5.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- types ------------------------------------------------------------------------------- */

static hid_t mem_type(checkpoint_type t)
{
    return t == CHECKPOINT_F64   ? H5T_NATIVE_DOUBLE
           : t == CHECKPOINT_I64 ? H5T_NATIVE_INT64
                                 : H5T_NATIVE_UINT8;
}

/* Fixed little-endian file types: the same state gives the same bytes on any machine. */
static hid_t file_type(checkpoint_type t)
{
    return t == CHECKPOINT_F64   ? H5T_IEEE_F64LE
           : t == CHECKPOINT_I64 ? H5T_STD_I64LE
                                 : H5T_STD_U8LE;
}

/* The checkpoint type of a dataset's file type; -1 for anything we never write. */
static int type_of_dataset(hid_t dset)
{
    hid_t type = H5Dget_type(dset);
    if (type < 0) return -1;
    H5T_class_t cls = H5Tget_class(type);
    size_t size = H5Tget_size(type);
    H5T_sign_t sign = H5Tget_sign(type);
    H5Tclose(type);
    if (cls == H5T_FLOAT && size == 8) return CHECKPOINT_F64;
    if (cls == H5T_INTEGER && size == 8 && sign == H5T_SGN_2) return CHECKPOINT_I64;
    if (cls == H5T_INTEGER && size == 1 && sign == H5T_SGN_NONE) return CHECKPOINT_BYTES;
    return -1;
}

/* ---- the user block: marker, length and whole-file checksum ----------------------------- */

/* HDF5 skips a user block of CHECKPOINT_HEADER bytes at the start of the file. Ours holds a
 * text header with fixed-width fields,
 *     vcsph checkpoint\nversion 2\nbytes 0000000000034580\nfnv1a64 0123456789abcdef\n
 * padded with NULs: the file's length and the FNV-1a 64-bit hash of the whole file, taken
 * with the hash field's 16 digits as '0's. HDF5's own checksums leave out the space it freed
 * or never used (a few percent of a small file), and a damaged object header can leave the
 * library in a state where it cannot shut down cleanly; the hash refuses any changed byte, a
 * truncation or an extension before HDF5 sees the file. (FNV-1a catches every single-byte
 * change: each step is a bijection of the running hash.) */
enum { HEADER_SIZE = CHECKPOINT_HEADER_SIZE, IO_BLOCK = 1 << 20 };
static const char header_magic[] = "vcsph checkpoint\n";
#define HEADER_FORMAT "vcsph checkpoint\nversion %d\nbytes %016lld\nfnv1a64 %016llx\n"
#define HEADER_SCAN   "vcsph checkpoint\nversion %d\nbytes %lld\nfnv1a64 %llx"
/* offset of the hash digits: the fixed-width text before them (a one-digit version) */
_Static_assert(CHECKPOINT_VERSION < 10, "HASH_AT counts a one-digit version");
#define HASH_AT (sizeof "vcsph checkpoint\nversion 2\nbytes 0000000000000000\nfnv1a64 " - 1)

static uint64_t fnv1a(uint64_t h, const unsigned char *p, size_t n)
{
    for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * 0x100000001b3ULL;
    return h;
}

/* The hash of the open file f (HEADER_SIZE bytes at least), its hash field read as '0's. */
static int hash_file(FILE *f, uint64_t *hash)
{
    unsigned char *buf = malloc(IO_BLOCK);
    if (!buf || fseeko(f, 0, SEEK_SET)) {
        free(buf);
        return -1;
    }
    uint64_t h = 0xcbf29ce484222325ULL;
    size_t n;
    for (long long at = 0; (n = fread(buf, 1, IO_BLOCK, f)) > 0; at += (long long)n) {
        if (at == 0 && n >= HASH_AT + 16) memset(buf + HASH_AT, '0', 16);
        h = fnv1a(h, buf, n);
    }
    int rc = ferror(f) ? -1 : 0;
    free(buf);
    *hash = h;
    return rc;
}

static int write_header_text(FILE *f, long long bytes, uint64_t hash)
{
    char header[HEADER_SIZE] = {0};
    snprintf(header, sizeof header, HEADER_FORMAT, CHECKPOINT_VERSION, bytes,
             (unsigned long long)hash);
    return fseeko(f, 0, SEEK_SET) == 0 && fwrite(header, 1, sizeof header, f) == sizeof header ? 0
                                                                                               : -1;
}

int checkpoint_seal(const char *path)
{
    FILE *f = fopen(path, "r+b");
    if (!f) return -1;
    struct stat st;
    uint64_t hash = 0;
    int rc = fstat(fileno(f), &st) == 0 && write_header_text(f, (long long)st.st_size, 0) == 0 &&
                     fflush(f) == 0 && hash_file(f, &hash) == 0 &&
                     write_header_text(f, (long long)st.st_size, hash) == 0 && fflush(f) == 0 &&
                     fsync(fileno(f)) == 0
                 ? 0
                 : -1;
    if (fclose(f)) rc = -1;
    return rc;
}

/* ---- writing ----------------------------------------------------------------------------- */

/* The format marker, and the vcsph that wrote the file: an attribute that the reader does not
 * ask for, so that checkpoints written before it existed load as they did. */
static int write_marker(hid_t file)
{
    const int version = CHECKPOINT_VERSION;
    return hdf5_attr_write_string(file, "format", CHECKPOINT_FORMAT) ||
                   hdf5_attr_write_scalar(file, "version", H5T_STD_I32LE, H5T_NATIVE_INT,
                                          &version) ||
                   hdf5_attr_write_string(file, "vcsph_version", vcsph_version())
               ? -1
               : 0;
}

/* Chunked storage, required by the Fletcher32 filter; an empty array gets an extendible
 * space, since a fixed size of 0 admits no chunk. No modification times: the same state gives
 * the same file. */
static hid_t create_dataset(hid_t file, const checkpoint_item *it)
{
    const hsize_t chunk_max = CHECKPOINT_CHUNK_BYTES / checkpoint_type_size(it->type);
    hsize_t dims[1] = {it->n}, max_dims[1] = {it->n ? it->n : H5S_UNLIMITED};
    hsize_t chunk[1] = {it->n == 0 ? 1 : it->n < chunk_max ? it->n : chunk_max};
    hid_t space = H5Screate_simple(1, dims, max_dims);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    hid_t dset = H5I_INVALID_HID;
    if (space >= 0 && dcpl >= 0 && H5Pset_chunk(dcpl, 1, chunk) >= 0 &&
        H5Pset_fletcher32(dcpl) >= 0 && H5Pset_obj_track_times(dcpl, 0) >= 0)
        dset =
            H5Dcreate2(file, it->name, file_type(it->type), space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    if (dcpl >= 0) H5Pclose(dcpl);
    if (space >= 0) H5Sclose(space);
    return dset;
}

static int write_item(hid_t file, const checkpoint_item *it)
{
    hid_t dset = create_dataset(file, it);
    if (dset < 0) return -1;
    int rc = 0;
    if (it->n > 0 &&
        H5Dwrite(dset, mem_type(it->type), H5S_ALL, H5S_ALL, H5P_DEFAULT, it->data) < 0)
        rc = -1;
    if (rc == 0 && it->columns) rc = hdf5_attr_write_string(dset, "columns", it->columns);
    if (H5Dclose(dset) < 0) rc = -1;
    return rc;
}

static int write_items(hid_t file, const checkpoint_item *items, int n_items, const char *path,
                       const hdf5_errors *h, char *err, size_t err_len)
{
    if (write_marker(file)) {
        io_error(err, err_len, "checkpoint %s: cannot write the format marker: %s", path,
                 hdf5_errors_detail(h, "HDF5 error"));
        return -1;
    }
    for (int k = 0; k < n_items; k++) {
        if (write_item(file, &items[k])) {
            io_error(err, err_len, "checkpoint %s: cannot write dataset '%s': %s", path,
                     items[k].name, hdf5_errors_detail(h, "HDF5 error"));
            return -1;
        }
    }
    return 0;
}

/* fsync of the folder that holds path: the rename that publishes the checkpoint reaches the
 * disk. */
static int sync_parent(const char *path)
{
    const char *slash = strrchr(path, '/');
    char *dir = !slash ? strdup(".") : strndup(path, slash == path ? 1 : (size_t)(slash - path));
    int fd = dir ? open(dir, O_RDONLY | O_DIRECTORY) : -1;
    free(dir);
    if (fd < 0) return -1;
    int rc = fsync(fd);
    close(fd);
    return rc;
}

/* The file with room for our header, the V110 format bounds and a compact root group
 * (checkpoint.h), whose object header keeps no modification times either: the same state
 * gives the same file (a run split among processes is compared with one process by them). */
static hid_t create_file(const char *tmp)
{
    hid_t fcpl = H5Pcreate(H5P_FILE_CREATE), fapl = H5Pcreate(H5P_FILE_ACCESS);
    hid_t file = H5I_INVALID_HID;
    if (fcpl >= 0 && fapl >= 0 && H5Pset_userblock(fcpl, HEADER_SIZE) >= 0 &&
        H5Pset_link_phase_change(fcpl, CHECKPOINT_MAX_ITEMS, CHECKPOINT_MAX_ITEMS / 2) >= 0 &&
        H5Pset_obj_track_times(fcpl, 0) >= 0 &&
        H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_LATEST) >= 0)
        file = H5Fcreate(tmp, H5F_ACC_TRUNC, fcpl, fapl);
    if (fcpl >= 0) H5Pclose(fcpl);
    if (fapl >= 0) H5Pclose(fapl);
    return file;
}

static int write_temp(const char *tmp, const checkpoint_item *items, int n_items,
                      const hdf5_errors *h, char *err, size_t err_len)
{
    hid_t file = create_file(tmp);
    if (file < 0) {
        io_error(err, err_len, "checkpoint %s: cannot create: %s", tmp,
                 hdf5_errors_detail(h, "HDF5 error"));
        return -1;
    }
    int rc = write_items(file, items, n_items, tmp, h, err, err_len);
    if (rc == 0 && H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) {
        io_error(err, err_len, "checkpoint %s: cannot flush: %s", tmp,
                 hdf5_errors_detail(h, "HDF5 error"));
        rc = -1;
    }
    if (H5Fclose(file) < 0 && rc == 0) {
        io_error(err, err_len, "checkpoint %s: cannot close: %s", tmp,
                 hdf5_errors_detail(h, "HDF5 error"));
        rc = -1;
    }
    if (rc == 0 && checkpoint_seal(tmp)) {
        io_error(err, err_len, "checkpoint %s: cannot write its header or sync it: %s", tmp,
                 strerror(errno));
        rc = -1;
    }
    return rc;
}

int checkpoint_write(const char *path, const checkpoint_item *items, int n_items, char *err,
                     size_t err_len)
{
    if (n_items > CHECKPOINT_MAX_ITEMS) {
        io_error(err, err_len, "checkpoint %s: %d arrays, more than the %d of the format", path,
                 n_items, CHECKPOINT_MAX_ITEMS);
        return -1;
    }
    char *tmp = atomic_temp_path(path);
    if (!tmp) {
        io_error(err, err_len, "checkpoint %s: out of memory", path);
        return -1;
    }
    hdf5_errors h;
    hdf5_errors_begin(&h);
    int rc = write_temp(tmp, items, n_items, &h, err, err_len);
    hdf5_errors_end(&h);
    /* a crash before the rename keeps the old checkpoint whole, one after it the new one */
    if (rc == 0)
        rc = atomic_commit("checkpoint", tmp, path, err, err_len);
    else
        remove(tmp);
    if (rc == 0) sync_parent(path); /* best effort: the rename itself has succeeded */
    free(tmp);
    return rc;
}

/* ---- reading ----------------------------------------------------------------------------- */

static int check_marker(hid_t file, const char *path, const hdf5_errors *h, char *err,
                        size_t err_len)
{
    /* a root object header that fails HDF5's checksum cannot even say what it holds */
    if (H5Aexists(file, "format") < 0) {
        io_error(err, err_len, "%s: damaged HDF5 file (%s)", path,
                 hdf5_errors_detail(h, "HDF5 error"));
        return -1;
    }
    char *format = hdf5_attr_read_string(file, "format");
    bool ours = format && strcmp(format, CHECKPOINT_FORMAT) == 0;
    free(format);
    if (!ours) {
        io_error(err, err_len,
                 "%s: not a vcsph checkpoint (an HDF5 file without the format marker '%s')", path,
                 CHECKPOINT_FORMAT);
        return -1;
    }
    int version = -1;
    if (hdf5_attr_read_scalar(file, "version", H5T_NATIVE_INT, &version)) version = -1;
    if (version != CHECKPOINT_VERSION) {
        io_error(err, err_len,
                 "%s: checkpoint format version %d, but this vcsph reads version %d only "
                 "(continue it with the vcsph that wrote it)",
                 path, version, CHECKPOINT_VERSION);
        return -1;
    }
    return 0;
}

static bool has_fletcher32(hid_t dset)
{
    hid_t dcpl = H5Dget_create_plist(dset);
    if (dcpl < 0) return false;
    unsigned flags;
    size_t n_values = 0;
    bool found = H5Pget_filter_by_id2(dcpl, H5Z_FILTER_FLETCHER32, &flags, &n_values, NULL, 0, NULL,
                                      NULL) >= 0;
    H5Pclose(dcpl);
    return found;
}

/* The length of a 1-D dataset, or -1. */
static long long dataset_length(hid_t dset)
{
    hid_t space = H5Dget_space(dset);
    if (space < 0) return -1;
    hsize_t dims[1] = {0};
    long long n =
        H5Sget_simple_extent_ndims(space) == 1 && H5Sget_simple_extent_dims(space, dims, NULL) == 1
            ? (long long)dims[0]
            : -1;
    H5Sclose(space);
    return n;
}

/* Reads one dataset whole into a (its checksums are checked by the read). */
static int read_array(hid_t dset, checkpoint_array *a, const char *path, const hdf5_errors *h,
                      char *err, size_t err_len)
{
    int type = type_of_dataset(dset);
    long long n = dataset_length(dset);
    if (type < 0 || n < 0 || !has_fletcher32(dset)) {
        io_error(err, err_len,
                 "%s: not a vcsph checkpoint (dataset '%s' is not a 1-D checksummed array of "
                 "float64, int64 or bytes)",
                 path, a->name);
        return -1;
    }
    a->type = (checkpoint_type)type;
    a->n = (size_t)n;
    a->columns = hdf5_attr_read_string(dset, "columns");
    if (a->n == 0) return 0;
    /* every value vcsph writes is stored: a length beyond the stored chunks (unwritten
       chunks read as fill values) is not ours, and is refused before it is allocated */
    size_t size = checkpoint_type_size(a->type);
    if (a->n > SIZE_MAX / size || H5Dget_storage_size(dset) < a->n * size) {
        io_error(err, err_len,
                 "%s: damaged or not a vcsph checkpoint: dataset '%s' claims %zu values, more "
                 "than it stores",
                 path, a->name, a->n);
        return -1;
    }
    a->data = malloc(a->n * size);
    if (!a->data) {
        io_error(err, err_len, "%s: out of memory for dataset '%s'", path, a->name);
        return -1;
    }
    if (H5Dread(dset, mem_type(a->type), H5S_ALL, H5S_ALL, H5P_DEFAULT, a->data) < 0) {
        io_error(err, err_len, "%s: damaged: dataset '%s' cannot be read (%s)", path, a->name,
                 hdf5_errors_detail(h, "HDF5 error"));
        return -1;
    }
    return 0;
}

static int read_all(hid_t file, checkpoint_data *cd, const char *path, const hdf5_errors *h,
                    char *err, size_t err_len)
{
    H5G_info_t info;
    if (H5Gget_info(file, &info) < 0) {
        io_error(err, err_len, "%s: damaged: cannot list its contents (%s)", path,
                 hdf5_errors_detail(h, "HDF5 error"));
        return -1;
    }
    if (info.storage_type != H5G_STORAGE_TYPE_COMPACT || info.nlinks > CHECKPOINT_MAX_ITEMS) {
        io_error(err, err_len,
                 "%s: not a vcsph checkpoint (its root group is not a compact list of at most "
                 "%d datasets)",
                 path, CHECKPOINT_MAX_ITEMS);
        return -1;
    }
    cd->arrays = calloc(info.nlinks ? info.nlinks : 1, sizeof *cd->arrays);
    if (!cd->arrays) {
        io_error(err, err_len, "%s: out of memory", path);
        return -1;
    }
    for (hsize_t k = 0; k < info.nlinks; k++) {
        checkpoint_array *a = &cd->arrays[cd->n_arrays++];
        ssize_t len = H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, k, a->name,
                                         sizeof a->name, H5P_DEFAULT);
        hid_t dset = len > 0 && (size_t)len < sizeof a->name ? H5Dopen2(file, a->name, H5P_DEFAULT)
                                                             : H5I_INVALID_HID;
        if (dset < 0) {
            io_error(err, err_len, "%s: damaged or not a vcsph checkpoint: object %llu (%s) %s",
                     path, (unsigned long long)k, len > 0 ? a->name : "?",
                     hdf5_errors_detail(h, "is not a dataset"));
            return -1;
        }
        int rc = read_array(dset, a, path, h, err, err_len);
        H5Dclose(dset);
        if (rc) return -1;
    }
    return 0;
}

/* Empty and missing files are named as such; HDF5 would only say it cannot open them. */
static int check_file(const char *path, long long *size, char *err, size_t err_len)
{
    struct stat st;
    if (stat(path, &st)) {
        io_error(err, err_len, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (!S_ISREG(st.st_mode)) {
        io_error(err, err_len, "%s: not a regular file", path);
        return -1;
    }
    if (st.st_size == 0) {
        io_error(err, err_len, "%s: empty file, not a checkpoint", path);
        return -1;
    }
    *size = (long long)st.st_size;
    return 0;
}

/* A file without our header: say whether it is HDF5 at all. */
static void foreign(const char *path, char *err, size_t err_len)
{
    if (H5Fis_hdf5(path) > 0)
        io_error(err, err_len,
                 "%s: not a vcsph checkpoint (an HDF5 file without the '%.16s' header)", path,
                 header_magic);
    else
        io_error(err, err_len, "%s: not a vcsph checkpoint (not an HDF5 file)", path);
}

/* The header (see "the user block"): ours, our version, the file whole and unchanged. */
static int check_header(const char *path, long long size, char *err, size_t err_len)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        io_error(err, err_len, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    char header[HEADER_SIZE + 1] = {0};
    size_t got = fread(header, 1, HEADER_SIZE, f);
    int version = -1;
    long long bytes = -1;
    unsigned long long stored = 0;
    uint64_t hash = 0;
    int rc = -1;
    if (strncmp(header, header_magic, got < strlen(header_magic) ? got : strlen(header_magic)))
        foreign(path, err, err_len);
    else if (got < HEADER_SIZE)
        io_error(err, err_len, "%s: truncated (%lld bytes)", path, size);
    else if (sscanf(header, HEADER_SCAN, &version, &bytes, &stored) != 3)
        io_error(err, err_len, "%s: damaged header", path);
    else if (version != CHECKPOINT_VERSION)
        io_error(err, err_len,
                 "%s: checkpoint format version %d, but this vcsph reads version %d only "
                 "(continue it with the vcsph that wrote it)",
                 path, version, CHECKPOINT_VERSION);
    else if (bytes != size)
        io_error(err, err_len, "%s: %s: %lld bytes, written with %lld", path,
                 size < bytes ? "truncated" : "damaged", size, bytes);
    else if (hash_file(f, &hash))
        io_error(err, err_len, "%s: cannot read: %s", path, strerror(errno));
    else if (hash != stored)
        io_error(err, err_len, "%s: damaged: its checksum does not match its contents", path);
    else
        rc = 0;
    fclose(f);
    return rc;
}

static int read_file(const char *path, checkpoint_data *cd, const hdf5_errors *h, char *err,
                     size_t err_len)
{
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) {
        io_error(err, err_len, "%s: damaged HDF5 file (%s)", path,
                 hdf5_errors_detail(h, "cannot open"));
        return -1;
    }
    int rc = check_marker(file, path, h, err, err_len);
    if (rc == 0) rc = read_all(file, cd, path, h, err, err_len);
    if (H5Fclose(file) < 0 && rc == 0) {
        io_error(err, err_len, "%s: damaged (%s)", path, hdf5_errors_detail(h, "cannot close"));
        rc = -1;
    }
    return rc;
}

int checkpoint_read(const char *path, checkpoint_data *cd, char *err, size_t err_len)
{
    memset(cd, 0, sizeof *cd);
    long long size;
    hdf5_errors h;
    hdf5_errors_begin(&h); /* H5Fis_hdf5 of a foreign file reports to the error stack too */
    int rc = check_file(path, &size, err, err_len) || check_header(path, size, err, err_len) ||
                     read_file(path, cd, &h, err, err_len)
                 ? -1
                 : 0;
    hdf5_errors_end(&h);
    if (rc) checkpoint_data_free(cd);
    return rc;
}

void checkpoint_data_free(checkpoint_data *cd)
{
    for (int k = 0; k < cd->n_arrays; k++) {
        free(cd->arrays[k].data);
        free(cd->arrays[k].columns);
    }
    free(cd->arrays);
    memset(cd, 0, sizeof *cd);
}

static const char *type_name(checkpoint_type t)
{
    return t == CHECKPOINT_F64 ? "float64" : t == CHECKPOINT_I64 ? "int64" : "bytes";
}

const checkpoint_array *checkpoint_find(const checkpoint_data *cd, const char *name,
                                        checkpoint_type type, size_t n, const char *columns,
                                        char *err, size_t err_len)
{
    for (int k = 0; k < cd->n_arrays; k++) {
        const checkpoint_array *a = &cd->arrays[k];
        if (strcmp(a->name, name)) continue;
        bool same_columns =
            columns ? a->columns && strcmp(a->columns, columns) == 0 : a->columns == NULL;
        if (a->type == type && (n == SIZE_MAX || a->n == n) && same_columns) return a;
        if (!same_columns)
            io_error(err, err_len, "dataset '%s' holds (%s), where (%s) is expected", name,
                     a->columns ? a->columns : "no column names", columns ? columns : "none");
        else
            io_error(err, err_len, "dataset '%s' holds %zu %s values, where %zu %s are expected",
                     name, a->n, type_name(a->type), n == SIZE_MAX ? a->n : n, type_name(type));
        return NULL;
    }
    io_error(err, err_len, "no dataset '%s'", name);
    return NULL;
}

char *checkpoint_text(const checkpoint_data *cd, const char *name, char *err, size_t err_len)
{
    const checkpoint_array *a =
        checkpoint_find(cd, name, CHECKPOINT_BYTES, SIZE_MAX, NULL, err, err_len);
    if (!a) return NULL;
    char *text = strndup(a->data ? (const char *)a->data : "", a->n);
    if (!text) io_error(err, err_len, "out of memory for dataset '%s'", name);
    return text;
}
