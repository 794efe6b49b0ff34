/* Checkpoints a restart must refuse (README.md, docs/architecture.md), with the real binary: a
 * damaged checkpoint (a byte flipped in a dataset's data or in HDF5's metadata, cut to half its
 * size, empty, a foreign HDF5 or text file, another format version), a forged state, and a
 * --set of a key a restart may not change are refused with exit 2, one message, and the output
 * folder untouched (names, sizes, modification times and contents of every file); the same
 * checkpoint undamaged restarts exactly (the run and its helpers: restart_group.h). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <hdf5.h>
#include <math.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "restart_group.h"

/* ---- (c), (d) refusals -------------------------------------------------------------------- */

static uint64_t hash_bytes(const char *data, size_t n)
{
    uint64_t h = 0xcbf29ce484222325ULL;
    for (size_t i = 0; i < n; i++) h = (h ^ (unsigned char)data[i]) * 0x100000001b3ULL;
    return h;
}

static FILE *listing;

static int list_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)ftw;
    uint64_t h = 0;
    if (flag == FTW_F) {
        size_t n;
        char *data = read_all(path, &n);
        h = data ? hash_bytes(data, n) : 0;
        free(data);
    }
    fprintf(listing, "%s %lld %lld.%09ld %016llx\n", path, (long long)st->st_size,
            (long long)st->st_mtim.tv_sec, st->st_mtim.tv_nsec, (unsigned long long)h);
    return 0;
}

/* Every entry under dir: path, size, modification time and a hash of the contents. */
static char *folder_listing(const char *dir)
{
    char path[600], *text = NULL;
    size_t len;
    path_in(dir, path, sizeof path);
    listing = open_memstream(&text, &len);
    assert_int_equal(nftw(path, list_entry, 16, FTW_PHYS), 0);
    fclose(listing);
    return text;
}

/* vcsph run --restart with extra args exits 2 with one line naming `expect`, and the output
 * folder is as it was. */
static void assert_refused(const char *dir, const char *const *args, const char *expect)
{
    char *before = folder_listing(dir);
    const char *argv[16] = {"run"};
    int n = 1;
    for (; args[n - 1]; n++) argv[n] = args[n - 1];
    argv[n++] = "--quiet";
    argv[n] = NULL;
    int rc = run_vcsph(argv, "refused");
    char *err = read_in_group("refused.err"), *out = read_in_group("refused.out");
    if (rc != 2 || !strstr(err, expect) || count_lines(err) != 1)
        fail_msg("expected exit 2 and one line with \"%s\", got %d:\n%s", expect, rc, err);
    assert_string_equal(out, "");
    char *after = folder_listing(dir);
    if (strcmp(before, after))
        fail_msg("the output folder changed:\n%s\nbecame\n%s", before, after);
    free(before);
    free(after);
    free(err);
    free(out);
}

/* The file offset of the values of dataset `name` (one chunk of float64) of the checkpoint
 * whose bytes are `file`: found by its first value, at HDF5's chunk address, which counts
 * from the superblock, after our 512-byte user block. */
static long long values_offset(const char *path, const char *file, size_t len, const char *name)
{
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    assert_true(f >= 0 && d >= 0);
    hsize_t offset[1], size;
    unsigned mask;
    haddr_t addr;
    hid_t space = H5Dget_space(d);
    assert_true(H5Dget_chunk_info(d, space, 0, offset, &mask, &addr, &size) >= 0);
    hssize_t n = H5Sget_simple_extent_npoints(space);
    double *values = malloc((size_t)n * sizeof *values);
    assert_true(H5Dread(d, H5T_IEEE_F64LE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) >= 0);
    H5Sclose(space);
    H5Dclose(d);
    H5Fclose(f);
    long long at = -1;
    for (long long base = 0; base <= 512 && at < 0; base += 512)
        if ((size_t)(base + (long long)addr) + 8 <= len &&
            !memcmp(file + base + (long long)addr, values, 8))
            at = base + (long long)addr;
    free(values);
    if (at < 0)
        fail_msg("the values of %s are not at address %llu", name, (unsigned long long)addr);
    assert_true((size_t)at + (size_t)size <= len);
    return at + (long long)(size / 2); /* the middle of the values */
}

static void write_flipped(const char *good, size_t len, long long at, bool resealed,
                          const char *dest)
{
    char *bad = malloc(len);
    assert_non_null(bad);
    memcpy(bad, good, len);
    bad[at] ^= 0x01;
    write_in_group(dest, bad, len);
    free(bad);
    /* the header's hash made to match the contents again, as a forger would */
    char path[600];
    path_in(dest, path, sizeof path);
    if (resealed) assert_int_equal(checkpoint_seal(path), 0);
}

/* An output folder as a kill -9 leaves it: rows, snapshots and images after the checkpoint,
 * which a wrong restart would rewind. */
static void make_killed_run(const char *dir)
{
    run_and_kill((const char *const[]){"run", "slosh.ini", "-o", dir, "--quiet", NULL}, dir, dir);
}

