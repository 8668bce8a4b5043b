#include "same_bits.h"

#include <check.h>
#include <string.h>

void sb_build(const sw_scene *sc, const double *p, sw_system *sys)
{
    char err[SW_ERRLEN];
    ck_assert_msg(sw_system_build(sys, sc, p, err, sizeof err) == SW_OK, "%s: %s", sc->name, err);
}

int sb_first_difference(const double *a, const double *b, int n)
{
    for (int i = 0; i < n; i++)
        if (memcmp(&a[i], &b[i], sizeof a[i]) != 0)
            return i;
    return -1;
}
