/* Integration: free sloshing in the INM tank (1 m long, H = 0.35 m, 2D, delta-SPH, N = 16).
 * A short sway (one period, A = 1 cm) excites the first mode; afterwards the liquid's centre
 * of mass oscillates with the first natural period, which linear theory gives as
 * T1 = 2 pi / sqrt(g k tanh(k H)), k = pi / L = 1.2651 s (theory §11, paper Fig. 6). The wave
 * is small (A/L = 1 %), so the nonlinear shift of the period is well below 0.1 %; what is
 * left is the discretisation error at this coarse N: measured -0.18 %, bound 0.55 % (3x). This
 * checks the dynamics end to end: pressure, gravity, walls, the moving-frame force and the time
 * integration. */
#include "app/simulation.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <cmocka.h>

#include "check.h"
#include "table.h"
#include "run_case.h"
#include "sloshing.h"

static void test_first_mode_period(void **state)
{
    (void)state;
    double period = free_sloshing_period(NULL, 0, 3, "free sloshing"), t1 = free_sloshing_t1();
    assert_close(t1, 1.2651, 1e-4);
    assert_close(period, t1, 3.0 * 0.0018 * t1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_first_mode_period)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
