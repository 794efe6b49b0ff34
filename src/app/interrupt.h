/* interrupt: SIGTERM and SIGINT during a run ask the time loop to stop at the next step
 * boundary, write a checkpoint and exit RUN_INTERRUPTED, instead of dying mid-step. */
#ifndef VCSPH_INTERRUPT_H
#define VCSPH_INTERRUPT_H

/* Installs the handlers (they only record the signal). A second signal of the same kind acts
 * as it would without them: it ends the process at once (the last checkpoint stays whole,
 * checkpoint.h), for a user who does not want to wait for the step to end. */
void interrupt_install(void);
/* Puts back the handlers that were there before interrupt_install and forgets any signal. */
void interrupt_restore(void);
/* The signal received since interrupt_install, or 0. */
int interrupt_signal(void);

#endif
