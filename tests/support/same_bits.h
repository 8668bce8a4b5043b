/* Shared by the suites that prove a production step equal to its lecture
 * form bit for bit (check_reference.c, check_reference_adaptive.c,
 * check_reference_implicit.c). */
#ifndef SW_TEST_SAME_BITS_H
#define SW_TEST_SAME_BITS_H

#include "stepwise/stepwise.h"

/* Scene sc with parameters p built into sys; fails the test if refused. */
void sb_build(const sw_scene *sc, const double *p, sw_system *sys);
/* The first of n components where a and b differ in their bits, or -1. */
int sb_first_difference(const double *a, const double *b, int n);

#endif
