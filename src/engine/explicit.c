/* The explicit fixed-step methods: Euler, symplectic Euler, midpoint, Heun,
 * RK4, velocity Verlet and Yoshida's 4th-order composition of it. Each step reads only its stepper's workspace and
 * allocates nothing; the Runge-Kutta family runs slice by slice on pointwise
 * systems with results bit-identical to a whole-state pass. Each method as
 * the lecture writes it, plain loops to read first, is in reference.c; these
 * steps are held to its bits (tests/check_reference.c). */
#include "engine/stepper.h"

#include <math.h>
#include <string.h>

#include "stepwise/base.h"

/* A method's step over a slice of len components (y points at it; the
 * work vectors are slice-local) or over the whole state; returns non-zero
 * when its final loop saw a component at or beyond the limit exponent elim
 * (see sw_beyond_bits). */
typedef unsigned range_step(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int len, unsigned elim);

/* Run a step: the system's own fused step when it offers one for this
 * method (the same arithmetic, sw_fused_step_fn), else the range step over
 * the whole state or slice by slice; count its evaluations once per stage.
 * The final loops test every component against the sim's runaway limit as
 * they write it, sparing the sim a pass. */
static int run_ranges(range_step *f, sw_fused_step_fn *fused, int stages, sw_stepper *s, sw_ode *ode, double *t,
                      double *y, double h)
{
    unsigned elim = s->limit_exp ? s->limit_exp : 0x800, beyond = 0; /* 0x800: never */
    if (fused)
        beyond = fused(ode->ctx, *t, y, h, elim);
    else if (sw_ode_deriv_part(ode))
        for (int lo = 0; lo < ode->dim; lo += SW_SLICE)
            beyond |= f(s, ode, *t, y + lo, h, (lo + SW_SLICE < ode->dim ? lo + SW_SLICE : ode->dim) - lo, elim);
    else
        beyond = f(s, ode, *t, y, h, ode->dim, elim);
    s->checked = s->limit_exp != 0;
    s->beyond = beyond != 0;
    ode->evals += stages;
    *t += h;
    return 0;
}

/* x1 = x0 + h·f(t0, x0) */
SW_CLONES static unsigned euler_range(sw_stepper *s, sw_ode *ode, double t, double *restrict y, double h, int len, unsigned elim)
{
    double *restrict k = SW_WORK(s, 0);
    unsigned long long over = 0, add = sw_beyond_add(elim);
    sw_eval_slice(ode, t, len, y, k);
    for (int i = 0; i < len; i++) {
        y[i] += h * k[i];
        over |= sw_beyond_bits(y[i], add);
    }
    return sw_beyond_any(over);
}

int sw_step_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return run_ranges(euler_range, sw_ode_fused_euler(ode), 1, s, ode, t, y, h);
}

/* Semi-implicit Euler: v1 = v0 + h·a(x0, v0), then x1 = x0 + h·v1. */
int sw_step_symplectic_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int half = ode->dim / 2;
    double *k = SW_WORK(s, 0);
    sw_ode_eval(ode, *t, y, k);
    sw_axpy(half, y + half, y + half, h, k + half);
    sw_axpy(half, y, y, h, y + half);
    *t += h;
    return 0;
}

/* Explicit midpoint: k1 = f(y), k2 = f(y + h/2·k1), y1 = y + h·k2. */
SW_CLONES static unsigned midpoint_range(sw_stepper *s, sw_ode *ode, double t, double *restrict y, double h, int len, unsigned elim)
{
    double *restrict k = SW_WORK(s, 0), *restrict ym = SW_WORK(s, 1);
    unsigned long long over = 0, add = sw_beyond_add(elim);
    sw_eval_slice(ode, t, len, y, k);
    for (int i = 0; i < len; i++)
        ym[i] = y[i] + 0.5 * h * k[i];
    sw_eval_slice(ode, t + 0.5 * h, len, ym, k);
    for (int i = 0; i < len; i++) {
        y[i] += h * k[i];
        over |= sw_beyond_bits(y[i], add);
    }
    return sw_beyond_any(over);
}

int sw_step_midpoint(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return run_ranges(midpoint_range, NULL, 2, s, ode, t, y, h);
}

/* Heun (explicit trapezoid): k1 = f(y), k2 = f(y + h·k1), y1 = y + h/2·(k1 + k2). */
SW_CLONES static unsigned heun_range(sw_stepper *s, sw_ode *ode, double t, double *restrict y, double h, int len, unsigned elim)
{
    double *restrict k1 = SW_WORK(s, 0), *restrict yp = SW_WORK(s, 1), *restrict k2 = SW_WORK(s, 2);
    unsigned long long over = 0, add = sw_beyond_add(elim);
    sw_eval_slice(ode, t, len, y, k1);
    for (int i = 0; i < len; i++)
        yp[i] = y[i] + h * k1[i];
    sw_eval_slice(ode, t + h, len, yp, k2);
    for (int i = 0; i < len; i++) {
        y[i] += 0.5 * h * (k1[i] + k2[i]);
        over |= sw_beyond_bits(y[i], add);
    }
    return sw_beyond_any(over);
}

int sw_step_heun(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return run_ranges(heun_range, NULL, 2, s, ode, t, y, h);
}

