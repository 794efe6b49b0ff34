/* hdf5_attr: scalar and string attributes of an HDF5 object, written and read the same way by
 * snapshots and checkpoints. */
#ifndef VCSPH_HDF5_ATTR_H
#define VCSPH_HDF5_ATTR_H

#include <hdf5.h>

/* A scalar attribute `name` of loc: value (mem_type) stored as file_type. Returns 0 or -1. */
int hdf5_attr_write_scalar(hid_t loc, const char *name, hid_t file_type, hid_t mem_type,
                           const void *value);

/* A fixed-length, NUL-terminated ASCII string: the simplest string type to read back from C,
 * and h5py/ParaView read it as a plain str. The size includes the terminator, so an empty
 * text (or NULL) still gives a valid type. Returns 0 or -1. */
int hdf5_attr_write_string(hid_t loc, const char *name, const char *text);

/* Reads scalar attribute `name` as mem_type into out. Returns 0, or -1 when it is missing or
 * unreadable (a missing one is asked first, so that it leaves no error on HDF5's stack). */
int hdf5_attr_read_scalar(hid_t loc, const char *name, hid_t mem_type, void *out);

/* The fixed-length string attribute `name` (malloc'd), or NULL when it is missing or is not
 * such a string. */
char *hdf5_attr_read_string(hid_t loc, const char *name);

#endif
