/* First-order flow-field systems: x' = g(x, t) for n massless points. The
 * state is y = x(2n); there are no velocities and no masses. */
#ifndef STEPWISE_FLOW_H
#define STEPWISE_FLOW_H

#include <stddef.h>
#include "stepwise/ode.h"

/* v[2i..2i+1] = g(x[2i..2i+1], t) for i < n; params is the scene's data. */
typedef void sw_field_fn(const void *params, double t, int n, const double *x, double *v);
/* jac[4i..4i+3] = ∂g/∂x at point i, row-major (gx_x, gx_y, gy_x, gy_y). */
typedef void sw_field_jac_fn(const void *params, double t, int n, const double *x, double *jac);

typedef struct sw_flow {
    sw_ode ode;            /* first member: the solver's view, ctx = this */
    int n;
    double *y;             /* x(2n), owned */
    sw_field_fn *field;
    sw_field_jac_fn *jac;  /* NULL: finite differences, two extra field calls */
    const void *params;
    double *work;          /* 10n: Jacobian blocks (4n) and perturbed points (6n) */
} sw_flow;

int sw_flow_init(sw_flow *f, int n, sw_field_fn *field, sw_field_jac_fn *jac,
                 const void *params, char *err, size_t errlen);
void sw_flow_free(sw_flow *f);

#endif
