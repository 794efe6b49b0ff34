/* version: the text cmake/vcsph_version.cmake generates at build time. */
#include "core/version.h"

#include "vcsph_version.h"

const char *vcsph_version(void) { return VCSPH_VERSION_TEXT; }
