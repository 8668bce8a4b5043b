/* Levi-Civita regularisation of one body about one centre: the regularised
 * system's derivative, the change of variables both ways, and a run to a
 * time of the true clock (engine/regularise.h has the equations). */
#include "engine/regularise.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "engine/ode_fast.h"
#include "stepwise/base.h"

/* w = [u1, u2, u1', u2', h, t]; f = dw/ds. */
static void lc_deriv(void *ctx, double s, const double *w, double *f)
{
    (void)s;
    sw_lc *lc = ctx;
    double u1 = w[0], u2 = w[1], r = u1 * u1 + u2 * u2;
    f[0] = w[2];
    f[1] = w[3];
    f[2] = 0.5 * w[4] * u1;
    f[3] = 0.5 * w[4] * u2;
    f[4] = 0.0;
    f[5] = r;
    if (lc->alone)
        return;
    /* P: the particle's acceleration less the field's, at its state */
    sw_lc_to(lc, w, lc->yb);
    sw_ode_eval(lc->base, w[5], lc->yb, lc->fb);
    double d1 = u1 * u1 - u2 * u2, d2 = 2 * u1 * u2, k = lc->mu / (r * r * r);
    double p1 = lc->fb[2] + k * d1, p2 = lc->fb[3] + k * d2;
    f[2] += 0.5 * r * (u1 * p1 + u2 * p2);
    f[3] += 0.5 * r * (u1 * p2 - u2 * p1);
    f[4] = r * (lc->yb[2] * p1 + lc->yb[3] * p2);
}

/* The same, alone in the field (P = 0): regularise.h's sw_lc_alone. */
void sw_lc_deriv_alone(void *ctx, double s, const double *w, double *f)
{
    (void)ctx, (void)s;
    sw_lc_alone(w, f);
}

int sw_lc_init(sw_lc *lc, sw_ode *base, double cx, double cy, double mu, char *err, size_t errlen)
{
    memset(lc, 0, sizeof *lc);
    if (base->dim != 4 || base->order != 2) {
        snprintf(err, errlen, "regularisation takes one particle in the plane (a state [x, y, vx, vy]); "
                 "this system has %d components", base->dim);
        return SW_EINVAL;
    }
    if (!(mu > 0) || !isfinite(mu) || !isfinite(cx) || !isfinite(cy)) {
        snprintf(err, errlen, "regularisation needs an attracting centre: mu > 0 and a finite position");
        return SW_EINVAL;
    }
    sw_central1 c;
    lc->base = base;
    lc->cx = cx;
    lc->cy = cy;
    lc->mu = mu;
    lc->alone = sw_ode_central1(base, &c) && c.cx == cx && c.cy == cy && c.mu * c.mass * c.inv == mu;
    lc->ode = (sw_ode){ .dim = SW_LC_DIM, .order = 1, .deriv = lc->alone ? sw_lc_deriv_alone : lc_deriv, .ctx = lc };
    return SW_OK;
}

int sw_lc_init_central(sw_lc *lc, sw_ode *base, char *err, size_t errlen)
{
    sw_central1 c;
    if (base->dim != 4 || !sw_ode_central1(base, &c)) {
        snprintf(err, errlen, "regularisation here takes one particle alone in one central field "
                 "(the orbit scene); this system is not that");
        return SW_EINVAL;
    }
    return sw_lc_init(lc, base, c.cx, c.cy, c.mu * c.mass * c.inv, err, errlen);
}

int sw_lc_from(const sw_lc *lc, double t, const double *y, double *w)
{
    double d1 = y[0] - lc->cx, d2 = y[1] - lc->cy, r = hypot(d1, d2), u1, u2;
    if (!(r > 0) || !isfinite(r) || !isfinite(y[2]) || !isfinite(y[3]))
        return SW_EINVAL;
    /* the square root with re(u) >= 0, each part from the larger of r ± d1 */
    if (d1 >= 0) {
        u1 = sqrt(0.5 * (r + d1));
        u2 = d2 / (2 * u1);
    } else {
        u2 = copysign(sqrt(0.5 * (r - d1)), d2);
        u1 = d2 / (2 * u2);
    }
    /* u' = conj(u)·v/2 */
    w[0] = u1;
    w[1] = u2;
    w[2] = 0.5 * (u1 * y[2] + u2 * y[3]);
    w[3] = 0.5 * (u1 * y[3] - u2 * y[2]);
    w[4] = 0.5 * (y[2] * y[2] + y[3] * y[3]) - lc->mu / r;
    w[5] = t;
    return SW_OK;
}

void sw_lc_to(const sw_lc *lc, const double *w, double *y)
{
    double u1 = w[0], u2 = w[1], r = u1 * u1 + u2 * u2;
    y[0] = lc->cx + (u1 * u1 - u2 * u2);
    y[1] = lc->cy + 2 * u1 * u2;
    /* v = 2u'/conj(u) = 2u'·u/r */
    y[2] = 2 * (w[2] * u1 - w[3] * u2) / r;
    y[3] = 2 * (w[2] * u2 + w[3] * u1) / r;
}

