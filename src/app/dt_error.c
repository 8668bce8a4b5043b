/* The error at the report time when Δt changes (app/dt_error.h). Pure C,
 * no terminal and no app: every run is its own sim, the truth its own copy
 * of the scene, so it may run on a worker while the picture steps the sims
 * on screen. Invariant: the numbers depend on the copied inputs alone. */
#include "app/dt_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "measure/bench.h"
#include "stepwise/stepwise.h"

void sw_dt_cache_free(sw_dt_cache *c)
{
    free(c->truth_report);
    sw_truth_work_free(c->work);
    memset(c, 0, sizeof *c);
}

static int stopped(const sw_dt_in *in) { return in->stop && atomic_load(in->stop); }

double sw_dt_state_error(int dim, int order, const double *y, const double *truth, int velocity)
{
    if (order != 2) /* a flow's state is positions alone */
        return velocity ? NAN : sw_truth_error(dim, y, truth);
    int half = dim / 2; /* y = [x | v] */
    return velocity ? sw_truth_error(half, y + half, truth + half) : sw_truth_error(half, y, truth);
}

/* The true state at the sample times to the report time (one reference
 * run, marching forward), computed once per scene, within the key-press
 * budget; the last sample is the report time's. */
static const double *truth_report(const sw_dt_in *in, sw_dt_cache *c)
{
    if (!c->have_truth_report && in->have_truth && in->truth_cost <= in->work_key) {
        size_t dim = (size_t)in->dim;
        sw_truth tr;
        char err[SW_ERRLEN];
        if (!c->truth_report) /* kept for the next try when this one finds no truth (fire, water) */
            c->truth_report = malloc(SW_TRUTH_SAMPLES * dim * sizeof *c->truth_report);
        if (c->truth_report && sw_truth_init(&tr, in->sc, in->p, err, sizeof err) == SW_OK) {
            int ok = tr.sys.ode->dim == in->dim;
            for (int j = 1; j <= SW_TRUTH_SAMPLES && ok && !stopped(in); j++) {
                const double *y = sw_truth_at(&tr, sw_truth_sample_time(in->sc->duration, j));
                if (y)
                    memcpy(c->truth_report + (size_t)(j - 1) * dim, y, dim * sizeof *y);
                ok = y != NULL;
            }
            c->have_truth_report = ok && !stopped(in);
            sw_truth_free(&tr);
        }
    }
    return c->have_truth_report ? c->truth_report : NULL;
}

/* The state's scale at the report time, for "the error is N% of the motion". */
static double report_scale(const sw_dt_in *in, sw_dt_cache *c)
{
    const double *want = truth_report(in, c);
    size_t dim = (size_t)in->dim;
    size_t npos = in->order == 2 ? dim / 2 : dim; /* positions: y = [x | v] */
    double scale = 1e-300;
    for (size_t j = 0; want && j < SW_TRUTH_SAMPLES; j++)
        for (size_t k = 0; k < npos; k++)
            scale = fmax(scale, fabs(want[j * dim + k]));
    return scale;
}

double sw_dt_error(const sw_dt_in *in, sw_dt_cache *c, const sw_integrator *m, double dt)
{
    const sw_scene *sc = in->sc;
    double T = sc->duration;
    if (!(dt > 0) || (T / dt) * in->step_work > in->work_key)
        return NAN;
    const double *want = truth_report(in, c);
    if (!want)
        return NAN;
    sw_sim s;
    char err[SW_ERRLEN];
    double e = NAN;
    if (sw_sim_init(&s, sc, in->p, m, dt, err, sizeof err) == SW_OK) {
        /* the run on screen's event mode: located events keep the order */
        if (sw_sim_set_events(&s, in->events, err, sizeof err) != SW_OK) {
            sw_sim_free(&s);
            return NAN;
        }
        /* the largest error over the samples (SW_TRUTH_SAMPLES): one report
         * time can be special, a whole run is not */
        int first = (m->flags & SW_ADAPTIVE) ? 1 : sw_truth_first_sample(T, dt);
        e = 0;
        for (int j = first; j <= SW_TRUTH_SAMPLES && !isnan(e); j++) {
            double t = sw_truth_sample_time(T, j);
            if (stopped(in) || sw_sim_run_until(&s, t) != 0 || fabs(s.t - t) > 1e-9 * fmax(1.0, T)) {
                e = NAN;
                break;
            }
            double ej = sw_dt_state_error(in->dim, in->order, s.sys.y, want + (size_t)(j - 1) * (size_t)in->dim, 0);
            if (!(ej <= e))
                e = ej;
        }
        sw_sim_free(&s);
    }
    return e;
}

