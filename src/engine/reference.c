/* The explicit fixed-step methods as the lecture writes them (see
 * reference.h): each step a few plain loops over the whole state, in the
 * order the formulas read. The production steps (explicit.c) take the same
 * floating-point operations in the same order, cut into slices, tested for
 * runaways as they write, or fused into a system's own loop; a test holds
 * them to these bits. Write 0.5 * h, not h / 2: the same number, but the
 * production code's spelling, so a reader comparing them sees one form. */
#include "engine/reference.h"

#include <stdlib.h>

#include "engine/stepper.h"
#include "stepwise/base.h"

int sw_ref_init(sw_ref *r, int dim)
{
    *r = (sw_ref){ .dim = dim };
    double *v = calloc((size_t)5 * (size_t)dim, sizeof *v);
    if (!v)
        return SW_ENOMEM;
    r->k1 = v;
    r->k2 = v + dim;
    r->k3 = v + 2 * dim;
    r->k4 = v + 3 * dim;
    r->yt = v + 4 * dim;
    return SW_OK;
}

void sw_ref_free(sw_ref *r)
{
    free(r->k1);
    *r = (sw_ref){ 0 };
}

/* Euler: k1 = f(t, y), y = y + h*k1. */
void sw_ref_euler(sw_ref *r, sw_ode *ode, double t, double *y, double h)
{
    double *k1 = r->k1;
    sw_ode_eval(ode, t, y, k1);
    for (int i = 0; i < ode->dim; i++)
        y[i] = y[i] + h * k1[i];
}

/* Symplectic (semi-implicit) Euler on y = [x | v]: a = a(t, x, v), then
 * v = v + h*a first, and x = x + h*v with the new v. */
void sw_ref_symplectic_euler(sw_ref *r, sw_ode *ode, double t, double *y, double h)
{
    int n = ode->dim / 2;
    double *x = y, *v = y + n, *a = r->k1 + n;
    sw_ode_eval(ode, t, y, r->k1);
    for (int i = 0; i < n; i++)
        v[i] = v[i] + h * a[i];
    for (int i = 0; i < n; i++)
        x[i] = x[i] + h * v[i];
}

/* Explicit midpoint: k1 = f(t, y), k2 = f(t + h/2, y + h/2*k1),
 * y = y + h*k2. */
void sw_ref_midpoint(sw_ref *r, sw_ode *ode, double t, double *y, double h)
{
    double *k1 = r->k1, *k2 = r->k2, *yt = r->yt;
    sw_ode_eval(ode, t, y, k1);
    for (int i = 0; i < ode->dim; i++)
        yt[i] = y[i] + 0.5 * h * k1[i];
    sw_ode_eval(ode, t + 0.5 * h, yt, k2);
    for (int i = 0; i < ode->dim; i++)
        y[i] = y[i] + h * k2[i];
}

/* Heun: k1 = f(t, y), k2 = f(t + h, y + h*k1), y = y + h/2*(k1 + k2). */
void sw_ref_heun(sw_ref *r, sw_ode *ode, double t, double *y, double h)
{
    double *k1 = r->k1, *k2 = r->k2, *yt = r->yt;
    sw_ode_eval(ode, t, y, k1);
    for (int i = 0; i < ode->dim; i++)
        yt[i] = y[i] + h * k1[i];
    sw_ode_eval(ode, t + h, yt, k2);
    for (int i = 0; i < ode->dim; i++)
        y[i] = y[i] + 0.5 * h * (k1[i] + k2[i]);
}

/* Classical RK4: k1 = f(t, y), k2 = f(t + h/2, y + h/2*k1),
 * k3 = f(t + h/2, y + h/2*k2), k4 = f(t + h, y + h*k3),
 * y = y + h/6*(k1 + 2*k2 + 2*k3 + k4), the sum left to right. */
