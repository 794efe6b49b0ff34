/* gnuplot_run: runs gnuplot on a script (gnuplot_run.h). */
#include "app/gnuplot_run.h"
#include "app/plot_command.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* Runs `gnuplot script` in dir without a shell (no quoting of the directory's name). A pipe
 * closed on exec tells a missing gnuplot apart from a gnuplot that failed. */
int gnuplot_run(const char *dir, const char *script, char *err, size_t err_len)
{
    int report[2];
    if (pipe(report) || fcntl(report[1], F_SETFD, FD_CLOEXEC)) {
        snprintf(err, err_len, "vcsph plot: cannot run gnuplot: %s", strerror(errno));
        return PLOT_FAILED;
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        close(report[0]);
        int why[2] = {0, 0}; /* {0 chdir / 1 exec, errno} */
        if (chdir(dir) == 0) {
            execlp("gnuplot", "gnuplot", script, (char *)NULL);
            why[0] = 1;
        }
        why[1] = errno;
        if (write(report[1], why, sizeof why) < 0) _exit(127);
        _exit(127);
    }
    close(report[1]);
    if (pid < 0) {
        close(report[0]);
        snprintf(err, err_len, "vcsph plot: cannot run gnuplot: %s", strerror(errno));
        return PLOT_FAILED;
    }
    int why[2];
    ssize_t got;
    while ((got = read(report[0], why, sizeof why)) < 0 && errno == EINTR) continue;
    close(report[0]);
    int status;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) continue;
    if (got == (ssize_t)sizeof why) {
        if (why[0] == 1 && why[1] == ENOENT)
            snprintf(err, err_len,
                     "vcsph plot: gnuplot is not installed (not found in PATH); "
                     "the script is %s/%s",
                     dir, script);
        else
            snprintf(err, err_len, "vcsph plot: cannot run gnuplot in %s: %s", dir,
                     strerror(why[1]));
        return PLOT_FAILED;
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return PLOT_OK;
    if (WIFEXITED(status))
        snprintf(err, err_len, "vcsph plot: gnuplot failed with exit status %d on %s/%s",
                 WEXITSTATUS(status), dir, script);
    else
        snprintf(err, err_len, "vcsph plot: gnuplot was killed by signal %d on %s/%s",
                 WTERMSIG(status), dir, script);
    return PLOT_FAILED;
}
