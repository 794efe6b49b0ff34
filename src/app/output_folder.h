/* output_folder: a run's claim on its output folder. One run at a time writes into a folder
 * (a lock that the system drops with the process, so a crashed run never blocks the next),
 * and a new run does not mix its files with those of an earlier one: it is refused, or with
 * --overwrite it first removes exactly the files a run writes, nothing else. */
#ifndef VCSPH_OUTPUT_FOLDER_H
#define VCSPH_OUTPUT_FOLDER_H

#include <stdbool.h>
#include <stddef.h>

/* The lock file in the folder; it holds the process id of the run that holds the lock. */
#define OUTPUT_FOLDER_LOCK ".vcsph.lock"

/* Creates `dir` (and its parents) if missing and takes its lock, an flock(2) on
 * dir/.vcsph.lock held until output_folder_release or the process ends. Returns the lock's
 * descriptor, or -1 with a message in err: -1 and *busy set when another process holds it
 * (the message names that process), -1 and *busy clear when the folder cannot be made. */
int output_folder_lock(const char *dir, bool *busy, char *err, size_t err_len);
void output_folder_release(int fd);

/* Creates dir and its parents where missing; 0, or -1 with errno set. */
int output_folder_make(const char *dir);

/* A restart's rewind of dir: removes the snapshots numbered n_snapshots on, the images
 * numbered n_images on, and the temporary files a stopped write left. */
void output_folder_rewind(const char *dir, long n_snapshots, long n_images);

/* Whether dir holds any file that a run writes (output_folder_clear's list); one of them is
 * named in `found`. */
bool output_folder_holds_run(const char *dir, char *found, size_t found_len);

/* Removes the files a run writes in dir: its CSV files, log.txt, case.ini, the copied motion
 * table, checkpoint.h5, snapshots.xmf, snapshots/NNNNNN.h5 and images/particles_NNNNNN.png
 * (and their .tmp files). Anything else stays, the folders too. Returns 0, or -1 with the
 * first failure in err. */
int output_folder_clear(const char *dir, char *err, size_t err_len);

#endif
