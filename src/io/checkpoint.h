/* checkpoint: a set of named one-dimensional arrays in one HDF5 file, written atomically and
 * read back only whole and verified (README.md: checkpoint.h5). It knows nothing of particles
 * or dimensions: app/restart.c decides what the arrays hold.
 *
 * File layout (format CHECKPOINT_FORMAT, version CHECKPOINT_VERSION):
 * - a 512-byte HDF5 user block holding a text header: the marker, the version, the file's
 *   length and an FNV-1a 64-bit hash of the whole file (checkpoint.c says how), checked
 *   before HDF5 opens the file: any changed byte, truncation or extension is refused;
 * - root attributes "format" (string) and "version" (int32): the same marker for HDF5 tools;
 * - at most CHECKPOINT_MAX_ITEMS datasets, listed in the root group's compact storage (link
 *   messages in its object header, never HDF5's "dense" fractal heap: the reader refuses a
 *   dense root group, which it never writes, and so never runs HDF5 1.10's dense-link code,
 *   which crashes on some damaged heaps; docs/choices.md);
 * - one dataset per item in the root group, 1-D, typed float64 / int64 (little-endian) or
 *   uint8 (bytes: texts), chunked (at most CHECKPOINT_CHUNK_BYTES a chunk) with HDF5's
 *   Fletcher32 checksum filter, so that a damaged chunk fails its read;
 * - an optional string attribute "columns" on a dataset of scalars names its entries in order,
 *   and the reader checks it, so that a change of meaning cannot pass for the old layout;
 * - the file is written with the HDF5 1.10 file format (libver bounds V110): its superblock,
 *   object headers (attributes included) and chunk indexes carry HDF5's own metadata
 *   checksums, so damage outside the data is detected too (on open or on read).
 *
 * Writing goes to PATH.tmp, flushed (H5Fflush, then fsync of the file), then renamed over PATH
 * (and the folder fsynced): a crash at any moment leaves either the old checkpoint or the new
 * one. Reading opens the file, checks the marker and the version and reads every dataset into
 * memory, so that a damaged file is refused before anything is done with it. */
#ifndef VCSPH_CHECKPOINT_H
#define VCSPH_CHECKPOINT_H

#include <stddef.h>
#include <stdint.h>

#define CHECKPOINT_FORMAT      "vcsph checkpoint"
#define CHECKPOINT_VERSION     2 /* 1: the root group could be dense */
#define CHECKPOINT_MAX_ITEMS   64
#define CHECKPOINT_HEADER_SIZE 512 /* the user block holding our header */
#define CHECKPOINT_NAME_MAX    64
#define CHECKPOINT_CHUNK_BYTES (4u << 20)

typedef enum { CHECKPOINT_F64, CHECKPOINT_I64, CHECKPOINT_BYTES } checkpoint_type;

/* Bytes of one value of type t. */
static inline size_t checkpoint_type_size(checkpoint_type t)
{
    return t == CHECKPOINT_BYTES ? 1 : 8;
}

/* One array: n values of `type` at data (n may be 0); columns: NULL, or the names of the
 * entries, comma-separated (stored as the dataset's "columns" attribute). */
typedef struct {
    const char *name;
    checkpoint_type type;
    size_t n;
    const void *data;
    const char *columns;
} checkpoint_item;

/* A checkpoint read back: its arrays, each in memory. */
typedef struct {
    char name[CHECKPOINT_NAME_MAX];
    checkpoint_type type;
    size_t n;
    void *data;    /* n values (NULL when n = 0) */
    char *columns; /* NULL when the dataset has none */
} checkpoint_array;

typedef struct checkpoint_data {
    int n_arrays;
    checkpoint_array *arrays;
} checkpoint_data;

/* Writes the items to path atomically (see above). Returns 0, or -1 with a message in err. */
int checkpoint_write(const char *path, const checkpoint_item *items, int n_items, char *err,
                     size_t err_len);

/* Reads and verifies the whole file: HDF5, our format marker, our version, every dataset
 * read (checksums checked). Returns 0, or -1 with a message in err naming the file and what
 * is wrong with it (empty, truncated or damaged, not a vcsph checkpoint, other version). */
int checkpoint_read(const char *path, checkpoint_data *cd, char *err, size_t err_len);
void checkpoint_data_free(checkpoint_data *cd);

/* Writes the header (the first 512 bytes: marker, version, length and hash; see checkpoint.c)
 * of the file at path for what it holds now, and syncs the file. checkpoint_write seals what
 * it writes; the tests and the fuzz target seal files they changed on purpose, so that the
 * checks behind the hash (HDF5's, and those of the reader) see them. Returns 0 or -1. */
int checkpoint_seal(const char *path);

/* The array `name` when it exists with this type and, unless n is SIZE_MAX, n values, and
 * with these columns (NULL: none expected); NULL otherwise, with a message in err. */
const checkpoint_array *checkpoint_find(const checkpoint_data *cd, const char *name,
                                        checkpoint_type type, size_t n, const char *columns,
                                        char *err, size_t err_len);

/* The bytes array `name` as a C string (up to its first NUL) in malloc'd memory: a text
 * item such as the case. NULL with a message in err when there is none or memory ran out. */
char *checkpoint_text(const checkpoint_data *cd, const char *name, char *err, size_t err_len);

#endif
