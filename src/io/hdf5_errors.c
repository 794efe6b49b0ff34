/* hdf5_errors: a silent HDF5 error handler that keeps the first failure. */
#include "io/hdf5_errors.h"

#include <stdio.h>
#include <string.h>

/* The reason of a file driver's failure: its "error message = '...'" (the system's, e.g. "No
 * space left on device"), not the buffer's address, offsets and sizes around it; any other
 * description as it is. */
static void reason_of(const char *desc, char *detail)
{
    static const char marker[] = "error message = '";
    const char *at = strstr(desc, marker);
    if (!at) {
        snprintf(detail, HDF5_DETAIL_LEN, "%s", desc);
        return;
    }
    at += sizeof marker - 1;
    const char *end = strchr(at, '\'');
    snprintf(detail, HDF5_DETAIL_LEN, "%.*s", end ? (int)(end - at) : (int)strlen(at), at);
}

static herr_t innermost(unsigned n, const H5E_error2_t *e, void *detail)
{
    if (n == 0 && e->desc) reason_of(e->desc, detail);
    return 0;
}

static herr_t capture(hid_t stack, void *client)
{
    hdf5_errors *h = client;
    if (!h->detail[0]) H5Ewalk2(stack, H5E_WALK_UPWARD, innermost, h->detail);
    return 0;
}

void hdf5_errors_begin(hdf5_errors *h)
{
    h->detail[0] = '\0';
    H5Eget_auto2(H5E_DEFAULT, &h->saved_func, &h->saved_data);
    H5Eset_auto2(H5E_DEFAULT, capture, h);
}

void hdf5_errors_end(const hdf5_errors *h)
{
    H5Eset_auto2(H5E_DEFAULT, h->saved_func, h->saved_data);
}

void hdf5_errors_quiet_exit(void) { H5dont_atexit(); }