/* make_killed_run, and the bytes of the checkpoint it left (free() them). */
static char *killed_run_checkpoint(const char *dir, size_t *len)
{
    make_killed_run(dir);
    char path[600];
    snprintf(path, sizeof path, "%s/%s/checkpoint.h5", group_dir, dir);
    char *bytes = read_all(path, len);
    assert_non_null(bytes);
    return bytes;
}

static void test_damaged_checkpoints_are_refused(void **state)
{
    (void)state;
    size_t len;
    char *good = killed_run_checkpoint("damaged", &len);
    char cp_path[600];
    path_in("damaged/checkpoint.h5", cp_path, sizeof cp_path);
    write_in_group("good.h5", good, len);
    const char *const args[] = {"--restart", "damaged/checkpoint.h5", NULL};

    /* a byte in the middle of the particles' x positions: the header's hash refuses it, and
       with the hash forged to match, HDF5's Fletcher32 checksum of the dataset */
    long long x_at = values_offset(cp_path, good, len, "x_0");
    write_flipped(good, len, x_at, false, "damaged/checkpoint.h5");
    assert_refused("damaged", args, "damaged");
    write_flipped(good, len, x_at, true, "damaged/checkpoint.h5");
    assert_refused("damaged", args,
                   "dataset 'x_0' cannot be read (data error detected by Fletcher32");
    /* a byte of HDF5's metadata (the superblock after the header), and the last byte */
    write_flipped(good, len, 512 + 20, false, "damaged/checkpoint.h5");
    assert_refused("damaged", args, "damaged");
    /* the same with the hash forged: HDF5's metadata checksum, and still one line (HDF5
       cannot close such a file, and its exit hook would complain: hdf5_errors.h) */
    write_flipped(good, len, 512 + 20, true, "damaged/checkpoint.h5");
    assert_refused("damaged", args, "incorrect metadata checksum");
    write_flipped(good, len, (long long)len - 1, false, "damaged/checkpoint.h5");
    assert_refused("damaged", args, "damaged");
    write_in_group("damaged/checkpoint.h5", good, len / 2);
    assert_refused("damaged", args, "truncated");
    write_in_group("damaged/checkpoint.h5", good, 0);
    assert_refused("damaged", args, "empty");
    /* foreign files: an HDF5 file of ours that is no checkpoint, a text */
    size_t snap_len;
    char snap[600];
    path_in("ref/snapshots/000001.h5", snap, sizeof snap);
    char *snapshot = read_all(snap, &snap_len);
    assert_non_null(snapshot);
    write_in_group("damaged/checkpoint.h5", snapshot, snap_len);
    assert_refused("damaged", args, "not a vcsph checkpoint");
    free(snapshot);
    write_in_group("damaged/checkpoint.h5", case_text, strlen(case_text));
    assert_refused("damaged", args, "not a vcsph checkpoint");
    /* another version of the format, as a later vcsph would write it (its header is text) */
    char *other = malloc(len);
    memcpy(other, good, len);
    char version_line[32];
    snprintf(version_line, sizeof version_line, "version %d\n", CHECKPOINT_VERSION);
    char *v = strstr(other, version_line); /* the header is text up to there */
    assert_true(v && v - other < 512);
    v[8] = '7';
    write_in_group("damaged/checkpoint.h5", other, len);
    assert_refused("damaged", args, "version 7");
    free(other);

    /* the folder was restartable all along: the good checkpoint continues it exactly */
    write_in_group("damaged/checkpoint.h5", good, len);
    restart_and_compare("damaged", "damaged-restart");
    free(good);
}

/* The size of timeseries.csv that a checkpoint recorded (its csv_sizes, app/restart.c). */
static long long recorded_series_bytes(const char *name)
{
    char path[600];
    path_in(name, path, sizeof path);
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, "csv_sizes", H5P_DEFAULT);
    assert_true(f >= 0 && d >= 0);
    hid_t space = H5Dget_space(d);
    hssize_t n = H5Sget_simple_extent_npoints(space);
    H5Sclose(space);
    long long sizes[8] = {0}; /* one per CSV file of a run (RUN_N_CSV) */
    assert_true(n >= 1 && n <= 8);
    assert_true(H5Dread(d, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, sizes) >= 0);
    H5Dclose(d);
    H5Fclose(f);
    return sizes[0];
}