/* The spectrum at the start (for the dt-change check), once per scene, on
 * a system of its own. */
static const sw_spectrum *spectrum0(const sw_dt_in *in, sw_dt_cache *c)
{
    if (!c->have_spec0 && in->have_truth) {
        sw_system sys;
        char err[SW_ERRLEN];
        if (!c->work)
            c->work = sw_truth_work_new();
        if (c->work && sw_system_build(&sys, in->sc, in->p, err, sizeof err) == SW_OK) {
            c->have_spec0 = sw_truth_spectrum_with(c->work, &sys, 0.0, sys.y, &c->spec0) == 0;
            sw_system_free(&sys);
        }
    }
    return c->have_spec0 ? &c->spec0 : NULL;
}

/* How much the method's worst mode grows over a run to the report time at
 * dt: ρ^(T/dt); NaN when unknown (adaptive, no spectrum). */
static double run_growth(const sw_dt_in *in, sw_dt_cache *c, double dt, double *rho)
{
    const sw_spectrum *sp = spectrum0(in, c);
    *rho = sp ? sw_truth_growth_with(c->work, in->m, sp, dt, NULL) : NAN;
    return pow(*rho, in->sc->duration / dt);
}

double sw_dt_change_work(const sw_dt_in *in, const sw_dt_cache *c)
{
    double T = in->sc->duration, small = fmin(in->old_dt, in->dt);
    double steps[3] = { T / in->old_dt, T / in->dt, 2 * T / small }, work = 0;
    for (int k = 0; k < 3; k++)
        if (steps[k] * in->step_work <= in->work_key)
            work += steps[k] * in->step_work;
    if (work > 0 && !c->have_truth_report && in->have_truth && in->truth_cost <= in->work_key)
        work += in->truth_cost;
    /* the spectrum: up to a few hundred passes, each about an evaluation */
    double evals = in->m->evals > 0 ? in->m->evals : 1;
    if (work > 0 && !c->have_spec0)
        work += 400 * in->step_work / evals;
    return work;
}

/* A symplectic method's large position error is mostly phase: it keeps
 * the energy and the path's shape, and runs ahead of or behind the truth
 * along it (lesson 8). */
/* Errors below this fraction of the motion are rounding (some 1e5 units
 * in the last place, summed over thousands of steps), never an order. */
#define SW_APP_ROUNDING 1e-11

/* The message fits errors up to half the motion (larger ones get "the
 * error is N% of the motion" above): the order rule's ceiling here. */
#define SW_APP_CEILING 0.5

#define PHASE_NOTE ". Symplectic: energy and path kept, the error is phase"

/* No order where the run's worst mode grows (the ratio measures growth),
 * the error is large against the motion, or the three runs disagree. */
