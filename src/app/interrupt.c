/* interrupt: the signal flag (interrupt.h). */
#include "app/interrupt.h"

#include <signal.h>
#include <stddef.h>

/* written by the handler, read by the time loop: the only thing a handler may safely do */
static volatile sig_atomic_t received;
static struct sigaction saved_term, saved_int;

static void on_signal(int sig) { received = sig; }

void interrupt_install(void)
{
    struct sigaction sa = {0};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    /* SA_RESTART: a write interrupted by the signal carries on instead of failing with EINTR;
       SA_RESETHAND: the second signal finds the default action (see interrupt.h) */
    sa.sa_flags = SA_RESTART | SA_RESETHAND;
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
