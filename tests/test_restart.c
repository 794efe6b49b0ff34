/* Checkpoints and `vcsph run --restart` (README.md, docs/architecture.md), with the real binary as
 * a user meets it. A short delta-plus-ALE sloshing run (2D, N = 10, adaptive eta control with its
 * history, EdBC toggled with eta = 0, probes, dissipation per period, snapshots and images) is
 * stopped and continued:
 * - SIGTERM once it has made progress: exit 4 with a checkpoint, then --restart;
 * - kill -9 at a few times (one of them twice, the restarted run killed again), then
 *   --restart from the last checkpoint written every output.checkpoint_every wall seconds;
 * and the outputs must be byte for byte those of the same run never stopped: timeseries.csv,
 * events.csv, dissipation.csv, probes.csv, snapshots.xmf, images, and every dataset of every
 * snapshot (their "case" attribute names the output folder, which differs).
 * A damaged checkpoint (a byte flipped in a dataset's data or in HDF5's metadata, cut to half
 * its size, empty, a foreign HDF5 or text file, another format version) and a --set of a key
 * a restart may not change are refused with exit 2, one message, and the output folder
 * untouched (names, sizes, modification times and contents of every file). */
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

#include "io/checkpoint.h"
#include "temp_dir.h"
#include "vcsph_child.h"

extern char **environ;

/* 1.2 s of sway at the first sloshing period's neighbourhood: the adaptive control leaves
 * its eta = 0 regime near t = 1.06 s (after 2 T_f of history), so a restart must carry its
 * history; U_max passes c0/10 (speed events); two periods end (dissipation.csv). Checkpoints
 * every 0.05 wall-clock seconds: several per run, some cut by kill -9. */
static const char case_text[] = "[case]\nname = slosh\nt_end = 1.2\n"
                                "[tank]\nlength = 0.4\nheight = 0.3\n"
                                "[liquid]\nheight = 0.1\n"
                                "[motion]\ntype = sway\namplitude = 0.03\nperiod = 0.5\n"
                                "[model]\nscheme = delta-plus-ale\neta_control = adaptive\n"
                                "eta_threshold = 0.001\nedbc = with-eta0\n"
                                "[numerics]\nresolution = 10\n"
                                "[probes]\ngauges = 0.05, 0.35\npressure = 0.2 0.02\n"
                                "[output]\ntimeseries_every = 0\nsnapshot_every = 0.1\n"
                                "image_every = 0.4\ncheckpoint_every = 0.05\n";

/* timeseries.csv bytes of about 0.2 s of the run (~100 rows): "it has made progress" */
enum { PROGRESS_BYTES = 30000 };
#define WAIT_LIMIT_S 120.0 /* polling gives up after this (a hung run) */

/* ---- the group's folder, the reference run ------------------------------------------------ */

static char group_dir[256];
static unsigned random_state;

static void path_in(const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", group_dir, name);
}

/* Starts vcsph with args (NULL-ended) in the group's folder, stdout and stderr into
 * <log>.out and <log>.err there. */
static pid_t spawn_vcsph(const char *const *args, const char *log)
{
    char out[300], err[300];
    snprintf(out, sizeof out, "%s.out", log);
    snprintf(err, sizeof err, "%s.err", log);
    return vcsph_child_spawn(group_dir, args, environ, out, err);
}

/* The exit status of vcsph with args, -1 when a signal ended it. */
static int run_vcsph(const char *const *args, const char *log)
{
    int status = vcsph_child_wait(spawn_vcsph(args, log));
    if (!WIFEXITED(status)) return -1;
    int rc = WEXITSTATUS(status);
    assert_true(rc != 126 && rc != 127); /* the child could not start vcsph */
    return rc;
}

static char *read_all(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *text = NULL;
    size_t n = 0;
    FILE *mem = open_memstream(&text, &n);
    char buf[65536];
    for (size_t got; (got = fread(buf, 1, sizeof buf, f)) > 0;) fwrite(buf, 1, got, mem);
    fclose(f);
    fclose(mem);
    if (len) *len = n;
    return text;
}

