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

/* A field written per point, and the steps taken with it fused into each
 * point's stages (src/engine/pointwise.h generates all three from one
 * per-point formula): x advanced n points from t by h; the result is the
 * runaway flag of sw_fused_step_fn. */
typedef unsigned sw_point_step_fn(const void *params, double t, int n, double *x, double h, unsigned elim);
typedef struct sw_point_field {
    sw_field_fn *field;
    sw_point_step_fn *euler, *rk4;
} sw_point_field;

typedef struct sw_flow {
    sw_ode ode;            /* first member: the solver's view, ctx = this */
    int n;
    double *y;             /* x(2n), owned */
    sw_field_fn *field;
    sw_field_jac_fn *jac;  /* NULL: finite differences, two extra field calls */
    const sw_point_field *point; /* NULL, or the field's fused steps */
    const void *params;
    double *work;          /* 10n: Jacobian blocks (4n) and perturbed points (6n) */
} sw_flow;

int sw_flow_init(sw_flow *f, int n, sw_field_fn *field, sw_field_jac_fn *jac,
                 const void *params, char *err, size_t errlen);
/* Use pf's field and its fused Euler and RK4 steps (ode.fused_*). */
void sw_flow_fuse(sw_flow *f, const sw_point_field *pf);
void sw_flow_free(sw_flow *f);

#endif
