/* The case-file schema as a user sees it: `vcsph keys` lists the parser's key table, and
 * docs/case-file.md documents exactly those keys with the same defaults (in both directions,
 * so that neither the docs nor the code can drift); `vcsph check --print` prints the resolved
 * case, which loads back to the same case and is byte for byte the case.ini a run writes. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config.h"

#include "temp_dir.h"
#include "vcsph_child.h"

#ifndef VCSPH_SOURCE_DIR
#error "VCSPH_SOURCE_DIR must name the source tree (CMake defines it)"
#endif
#define CASE_FILE_DOC VCSPH_SOURCE_DIR "/docs/case-file.md"
#define KEYS_MAX      256
#define FIELD_MAX     512

extern char **environ;

static int setup(void **state) { return temp_fixture_setup(state, "vcsph-keys"); }

static int teardown(void **state) { return temp_fixture_teardown(state); }

/* One key and its default, as `vcsph keys` or the docs give them. */
typedef struct {
    char key[128];
    char def[FIELD_MAX];
} key_row;

typedef struct {
    key_row rows[KEYS_MAX];
    int n;
} key_list;

static const key_row *find_row(const key_list *list, const char *key)
{
    for (int i = 0; i < list->n; i++)
        if (!strcmp(list->rows[i].key, key)) return &list->rows[i];
    return NULL;
}

static void add_row(key_list *list, const char *key, size_t key_len, const char *def,
                    size_t def_len)
{
    assert_true(list->n < KEYS_MAX);
    if (key_len >= sizeof list->rows[0].key || def_len >= sizeof list->rows[0].def)
        fail_msg("key or default too long: %.*s", (int)key_len, key);
    char name[128];
    snprintf(name, sizeof name, "%.*s", (int)key_len, key);
    if (find_row(list, name)) fail_msg("%s listed twice", name);
    key_row *r = &list->rows[list->n++];
    snprintf(r->key, sizeof r->key, "%s", name);
    snprintf(r->def, sizeof r->def, "%.*s", (int)def_len, def);
}

/* A "section.key": lower-case words and digits joined by one dot. */
static bool is_key_name(const char *s, size_t n)
{
    const char *dot = memchr(s, '.', n);
    if (!dot || dot == s || dot == s + n - 1) return false;
    for (size_t i = 0; i < n; i++) {
        char c = s[i];
        bool ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
        if (!ok && &s[i] != dot) return false;
    }
    return true;
}

/* `vcsph keys`: section.key TAB default TAB allowed TAB meaning, every line. */
static void parse_keys_output(const char *text, key_list *list)
{
    for (const char *line = text; *line;) {
        size_t len = strcspn(line, "\n");
        const char *tab[3], *p = line;
        for (int k = 0; k < 3; k++) {
            tab[k] = memchr(p, '\t', (size_t)(line + len - p));
            if (!tab[k]) fail_msg("fewer than 4 fields: %.*s", (int)len, line);
            p = tab[k] + 1;
        }
        if (memchr(p, '\t', (size_t)(line + len - p)))
            fail_msg("more than 4 fields: %.*s", (int)len, line);
        size_t key_len = (size_t)(tab[0] - line);
        if (!is_key_name(line, key_len)) fail_msg("not a section.key: %.*s", (int)len, line);
        /* allowed and meaning are never empty */
        assert_true(tab[2] > tab[1] + 1);
        assert_true(line + len > tab[2] + 1);
        add_row(list, line, key_len, tab[0] + 1, (size_t)(tab[1] - tab[0] - 1));
        line += len + (line[len] == '\n');
    }
}

/* The cell [s, s + n) without surrounding blanks and backticks. */
static void trim_cell(const char **s, size_t *n)
{
    while (*n && strchr(" `", **s)) (*s)++, (*n)--;
    while (*n && strchr(" `", (*s)[*n - 1])) (*n)--;
}

/* The table rows of docs/case-file.md whose first cell is a `section.key`: the key and the
 * second cell, its default. */
