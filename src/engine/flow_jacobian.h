/* Private to the engine and the layers above it: the Jacobian blocks of a
 * flow field. */
#ifndef SW_ENGINE_FLOW_JACOBIAN_H
#define SW_ENGINE_FLOW_JACOBIAN_H

#include "stepwise/flow.h"

/* jac[4i..4i+3] = ∂g/∂x at point i and time t, row-major: analytic when the
 * field has a Jacobian, else forward differences (two extra field calls). */
void sw_flow_jacobian(sw_flow *f, double t, const double *y, double *jac);

#endif
