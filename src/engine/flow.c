/* Flow-field systems: n massless points carried by x' = g(x, t). Each point
 * moves independently, so ∂f/∂y is block diagonal with one 2x2 block per
 * point and implicit solves are per point. Invariant: no allocation after init. */
#include "engine/flow_jacobian.h"
#include "engine/ode_fast.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"

static void flow_deriv(void *ctx, double t, const double *y, double *dydt)
{
    const sw_flow *f = ctx;
    f->field(f->params, t, f->n, y, dydt);
}

/* Points move independently: a slice of the state is a smaller flow. */
static void flow_deriv_part(void *ctx, double t, int len, const double *y, double *dydt)
{
    const sw_flow *f = ctx;
    f->field(f->params, t, len / 2, y, dydt);
}

/* The 2x2 blocks of ∂g/∂x at every point: analytic when the field has a
 * Jacobian, else forward differences with every point perturbed at once
 * (points are independent, so two extra field calls give all blocks). */
void sw_flow_jacobian(sw_flow *f, double t, const double *y, double *jac)
{
    if (f->jac) {
        f->jac(f->params, t, f->n, y, jac);
        return;
    }
    int n2 = 2 * f->n;
    double *g0 = f->work + 4 * f->n, *yp = g0 + n2, *g1 = yp + n2;
    f->field(f->params, t, f->n, y, g0);
    f->ode.evals++;
    for (int d = 0; d < 2; d++) {
        memcpy(yp, y, (size_t)n2 * sizeof *yp);
        for (int i = 0; i < f->n; i++)
            yp[2 * i + d] += 1e-7 * fmax(1.0, fabs(y[2 * i + d]));
        f->field(f->params, t, f->n, yp, g1);
        f->ode.evals++;
        for (int i = 0; i < f->n; i++) {
            double eps = yp[2 * i + d] - y[2 * i + d];
            jac[4 * i + d] = (g1[2 * i] - g0[2 * i]) / eps;         /* ∂gx/∂x_d */
            jac[4 * i + 2 + d] = (g1[2 * i + 1] - g0[2 * i + 1]) / eps; /* ∂gy/∂x_d */
        }
    }
}

/* (I - c·J_i) z_i = r_i for every point, by Cramer's rule on each 2x2 block. */
static int flow_solve(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    sw_flow *f = ctx;
    double *jac = f->work;
    sw_flow_jacobian(f, t, y, jac);
    for (int i = 0; i < f->n; i++) {
        const double *j = jac + 4 * i;
        double a = 1 - c * j[0], b = -c * j[1], cc = -c * j[2], d = 1 - c * j[3];
        double det = a * d - b * cc;
        if (!(fabs(det) > 0) || !isfinite(det))
            return SW_EDIVERGED;
        double rx = r[2 * i], ry = r[2 * i + 1];
        z[2 * i] = (d * rx - b * ry) / det;
        z[2 * i + 1] = (a * ry - cc * rx) / det;
    }
    return SW_OK;
}

#ifndef SW_FIELD_ONLY
static unsigned flow_euler(void *ctx, double t, double *y, double h, unsigned elim)
{
    const sw_flow *f = ctx;
    return f->point->euler(f->params, t, f->n, y, h, elim);
}

static unsigned flow_rk4(void *ctx, double t, double *y, double h, unsigned elim)
{
    const sw_flow *f = ctx;
    return f->point->rk4(f->params, t, f->n, y, h, elim);
}

/* The fast paths: slices always; the fused steps the field offers
 * (index: 1 Euler's, 2 RK4's). First order: no position_only, no central1. */
static const struct sw_ode_fast fast_paths[4] = {
    { .deriv_part = flow_deriv_part },
    { .deriv_part = flow_deriv_part, .fused_euler = flow_euler },
    { .deriv_part = flow_deriv_part, .fused_rk4 = flow_rk4 },
    { .deriv_part = flow_deriv_part, .fused_euler = flow_euler, .fused_rk4 = flow_rk4 },
};
#else
/* A plugin's host (-DSW_FIELD_ONLY): the field alone, no fused step. */
static const struct sw_ode_fast fast_paths[4] = {
    { .deriv_part = flow_deriv_part }, { .deriv_part = flow_deriv_part },
    { .deriv_part = flow_deriv_part }, { .deriv_part = flow_deriv_part },
};
#endif

int sw_flow_init(sw_flow *f, int n, sw_field_fn *field, sw_field_jac_fn *jac, const void *params,
                 char *err, size_t errlen)
{
    memset(f, 0, sizeof *f);
    if (n < 1) {
        snprintf(err, errlen, "a flow needs at least one point (got %d)", n);
        return SW_EINVAL;
    }
    f->n = n;
    f->field = field;
    f->jac = jac;
    f->params = params;
    f->y = calloc((size_t)2 * n, sizeof *f->y);
    f->work = calloc((size_t)10 * n, sizeof *f->work);
    if (!f->y || !f->work) {
        sw_flow_free(f);
        snprintf(err, errlen, "out of memory for %d flow points", n);
        return SW_ENOMEM;
    }
    f->ode.dim = 2 * n;
    f->ode.order = 1;
    f->ode.deriv = flow_deriv;
    f->ode.solve = flow_solve;
    f->ode.fast = &fast_paths[0];
    f->ode.ctx = f;
    return SW_OK;
}

void sw_flow_fuse(sw_flow *f, const sw_point_field *pf)
{
    f->point = pf;
    f->field = pf->field;
    f->ode.fast = &fast_paths[(pf->euler ? 1 : 0) | (pf->rk4 ? 2 : 0)];
}

void sw_flow_free(sw_flow *f)
{
    free(f->y);
    free(f->work);
    memset(f, 0, sizeof *f);
}
