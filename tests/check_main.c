/* Runs every Check suite; the list comes from build/tests/suites.h, which
 * the Makefile generates from the tests/check_*.c file names. */
#include <check.h>
#include <stdlib.h>

#define SW_SUITE(fn) Suite *fn(void);
#include "suites.h"
#undef SW_SUITE

int main(void)
{
    SRunner *sr = srunner_create(NULL);
#define SW_SUITE(fn) srunner_add_suite(sr, fn());
#include "suites.h"
#undef SW_SUITE
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
