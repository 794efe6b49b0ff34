/* Replays fuzz inputs through LLVMFuzzerTestOneInput without libFuzzer, so that the normal
 * build (gcc, no fuzzer runtime) checks the committed corpus on every `make test`, and a crash
 * file from tools/fuzz can be rerun under gdb or the sanitizer build.
 *
 *   fuzz_replay_config DIR|FILE...
 *
 * Runs every regular file of each DIR but dot files (in name order, so that a failure is
 * reproducible) and each FILE; prints how many ran. Exit status 1 when nothing ran (a corpus that
 * went missing must not pass); a broken property aborts in the fuzz target itself. */
#include <dirent.h>
#include <errno.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "fuzz_replay: %s: %s\n", path, strerror(errno));
        return -1;
    }
    size_t cap = 4096, len = 0;
    uint8_t *buf = malloc(cap);
    for (size_t got = 1; buf && got > 0;) {
        if (len == cap) {
            uint8_t *more = realloc(buf, cap *= 2);
            if (!more) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = more;
        }
        got = fread(buf + len, 1, cap - len, f);
        len += got;
    }
    bool failed = !buf || ferror(f);
    fclose(f);
    if (failed) {
        fprintf(stderr, "fuzz_replay: %s: cannot read\n", path);
        free(buf);
        return -1;
    }
    LLVMFuzzerTestOneInput(buf, len);
    free(buf);
    return 0;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Runs the regular files of dir; returns how many, or -1. */
static long run_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "fuzz_replay: %s: %s\n", dir, strerror(errno));
        return -1;
    }
    char **paths = NULL;
    size_t n = 0, cap = 0;
    long status = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.') continue;
        if (n == cap) {
            char **more = realloc(paths, (cap ? 2 * cap : 256) * sizeof *paths);
            if (!more) {
                status = -1;
                break;
            }
            paths = more;
            cap = cap ? 2 * cap : 256;
        }
        size_t size = strlen(dir) + strlen(e->d_name) + 2;
        char *path = malloc(size);
        if (!path) {
            status = -1;
            break;
        }
        snprintf(path, size, "%s/%s", dir, e->d_name);
        paths[n++] = path;
    }
    closedir(d);
    if (status) fprintf(stderr, "fuzz_replay: out of memory\n");
    if (n) qsort(paths, n, sizeof *paths, by_name);
    long ran = 0;
    for (size_t i = 0; i < n; i++) {
        struct stat st;
        if (status == 0 && stat(paths[i], &st) == 0 && S_ISREG(st.st_mode)) {
            if (run_file(paths[i]) != 0)
                status = -1;
            else
                ran++;
        }
        free(paths[i]);
    }
    free(paths);
    return status ? status : ran;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s DIR|FILE...\n", argv[0]);
        return 2;
    }
    long total = 0;
    for (int i = 1; i < argc; i++) {
        struct stat st;
        long ran;
        if (stat(argv[i], &st) == 0 && S_ISDIR(st.st_mode))
            ran = run_dir(argv[i]);
        else
            ran = run_file(argv[i]) == 0 ? 1 : -1;
        if (ran < 0) return 1;
        printf("fuzz_replay: %ld input%s from %s\n", ran, ran == 1 ? "" : "s", argv[i]);
        total += ran;
    }
    if (total == 0) {
        fprintf(stderr, "fuzz_replay: no inputs ran\n");
        return 1;
    }
    printf("fuzz_replay: %ld inputs, no property broken\n", total);
    return 0;
}
