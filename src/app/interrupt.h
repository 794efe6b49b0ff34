/* interrupt: SIGTERM and SIGINT during a run ask the time loop to stop at the next step
 * boundary, write a checkpoint and exit RUN_INTERRUPTED, instead of dying mid-step. */
#ifndef VCSPH_INTERRUPT_H
#define VCSPH_INTERRUPT_H

/* Installs the handlers (the first signal is only recorded). A second SIGTERM or SIGINT ends
 * the process at once, for a user who does not want to wait for the step to end: it says so
 * on stderr, naming checkpoint_path (the last checkpoint stays whole, checkpoint.h), and
 * exits 128 + the signal's number (130 for SIGINT, 143 for SIGTERM). */
void interrupt_install(const char *checkpoint_path);
/* Puts back the handlers that were there before interrupt_install and forgets any signal. */
void interrupt_restore(void);
/* The signal received since interrupt_install, or 0. */
int interrupt_signal(void);

#endif
