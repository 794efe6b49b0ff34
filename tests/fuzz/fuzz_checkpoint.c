/* Fuzz target of the checkpoint reader (libFuzzer's entry point; tests/fuzz/replay.c calls the
 * same function on the committed corpus in the normal build, tools/fuzz runs libFuzzer on it).
 *
 * An input is the bytes of a checkpoint.h5. Each goes through what `vcsph run --restart` does
 * before it touches the output folder:
 * 1. as it is: checkpoint_read. This is what damage on a disk gives; nearly every change is
 *    refused by the header's hash (io/checkpoint.c) before HDF5 sees the file;
 * 2. resealed (checkpoint_seal: the header's length and hash made to fit the bytes, as a
 *    forger or another program would), so that the changes reach what lies behind the hash:
 *    HDF5's parser and checksums, the reader's checks of every dataset, and, when it reads,
 *    the case text parsed and the state loaded into a solver of that case and checked
 *    (simulation_check_checkpoint, app/restart.c).
 * 3. An input shorter than a checkpoint's header is also read as a list of edits of a seed
 *    checkpoint (see edit_seed): values written into its datasets through HDF5, which keeps
 *    the checksums right, then resealed and read as in 2. Changed bytes seldom pass HDF5's
 *    Fletcher32, so 2 rarely reaches the checks of the loaded state; 3 reaches them with
 *    every input.
 * Besides "no crash, hang or sanitizer report", it checks the reader's promises: a refusal
 * says why (a message in err), and what it accepts is whole (every array's bytes readable).
 *
 * HDF5 is Debian's build, without the fuzzer's instrumentation: libFuzzer is guided by the
 * coverage of vcsph's own code, and AddressSanitizer still checks HDF5's heap accesses
 * through its malloc. The input goes to a scratch file (HDF5 and the hash read a path). */
#define FUZZ_TARGET "fuzz_checkpoint"
#include "fuzz_target.h"
#include "scheme/case_numbers.h"

#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/simulation.h"
#include "boundary/motion.h"
#include "core/config.h"
#include "core/derived.h"
#include "io/checkpoint.h"
#include "io/hdf5_errors.h"

#include <hdf5.h>

#define ERR_LEN 2048
/* Cases of more particles are not loaded: the solver's arrays for millions of particles
 * would test the memory of the machine, not the reader. The seeds have a few dozen. */
#define MAX_PARTICLES 20000

static char scratch[4096];

static void remove_scratch(void) { unlink(scratch); }

/* The scratch file's path, made on the first call (the first of the process) and removed at
 * exit. */
static const char *scratch_path(void)
{
    if (scratch[0]) return scratch;
    hdf5_errors_quiet_exit(); /* before any HDF5 call: see hdf5_errors.h */
    const char *tmp = getenv("TMPDIR");
    snprintf(scratch, sizeof scratch, "%s/vcsph-fuzz-checkpoint-XXXXXX",
             tmp && tmp[0] ? tmp : "/tmp");
    int fd = mkstemp(scratch);
    if (fd < 0) broken("cannot make a scratch file", strerror(errno));
    close(fd);
    atexit(remove_scratch);
    return scratch;
}

static void write_scratch(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f))
        broken("cannot write the scratch file", strerror(errno));
}

/* Every byte of every array, read: a short allocation is AddressSanitizer's to report. */
static void check_arrays(const checkpoint_data *cd)
{
    unsigned sum = 0;
    for (int k = 0; k < cd->n_arrays; k++) {
        const checkpoint_array *a = &cd->arrays[k];
        if (!memchr(a->name, '\0', sizeof a->name)) broken("an array name without its NUL", NULL);
        if (a->n > 0 && !a->data) broken("an array of values without data", a->name);
        const unsigned char *bytes = a->data;
        for (size_t i = 0; i < a->n * checkpoint_type_size(a->type); i++) sum += bytes[i];
        if (a->columns) sum += (unsigned)strlen(a->columns);
    }
    volatile unsigned keep = sum; /* the reads are not optimised away */
    (void)keep;
}

/* The case text of a checkpoint that read, parsed; 0 when it is a case to load. */
static int checkpoint_config(const checkpoint_data *cd, config *cfg)
{
    char err[ERR_LEN];
    char *text = checkpoint_text(cd, "case", err, sizeof err);
    if (!text) return -1;
    int rc = config_load_string(cfg, text, "fuzz", NULL, 0, err, sizeof err);
    free(text);
    if (rc) return -1;
    /* motion_init would read the table file the case names (any file of this machine): the
       state is loaded into the case without tank motion instead */
    if (cfg->motion == MOTION_TABLE) cfg->motion = MOTION_NONE;
    motion mo;
    if (motion_init(&mo, cfg, err, sizeof err)) return -1;
    derived dv;
    case_numbers(cfg, &mo, &dv);
    motion_free(&mo);
    return derived_check(cfg, &dv, err, sizeof err) || dv.n_fluid > MAX_PARTICLES ? -1 : 0;
}

