/* snapshot: particle fields to HDF5 files (docs/outputs.md) and the XDMF index ParaView opens. */
#ifndef VCSPH_SNAPSHOT_H
#define VCSPH_SNAPSHOT_H

#include <stddef.h>
#include <stdint.h>

typedef enum { FIELD_DOUBLE, FIELD_FLOAT, FIELD_INT64, FIELD_INT32, FIELD_UINT8 } field_type;

/* One dataset: n rows of ncomp components. Components are separate arrays (SoA); the file
 * stores them interleaved as an n x ncomp dataset (n when ncomp == 1). */
typedef struct {
    const char *name;
    field_type type;
    int ncomp;                /* 1, or dim for vectors */
    const void *component[3]; /* ncomp pointers to n values each */
} snapshot_field;

/* The file's attributes, one each; besides them every snapshot holds the string attribute
 * vcsph_version, the vcsph that wrote it (core/version.h). */
typedef struct {
    double time;
    long step;
    double eta;
    int dim;
    double dr, h;
    const char *case_text; /* the resolved case.ini */
} snapshot_attrs;

/* Besides one dataset per field, every snapshot file holds this dataset: the row numbers
 * 0 .. n-1 (int32, or int64 when n exceeds INT32_MAX), which the XDMF index uses as the
 * Polyvertex connectivity. ParaView's XDMF3 reader makes vertex cells only from explicit
 * connectivity; without them the particles are points with no cells, which the Surface and
 * Points representations do not draw. Readers of the physical fields can ignore it. */
#define SNAPSHOT_VERTICES_DATASET "xdmf_vertices"

/* Writes one snapshot file (atomically: temporary file, then rename). The field named
 * "position" (ncomp = dim) is the geometry. Returns 0, or -1 with a message in err. */
int snapshot_write(const char *path, size_t n, const snapshot_field *fields, int n_fields,
                   const snapshot_attrs *attrs, char *err, size_t err_len);

/* Whether snapshot_write_part can write a file with several processes: the build's HDF5 is
 * the parallel one (the MPI build). */
#ifdef VCSPH_PARALLEL_HDF5
#define SNAPSHOT_PARALLEL 1
#else
#define SNAPSHOT_PARALLEL 0
#endif

/* snapshot_write by every process of the MPI communicator *comm (an MPI_Comm, passed as a
 * pointer so that this header needs no MPI) at once, collectively through parallel HDF5: this
 * process's n rows (the components of `fields` hold them) are rows first .. first + n - 1 of
 * the file's total. Every process gives the same fields, attributes and path; the file is
 * the one snapshot_write makes of all the rows, byte for byte, and is renamed into place by
 * rank 0 once every process has written. With comm NULL one process writes the whole file,
 * first 0 and total n. Returns 0, or -1 with a message, the same on every process. */
int snapshot_write_part(const char *path, size_t n, size_t first, size_t total, const void *comm,
                        const snapshot_field *fields, int n_fields, const snapshot_attrs *attrs,
                        char *err, size_t err_len);

/* Writes (atomically) the XDMF temporal collection `xmf_path` that lists the snapshot files
 * `files[k]` (paths relative to the XDMF file's folder) at times `times[k]` with particle
 * counts `counts[k]`; every file holds the same fields. */
int snapshot_write_xdmf(const char *xmf_path, int n_snapshots, const char *const *files,
                        const double *times, const size_t *counts, const snapshot_field *fields,
                        int n_fields, int dim, char *err, size_t err_len);

#endif
