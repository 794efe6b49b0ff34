/* interrupt: the signal flag (interrupt.h). */
#include "app/interrupt.h"

#include <signal.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* written by the handler, read by the time loop: the only thing a handler may safely do */
static volatile sig_atomic_t received;
static struct sigaction saved_term, saved_int;
/* the second signal's words, made before any signal can come: a handler may not format */
static char second_message[512];
static size_t second_length;

static void on_signal(int sig)
{
    if (!received) {
        received = sig;
        return;
    }
    /* the second one: the user does not want to wait for the step to end */
    ssize_t ignored = write(STDERR_FILENO, second_message, second_length);
    (void)ignored;
    _exit(128 + sig);
}

void interrupt_install(const char *checkpoint_path)
{
    int n = snprintf(second_message, sizeof second_message,
                     "\nvcsph: second interrupt: stopped at once, mid-step, without a new "
                     "checkpoint (exit 128 + signal: 130 for SIGINT); %s, if there, holds the "
                     "last one\n",
                     checkpoint_path);
    second_length = n < 0 ? 0 : strnlen(second_message, sizeof second_message);
    struct sigaction sa = {0};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    /* SA_RESTART: a write interrupted by the signal carries on instead of failing with EINTR */
    sa.sa_flags = SA_RESTART;
    received = 0;
    sigaction(SIGTERM, &sa, &saved_term);
    sigaction(SIGINT, &sa, &saved_int);
}

void interrupt_restore(void)
{
    sigaction(SIGTERM, &saved_term, NULL);
    sigaction(SIGINT, &saved_int, NULL);
    received = 0;
}

int interrupt_signal(void) { return received; }
