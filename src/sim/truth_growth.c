/* Growth per step and stability limits, computed rather than quoted: a
 * method's growth on a mode is the spectral radius of the method's own
 * one-step map on that mode's test system, found by stepping unit states
 * with the method itself (so Verlet as implemented, damping, real
 * eigenvalues and plugins are all covered, with no formula per method); the
 * largest stable Δt is where the growth of some mode first exceeds one.
 * Invariant: with a workspace, nothing allocates after the first call for
 * a method (the live meter asks every frame). */
#include "sim/truth_work.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/linalg.h"
#include "engine/linear2.h"
#include "stepwise/stepwise.h"

double sw_truth_horizon(const sw_scene *sc, double stiffest)
{
    double unit = stiffest > 0 && isfinite(stiffest) ? 6.283185307179586 / stiffest : sc->duration;
    return fmax(100 * unit, 20 * sc->duration);
}

int sw_truth_growth_visible(double rho, double dt, double horizon)
{
    return rho > 1 && (horizon / dt) * log(rho) > log(1.01);
}

/* ---- a mode's test system --------------------------------------------------- */

static void test_system_init(sw_test_system *ts, int order, const sw_mode *md)
{
    double j[4] = { 0, 0, 0, 0 };
    if (order == 1) {
        j[0] = j[3] = md->re;
        j[1] = -md->im;
        j[2] = md->im;
    } else {
        /* B = λ + μ, A = -λμ (real: μ is λ's conjugate or both are real) */
        j[1] = 1;
        j[2] = -(md->re * md->pre - md->im * md->pim);
        j[3] = md->re + md->pre;
    }
    sw_linear2_init(ts, order, j);
}

/* Spectral radius of one step of size h from the stepper's method on the
 * test system. Columns of the map come from stepping the unit states; when
 * the method carries a derivative from one step to the next (FSAL: its
 * stepper keeps it in work vector 0), the map acts on the state and that
 * cache together, a 4x4 matrix. */
static double map_growth(sw_stepper *st, sw_test_system *ts, double h)
{
    double m[16], t;
    int cached = 0;
    for (int pass = 0; pass < 2; pass++) {
        int n = cached ? 4 : 2;
        for (int col = 0; col < n; col++) {
            double y[2] = { col == 0, col == 1 };
            sw_stepper_touch(st);
            if (cached) {
                st->work[0] = col == 2;
                st->work[1] = col == 3;
                st->have_cache = 1;
            }
            t = 0;
            if (sw_stepper_step(st, &ts->ode, &t, y, h) != SW_OK)
                return NAN;
            if (!cached && st->have_cache) {
                cached = 1; /* start over on the augmented state */
                break;
            }
            m[0 * n + col] = y[0];
            m[1 * n + col] = y[1];
            if (cached) {
                m[2 * n + col] = st->work[0];
                m[3 * n + col] = st->work[1];
            }
            if (col == n - 1)
                return sw_spectral_radius(n, m);
        }
    }
    return NAN;
}

/* Steppers of method m for the spectrum's modes: made once per method and
 * mode count, the test systems' matrices refreshed every call. */
static int steppers_for(sw_truth_work *w, const sw_integrator *m, const sw_spectrum *sp)
{
    char err[SW_ERRLEN];
    if (w->method != m)
        sw_truth_work_drop_steppers(w);
    w->method = m;
    for (int k = 0; k < sp->n; k++) {
        double was[4];
        int was_order = w->ts[k].ode.order;
        memcpy(was, w->ts[k].j, sizeof was);
        test_system_init(&w->ts[k], sp->order, &sp->mode[k]);
        if (k < w->ready && (m->flags & SW_PLUGIN) &&
            (was_order != w->ts[k].ode.order || memcmp(was, w->ts[k].j, sizeof was) != 0)) {
            /* A plugin steps in a child forked at its first step, which
             * keeps the test system as it was then: a new mode needs a new
             * stepper (a built-in reads the matrix afresh every step). */
            sw_stepper_free(&w->st[k]);
            if (sw_stepper_init(&w->st[k], m, &w->ts[k].ode, err, sizeof err) != SW_OK) {
                for (int i = k + 1; i < w->ready; i++)
                    sw_stepper_free(&w->st[i]);
                w->ready = k;
                return -1;
            }
        }
        if (k >= w->ready) {
            if (sw_stepper_init(&w->st[k], m, &w->ts[k].ode, err, sizeof err) != SW_OK)
                return -1;
            w->ready++;
        }
    }
    return 0;
}

static double steppers_growth(sw_truth_work *w, int n, double h, int *worst)
{
    double rho = 0;
    for (int k = 0; k < n; k++) {
        double g = map_growth(&w->st[k], &w->ts[k], h);
        if (!(g <= rho)) {
            rho = g;
            if (worst)
                *worst = k;
        }
    }
    return rho;
}

double sw_truth_growth_with(sw_truth_work *w, const sw_integrator *m, const sw_spectrum *sp, double h,
                            int *worst)
{
    if (m->flags & SW_ADAPTIVE)
        return NAN;
    if (sp->n == 0)
        return 1.0;
    return steppers_for(w, m, sp) == 0 ? steppers_growth(w, sp->n, h, worst) : NAN;
}

double sw_truth_growth_all(const sw_integrator *m, const sw_spectrum *sp, double h, int *worst)
{
    sw_truth_work *w = sw_truth_work_new();
    double rho = w ? sw_truth_growth_with(w, m, sp, h, worst) : NAN;
    sw_truth_work_free(w);
    return rho;
}

double sw_truth_limit_with(sw_truth_work *w, const sw_integrator *m, const sw_spectrum *sp, double h_max,
                           int *unbounded)
{
    *unbounded = 0;
    if (m->flags & SW_ADAPTIVE)
        return NAN;
    if (sp->n == 0 || !(sp->largest > 0)) {
        *unbounded = 1; /* nothing moves fast enough to constrain a step */
        return h_max;
    }
    if (steppers_for(w, m, sp) != 0)
        return NAN;
    /* Scan up geometrically for the first step that grows, then bisect.
     * A method growing already at |λ|·h = 0.01 has no stable step. */
    const double ok = 1.0 + SW_TRUTH_NEUTRAL;
    double lo = 0, hi = NAN, h = fmin(1e-2 / sp->largest, h_max);
    for (;;) {
        double g = steppers_growth(w, sp->n, h, NULL);
        if (isnan(g))
            return NAN; /* the method failed on a test system (a broken plugin) */
        if (!(g <= ok)) {
            hi = h;
            break;
        }
        lo = h;
        if (h >= h_max)
            break;
        h = fmin(h * 1.03, h_max);
    }
    if (isnan(hi)) {
        *unbounded = 1;
        return h_max;
    }
    if (lo > 0)
        for (int it = 0; it < 40 && hi / lo - 1 > 1e-9; it++) {
            double mid = sqrt(lo * hi);
            if (steppers_growth(w, sp->n, mid, NULL) <= ok)
                lo = mid;
            else
                hi = mid;
        }
    return lo;
}

double sw_truth_limit(const sw_integrator *m, const sw_spectrum *sp, double h_max, int *unbounded)
{
    sw_truth_work *w = sw_truth_work_new();
    *unbounded = 0; /* out of memory: NaN, not unbounded */
    double h = w ? sw_truth_limit_with(w, m, sp, h_max, unbounded) : NAN;
    sw_truth_work_free(w);
    return h;
}
