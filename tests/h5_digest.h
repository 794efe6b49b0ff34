/* h5_digest: a text that names every dataset and attribute of an HDF5 file with its type,
 * shape and a 64-bit FNV-1a hash of its bytes, for the tests that compare a run's snapshots
 * with reference outputs byte for byte without keeping the files themselves. Strings have
 * `dir` (the run's folder, which differs between runs) replaced by "<dir>" before hashing.
 * Include after <cmocka.h>. */
#ifndef VCSPH_TEST_H5_DIGEST_H
#define VCSPH_TEST_H5_DIGEST_H

#include <hdf5.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static inline uint64_t fnv1a(const void *data, size_t len)
{
    const unsigned char *b = data;
    uint64_t hash = 14695981039346656037ULL;
    for (size_t k = 0; k < len; k++) hash = (hash ^ b[k]) * 1099511628211ULL;
    return hash;
}

typedef struct {
    FILE *out;
    const char *dir;
    const char *skip; /* an attribute left out (the version, which every commit changes) */
} h5_digest_context;

/* One line: kind, name, type class, bytes, element count, hash. Strings are hashed as
 * text with the run folder replaced. */
static inline void h5_digest_line(h5_digest_context *c, const char *kind, const char *name,
                                  hid_t type, size_t count, const char *bytes)
{
    size_t size = H5Tget_size(type) * count;
    uint64_t hash;
    if (H5Tget_class(type) == H5T_STRING) {
        char *text = strndup(bytes, size), *at;
        size_t dir_len = strlen(c->dir);
        while ((at = strstr(text, c->dir)) != NULL) { /* shorten in place: "<dir>" is shorter */
            memcpy(at, "<dir>", 5);
            memmove(at + 5, at + dir_len, strlen(at + dir_len) + 1);
        }
        size = strlen(text);
        hash = fnv1a(text, size);
        free(text);
    } else {
        hash = fnv1a(bytes, size);
    }
    fprintf(c->out, "%s %s class %d bytes %zu count %zu fnv1a %016llx\n", kind, name,
            (int)H5Tget_class(type), size, count, (unsigned long long)hash);
}

static inline herr_t h5_digest_attribute(hid_t owner, const char *name, const H5A_info_t *info,
                                         void *data)
{
    (void)info;
    h5_digest_context *c = data;
    if (strcmp(name, c->skip) == 0) return 0;
    hid_t attr = H5Aopen(owner, name, H5P_DEFAULT), type = H5Aget_type(attr);
    hid_t space = H5Aget_space(attr);
    size_t count = (size_t)H5Sget_simple_extent_npoints(space);
    hid_t native =
        H5Tget_class(type) == H5T_STRING ? H5Tcopy(type) : H5Tget_native_type(type, H5T_DIR_ASCEND);
    char *bytes = calloc(count * H5Tget_size(native) + 1, 1);
    assert_true(H5Aread(attr, native, bytes) >= 0);
    h5_digest_line(c, "attribute", name, native, count, bytes);
    free(bytes);
    H5Tclose(native);
    H5Sclose(space);
    H5Tclose(type);
    H5Aclose(attr);
    return 0;
}

static inline herr_t h5_digest_object(hid_t group, const char *name, const H5L_info_t *info,
                                      void *data)
{
    (void)info;
    h5_digest_context *c = data;
    hid_t set = H5Dopen2(group, name, H5P_DEFAULT);
    assert_true(set >= 0); /* vcsph's files are flat: datasets under the root */
    hid_t type = H5Dget_type(set), space = H5Dget_space(set);
    hid_t native = H5Tget_native_type(type, H5T_DIR_ASCEND);
    size_t count = (size_t)H5Sget_simple_extent_npoints(space);
    char *bytes = calloc(count * H5Tget_size(native) + 1, 1);
    assert_true(H5Dread(set, native, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes) >= 0);
    h5_digest_line(c, "dataset", name, native, count, bytes);
    free(bytes);
    hsize_t at = 0;
    H5Aiterate2(set, H5_INDEX_NAME, H5_ITER_INC, &at, h5_digest_attribute, c);
    H5Tclose(native);
    H5Sclose(space);
    H5Tclose(type);
    H5Dclose(set);
    return 0;
}

/* Appends the digest of the HDF5 file at path to out (its objects in name order). */
static inline void h5_digest(FILE *out, const char *path, const char *dir)
{
    h5_digest_context c = {out, dir, "vcsph_version"};
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(file >= 0);
    hsize_t at = 0;
    H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_INC, &at, h5_digest_attribute, &c);
    at = 0;
    H5Literate(file, H5_INDEX_NAME, H5_ITER_INC, &at, h5_digest_object, &c);
    H5Fclose(file);
}

#endif
