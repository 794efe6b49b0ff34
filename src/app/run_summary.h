/* run_summary: what a user reads at the end of a run, from the run's own files (so that a
 * restarted run sums up the whole run, not only the part since its checkpoint): the final and
 * the extreme eps_v1, the eta switches and how many of each event events.csv holds. */
#ifndef VCSPH_RUN_SUMMARY_H
#define VCSPH_RUN_SUMMARY_H

#include <stddef.h>

/* Writes the summary of the run in folder `dir` into text (one line per item, each starting
 * with "vcsph: "); an empty text if the files cannot be read. */
void run_summary(const char *dir, char *text, size_t size);

#endif
