/* The implicit methods and the linear solve they share: a system's own
 * solve, or a dense finite-difference fallback for small systems. */
#include "engine/stepper.h"

#include <math.h>
#include <string.h>

#include "stepwise/base.h"

/* Linearised backward Euler (Baraff & Witkin): one Newton step of
 * y1 = y0 + h·f(y1) from y0, i.e. (I - h·J)·Δy = h·f(y0). Exact backward
 * Euler when f is linear. */
int sw_step_implicit_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    double *r = SW_WORK(s, 0), *dy = SW_WORK(s, 1);
    sw_ode_eval(ode, *t, y, r);
    for (int i = 0; i < ode->dim; i++)
        r[i] *= h;
    int rc = sw_ode_solve(s, ode, *t + h, y, h, r, dy);
    if (rc != 0)
        return rc;
    sw_axpy(ode->dim, y, y, 1.0, dy);
    *t += h;
    return 0;
}

/* Implicit midpoint: y1 = y0 + h·f(t + h/2, (y0 + y1)/2). Newton on
 * Δ = y1 - y0 with residual R(Δ) = Δ - h·f(y0 + Δ/2), Jacobian I - h/2·J. */
int sw_step_implicit_midpoint(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int n = ode->dim;
    double *d = SW_WORK(s, 0), *ym = SW_WORK(s, 1), *r = SW_WORK(s, 2), *delta = SW_WORK(s, 3);
    double tm = *t + 0.5 * h;
    double scale = 1.0 + sw_norm_inf(n, y);
    double tol = s->rtol > 0 ? s->rtol * 1e-6 : 1e-12;
    memset(d, 0, (size_t)n * sizeof *d);
    for (int iter = 0; iter < 50; iter++) {
        sw_axpy(n, ym, y, 0.5, d);
        sw_ode_eval(ode, tm, ym, r);
        for (int i = 0; i < n; i++)
            r[i] = h * r[i] - d[i]; /* -R */
        int rc = sw_ode_solve(s, ode, tm, ym, 0.5 * h, r, delta);
        if (rc != 0)
            return rc;
        sw_axpy(n, d, d, 1.0, delta);
        s->newton_iters++;
        double step = sw_norm_inf(n, delta);
        if (!(step == step))
            return SW_EDIVERGED;
        if (step <= tol * (scale + sw_norm_inf(n, d))) {
            sw_axpy(n, y, y, 1.0, d);
            *t += h;
            return 0;
        }
    }
    return SW_EDIVERGED;
}


/* Dense fallback: J by forward differences, one column per evaluation, then
 * (I - c·J) z = r by Gaussian elimination with partial pivoting. */
static int dense_solve(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                       const double *r, double *z)
{
    int n = ode->dim;
    double *a = s->dense, *f0 = a + (size_t)n * n, *yp = f0 + n, *f1 = yp + n;
    sw_ode_eval(ode, t, y, f0);
    memcpy(yp, y, (size_t)n * sizeof *yp);
    for (int j = 0; j < n; j++) {
        double eps = 1e-7 * fmax(1.0, fabs(y[j]));
        yp[j] = y[j] + eps;
        sw_ode_eval(ode, t, yp, f1);
        yp[j] = y[j];
        for (int i = 0; i < n; i++)
            a[i * n + j] = (i == j) - c * (f1[i] - f0[i]) / eps;
    }
    memcpy(z, r, (size_t)n * sizeof *z);
    for (int col = 0; col < n; col++) {
        int piv = col;
        for (int i = col + 1; i < n; i++)
            if (fabs(a[i * n + col]) > fabs(a[piv * n + col]))
                piv = i;
        if (!(fabs(a[piv * n + col]) > 0))
            return SW_EDIVERGED;
        if (piv != col) {
            for (int j = 0; j < n; j++) {
                double tmp = a[col * n + j];
                a[col * n + j] = a[piv * n + j];
                a[piv * n + j] = tmp;
            }
            double tmp = z[col];
            z[col] = z[piv];
            z[piv] = tmp;
        }
        for (int i = col + 1; i < n; i++) {
            double f = a[i * n + col] / a[col * n + col];
            for (int j = col; j < n; j++)
                a[i * n + j] -= f * a[col * n + j];
            z[i] -= f * z[col];
        }
    }
    for (int i = n - 1; i >= 0; i--) {
        double acc = z[i];
        for (int j = i + 1; j < n; j++)
            acc -= a[i * n + j] * z[j];
        z[i] = acc / a[i * n + i];
    }
    return SW_OK;
}

int sw_ode_solve(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                 const double *r, double *z)
{
    ode->solves++;
    if (ode->solve)
        return ode->solve(ode->ctx, t, y, c, r, z);
    return dense_solve(s, ode, t, y, c, r, z);
}
