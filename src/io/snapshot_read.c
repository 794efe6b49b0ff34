/* snapshot_read: HDF5 reading of our own snapshot layout (docs/outputs.md). */
#include "io/snapshot_read.h"
#include "io/hdf5_attr.h"

#include <errno.h>
#include <hdf5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int snapshot_read_info(const char *path, snapshot_info *info, char *err, size_t err_len)
{
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    info->case_text = NULL;
    FILE *readable = fopen(path, "rb");
    if (!readable) {
        snprintf(err, err_len, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    fclose(readable);
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) {
        snprintf(err, err_len, "%s: not an HDF5 file (or a damaged one)", path);
        return -1;
    }
    int rc = -1;
    hid_t d = H5Dopen2(file, "position", H5P_DEFAULT);
    if (d >= 0) {
        hid_t space = H5Dget_space(d);
        hsize_t dims[2] = {0, 0};
        if (H5Sget_simple_extent_ndims(space) == 2) {
            H5Sget_simple_extent_dims(space, dims, NULL);
            info->n = (size_t)dims[0];
            rc = 0;
        }
        H5Sclose(space);
        H5Dclose(d);
    }
    if (rc == 0 && (hdf5_attr_read_scalar(file, "time", H5T_NATIVE_DOUBLE, &info->time) ||
                    hdf5_attr_read_scalar(file, "step", H5T_NATIVE_LONG, &info->step) ||
                    hdf5_attr_read_scalar(file, "dim", H5T_NATIVE_INT, &info->dim) ||
                    !(info->case_text = hdf5_attr_read_string(file, "case"))))
        rc = -1;
    H5Fclose(file);
    if (rc)
        snprintf(err, err_len, "%s: not a vcsph snapshot (position, time, step, dim, case)", path);
    return rc;
}

void snapshot_info_free(snapshot_info *info)
{
    free(info->case_text);
    info->case_text = NULL;
}

int snapshot_read_doubles(const char *path, const char *name, int ncomp, double *const *out,
                          size_t n, char *err, size_t err_len)
{
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) {
        snprintf(err, err_len, "%s: cannot open", path);
        return -1;
    }
    double *buf = malloc((n ? n : 1) * (size_t)ncomp * sizeof *buf);
    hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
    int rc = -1;
    if (buf && d >= 0) {
        /* the dataset must hold exactly n x ncomp values before it is read into buf */
        hid_t space = H5Dget_space(d);
        hssize_t points = H5Sget_simple_extent_npoints(space);
        H5Sclose(space);
        if (points == (hssize_t)(n * (size_t)ncomp) &&
            H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) >= 0)
            rc = 0;
    }
    if (rc == 0)
        for (size_t i = 0; i < n; i++)
            for (int c = 0; c < ncomp; c++) out[c][i] = buf[i * (size_t)ncomp + (size_t)c];
    else
        snprintf(err, err_len, "%s: cannot read dataset %s", path, name);
    if (d >= 0) H5Dclose(d);
    H5Fclose(file);
    free(buf);
    return rc;
}