static char *read_in_group(const char *name)
{
    char path[600];
    path_in(name, path, sizeof path);
    char *text = read_all(path, NULL);
    return text ? text : strdup("");
}

static void write_in_group(const char *name, const void *data, size_t len)
{
    char path[600];
    path_in(name, path, sizeof path);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, len, f), len);
    assert_int_equal(fclose(f), 0);
}

static long long size_in_group(const char *name)
{
    char path[600];
    struct stat st;
    path_in(name, path, sizeof path);
    return stat(path, &st) == 0 ? (long long)st.st_size : -1;
}

static void sleep_ms(long ms)
{
    struct timespec ts = {ms / 1000, (ms % 1000) * 1000000L};
    while (nanosleep(&ts, &ts) && errno == EINTR) continue;
}

/* A delay in [0, max_ms), different from run to run (printed, to repeat a failure). */
static long random_ms(long max_ms)
{
    random_state = random_state * 1103515245u + 12345u;
    return (long)((random_state >> 8) % (unsigned)max_ms);
}

/* Polls until `name` in the group's folder holds at least `bytes` bytes; false when the
 * child ended first (or the wait limit passed). */
static bool wait_for_size(pid_t pid, const char *name, long long bytes)
{
    for (double waited = 0.0; waited < WAIT_LIMIT_S; waited += 0.005) {
        if (size_in_group(name) >= bytes) return true;
        int status;
        if (waitpid(pid, &status, WNOHANG) == pid) {
            fail_msg("vcsph ended (status %d) before %s reached %lld bytes", status, name, bytes);
            return false;
        }
        sleep_ms(5);
    }
    return false;
}

static int group_setup(void **state)
{
    (void)state;
    if (temp_dir_make(group_dir, sizeof group_dir, "vcsph-restart")) return -1;
    random_state = (unsigned)time(NULL) ^ (unsigned)getpid();
    printf("restart tests in %s, random seed %u\n", group_dir, random_state);
    char path[600];
    path_in("slosh.ini", path, sizeof path);
    FILE *f = fopen(path, "w");
    if (!f || fputs(case_text, f) == EOF || fclose(f)) return -1;
    /* the run never stopped, which every stopped and continued run must reproduce */
    return run_vcsph((const char *const[]){"run", "slosh.ini", "-o", "ref", "--quiet", NULL},
                     "ref") == 0
               ? 0
               : -1;
}

static int group_teardown(void **state)
{
    (void)state;
    return temp_dir_remove(group_dir);
}

/* ---- comparing two runs ------------------------------------------------------------------- */

static void assert_same_file(const char *a, const char *b)
{
    char pa[600], pb[600];
    path_in(a, pa, sizeof pa);
    path_in(b, pb, sizeof pb);
    size_t la = 0, lb = 0;
    char *ta = read_all(pa, &la), *tb = read_all(pb, &lb);
    if (!ta || !tb) fail_msg("cannot read %s or %s", pa, pb);
    size_t k = 0;
    while (k < la && k < lb && ta[k] == tb[k]) k++;
    if (la != lb || k < la)
        fail_msg("%s and %s differ from byte %zu (sizes %zu, %zu)", a, b, k, la, lb);
    free(ta);
    free(tb);
}

/* Every dataset of snapshot file a, read with its own file type (no conversion), has the
 * bytes of the same dataset of b, and b has no other. */