static void parse_doc(const char *text, key_list *list)
{
    for (const char *line = text; *line;) {
        size_t len = strcspn(line, "\n");
        if (!strncmp(line, "| `", 3)) {
            const char *first = line + 1;
            const char *bar1 = memchr(first, '|', (size_t)(line + len - first));
            const char *bar2 = bar1 ? memchr(bar1 + 1, '|', (size_t)(line + len - bar1 - 1)) : 0;
            if (!bar2) fail_msg("a table row with fewer than 2 cells: %.*s", (int)len, line);
            const char *key = first, *def = bar1 + 1;
            size_t key_len = (size_t)(bar1 - first), def_len = (size_t)(bar2 - bar1 - 1);
            trim_cell(&key, &key_len);
            trim_cell(&def, &def_len);
            if (is_key_name(key, key_len)) add_row(list, key, key_len, def, def_len);
        }
        line += len + (line[len] == '\n');
    }
}

static void keys_of_binary(const temp_fixture *fx, key_list *list)
{
    int rc = vcsph_child_run(fx->dir, (const char *const[]){"keys", NULL}, environ);
    char path[600];
    snprintf(path, sizeof path, "%s/stderr.txt", fx->dir);
    char *err = text_file_read(path);
    if (rc) print_error("stderr: %s\n", err);
    assert_int_equal(rc, 0);
    assert_string_equal(err, "");
    free(err);
    snprintf(path, sizeof path, "%s/stdout.txt", fx->dir);
    char *out = text_file_read(path);
    parse_keys_output(out, list);
    free(out);
}

/* Every key the parser knows is documented with its default, and the docs list no other. */
static void test_docs_list_every_key(void **state)
{
    temp_fixture *fx = *state;
    static key_list code, doc;
    memset(&code, 0, sizeof code);
    memset(&doc, 0, sizeof doc);
    keys_of_binary(fx, &code);
    char *text = text_file_read(CASE_FILE_DOC);
    parse_doc(text, &doc);
    free(text);
    assert_true(code.n > 0);
    int problems = 0;
    for (int i = 0; i < code.n; i++) {
        const key_row *d = find_row(&doc, code.rows[i].key);
        if (!d) {
            print_error("%s: not documented in docs/case-file.md\n", code.rows[i].key);
            problems++;
        } else if (strcmp(d->def, code.rows[i].def)) {
            print_error("%s: docs/case-file.md says default '%s', vcsph keys '%s'\n",
                        code.rows[i].key, d->def, code.rows[i].def);
            problems++;
        }
    }
    for (int i = 0; i < doc.n; i++) {
        if (!find_row(&code, doc.rows[i].key)) {
            print_error("%s: documented in docs/case-file.md but not a key\n", doc.rows[i].key);
            problems++;
        }
    }
    assert_int_equal(problems, 0);
    assert_int_equal(doc.n, code.n);
}

/* ---- vcsph check --print ----------------------------------------------------------------- */

/* A small case with a comment of each kind; motion and probes so that several kinds of key
 * are resolved. */
static const char print_case[] = "# a tank that sways for 2 ms\n"
                                 "[case]\nt_end = 0.002 ; s\n"
                                 "[tank]\nlength = 0.2\nheight = 0.1\n"
                                 "[liquid]\nheight = 0.05\n"
                                 "[motion]\ntype = sway  # along x\namplitude = 0.005\n"
                                 "period = 0.5\n"
                                 "[probes]\ngauges = 0.1\npressure = 0.1 0.01\n"
                                 "[output]\ncheckpoint_every = 0\n";

static char *read_in(const temp_fixture *fx, const char *name)
{
    char path[600];
    snprintf(path, sizeof path, "%s/%s", fx->dir, name);
    return text_file_read(path);
}

