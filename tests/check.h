/* check: assertions on doubles for the cmocka tests (Debian's cmocka 1.1 compares floats
 * only). Include after <cmocka.h>. */
#ifndef VCSPH_TEST_CHECK_H
#define VCSPH_TEST_CHECK_H

#include <math.h>

/* |actual - expected| <= tol, printing both values when it fails */
#define assert_close(actual, expected, tol)                                                        \
    do {                                                                                           \
        double a_ = (actual), e_ = (expected), t_ = (tol);                                         \
        if (!(fabs(a_ - e_) <= t_))                                                                \
            fail_msg("%s = %.17g, expected %.17g within %.3g (off by %.3g)", #actual, a_, e_, t_,  \
                     a_ - e_);                                                                     \
    } while (0)

#endif