static void assert_same_datasets(const char *a, const char *b)
{
    hid_t fa = H5Fopen(a, H5F_ACC_RDONLY, H5P_DEFAULT),
          fb = H5Fopen(b, H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(fa >= 0 && fb >= 0);
    H5G_info_t ia, ib;
    assert_true(H5Gget_info(fa, &ia) >= 0 && H5Gget_info(fb, &ib) >= 0);
    assert_int_equal(ia.nlinks, ib.nlinks);
    for (hsize_t k = 0; k < ia.nlinks; k++) {
        char name[128];
        assert_true(H5Lget_name_by_idx(fa, ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof name,
                                       H5P_DEFAULT) > 0);
        hid_t da = H5Dopen2(fa, name, H5P_DEFAULT), db = H5Dopen2(fb, name, H5P_DEFAULT);
        if (da < 0 || db < 0) fail_msg("%s: dataset %s missing in %s", a, name, b);
        hid_t ta = H5Dget_type(da), tb = H5Dget_type(db);
        assert_true(H5Tequal(ta, tb) > 0);
        hid_t sa = H5Dget_space(da), sb = H5Dget_space(db);
        hssize_t na = H5Sget_simple_extent_npoints(sa), nb = H5Sget_simple_extent_npoints(sb);
        assert_true(na == nb && na >= 0);
        size_t bytes = (size_t)na * H5Tget_size(ta);
        unsigned char *ba = malloc(bytes + 1), *bb = malloc(bytes + 1);
        assert_true(ba && bb);
        assert_true(H5Dread(da, ta, H5S_ALL, H5S_ALL, H5P_DEFAULT, ba) >= 0);
        assert_true(H5Dread(db, tb, H5S_ALL, H5S_ALL, H5P_DEFAULT, bb) >= 0);
        if (memcmp(ba, bb, bytes)) fail_msg("dataset %s of %s differs from %s's", name, a, b);
        free(ba);
        free(bb);
        H5Sclose(sa);
        H5Sclose(sb);
        H5Tclose(ta);
        H5Tclose(tb);
        H5Dclose(da);
        H5Dclose(db);
    }
    H5Fclose(fa);
    H5Fclose(fb);
}

/* The names of the files of numbered outputs folder/prefix NNNNNN suffix, k = 0, 1, ... */
static int count_numbered(const char *dir, const char *pattern)
{
    int n = 0;
    for (;; n++) {
        char name[300], path[600];
        snprintf(name, sizeof name, pattern, n);
        snprintf(path, sizeof path, "%s/%s/%s", group_dir, dir, name);
        if (access(path, F_OK)) return n;
    }
}

/* The outputs of run `dir` are those of the reference run, byte for byte. */
static void assert_same_run(const char *dir)
{
    static const char *const files[] = {"timeseries.csv", "events.csv", "dissipation.csv",
                                        "probes.csv", "snapshots.xmf"};
    char a[600], b[600];
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        snprintf(a, sizeof a, "ref/%s", files[k]);
        snprintf(b, sizeof b, "%s/%s", dir, files[k]);
        assert_same_file(a, b);
    }
    int n = count_numbered("ref", "snapshots/%06d.h5");
    assert_true(n >= 12); /* every 0.1 s of 1.2 s, and t = 0 */
    assert_int_equal(count_numbered(dir, "snapshots/%06d.h5"), n);
    for (int k = 0; k < n; k++) {
        snprintf(a, sizeof a, "%s/ref/snapshots/%06d.h5", group_dir, k);
        snprintf(b, sizeof b, "%s/%s/snapshots/%06d.h5", group_dir, dir, k);
        assert_same_datasets(a, b);
    }
    int m = count_numbered("ref", "images/particles_%06d.png");
    assert_true(m >= 3);
    assert_int_equal(count_numbered(dir, "images/particles_%06d.png"), m);
    for (int k = 0; k < m; k++) {
        snprintf(a, sizeof a, "ref/images/particles_%06d.png", k);
        snprintf(b, sizeof b, "%s/images/particles_%06d.png", dir, k);
        assert_same_file(a, b);
    }
}

static void restart_and_compare(const char *dir, const char *log)
{
    char checkpoint[300];
    snprintf(checkpoint, sizeof checkpoint, "%s/checkpoint.h5", dir);
    int rc = run_vcsph((const char *const[]){"run", "--restart", checkpoint, "--quiet", NULL}, log);
    if (rc != 0) {
        char name[300];
        snprintf(name, sizeof name, "%s.err", log);
        char *err = read_in_group(name);
        fail_msg("restart of %s: exit %d: %s", dir, rc, err);
    }
    assert_same_run(dir);
}

/* ---- (a) SIGTERM -------------------------------------------------------------------------- */

