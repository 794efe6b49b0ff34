/* The CSV writer keeps the first failure of a row to reach its file, with the system's
 * reason, so that a run on a full disk stops with "No space left on device" instead of going
 * on with a record full of holes. /dev/full fails every write with ENOSPC (Linux). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "io/csv.h"

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

static void test_rows_written_without_error(void **state)
{
    (void)state;
    char path[] = "/tmp/vcsph-csv-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    csv_file c = {0};
    assert_int_equal(csv_open(&c, path, "t,x"), 0);
    csv_put(&c, 0.5);
    csv_put_long(&c, 3);
    csv_end_row(&c);
    assert_int_equal(csv_error(&c), 0);
    assert_int_equal(csv_size(&c), (long long)strlen("t,x\n0.5,3\n"));
    csv_close(&c);
    remove(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_full_disk_is_reported),
        cmocka_unit_test(test_rows_written_without_error),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
