/* y' = J y for a 2x2 J (linear2.h): the derivative and the exact solve of
 * (I - c·J) z = r by Cramer's rule. */
#include "engine/linear2.h"

#include <math.h>
#include <string.h>

#include "stepwise/base.h"

static void linear2_deriv(void *ctx, double t, const double *y, double *dydt)
{
    (void)t;
    const sw_linear2 *l = ctx;
    dydt[0] = l->j[0] * y[0] + l->j[1] * y[1];
    dydt[1] = l->j[2] * y[0] + l->j[3] * y[1];
}

static int linear2_solve(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    (void)t;
    (void)y;
    const sw_linear2 *l = ctx;
    double a = 1 - c * l->j[0], b = -c * l->j[1], d = -c * l->j[2], e = 1 - c * l->j[3];
    double det = a * e - b * d;
    if (!(fabs(det) > 0) || !isfinite(det))
        return SW_EDIVERGED;
    z[0] = (e * r[0] - b * r[1]) / det;
    z[1] = (a * r[1] - d * r[0]) / det;
    return SW_OK;
}

void sw_linear2_init(sw_linear2 *l, int order, const double j[4])
{
    memset(l, 0, sizeof *l);
    memcpy(l->j, j, sizeof l->j);
    l->ode.dim = 2;
    l->ode.order = order;
    l->ode.deriv = linear2_deriv;
    l->ode.solve = linear2_solve;
    l->ode.ctx = l;
    l->ode.maker_kind = SW_MAKER_LINEAR2;
    l->ode.maker = l;
}