static void test_sigterm_then_restart_is_exact(void **state)
{
    (void)state;
    pid_t pid = spawn_vcsph((const char *const[]){"run", "slosh.ini", "-o", "term", NULL}, "term");
    assert_true(wait_for_size(pid, "term/timeseries.csv", PROGRESS_BYTES));
    long delay = random_ms(300);
    printf("SIGTERM %ld ms after the run passed %d bytes of time series\n", delay, PROGRESS_BYTES);
    sleep_ms(delay);
    assert_int_equal(kill(pid, SIGTERM), 0);
    int status = vcsph_child_wait(pid);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 4); /* RUN_INTERRUPTED */
    char *out = read_in_group("term.out");
    if (!strstr(out, "stopped by SIGTERM") || !strstr(out, "--restart term/checkpoint.h5"))
        fail_msg("no clear message on stdout:\n%s", out);
    free(out);
    restart_and_compare("term", "term-restart");
    char *log = read_in_group("term/log.txt");
    assert_non_null(strstr(log, "stopped by SIGTERM"));
    assert_non_null(strstr(log, "restarted from the checkpoint"));
    free(log);
}

/* ---- (b) kill -9 -------------------------------------------------------------------------- */

static unsigned long long inode_in_group(const char *name)
{
    char path[600];
    struct stat st;
    path_in(name, path, sizeof path);
    return stat(path, &st) == 0 ? (unsigned long long)st.st_ino : 0;
}

/* Starts args, waits until it has written a checkpoint (a new file: each one is renamed into
 * place), then kills it with SIGKILL a random moment later (perhaps in the middle of writing
 * the next checkpoint, a snapshot or a row). */