static void test_restart_changes_only_end_and_outputs(void **state)
{
    (void)state;
    make_killed_run("settings");
    static const char *const refused[] = {"model.scheme=delta", "numerics.resolution=12",
                                          "fluid.viscosity=1e-3", "case.name=other",
                                          "output.dir=elsewhere"};
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; k++) {
        const char *args[] = {"--restart", "settings/checkpoint.h5", "--set", refused[k], NULL};
        char key[64];
        snprintf(key, sizeof key, "%.*s", (int)strcspn(refused[k], "="), refused[k]);
        assert_refused("settings", args, key);
    }
    assert_refused("settings",
                   (const char *const[]){"--restart", "settings/checkpoint.h5", "-o", "x", NULL},
                   "-o");
    assert_refused("settings",
                   (const char *const[]){"slosh.ini", "--restart", "settings/checkpoint.h5", NULL},
                   "case file");

    /* what may change: a later end and the output settings. The rows up to the checkpoint
       stay those of the reference run, and the run ends at the new t_end. */
    long long kept = recorded_series_bytes("settings/checkpoint.h5");
    int rc = run_vcsph((const char *const[]){"run", "--restart", "settings/checkpoint.h5", "--set",
                                             "case.t_end=1.25", "--set",
                                             "output.checkpoint_every=0", "--quiet", NULL},
                       "settings-restart");
    assert_int_equal(rc, 0);
    char *ref = read_in_group("ref/timeseries.csv"),
         *got = read_in_group("settings/timeseries.csv");
    assert_true(kept > 0 && strncmp(ref, got, (size_t)kept) == 0);
    char *end = strrchr(got, '\n');
    assert_non_null(end);
    *end = '\0';
    const char *last_row = strrchr(got, '\n') + 1;
    if (strncmp(last_row, "1.25,", 5)) fail_msg("the run did not end at 1.25 s: %s", last_row);
    free(ref);
    free(got);
}

/* ---- (e) forged states ------------------------------------------------------------------- */

/* Value k of dataset `name` of the checkpoint `name_in_group` set to v (read and written as
 * type `mem`, HDF5 recomputing the chunk's Fletcher32), and the header resealed: a file that
 * passes every checksum, as another program could write it. */
static void forge(const char *file, const char *name, hid_t mem, hsize_t k, const void *v)
{
    char path[600];
    path_in(file, path, sizeof path);
    hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    assert_true(f >= 0 && d >= 0);
    hid_t space = H5Dget_space(d), one = H5Screate_simple(1, (hsize_t[]){1}, NULL);
    assert_true(H5Sselect_elements(space, H5S_SELECT_SET, 1, &k) >= 0);
    assert_true(H5Dwrite(d, mem, one, space, H5P_DEFAULT, v) >= 0);
    H5Sclose(one);
    H5Sclose(space);
    H5Dclose(d);
    assert_true(H5Fclose(f) >= 0);
    assert_int_equal(checkpoint_seal(path), 0);
}

/* Value k of the int64 dataset `name` of the checkpoint `file`. */
static int64_t read_int64(const char *file, const char *name, hsize_t k)
{
    char path[600];
    path_in(file, path, sizeof path);
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    assert_true(f >= 0 && d >= 0);
    hid_t space = H5Dget_space(d), one = H5Screate_simple(1, (hsize_t[]){1}, NULL);
    assert_true(H5Sselect_elements(space, H5S_SELECT_SET, 1, &k) >= 0);
    int64_t v;
    assert_true(H5Dread(d, H5T_NATIVE_INT64, one, space, H5P_DEFAULT, &v) >= 0);
    H5Sclose(one);
    H5Sclose(space);
    H5Dclose(d);
    H5Fclose(f);
    return v;
}

/* A checkpoint with a valid hash and checksums whose state no run writes (a particle at NaN,
 * a negative sample count of the eta control, which would index its history, a duplicated
 * particle id, another eta control than the case's) is refused like a damaged one. */
static void test_forged_states_are_refused(void **state)
{
    (void)state;
    size_t len;
    char *good = killed_run_checkpoint("forged", &len);
    const char *const args[] = {"--restart", "forged/checkpoint.h5", NULL};
    const double nan_value = NAN;
    const int64_t minus_one = -1, other_kind = 0;
    /* the second particle given the first one's id: a duplicate whatever order the cell sort
       left them in (a fixed id such as 0 may already be the second one's) */
    const int64_t first_id = read_int64("forged/checkpoint.h5", "id", 0);
    struct {
        const char *dataset;
        hid_t type;
        hsize_t index;
        const void *value;
        const char *expect;
    } forgeries[] = {
        {"x_1", H5T_NATIVE_DOUBLE, 3, &nan_value, "fail the health check"},
        {"eta_i64", H5T_NATIVE_INT64, 4, &minus_one, "negative count of the eta control"},
        {"id", H5T_NATIVE_INT64, 1, &first_id, "particle ids"},
        {"eta_i64", H5T_NATIVE_INT64, 1, &other_kind, "another eta control"},
    };
    for (size_t k = 0; k < sizeof forgeries / sizeof forgeries[0]; k++) {
        write_in_group("forged/checkpoint.h5", good, len);
        forge("forged/checkpoint.h5", forgeries[k].dataset, forgeries[k].type, forgeries[k].index,
              forgeries[k].value);
        assert_refused("forged", args, forgeries[k].expect);
    }
    write_in_group("forged/checkpoint.h5", good, len);
    restart_and_compare("forged", "forged-restart");
    free(good);
}

int main(void)
{
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_damaged_checkpoints_are_refused),
        cmocka_unit_test(test_restart_changes_only_end_and_outputs),
        cmocka_unit_test(test_forged_states_are_refused),
    };
    return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