/* Classical RK4: y1 = y + h/6·(k1 + 2k2 + 2k3 + k4), with three work vectors:
 * the stage state yt, the latest stage's k, and the running sum acc = k1,
 * k1 + 2k2, (k1 + 2k2) + 2k3. The final sum adds left to right as the
 * formula reads, so acc + k4 is the same operations in the same order and
 * the bits are those of keeping the four k apart. */
SW_CLONES static unsigned rk4_range(sw_stepper *s, sw_ode *ode, double t, double *restrict y, double h, int len, unsigned elim)
{
    double *restrict acc = SW_WORK(s, 0), *restrict k = SW_WORK(s, 1), *restrict yt = SW_WORK(s, 2);
    unsigned long long over = 0, add = sw_beyond_add(elim);
    sw_eval_slice(ode, t, len, y, acc);
    for (int i = 0; i < len; i++)
        yt[i] = y[i] + 0.5 * h * acc[i];
    sw_eval_slice(ode, t + 0.5 * h, len, yt, k);
    for (int i = 0; i < len; i++) {
        acc[i] += 2.0 * k[i];
        yt[i] = y[i] + 0.5 * h * k[i];
    }
    sw_eval_slice(ode, t + 0.5 * h, len, yt, k);
    for (int i = 0; i < len; i++) {
        acc[i] += 2.0 * k[i];
        yt[i] = y[i] + h * k[i];
    }
    sw_eval_slice(ode, t + h, len, yt, k);
    for (int i = 0; i < len; i++) {
        y[i] += h / 6.0 * (acc[i] + k[i]);
        over |= sw_beyond_bits(y[i], add);
    }
    return sw_beyond_any(over);
}

int sw_step_rk4(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return run_ranges(rk4_range, sw_ode_fused_rk4(ode), 4, s, ode, t, y, h);
}

/* Velocity Verlet (kick-drift-kick), one evaluation per step by reusing the
 * last acceleration (FSAL):
 *   v½ = v0 + h/2·a0,  x1 = x0 + h·v½,  a1 = a(x1, ṽ1),  v1 = v½ + h/2·a1.
 * With velocity-independent forces ṽ1 does not matter and this is the
 * symplectic leapfrog. With drag, ṽ1 = v0 + h·a0 (an Euler predictor) keeps
 * the method second order: its O(h²) error enters a1 multiplied by h. */
int sw_step_verlet(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int half = ode->dim / 2;
    double *cache = SW_WORK(s, 0), *yt = SW_WORK(s, 1);
    double *x = y, *v = y + half, *a0 = cache + half;
    if (!s->have_cache)
        sw_ode_eval(ode, *t, y, cache);
    for (int i = 0; i < half; i++) {
        double vh = v[i] + 0.5 * h * a0[i];
        yt[i] = x[i] + h * vh;
        yt[half + i] = v[i] + h * a0[i];
        x[i] = yt[i];
        v[i] = vh;
    }
    sw_ode_eval(ode, *t + h, yt, cache);
    sw_axpy(half, v, v, 0.5 * h, a0);
    s->have_cache = 1;
    *t += h;
    return 0;
}


/* One kick-drift-kick substep of size c·h from the acceleration in a
 * (a(x0, ·), kept in cache + half), leaving a(x1, ṽ1) there: velocity
 * Verlet's body, with the Euler velocity predictor for velocity-dependent
 * forces. The one evaluation is at time t. */
static void verlet_substep(sw_ode *ode, double t, double *y, double ch, double *cache, double *yt)
{
    int half = ode->dim / 2;
    double *x = y, *v = y + half, *a = cache + half;
    for (int i = 0; i < half; i++) {
        double vh = v[i] + 0.5 * ch * a[i];
        yt[i] = x[i] + ch * vh;
        yt[half + i] = v[i] + ch * a[i];
        x[i] = yt[i];
        v[i] = vh;
    }
    sw_ode_eval(ode, t, yt, cache);
    sw_axpy(half, v, v, 0.5 * ch, a);
}

/* Yoshida's (and Forest-Ruth's) triple jump: velocity Verlet composed as
 * V(w1·h) V(w0·h) V(w1·h) with w1 = 1/(2 - 2^(1/3)), w0 = -2^(1/3)·w1, so
 * that 2·w1 + w0 = 1 and 2·w1³ + w0³ = 0 cancel the h³ error of the
 * symmetric Verlet step: 4th order, symmetric and symplectic. Each substep's
 * last acceleration is the next one's first (FSAL, as verlet), so a step
 * costs 3 evaluations; the middle substep goes backwards in time. */
int sw_step_yoshida4(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    const double cbrt2 = 1.2599210498948731647672106; /* 2^(1/3) */
    const double w1 = 1.0 / (2.0 - cbrt2), w0 = -cbrt2 * w1;
    double *cache = SW_WORK(s, 0), *yt = SW_WORK(s, 1);
    if (!s->have_cache)
        sw_ode_eval(ode, *t, y, cache);
    double t0 = *t;
    verlet_substep(ode, t0 + w1 * h, y, w1 * h, cache, yt);
    verlet_substep(ode, t0 + (w1 + w0) * h, y, w0 * h, cache, yt);
    verlet_substep(ode, t0 + h, y, w1 * h, cache, yt);
    s->have_cache = 1;
    *t = t0 + h;
    return 0;
}