int sw_lc_resume(sw_lc_left *left, const sw_lc *lc, double t, const double *y)
{
    int same = left->valid && lc->alone && left->base == lc->base && left->cx == lc->cx && left->cy == lc->cy &&
               left->mu == lc->mu && memcmp(&left->t, &t, sizeof t) == 0 && /* bit for bit: -0 is not +0 */
               memcmp(left->y, y, sizeof left->y) == 0;
    left->valid = 0;
    return same ? 1 : sw_lc_from(lc, t, y, left->w);
}

void sw_lc_leave(sw_lc_left *left, const sw_lc *lc, double *y)
{
    sw_lc_to(lc, left->w, y);
    left->valid = 1;
    left->base = lc->base;
    left->cx = lc->cx;
    left->cy = lc->cy;
    left->mu = lc->mu;
    left->t = left->w[5];
    memcpy(left->y, y, sizeof left->y);
}

/* No component of w is infinite or NaN: the engine's runaway test with
 * the exponent limit at 0x7FF, which only those reach (stepper.h). */
static int finite6(const double *w) { return !sw_state_beyond(w, 0, SW_LC_DIM, 0x7FF); }

/* Newton's method on the length of the step from saved that ends at t_end,
 * from the step just taken past it (its length len). 1: w at t_end within 4
 * ulps of it (or, where 16 iterations did not get there, as t' -> 0 at a
 * collision, within 1e-9 of it); 0: a trial came out shorter than asked
 * (the error control shrank it), and w is that accepted step; -1: a step
 * failed. */
static int land(sw_lc *lc, sw_stepper *s, double *w, const double *saved, double len, double t_end)
{
    double tol = 4 * 0x1p-52 * fabs(t_end);
    for (int it = 0; it < 16; it++) {
        double g = w[5] - t_end;
        if (fabs(g) <= tol)
            return 1;
        len -= g / (w[0] * w[0] + w[1] * w[1]);
        memcpy(w, saved, SW_LC_DIM * sizeof *w);
        double sig = 0;
        s->have_cache = 0; /* its first-same-as-last derivative was the state it left */
        if (!(len > 0) || s->method->step(s, &lc->ode, &sig, w, len) != SW_OK || !finite6(w))
            return -1;
        if (sig < len * (1 - 1e-12))
            return 0;
    }
    return fabs(w[5] - t_end) <= 1e-9 * (1 + fabs(t_end)) ? 1 : -1;
}

static int failed(sw_lc *lc, const char *why)
{
    lc->why = why;
    return SW_EDIVERGED;
}

int sw_lc_step(sw_lc *lc, sw_stepper *s, double *w, double dt)
{
    double saved[SW_LC_DIM], sig = 0, t_end = w[5] + dt;
    memcpy(saved, w, sizeof saved);
    /* the length that reaches t_end, from t' = r and t'' = r' = 2 u·u',
     * a little more, so that a step the error control lets through passes
     * t_end and is then landed on it */
    double r = w[0] * w[0] + w[1] * w[1], rp = 2 * (w[0] * w[2] + w[1] * w[3]), disc = r * r + 2 * rp * dt;
    double len = disc > 0 ? 2 * dt / (r + sqrt(disc)) : dt / r, cap = isfinite(dt) ? 1.001 * len : INFINITY;
    if (!(cap > 0))
        return failed(lc, "in Levi-Civita's variables: no step reaches the time asked (the body at the centre)");
    if (s->method->step(s, &lc->ode, &sig, w, isfinite(cap) ? cap : 0x1p1000) != SW_OK)
        return failed(lc, "in Levi-Civita's variables: step size underflow, the error control gave up");
    if (!finite6(w))
        return failed(lc, "in Levi-Civita's variables: the state became non-finite");
    if (w[5] > t_end) {
        int rc = land(lc, s, w, saved, sig, t_end);
        if (rc < 0)
            return failed(lc, "in Levi-Civita's variables: the step could not be landed on the time asked "
                          "(Newton's method on its length failed; the orbit is lost: tighten rtol and atol)");
        if (rc > 0)
            w[5] = t_end; /* within 4 ulps of it: the clock is set, not the state carried */
    }
    if (!(w[5] > saved[5]))
        return failed(lc, "in Levi-Civita's variables: the clock stopped (t' = r = 0)");
    return SW_OK;
}

int sw_lc_run_until(sw_lc *lc, sw_stepper *s, double *w, double t_end, double *y)
{
    for (long steps = 0; w[5] < t_end; steps++)
        if (steps == 100000000L || sw_lc_step(lc, s, w, t_end - w[5]) != SW_OK)
            return SW_EDIVERGED;
    sw_lc_to(lc, w, y);
    return SW_OK;
}