static void run_and_kill(const char *const *args, const char *dir, const char *log)
{
    char checkpoint[300];
    snprintf(checkpoint, sizeof checkpoint, "%s/checkpoint.h5", dir);
    unsigned long long old = inode_in_group(checkpoint);
    pid_t pid = spawn_vcsph(args, log);
    bool written = false;
    for (double waited = 0.0; !written && waited < WAIT_LIMIT_S; waited += 0.005) {
        unsigned long long now = inode_in_group(checkpoint);
        written = now != 0 && now != old;
        int status;
        if (!written && waitpid(pid, &status, WNOHANG) == pid)
            fail_msg("%s: vcsph ended (status %d) before writing a checkpoint", log, status);
        if (!written) sleep_ms(5);
    }
    assert_true(written);
    long delay = random_ms(250);
    printf("%s: kill -9 %ld ms after a checkpoint was written\n", log, delay);
    sleep_ms(delay);
    assert_int_equal(kill(pid, SIGKILL), 0);
    int status = vcsph_child_wait(pid);
    assert_true(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
}

static void test_kill9_then_restart_is_exact(void **state)
{
    (void)state;
    for (int round = 0; round < 3; round++) {
        char dir[32], log[48], checkpoint[64];
        snprintf(dir, sizeof dir, "kill%d", round);
        snprintf(log, sizeof log, "kill%d", round);
        snprintf(checkpoint, sizeof checkpoint, "%s/checkpoint.h5", dir);
        run_and_kill((const char *const[]){"run", "slosh.ini", "-o", dir, "--quiet", NULL}, dir,
                     log);
        if (round == 1) { /* the restarted run killed too: its checkpoints continue the first's */
            snprintf(log, sizeof log, "kill%d-again", round);
            run_and_kill((const char *const[]){"run", "--restart", checkpoint, "--quiet", NULL},
                         dir, log);
        }
        snprintf(log, sizeof log, "kill%d-restart", round);
        restart_and_compare(dir, log);
    }
}

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
    const int64_t minus_one = -1, zero = 0, other_kind = 0;
    struct {
        const char *dataset;
        hid_t type;
        hsize_t index;
        const void *value;
        const char *expect;
    } forgeries[] = {
        {"x_1", H5T_NATIVE_DOUBLE, 3, &nan_value, "fail the health check"},
        {"eta_i64", H5T_NATIVE_INT64, 4, &minus_one, "negative count of the eta control"},
        {"id", H5T_NATIVE_INT64, 1, &zero, "particle ids"},
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

/* ---- (f) a breakdown keeps the last good checkpoint --------------------------------------- */

/* A heaving tank whose liquid passes density_bound = 2 % within a few steps (the heave's
 * start and its extra effective gravity), with a checkpoint after every step. */
static const char breakdown_case[] = "[case]\nname = heave\nt_end = 0.5\n"
                                     "[tank]\nlength = 0.2\nheight = 0.1\n"
                                     "[liquid]\nheight = 0.05\n"
                                     "[motion]\ntype = heave\namplitude = 0.02\nperiod = 0.2\n"
                                     "[numerics]\nresolution = 8\nsound_speed = 10\n"
                                     "density_bound = 0.02\n"
                                     "[output]\ntimeseries_every = 0\nsnapshot_every = 0.1\n"
                                     "checkpoint_every = 1e-9\n";

/* The first line of a run's stderr that holds "breakdown at", without its folder. */
static char *breakdown_line(const char *log)
{
    char *err = read_in_group(log);
    const char *at = strstr(err, "breakdown at");
    if (!at) fail_msg("%s: no breakdown:\n%s", log, err);
    char *line = strndup(at, strcspn(at, "\n"));
    free(err);
    return line;
}

static int64_t checkpoint_step(const char *name)
{
    char path[600], err[512];
    path_in(name, path, sizeof path);
    checkpoint_data cd;
    if (checkpoint_read(path, &cd, err, sizeof err)) fail_msg("%s", err);
    const checkpoint_array *a = checkpoint_find(&cd, "solver_i64", CHECKPOINT_I64, 4,
                                                "dim,n_fluid,step,n_edbc", err, sizeof err);
    if (!a) fail_msg("%s", err);
    int64_t step = ((const int64_t *)a->data)[2];
    checkpoint_data_free(&cd);
    return step;
}

/* docs/architecture.md and issue 8: a breakdown exits 3 and leaves the checkpoint of the step
 * before it, which continues into the same breakdown, and leaves it again. */
static void test_breakdown_keeps_the_last_good_checkpoint(void **state)
{
    (void)state;
    write_in_group("heave.ini", breakdown_case, strlen(breakdown_case));
    int rc = run_vcsph((const char *const[]){"run", "heave.ini", "-o", "broken", "--quiet", NULL},
                       "broken");
    assert_int_equal(rc, 3);
    char *first = breakdown_line("broken.err");
    const char *at_step = strstr(first, "step ");
    assert_non_null(at_step);
    long step = strtol(at_step + 5, NULL, 10);
    assert_true(step >= 3); /* good steps, each checkpointed, came before it */
    assert_int_equal(checkpoint_step("broken/checkpoint.h5"), step - 1);

    char path[600];
    path_in("broken/checkpoint.h5", path, sizeof path);
    size_t len;
    char *saved = read_all(path, &len);
    assert_non_null(saved);
    rc = run_vcsph(
        (const char *const[]){"run", "--restart", "broken/checkpoint.h5", "--quiet", NULL},
        "broken-restart");
    assert_int_equal(rc, 3);
    char *again = breakdown_line("broken-restart.err");
    assert_string_equal(first, again); /* the same time, step, particle and density */
    size_t len_after;
    char *after = read_all(path, &len_after);
    assert_non_null(after);
    assert_true(len_after == len && memcmp(saved, after, len) == 0);
    free(first);
    free(again);
    free(saved);
    free(after);
}

/* The size of timeseries.csv that a checkpoint recorded (its csv_sizes, app/restart.c). */
static long long recorded_series_bytes(const char *name)
{
    char path[600];
    path_in(name, path, sizeof path);
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, "csv_sizes", H5P_DEFAULT);
    assert_true(f >= 0 && d >= 0);
    long long sizes[4] = {0};
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

int main(void)
{
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sigterm_then_restart_is_exact),
        cmocka_unit_test(test_kill9_then_restart_is_exact),
        cmocka_unit_test(test_damaged_checkpoints_are_refused),
        cmocka_unit_test(test_restart_changes_only_end_and_outputs),
        cmocka_unit_test(test_forged_states_are_refused),
        cmocka_unit_test(test_breakdown_keeps_the_last_good_checkpoint),
    };
    return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
