/* hdf5_attr: scalar and string attributes. */
#include "io/hdf5_attr.h"

#include <stdlib.h>
#include <string.h>

int hdf5_attr_write_scalar(hid_t loc, const char *name, hid_t file_type, hid_t mem_type,
                           const void *value)
{
    hid_t space = H5Screate(H5S_SCALAR);
    if (space < 0) return -1;
    hid_t attr = H5Acreate2(loc, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT);
    int rc = -1;
    if (attr >= 0) {
        rc = H5Awrite(attr, mem_type, value) < 0 ? -1 : 0;
        if (H5Aclose(attr) < 0) rc = -1;
    }
    H5Sclose(space);
    return rc;
}

int hdf5_attr_write_string(hid_t loc, const char *name, const char *text)
{
    if (!text) text = "";
    hid_t type = H5Tcopy(H5T_C_S1);
    if (type < 0) return -1;
    int rc = -1;
    if (H5Tset_size(type, strlen(text) + 1) >= 0 && H5Tset_strpad(type, H5T_STR_NULLTERM) >= 0 &&
        H5Tset_cset(type, H5T_CSET_ASCII) >= 0)
        rc = hdf5_attr_write_scalar(loc, name, type, type, text);
    H5Tclose(type);
    return rc;
}

int hdf5_attr_read_scalar(hid_t loc, const char *name, hid_t mem_type, void *out)
{
    if (H5Aexists(loc, name) <= 0) return -1;
    hid_t attr = H5Aopen(loc, name, H5P_DEFAULT);
    if (attr < 0) return -1;
    int rc = H5Aread(attr, mem_type, out) < 0 ? -1 : 0;
    H5Aclose(attr);
    return rc;
}

char *hdf5_attr_read_string(hid_t loc, const char *name)
{
    if (H5Aexists(loc, name) <= 0) return NULL;
    hid_t attr = H5Aopen(loc, name, H5P_DEFAULT);
    if (attr < 0) return NULL;
    hid_t type = H5Aget_type(attr);
    char *text = NULL;
    if (type >= 0 && H5Tget_class(type) == H5T_STRING && !H5Tis_variable_str(type)) {
        text = calloc(H5Tget_size(type) + 1, 1);
        if (text && H5Aread(attr, type, text) < 0) {
            free(text);
            text = NULL;
        }
    }
    if (type >= 0) H5Tclose(type);
    H5Aclose(attr);
    return text;
}