static void test_check_print_loads_back(void **state)
{
    temp_fixture *fx = *state;
    char path[600];
    snprintf(path, sizeof path, "%s/sway.ini", fx->dir);
    text_file_write(path, print_case);
    const char *set[] = {"numerics.resolution=8", "model.scheme=delta"};
    int rc = vcsph_child_run(fx->dir,
                             (const char *const[]){"check", "--print", "sway.ini", "--set", set[0],
                                                   "--set", set[1], "-o", "res", NULL},
                             environ);
    char *out = read_in(fx, "stdout.txt"), *err = read_in(fx, "stderr.txt");
    if (rc) print_error("stderr: %s\n", err);
    assert_int_equal(rc, 0);
    assert_string_equal(err, "");

    /* it loads back to the case the file and the options make */
    static config printed, direct;
    char msg[1024];
    rc = config_load_string(&printed, out, "printed", NULL, 0, msg, sizeof msg);
    if (rc) print_error("%s\n%s", msg, out);
    assert_int_equal(rc, 0);
    rc = config_load(&direct, path, set, 2, msg, sizeof msg);
    if (rc) print_error("%s\n", msg);
    assert_int_equal(rc, 0);
    assert_string_equal(printed.name, "sway"); /* the file's name */
    assert_string_equal(printed.output_dir, "res");
    assert_int_equal(printed.scheme, SCHEME_DELTA);
    /* what -o does (the bytes after the string zeroed, as config_load leaves them) */
    memset(direct.output_dir, 0, sizeof direct.output_dir);
    snprintf(direct.output_dir, sizeof direct.output_dir, "res");
    assert_memory_equal(&printed, &direct, sizeof direct);
    char *again = config_text(&printed);
    assert_non_null(again);
    assert_string_equal(out, again); /* and writes itself again */
    free(again);

    /* byte for byte the case.ini of a run with the same file and options */
    rc = vcsph_child_run(fx->dir,
                         (const char *const[]){"run", "sway.ini", "--set", set[0], "--set", set[1],
                                               "-o", "res", "--quiet", NULL},
                         environ);
    char *run_err = read_in(fx, "stderr.txt");
    if (rc) print_error("run: %s\n", run_err);
    assert_int_equal(rc, 0);
    char *case_ini = read_in(fx, "res/case.ini");
    assert_string_equal(case_ini, out);
    free(case_ini);
    free(run_err);
    free(out);
    free(err);
}

/* A case that would not run prints nothing and exits 2; only check takes --print. */
static void test_check_print_refuses_bad_cases(void **state)
{
    temp_fixture *fx = *state;
    char path[600];
    snprintf(path, sizeof path, "%s/bad.ini", fx->dir);
    text_file_write(path, "[case]\nt_end = 1\n[tank]\nlength = 1\n");
    int rc = vcsph_child_run(fx->dir, (const char *const[]){"check", "--print", "bad.ini", NULL},
                             environ);
    char *out = read_in(fx, "stdout.txt"), *err = read_in(fx, "stderr.txt");
    assert_int_equal(rc, 2);
    assert_string_equal(out, "");
    assert_contains(err, "3 required keys missing");
    free(out);
    free(err);
    /* sound_speed = auto without gravity or motion: refused by the run's own checks */
    text_file_write(path, "[case]\nt_end = 1\n[tank]\nlength = 1\nheight = 1\n"
                          "[liquid]\nheight = 0.5\n[fluid]\ngravity = 0\n"
                          "[numerics]\nresolution = 4\n");
    rc = vcsph_child_run(fx->dir, (const char *const[]){"check", "--print", "bad.ini", NULL},
                         environ);
    out = read_in(fx, "stdout.txt");
    err = read_in(fx, "stderr.txt");
    assert_int_equal(rc, 2);
    assert_string_equal(out, "");
    assert_contains(err, "sound_speed");
    free(out);
    free(err);
    rc =
        vcsph_child_run(fx->dir, (const char *const[]){"run", "--print", "bad.ini", NULL}, environ);
    err = read_in(fx, "stderr.txt");
    assert_int_equal(rc, 2);
    assert_contains(err, "--print");
    free(err);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_docs_list_every_key, setup, teardown),
        cmocka_unit_test_setup_teardown(test_check_print_loads_back, setup, teardown),
        cmocka_unit_test_setup_teardown(test_check_print_refuses_bad_cases, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
