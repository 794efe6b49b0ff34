/* vcsph_child: the real vcsph binary run as a child process in a folder, and the texts it
 * leaves, for the tests of the command line. Include after <cmocka.h>; needs VCSPH_BINARY. */
#ifndef VCSPH_TEST_VCSPH_CHILD_H
#define VCSPH_TEST_VCSPH_CHILD_H

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef VCSPH_BINARY
#error "VCSPH_BINARY must name the vcsph executable (CMake defines it)"
#endif

/* Starts vcsph with args (NULL-ended) in `dir` with the environment envp, its stdout and stderr
 * into the files `out` and `err` there. Returns the child's pid. */
static inline pid_t vcsph_child_spawn(const char *dir, const char *const *args, char *const *envp,
                                      const char *out, const char *err)
{
    const char *argv[32] = {VCSPH_BINARY};
    int argc = 1;
    for (; args[argc - 1]; argc++) {
        assert_true(argc < 31);
        argv[argc] = args[argc - 1];
    }
    argv[argc] = NULL;
    fflush(NULL);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        /* the child: only async-signal-safe calls until execve */
        if (chdir(dir)) _exit(126);
        int o = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int e = open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (o < 0 || e < 0 || dup2(o, 1) < 0 || dup2(e, 2) < 0) _exit(126);
        close(o);
        close(e);
        execve(VCSPH_BINARY, (char *const *)argv, envp);
        _exit(127);
    }
    return pid;
}

/* The wait status of child pid once it has ended. */
static inline int vcsph_child_wait(pid_t pid)
{
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) fail_msg("waitpid: %s", strerror(errno));
    return status;
}

/* Runs vcsph with args (NULL-ended) in `dir` with the environment envp, its stdout and stderr
 * into stdout.txt and stderr.txt there. Returns the exit status, or -1 when a signal killed
 * it. */
static inline int vcsph_child_run(const char *dir, const char *const *args, char *const *envp)
{
    int status = vcsph_child_wait(vcsph_child_spawn(dir, args, envp, "stdout.txt", "stderr.txt"));
    if (WIFSIGNALED(status)) {
        print_error("vcsph died of signal %d\n", WTERMSIG(status));
        return -1;
    }
    int rc = WEXITSTATUS(status);
    assert_true(rc != 126 && rc != 127); /* the child could not start vcsph */
    return rc;
}

/* The whole file as a string (empty if it cannot be read); free() it. */
static inline char *text_file_read(const char *path)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len), *f = fopen(path, "r");
    assert_non_null(mem);
    if (f) {
        char buf[4096];
        size_t n;
        while ((n = fread(buf, 1, sizeof buf, f)) > 0) fwrite(buf, 1, n, mem);
        fclose(f);
    }
    fclose(mem);
    return text;
}

/* Writes text as the whole file at path (the case files and hand-made outputs of a test). */
static inline void text_file_write(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    assert_true(fputs(text, f) != EOF);
    assert_int_equal(fclose(f), 0);
}

static inline void assert_contains(const char *text, const char *part)
{
    if (!strstr(text, part)) fail_msg("expected \"%s\" in:\n%s", part, text);
}

static inline int count_lines(const char *text)
{
    int n = 0;
    for (; *text; text++) n += *text == '\n';
    return n;
}

#endif
