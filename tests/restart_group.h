/* restart_group: the sloshing case, the group folder with its reference run (the run never
 * stopped), the child-process helpers and the comparisons of the checkpoint and restart tests
 * (test_restart.c, test_restart_refused.c). Include after <cmocka.h>. */
#ifndef VCSPH_TEST_RESTART_GROUP_H
#define VCSPH_TEST_RESTART_GROUP_H

#include "io/checkpoint.h"
#include "temp_dir.h"
#include "vcsph_child.h"

#include <errno.h>
#include <fcntl.h>
#include <hdf5.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

/* 1.2 s of sway with roll about the tank's centre (a rotating frame: the Coriolis, Euler and
 * centrifugal terms and the turning gravity must all restart exactly) at the first sloshing
 * period's neighbourhood: the adaptive control leaves its eta = 0 regime after 2 T_f of
 * history, so a restart must carry its history; probes.csv has rows of its own interval and
 * a filtered sensor, whose filter state a restart must carry; U_max passes c0/10 (speed events);
 * two periods end (dissipation.csv). Checkpoints every 0.05 wall-clock seconds: several per run,
 * some cut by kill -9. */
static const char case_text[] =
    "[case]\nname = slosh\nt_end = 1.2\n"
    "[tank]\nlength = 0.4\nheight = 0.3\n"
    "[liquid]\nheight = 0.1\n"
    "[motion]\ntype = sway+roll\namplitude = 0.03\nangle = 0.05\n"
    "period = 0.5\ncenter = 0.2 0.15\n"
    "[model]\nscheme = delta-plus-ale\neta_control = adaptive\n"
    "eta_threshold = 0.001\nedbc = with-eta0\n"
    "[numerics]\nresolution = 10\n"
    "[probes]\ngauges = 0.05, 0.35\npressure = 0.2 0.02; 0 0.05 d=0.01\n"
    "every = 0.005\nfilter = butterworth\ncutoff = 40\n"
    "[output]\ntimeseries_every = 0\nsnapshot_every = 0.1\n"
    "image_every = 0.4\ncheckpoint_every = 0.05\n";

/* timeseries.csv bytes of about 0.2 s of the run (~100 rows): "it has made progress" */
enum { PROGRESS_BYTES = 30000 };
#define WAIT_LIMIT_S 120.0 /* polling gives up after this (a hung run) */

/* ---- the group's folder, the reference run ------------------------------------------------ */

static char group_dir[256];
static unsigned random_state;

static inline void path_in(const char *name, char *buf, size_t size)
{
    int n = snprintf(buf, size, "%s/%s", group_dir, name);
    if (n < 0 || (size_t)n >= size) fail_msg("path %s/%s too long", group_dir, name);
}

/* Starts vcsph with args (NULL-ended) in the group's folder, stdout and stderr into
 * <log>.out and <log>.err there. */
static inline pid_t spawn_vcsph(const char *const *args, const char *log)
{
    char out[300], err[300];
    snprintf(out, sizeof out, "%s.out", log);
    snprintf(err, sizeof err, "%s.err", log);
    return vcsph_child_spawn(group_dir, args, environ, out, err);
}

/* The exit status of vcsph with args, -1 when a signal ended it. */
static inline int run_vcsph(const char *const *args, const char *log)
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

static inline void write_in_group(const char *name, const void *data, size_t len)
{
    char path[600];
    path_in(name, path, sizeof path);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, len, f), len);
    assert_int_equal(fclose(f), 0);
}

static inline long long size_in_group(const char *name)
{
    char path[600];
    struct stat st;
    path_in(name, path, sizeof path);
    return stat(path, &st) == 0 ? (long long)st.st_size : -1;
}

static inline void sleep_ms(long ms)
{
    struct timespec ts = {ms / 1000, (ms % 1000) * 1000000L};
    while (nanosleep(&ts, &ts) && errno == EINTR) continue;
}

/* A delay in [0, max_ms), different from run to run (printed, to repeat a failure). */
static inline long random_ms(long max_ms)
{
    random_state = random_state * 1103515245u + 12345u;
    return (long)((random_state >> 8) % (unsigned)max_ms);
}

/* Polls until `name` in the group's folder holds at least `bytes` bytes; false when the
 * child ended first (or the wait limit passed). */
static inline bool wait_for_size(pid_t pid, const char *name, long long bytes)
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

static inline int group_setup(void **state)
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

static inline int group_teardown(void **state)
{
    (void)state;
    return temp_dir_remove(group_dir);
}

/* ---- comparing two runs ------------------------------------------------------------------- */

static inline void assert_same_file(const char *a, const char *b)
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
static inline void assert_same_datasets(const char *a, const char *b)
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
static inline int count_numbered(const char *dir, const char *pattern)
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
static inline void assert_same_run(const char *dir)
{
    static const char *const files[] = {"timeseries.csv", "events.csv", "dissipation.csv",
                                        "probes.csv",     "loads.csv",  "snapshots.xmf"};
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

static inline void restart_and_compare(const char *dir, const char *log)
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
static inline void run_and_kill(const char *const *args, const char *dir, const char *log)
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

#endif
