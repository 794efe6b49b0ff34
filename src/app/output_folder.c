/* output_folder: the lock on a run's folder and the list of the files a run writes
 * (output_folder.h). */
#include "app/output_folder.h"
#include "core/config.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

/* The files of a run at the top of its folder (run_outputs.c, restart.c, motion table). */
static const char *const run_files[] = {
    "timeseries.csv",    "events.csv",    "dissipation.csv",  "probes.csv",
    "loads.csv",         "log.txt",       "case.ini",         "checkpoint.h5",
    "checkpoint.h5.tmp", "snapshots.xmf", "motion_table.csv", "motion_table.csv.tmp",
};
enum { N_RUN_FILES = sizeof run_files / sizeof run_files[0] };

/* The numbered files of a run, in a subfolder: folder/prefix NNNNNN suffix; a rewind keeps
 * those of `kind` below its count (temporary files: none). */
enum { SNAPSHOT_FILES, IMAGE_FILES, TEMPORARY_FILES };
static const struct {
    const char *folder, *prefix, *suffix;
    int kind;
} numbered_files[] = {
    {"snapshots", "", ".h5", SNAPSHOT_FILES},
    {"snapshots", "", ".h5.tmp", TEMPORARY_FILES},
    {"images", "particles_", ".png", IMAGE_FILES},
    {"images", "particles_", ".png.tmp", TEMPORARY_FILES},
};
enum { N_NUMBERED = sizeof numbered_files / sizeof numbered_files[0] };

int output_folder_make(const char *dir)
{
    char buf[CONFIG_PATH_MAX + 32];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *q = buf + 1; *q; q++) {
        if (*q != '/') continue;
        *q = '\0';
        if (mkdir(buf, 0777) && errno != EEXIST) return -1;
        *q = '/';
    }
    return mkdir(buf, 0777) && errno != EEXIST ? -1 : 0;
}

/* The process id written in the lock file, or 0 if it cannot be read (yet). */
static long lock_holder(int fd)
{
    char text[32] = {0};
    ssize_t n = pread(fd, text, sizeof text - 1, 0);
    return n > 0 ? strtol(text, NULL, 10) : 0;
}

int output_folder_lock(const char *dir, bool *busy, char *err, size_t err_len)
{
    *busy = false;
    if (output_folder_make(dir)) {
        snprintf(err, err_len, "cannot create output directory %s: %s", dir, strerror(errno));
        return -1;
    }
    char path[CONFIG_PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/%s", dir, OUTPUT_FOLDER_LOCK);
    int fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0) {
        snprintf(err, err_len, "cannot create the lock file %s: %s", path, strerror(errno));
        return -1;
    }
    /* flock, not a lock file's mere existence: the kernel drops it when the holder dies */
    if (flock(fd, LOCK_EX | LOCK_NB)) {
        int why = errno;
        *busy = why == EWOULDBLOCK;
        if (*busy) {
            /* the holder writes its id just after it takes the lock: it may not be there yet */
            long holder = lock_holder(fd);
            char who[48] = "";
            if (holder > 0) snprintf(who, sizeof who, " (process %ld)", holder);
            snprintf(err, err_len,
                     "%s is in use by another vcsph run%s; wait for it to end or choose another "
                     "folder with -o",
                     dir, who);
        } else {
            snprintf(err, err_len, "cannot lock %s: %s", path, strerror(why));
        }
        close(fd);
        return -1;
    }
    char pid[32];
    int len = snprintf(pid, sizeof pid, "%ld\n", (long)getpid());
    if (ftruncate(fd, 0) || pwrite(fd, pid, (size_t)len, 0) != len) {
        snprintf(err, err_len, "cannot write the lock file %s: %s", path, strerror(errno));
        close(fd);
        return -1;
    }
    return fd;
}

void output_folder_release(int fd)
{
    if (fd >= 0) close(fd); /* closing the last descriptor drops the flock */
}

/* The number in `name` = prefix NNNNNN suffix (six digits), or -1 for any other name. */
static long numbered(const char *name, const char *prefix, const char *suffix)
{
    size_t lp = strlen(prefix);
    if (strncmp(name, prefix, lp)) return -1;
    long k = 0;
    for (int i = 0; i < 6; i++) {
        char c = name[lp + (size_t)i];
        if (c < '0' || c > '9') return -1;
        k = 10 * k + (c - '0');
    }
    return strcmp(name + lp + 6, suffix) == 0 ? k : -1;
}

/* Calls visit(path, data) for each file dir/prefix NNNNNN suffix with NNNNNN >= first; stops
 * when visit returns nonzero and returns that. */
static int each_numbered(const char *dir, const char *prefix, const char *suffix, long first,
                         int (*visit)(const char *path, void *data), void *data)
{
    DIR *d = opendir(dir);
    if (!d) return 0;
    char path[CONFIG_PATH_MAX + 300];
    int status = 0;
    for (struct dirent *e; !status && (e = readdir(d));) {
        if (numbered(e->d_name, prefix, suffix) < first) continue;
        if (snprintf(path, sizeof path, "%s/%s", dir, e->d_name) >= (int)sizeof path) continue;
        status = visit(path, data);
    }
    closedir(d);
    return status;
}

static int remove_quietly(const char *path, void *data)
{
    (void)data;
    remove(path);
    return 0;
}

void output_folder_rewind(const char *dir, long n_snapshots, long n_images)
{
    const long kept[] = {
        [SNAPSHOT_FILES] = n_snapshots, [IMAGE_FILES] = n_images, [TEMPORARY_FILES] = 0};
    char path[CONFIG_PATH_MAX + 64];
    for (int k = 0; k < N_NUMBERED; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, numbered_files[k].folder);
        each_numbered(path, numbered_files[k].prefix, numbered_files[k].suffix,
                      kept[numbered_files[k].kind], remove_quietly, NULL);
    }
    snprintf(path, sizeof path, "%s/checkpoint.h5.tmp", dir);
    remove(path);
}

typedef struct {
    char *text;
    size_t len;
} message;

static int note_found(const char *path, void *data)
{
    message *m = data;
    snprintf(m->text, m->len, "%s", path);
    return 1;
}

static int remove_or_note(const char *path, void *data)
{
    if (remove(path) == 0 || errno == ENOENT) return 0;
    message *m = data;
    snprintf(m->text, m->len, "cannot remove %s: %s", path, strerror(errno));
    return 1;
}

/* Visits every file of a run in dir (run_files, then the numbered ones) until visit returns
 * nonzero. A top-level file is visited only if it exists. */
static int each_run_file(const char *dir, int (*visit)(const char *path, void *data), void *data)
{
    char path[CONFIG_PATH_MAX + 64];
    for (int k = 0; k < N_RUN_FILES; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, run_files[k]);
        struct stat st;
        if (lstat(path, &st) == 0 && visit(path, data)) return 1;
    }
    for (int k = 0; k < N_NUMBERED; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, numbered_files[k].folder);
        if (each_numbered(path, numbered_files[k].prefix, numbered_files[k].suffix, 0, visit, data))
            return 1;
    }
    return 0;
}

bool output_folder_holds_run(const char *dir, char *found, size_t found_len)
{
    message m = {found, found_len};
    return each_run_file(dir, note_found, &m) != 0;
}

int output_folder_clear(const char *dir, char *err, size_t err_len)
{
    message m = {err, err_len};
    return each_run_file(dir, remove_or_note, &m) ? -1 : 0;
}