/* What `vcsph run --restart` does with the file at path before it touches the output folder
 * (load: also the state into a solver of its case). */
static void read_checkpoint(const char *path, int load)
{
    checkpoint_data cd;
    char err[ERR_LEN];
    err[0] = '\0';
    if (checkpoint_read(path, &cd, err, sizeof err)) {
        if (!err[0]) broken("checkpoint_read refused a file without a message", NULL);
        return;
    }
    check_arrays(&cd);
    static config cfg; /* static: a config holds ~6 kB of paths */
    if (load && checkpoint_config(&cd, &cfg) == 0) {
        err[0] = '\0';
        int rc = simulation_check_checkpoint(&cfg, &cd, err, sizeof err);
        if (rc != RUN_OK && (rc != RUN_BAD_INPUT || !err[0]))
            broken("loading the checkpoint's state failed without a message", err);
    }
    checkpoint_data_free(&cd);
}

/* ---- edits of a seed checkpoint ---------------------------------------------------------- */

/* The committed seeds (FUZZ_SEED_DIR: tests/fuzz/corpus/checkpoint), read once. */
typedef struct {
    uint8_t *bytes;
    size_t size;
} seed;

static const seed *seed_file(int k)
{
    static const char *const names[2] = {"seed-2d-delta-plus-ale.h5", "seed-3d-delta-ale.h5"};
    static seed seeds[2];
    seed *sd = &seeds[k];
    if (sd->bytes) return sd;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", FUZZ_SEED_DIR, names[k]);
    FILE *f = fopen(path, "rb");
    if (!f || fseek(f, 0, SEEK_END) || (sd->size = (size_t)ftell(f)) == 0 ||
        fseek(f, 0, SEEK_SET) || !(sd->bytes = malloc(sd->size)) ||
        fread(sd->bytes, 1, sd->size, f) != sd->size)
        broken("cannot read the seed checkpoint", path);
    fclose(f);
    return sd;
}

/* One edit: value bytes v written as element `index` (modulo its length) of dataset `k`
 * (modulo their number, in name order), in the dataset's own type (8 bytes of v as a float64
 * or int64, its first byte as a byte). */
static void edit_value(hid_t file, hsize_t n_links, unsigned k, hsize_t index, const uint8_t *v)
{
    char name[CHECKPOINT_NAME_MAX];
    if (H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, k % n_links, name, sizeof name,
                           H5P_DEFAULT) <= 0)
        return;
    hid_t d = H5Dopen2(file, name, H5P_DEFAULT), space = H5Dget_space(d), type = H5Dget_type(d);
    hssize_t n = H5Sget_simple_extent_npoints(space);
    if (n > 0) {
        hsize_t at = index % (hsize_t)n, one = 1;
        hid_t mem = H5Tget_class(type) == H5T_FLOAT ? H5T_NATIVE_DOUBLE
                    : H5Tget_size(type) == 8        ? H5T_NATIVE_INT64
                                                    : H5T_NATIVE_UINT8;
        hid_t mem_space = H5Screate_simple(1, &one, NULL);
        uint8_t value[8];
        memcpy(value, v, sizeof value);
        if (H5Sselect_elements(space, H5S_SELECT_SET, 1, &at) < 0 ||
            H5Dwrite(d, mem, mem_space, space, H5P_DEFAULT, value) < 0)
            broken("cannot edit the seed checkpoint", name);
        H5Sclose(mem_space);
    }
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(d);
}

/* The input as edits of a seed: its first byte picks the seed (bit 0: 2D or 3D), then each
 * EDIT_BYTES bytes are one edit: the dataset, the element (2 bytes, little-endian) and the
 * value (8 bytes). The file at path is the seed edited and resealed. */
enum { EDIT_BYTES = 11 };

static void edit_seed(const char *path, const uint8_t *data, size_t size)
{
    const seed *sd = seed_file(size > 0 ? data[0] & 1 : 0);
    write_scratch(path, sd->bytes, sd->size);
    hid_t file = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
    H5G_info_t info;
    if (file < 0 || H5Gget_info(file, &info) < 0 || info.nlinks == 0)
        broken("cannot open the seed checkpoint", path);
    for (size_t at = 1; at + EDIT_BYTES <= size; at += EDIT_BYTES)
        edit_value(file, info.nlinks, data[at], (hsize_t)data[at + 1] | (hsize_t)data[at + 2] << 8,
                   data + at + 3);
    if (H5Fclose(file) < 0 || checkpoint_seal(path))
        broken("cannot write the edited seed checkpoint", path);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = scratch_path();
    write_scratch(path, data, size);
    read_checkpoint(path, 0);
    if (size >= CHECKPOINT_HEADER_SIZE) { /* room for the header checkpoint_seal writes */
        if (checkpoint_seal(path)) broken("checkpoint_seal failed", strerror(errno));
    } else {
        edit_seed(path, data, size);
    }
    read_checkpoint(path, 1);
    return 0;
}
