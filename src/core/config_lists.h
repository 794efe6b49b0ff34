/* config_lists: the case file's keys whose value is a list of numbers (probes.gauges,
 * probes.pressure, motion.center), read and written by their own functions for the schema of
 * core/config.c, and what reading a case keeps beside the config. Internal to core/config*.c. */
#ifndef VCSPH_CONFIG_LISTS_H
#define VCSPH_CONFIG_LISTS_H

#include "core/config.h"
#include "core/ini_schema.h"

#include <stdbool.h>
#include <stddef.h>

/* What reading a case keeps beside the config: how many coordinates the pressure points were
 * given with, checked against case.dim once dim is final. */
typedef struct {
    int point_coords;        /* 0 if no point */
    config_case_check check; /* config_load_checked's, NULL for none */
    void *check_user;
} case_reading;

bool config_set_gauges(ini_session *ctx, const ini_key *k, const char *s, char *why, size_t n);
void config_format_gauges(const void *target, const ini_key *k, char *buf, size_t size);
/* probes.pressure: points `x y[ z][ d=D]` separated by ';' (the count of coordinates goes to
 * case_reading, checked against case.dim once dim is final) */
bool config_set_points(ini_session *ctx, const ini_key *k, const char *s, char *why, size_t n);
void config_format_points(const void *target, const ini_key *k, char *buf, size_t size);
/* the pressure points with `coords` coordinates each, as a case file would give them */
void config_format_point_list(const config *cfg, int coords, char *buf, size_t size);
bool config_set_center(ini_session *ctx, const ini_key *k, const char *s, char *why, size_t n);
void config_format_center(const void *target, const ini_key *k, char *buf, size_t size);

#endif