static void read_order(const sw_dt_in *in, sw_dt_cache *c, double big, double small, sw_dt_result *out)
{
    const sw_integrator *m = in->m;
    double old_dt = in->old_dt, big_dt = fmax(old_dt, in->dt), T = in->sc->duration;
    double e_old = out->err[0], e_new = out->err[1], ratio = big / small;
    double rho, grow = run_growth(in, c, big_dt, &rho);
    double scale = report_scale(in, c);
    if (small <= SW_APP_ROUNDING * scale) {
        /* rounding, not truncation: a ratio of rounding errors is no order
         * (RK4 on a parabola, a located bounce without drag) */
        snprintf(out->message, sizeof out->message, "dt=%g: position error %.3g m to t=%.3g (%.3g m at dt=%g): "
                 "at rounding level (below %.0e of the motion), so %s is exact here and shows no order",
                 in->dt, e_new, T, e_old, old_dt, SW_APP_ROUNDING, m->name);
        return;
    }
    char head[160];
    snprintf(head, sizeof head, "dt=%g: position error %.3g m to t=%.3g (%.3g m at dt=%g), ratio %.3g",
             in->dt, e_new, T, e_old, old_dt, ratio);
    if (grow > 2) {
        snprintf(out->message, sizeof out->message, "%s: not an order - at dt=%g %s grows ×%.4g per step, "
                 "×%.2g by t=%.3g", head, big_dt, m->name, rho, grow, T);
        return;
    }
    if (big >= SW_APP_CEILING * scale) {
        /* an order shows only where the error is small: say which way that is */
        snprintf(out->message, sizeof out->message, "%s: not an order - at dt=%g the error is %.0f%% of the motion%s%s",
                 head, big_dt, 100 * big / scale,
                 in->dt < old_dt ? "; halve dt again" : " (an order shows at small dt only)",
                 (m->flags & SW_SYMPLECTIC) ? PHASE_NOTE : "");
        return;
    }
    /* the three runs through the order rule every printed order passes
     * (sw_bench_order_rule): above round-off, falling, local slopes within
     * 0.15 + 0.03·p of each other */
    double small_dt = fmin(old_dt, in->dt), e_next = sw_dt_error(in, c, m, 0.5 * small_dt);
    double h[3] = { big_dt, small_dt, 0.5 * small_dt }, e[3] = { big, small, e_next };
    long steps[3];
    for (int k = 0; k < 3; k++)
        steps[k] = (long)ceil(T / h[k]);
    sw_bench_series *fit = malloc(sizeof *fit); /* large: kept off the stack */
    double order = fit ? sw_bench_order_rule(h, e, steps, 3, scale, SW_APP_CEILING, fit) : NAN;
    if (stopped(in))
        out->stopped = 1;
    else if (!fit)
        snprintf(out->message, sizeof out->message, "%s: out of memory for the order", head);
    else if (isnan(order))
        snprintf(out->message, sizeof out->message, "%s: not an order yet - with dt=%g too, %s%s%s", head,
                 0.5 * small_dt, sw_bench_no_order_text(fit),
                 in->dt < old_dt ? "; halve dt again" : " (an order shows at small dt only)",
                 (m->flags & SW_SYMPLECTIC) && big > 0.05 * scale ? PHASE_NOTE : "");
    else {
        out->error_ratio = ratio;
        snprintf(out->message, sizeof out->message, "%s, order ~%.2f", head, order);
    }
    free(fit);
}

void sw_dt_change(const sw_dt_in *in, sw_dt_cache *c, sw_dt_result *out)
{
    const sw_integrator *m = in->m;
    double old_dt = in->old_dt, dt = in->dt;
    memset(out, 0, sizeof *out);
    out->error_ratio = NAN;
    out->err[0] = sw_dt_error(in, c, m, old_dt);
    out->err[1] = sw_dt_error(in, c, m, dt);
    if (stopped(in)) {
        out->stopped = 1;
        return;
    }
    double e_old = out->err[0], e_new = out->err[1];
    double big = old_dt > dt ? e_old : e_new, small = old_dt > dt ? e_new : e_old;
    double ratio = big / small, T = in->sc->duration;
    if (!isfinite(ratio) || !(small > 0)) {
        char why[SW_ERRLEN];
        double cost = (T / fmin(old_dt, dt)) * in->step_work;
        if (in->have_truth && in->truth_cost > in->work_key)
            snprintf(why, sizeof why, "no error measured: the reference to t=%.3g would cost %.2g state "
                     "evaluations, over the %.0e a key press may spend", T, in->truth_cost, in->work_key);
        else if (cost > in->work_key)
            snprintf(why, sizeof why, "no error measured: the run to t=%.3g would cost %.2g state evaluations, "
                     "over the %.0e a key press may spend", T, cost, in->work_key);
        else if (isnan(e_new) || isnan(e_old))
            snprintf(why, sizeof why, "no error to compare (%.200s)",
                     truth_report(in, c) ? "a run blew up" : in->truth_why);
        else
            snprintf(why, sizeof why, "the error is zero at one step: no ratio");
        snprintf(out->message, sizeof out->message, "dt=%g: %s", dt, why);
        return;
    }
    /* An order can be read from the ratio only where both runs are in the
     * asymptotic range: no mode grows much over the run (else the ratio
     * measures growth), the error is small against the motion, and halving
     * once more gives the same ratio (within 0.15 in its base-2 logarithm;
     * Euler's amplitude error on an oscillator, e^(ω²ΔtT/2) - 1, is not yet
     * proportional to Δt while the exponent is near 1). */
    if (m->flags & SW_ADAPTIVE) {
        /* dt only caps the steps: the error follows rtol and atol */
        snprintf(out->message, sizeof out->message, "dt=%g, the largest step %s may take: position error %.3g m "
                 "to t=%.3g (%.3g m at dt=%g); the tolerances set the error, not dt, so no order", dt, m->name,
                 e_new, T, e_old, old_dt);
        return;
    }
    read_order(in, c, big, small, out);
}