void sw_ref_rk4(sw_ref *r, sw_ode *ode, double t, double *y, double h)
{
    double *k1 = r->k1, *k2 = r->k2, *k3 = r->k3, *k4 = r->k4, *yt = r->yt;
    int dim = ode->dim;
    sw_ode_eval(ode, t, y, k1);
    for (int i = 0; i < dim; i++)
        yt[i] = y[i] + 0.5 * h * k1[i];
    sw_ode_eval(ode, t + 0.5 * h, yt, k2);
    for (int i = 0; i < dim; i++)
        yt[i] = y[i] + 0.5 * h * k2[i];
    sw_ode_eval(ode, t + 0.5 * h, yt, k3);
    for (int i = 0; i < dim; i++)
        yt[i] = y[i] + h * k3[i];
    sw_ode_eval(ode, t + h, yt, k4);
    for (int i = 0; i < dim; i++)
        y[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

/* One kick-drift-kick of size c on y = [x | v], ending at time t_end, from
 * the acceleration a0 in the second half of k1 (left there: a1):
 *   v½ = v0 + c/2*a0,  x1 = x0 + c*v½,  a1 = a(t_end, x1, ṽ1),  v1 = v½ + c/2*a1,
 * with ṽ1 = v0 + c*a0 (an Euler guess; it matters only when forces read
 * velocities). */
static void kick_drift_kick(sw_ref *r, sw_ode *ode, double t_end, double *y, double c)
{
    int n = ode->dim / 2;
    double *x = y, *v = y + n, *a = r->k1 + n, *v_half = r->k2;
    double *x_new = r->yt, *v_guess = r->yt + n;
    for (int i = 0; i < n; i++) {
        v_half[i] = v[i] + 0.5 * c * a[i];
        x[i] = x[i] + c * v_half[i];
        v_guess[i] = v[i] + c * a[i];
        x_new[i] = x[i];
    }
    sw_ode_eval(ode, t_end, r->yt, r->k1);
    for (int i = 0; i < n; i++)
        v[i] = v_half[i] + 0.5 * c * a[i];
}

/* The acceleration a step starts from: the last step's a1 (first same as
 * last), or evaluated on the first step. */
static void start_acceleration(sw_ref *r, sw_ode *ode, double t, const double *y)
{
    if (!r->have_a)
        sw_ode_eval(ode, t, y, r->k1);
    r->have_a = 1;
}

/* Velocity Verlet: one kick-drift-kick of size h. */
void sw_ref_verlet(sw_ref *r, sw_ode *ode, double t, double *y, double h)
{
    start_acceleration(r, ode, t, y);
    kick_drift_kick(r, ode, t + h, y, h);
}

/* Yoshida's 4th order: kick-drift-kicks of w1*h, w0*h (backwards) and w1*h,
 * w1 = 1/(2 - 2^(1/3)), w0 = -2^(1/3)*w1. */
void sw_ref_yoshida4(sw_ref *r, sw_ode *ode, double t, double *y, double h)
{
    const double cbrt2 = 1.2599210498948731647672106; /* 2^(1/3) */
    const double w1 = 1.0 / (2.0 - cbrt2), w0 = -cbrt2 * w1;
    start_acceleration(r, ode, t, y);
    kick_drift_kick(r, ode, t + w1 * h, y, w1 * h);
    kick_drift_kick(r, ode, t + (w1 + w0) * h, y, w0 * h);
    kick_drift_kick(r, ode, t + h, y, w1 * h);
}

sw_ref_step_fn *sw_ref_of(sw_step_fn *step)
{
    static const struct {
        sw_step_fn *step;
        sw_ref_step_fn *ref;
    } pairs[] = {
        { sw_step_euler, sw_ref_euler },     { sw_step_symplectic_euler, sw_ref_symplectic_euler },
        { sw_step_midpoint, sw_ref_midpoint }, { sw_step_heun, sw_ref_heun },
        { sw_step_rk4, sw_ref_rk4 },         { sw_step_verlet, sw_ref_verlet },
        { sw_step_yoshida4, sw_ref_yoshida4 },
    };
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++)
        if (pairs[i].step == step)
            return pairs[i].ref;
    return NULL;
}
