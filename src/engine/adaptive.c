/* The step-size controller of the embedded explicit Runge-Kutta pairs
 * (rk45, dop853, the Nystrom pairs rkn and rkn12) and the Rosenbrock method (rodas4): trial, error
 * norm, accept or reject, next step. It copies
 * nothing on an accepted step and allocates nothing. */
#include "engine/adaptive.h"

#include <math.h>
#include <string.h>

#include "stepwise/base.h"

/* Hairer's HINIT: a first step from the size of f and of its change over an
 * explicit Euler step, such that h^order·max(|f|, |f'|) ≈ 0.01 in the
 * weighted norm; at most 100 times the Euler probe and at most h_max. One
 * evaluation, into scratch vectors y1 and f1. */
static double first_step(sw_stepper *s, sw_ode *ode, double t, const double *y, const double *f0,
                         double *y1, double *f1, double order, double h_max)
{
    int n = ode->dim;
    double dnf = 0, dny = 0;
    for (int i = 0; i < n; i++) {
        double sk = s->atol + s->rtol * fabs(y[i]);
        dnf += (f0[i] / sk) * (f0[i] / sk);
        dny += (y[i] / sk) * (y[i] / sk);
    }
    double h = dnf <= 1e-10 || dny <= 1e-10 ? 1e-6 : sqrt(dny / dnf) * 0.01;
    h = fmin(h, h_max);
    for (int i = 0; i < n; i++)
        y1[i] = y[i] + h * f0[i];
    sw_ode_eval(ode, t + h, y1, f1);
    double der2 = 0;
    for (int i = 0; i < n; i++) {
        double sk = s->atol + s->rtol * fabs(y[i]), d = (f1[i] - f0[i]) / sk;
        der2 += d * d;
    }
    der2 = sqrt(der2) / h;
    double der12 = fmax(fabs(der2), sqrt(dnf));
    double h1 = der12 <= 1e-15 ? fmax(1e-6, h * 1e-3) : pow(0.01 / der12, 1.0 / order);
    h = fmin(fmin(100 * h, h1), h_max);
    return h > 0 ? h : h_max; /* NaN (a non-finite f) falls back to h_max */
}

/* fmax(lo, x) and fmin(hi, x) as comparisons the compiler keeps inline
 * (fmax and fmin are library calls without -ffinite-math-only): the same
 * values, a NaN x giving the bound as they do. The controller calls them
 * on every step. */
static inline double at_least(double lo, double x) { return x > lo ? x : lo; }
static inline double at_most(double hi, double x) { return x < hi ? x : hi; }

/* The trial over the whole state, or slice by slice on pointwise systems
 * (every stage of a slice needs only that slice, and the sums are added in
 * the same order either way). */
static void run_trial(const sw_adaptive *m, sw_stepper *s, sw_ode *ode, double t, double *y, double h,
                      unsigned elim, sw_trial_sums *sums)
{
    memset(sums, 0, sizeof *sums);
    if (sw_ode_deriv_part(ode) && !m->coupled)
        for (int lo = 0; lo < ode->dim; lo += m->slice)
            m->trial(s, ode, t, y, h, lo, lo + m->slice < ode->dim ? lo + m->slice : ode->dim, elim, sums);
    else
        m->trial(s, ode, t, y, h, 0, ode->dim, elim, sums);
    ode->evals += m->evals;
}

int sw_adaptive_step(const sw_adaptive *m, sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    int n = ode->dim;
    if (!s->have_cache) {
        s->fsal = 0;
        sw_ode_eval(ode, *t, y, SW_WORK(s, 0));
        s->have_cache = 1;
    }
    double *saved = SW_WORK(s, m->saved);
    double h = s->h_next > 0 && s->h_next < h_max ? s->h_next : h_max;
    if (m->guess_first && !(s->h_next > 0) && s->rtol < SW_TOL_NONE) /* no control: h_max from the start */
        h = first_step(s, ode, *t, y, SW_WORK(s, s->fsal), saved, SW_WORK(s, s->fsal ? 0 : m->fsal_other),
                       1.0 / m->expo, h_max);
    unsigned elim = s->limit_exp ? s->limit_exp : 0x800; /* 0x800: never */
    int rejected = 0;
    for (int tries = 0; tries < 200; tries++) {
        sw_trial_sums sums;
        run_trial(m, s, ode, *t, y, h, elim, &sums);
        double err;
        if (m->hairer_norm) {
            /* err5²/√(err5² + 0.01·err3²): the 5th-order estimate, damped
             * where the 3rd-order one says the 5th is unreliably small. */
            double deno = sums.err + 0.01 * sums.err3;
            err = fabs(h) * sums.err * sqrt(1.0 / (n * (deno > 0 ? deno : 1.0)));
        } else {
            err = sqrt(sums.err / n);
        }
        if (!(err == err)) { /* non-finite trial: shrink hard */
            memcpy(y, saved, (size_t)n * sizeof *y);
            s->rejected++;
            rejected = 1;
            h *= 0.1;
            continue;
        }
        double grow = err > 0 ? m->safety * pow(err, -m->expo) : m->fac_max;
        if (err <= 1.0) {
            s->fsal = s->fsal ? 0 : m->fsal_other;
            *t += h;
            if (m->predict && s->err_last > 0) {
                /* err ≈ C·h^(1/expo) with C extrapolated from the last step:
                 * equal to grow while C stays the same, smaller while it grows
                 * (an orbit falling towards its pericentre) */
                double trend = m->safety * (h / s->h_last) * pow(s->err_last / (err * err), m->expo);
                grow = at_most(grow, trend); /* grow is finite: fmin(grow, trend) */
            }
            s->h_last = h;
            s->err_last = m->predict ? at_least(0.01, err) : 0;
            s->h_next = h * at_most(m->fac_max, at_least(m->fac_min, grow));
            if (m->hold && rejected && s->h_next > h)
                s->h_next = h;
            s->accepted++;
            s->checked = s->limit_exp != 0;
            s->beyond = sums.beyond != 0;
            return 0;
        }
        memcpy(y, saved, (size_t)n * sizeof *y);
        s->rejected++;
        rejected = 1;
        h *= at_least(m->fac_min, grow);
        if (h < 1e-14 * at_least(1.0, fabs(*t)))
            break;
    }
    return SW_EDIVERGED;
}
