/* version: what this vcsph is, as `vcsph --version` prints it, log.txt's first line says and
 * the snapshots and checkpoints keep (attribute vcsph_version): the output of
 * `git describe --always --dirty` when it was built from a git work tree (e.g. "0705be2" or
 * "v0.1.0-12-g0705be2-dirty"), else the release number (project() in CMakeLists.txt). */
#ifndef VCSPH_VERSION_H
#define VCSPH_VERSION_H

/* A non-empty static string. */
const char *vcsph_version(void);

#endif
