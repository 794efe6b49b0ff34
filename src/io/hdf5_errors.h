/* hdf5_errors: HDF5's error stack silenced and its first failure kept, so that a failed
 * write or read gives one clear message of ours instead of HDF5's stack on stderr. */
#ifndef VCSPH_HDF5_ERRORS_H
#define VCSPH_HDF5_ERRORS_H

#include <hdf5.h>

enum { HDF5_DETAIL_LEN = 256 };

typedef struct {
    char detail[HDF5_DETAIL_LEN]; /* the innermost description of the first failure, or "" */
    H5E_auto2_t saved_func;
    void *saved_data;
} hdf5_errors;

/* From here until hdf5_errors_end, HDF5 prints nothing and h->detail keeps the innermost
 * entry of the first failure (e.g. "Permission denied" from the file driver, or "data error
 * detected by Fletcher32 checksum"): the API-level entries only say which call failed, and
 * the later calls on the way out would clear it. */
void hdf5_errors_begin(hdf5_errors *h);
/* Restores the handler that was in place before hdf5_errors_begin. */
void hdf5_errors_end(const hdf5_errors *h);

/* Keeps HDF5 from closing itself at exit; call first thing in main, before any HDF5 call.
 * vcsph closes every file it opens, so the library's exit hook has nothing to flush; it only
 * acts after HDF5 failed to close a file whose metadata is damaged (a refused checkpoint),
 * and then prints "HDF5: infinite loop closing library" after our one-line message. */
void hdf5_errors_quiet_exit(void);

/* The kept description, or fallback when there is none. */
static inline const char *hdf5_errors_detail(const hdf5_errors *h, const char *fallback)
{
    return h->detail[0] ? h->detail : fallback;
}

#endif
