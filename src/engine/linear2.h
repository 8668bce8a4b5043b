/* Private to the engine and the layers above it: y' = J y for one 2x2
 * matrix J, the test system on which the truth module measures a method's
 * one-step map (and a plugin's host builds it again: plugin/host_proto.h).
 * A flow (order 1) has J = [[a, -b], [b, a]] (eigenvalues a ± ib); a
 * second-order system (x, v) has J = [[0, 1], [A, B]]. */
#ifndef SW_ENGINE_LINEAR2_H
#define SW_ENGINE_LINEAR2_H

#include "stepwise/ode.h"

typedef struct sw_linear2 {
    sw_ode ode;            /* first member: the solver's view, ctx = this */
    double j[4];           /* row-major */
} sw_linear2;

/* Set l up as y' = J y (order 1 or 2, as above) with its exact solve. */
void sw_linear2_init(sw_linear2 *l, int order, const double j[4]);

#endif
