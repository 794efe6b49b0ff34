/* ini_value: the values of ini_schema's built-in key kinds (int, real, real or auto, bool,
 * word, name, path): text to field with the range check, and field to text that reads back
 * to the same bits. Internal to core/ini_schema.c. */
#ifndef VCSPH_INI_VALUE_H
#define VCSPH_INI_VALUE_H

#include "core/ini_schema.h"

/* Sets the field of key k (not INI_CUSTOM) in target from s; false with the reason in why. */
bool ini_value_set(void *target, const ini_key *k, const char *s, char *why, size_t n);
/* The field of key k (any kind) as a file spells it. */
void ini_value_format(const void *target, const ini_key *k, char *buf, size_t size);

#endif
