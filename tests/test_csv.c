/* The CSV writer and its reader (io/csv_read.c, which `vcsph plot` uses) agree: what the writer
 * quotes, the reader reads back as it was written.
 * The CSV writer keeps the first failure of a row to reach its file, with the system's
 * reason, so that a run on a full disk stops with "No space left on device" instead of going
 * on with a record full of holes. /dev/full fails every write with ENOSPC (Linux). A restart
 * reopens a file written before columns were added with the new header. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "io/csv.h"
#include "io/csv_read.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void test_full_disk_is_reported(void **state)
{
    (void)state;
    csv_file c = {0};
    /* the header's flush already fails: the open reports it */
    assert_int_equal(csv_open(&c, "/dev/full", "t,x"), -1);
    assert_int_equal(errno, ENOSPC);
    csv_put(&c, 1.0);
    csv_put(&c, 2.0);
    csv_end_row(&c);
    assert_int_equal(csv_error(&c), ENOSPC);
    printf("a row written to /dev/full: %s\n", strerror(csv_error(&c)));
    csv_close(&c);
}

/* A CSV file with `header` at a new temporary path made from the template `path`. */
static csv_file open_temporary(char *path, const char *header)
{
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    csv_file c = {0};
    assert_int_equal(csv_open(&c, path, header), 0);
    return c;
}

static void test_rows_written_without_error(void **state)
{
    (void)state;
    char path[] = "/tmp/vcsph-csv-XXXXXX";
    csv_file c = open_temporary(path, "t,x");
    csv_put(&c, 0.5);
    csv_put_long(&c, 3);
    csv_end_row(&c);
    assert_int_equal(csv_error(&c), 0);
    assert_int_equal(csv_size(&c), (long long)strlen("t,x\n0.5,3\n"));
    csv_close(&c);
    remove(path);
}

/* Text with commas, quotes and a newline (the writer turns a newline into a space) among
 * numbers, written and read back: the fields and the column summaries. */
static void test_reader_reads_what_the_writer_wrote(void **state)
{
    (void)state;
    char path[] = "/tmp/vcsph-csv-XXXXXX";
    csv_file c = open_temporary(path, "t,event,detail");
    csv_put(&c, 0.25);
    csv_put_text(&c, "eta_switch");
    csv_put_text(&c, "eta 0 -> 1, at \"+1 %\"\nnow");
    csv_end_row(&c);
    csv_put(&c, -2.5);
    csv_put_empty(&c);
    csv_put_text(&c, "");
    csv_end_row(&c);
    csv_close(&c);

    FILE *f = fopen(path, "r");
    char line[256], *fields[4];
    assert_non_null(fgets(line, sizeof line, f));
    assert_non_null(fgets(line, sizeof line, f));
    fclose(f);
    assert_int_equal(csv_split_fields(line, fields, 4), 3);
    assert_string_equal(fields[0], "0.25");
    assert_string_equal(fields[1], "eta_switch");
    assert_string_equal(fields[2], "eta 0 -> 1, at \"+1 %\" now");

    csv_summary s;
    assert_int_equal(csv_summary_read(path, &s, NULL, NULL), 0);
    assert_int_equal(s.n_rows, 2);
    assert_int_equal(s.n_cols, 3);
    const column_summary *t = csv_summary_values(&s, "t");
    assert_non_null(t);
    assert_int_equal(t->n_values, 2);
    assert_true(t->min == -2.5 && t->max == 0.25 && t->first == 0.25 && t->nonzero);
    assert_null(csv_summary_values(&s, "event")); /* text only: no value to draw */
    assert_int_equal(csv_summary_column(&s, "detail"), 2);
    csv_summary_free(&s);
    remove(path);
}

/* The whole file as text (at most 255 bytes). */
static void read_all(const char *path, char *text)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t n = fread(text, 1, 255, f);
    text[n] = '\0';
    fclose(f);
}

/* A restart of a run whose file was written before columns were added: the rows up to the
 * checkpoint's size gain the new columns empty, the rows after it are dropped, and the appends
 * follow; the same header reopens as it is; another header is refused. */
static void test_reopen_adds_columns(void **state)
{
    (void)state;
    char path[] = "/tmp/vcsph-csv-XXXXXX", text[256];
    csv_file c = open_temporary(path, "t,x");
    for (int row = 0; row < 3; row++) {
        csv_put(&c, row);
        csv_put(&c, 10 * row);
        csv_end_row(&c);
    }
    csv_close(&c);
    long long checkpoint_size = (long long)strlen("t,x\n0,0\n1,10\n"); /* the third row after it */
    assert_int_equal(csv_reopen_with_header(&c, path, checkpoint_size, "t,x,y,z"), 0);
    assert_int_equal(csv_size(&c), (long long)strlen("t,x,y,z\n0,0,,\n1,10,,\n"));
    csv_put(&c, 2);
    csv_put(&c, 20);
    csv_put(&c, 1);
    csv_put(&c, 2);
    csv_end_row(&c);
    csv_close(&c);
    read_all(path, text);
    assert_string_equal(text, "t,x,y,z\n0,0,,\n1,10,,\n2,20,1,2\n");

    long long size = (long long)strlen(text);
    assert_int_equal(csv_reopen_with_header(&c, path, size, "t,x,y,z"), 0);
    assert_int_equal(csv_size(&c), size);
    csv_close(&c);
    assert_int_equal(csv_reopen_with_header(&c, path, size, "t,x,w,z"), -2);
    assert_int_equal(csv_reopen_with_header(&c, path, size, "t,x,y"), -2);
    read_all(path, text);
    assert_string_equal(text, "t,x,y,z\n0,0,,\n1,10,,\n2,20,1,2\n"); /* left as it was */
    remove(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_full_disk_is_reported),
        cmocka_unit_test(test_rows_written_without_error),
        cmocka_unit_test(test_reader_reads_what_the_writer_wrote),
        cmocka_unit_test(test_reopen_adds_columns),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
