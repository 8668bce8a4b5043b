/* Measured order and stability limit of a method: the order on the run a
 * plugin is graded on (its probe) or on the undamped spring, the stability
 * limit on the spring. The order is read by the order rule every printed
 * order passes (sw_bench_order_rule): only from points above round-off,
 * below 1e-2 of the state, whose local slopes agree; else no order and why.
 * On a probe the fit must also stand on the graded dt, and the run there
 * must repeat the graded run bit for bit. */
#include "measure/measure.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "plugin/plugin.h"
#include "measure/stability.h"
#include "sim/truth.h"
#include "stepwise/stepwise.h"

static const sw_scene *spring_undamped(double *p)
{
    const sw_scene *sc = sw_scene_find("spring");
    if (!sc)
        return NULL;
    sw_scene_defaults(sc, p);
    int c = sw_scene_param_index(sc, "c");
    if (c >= 0)
        p[c] = 0.0;
    return sc;
}

/* One sweep: where it runs and how its points are sampled. */
typedef struct sweep {
    const sw_measure_probe *pr; /* NULL: the spring, sampled at the times to SW_MEASURE_T */
    sw_truth truth;
    double T;                   /* the samples' horizon */
    long n;                     /* a probe's: the steps of its first point to T */
} sweep;

/* The truth's size over the samples: max(1, max |truth|). */
static double truth_scale(sweep *w)
{
    double scale = 1;
    int dim = w->truth.sys.ode->dim;
    for (int j = 1; j <= SW_TRUTH_SAMPLES; j++) {
        const double *y = sw_truth_at(&w->truth, sw_truth_sample_time(w->T, j));
        for (int i = 0; y && i < dim; i++)
            scale = fmax(scale, fabs(y[i]));
    }
    return scale;
}

/* The error of s now against the truth at its own time (fmax drops NaN:
 * a blown run is told by s->blown). */
static double error_now(sweep *w, const sw_sim *s, double e)
{
    const double *y = sw_truth_at(&w->truth, s->t);
    return y ? fmax(e, sw_truth_error(s->sys.ode->dim, s->sys.y, y)) : NAN;
}

/* Point k of a probe's sweep (step dt/2^k): n·2^k whole steps from the
 * graded run's start, as the graded run steps, the error after every
 * 16th of them; point 0 goes on to the graded run's end and must land
 * where the graded run did, bit for bit. */
static double probe_point(sweep *w, sw_sim *s, int k, long *sampled, int *echo)
{
    const sw_measure_probe *pr = w->pr;
    long n = w->n << k, every = n >= SW_TRUTH_SAMPLES ? n / SW_TRUTH_SAMPLES : n;
    long last = k == 0 && pr->graded_y ? pr->graded_steps : n;
    double e = 0;
    while (s->steps < last && !s->blown) {
        sw_sim_step_until(s, k == 0 ? pr->stop_at : 0.0);
        if (s->steps <= n && s->steps % every == 0 && !s->blown)
            e = error_now(w, s, e);
    }
    if (k == 0 && pr->graded_y && !s->blown)
        *echo &= memcmp(s->sys.y, pr->graded_y, (size_t)s->sys.ode->dim * sizeof *s->sys.y) == 0;
    *sampled = n;
    return e;
}

/* The largest error against the truth over the point's samples (one time
 * can sit where a term cancels: symplectic Euler's first-order one read
 * 1.45 at t = 2 alone). NaN when the run blew up; -1 with err when it
 * could not start. */
static double run_error(sweep *w, const sw_integrator *m, int k, double h, long *steps, int *echo,
                        char *err, size_t errlen)
{
    sw_sim s;
    const sw_system *sys = &w->truth.sys;
    if (sw_sim_init(&s, sys->scene, sys->p, m, h, err, errlen) != SW_OK)
        return -1;
    double e = 0;
    *steps = 0;
    if (w->pr)
        e = probe_point(w, &s, k, steps, echo);
    else
        for (int j = sw_truth_first_sample(w->T, h); j <= SW_TRUTH_SAMPLES && !s.blown; j++) {
            sw_sim_run_until(&s, sw_truth_sample_time(w->T, j));
            if (!s.blown)
                e = error_now(w, &s, e);
        }
    if (s.blown) {
        sw_plugin_failed(&s);
        e = NAN;
    }
    if (!w->pr)
        *steps = s.steps;
    sw_sim_free(&s);
    return e;
}

double sw_measure_step_work(const sw_system *sys, const sw_integrator *m)
{
    double solve, evals = m->evals < 1 ? 1 : m->evals > 16 ? 16 : m->evals;
    return sw_truth_eval_work(sys, &solve) * evals;
}

/* Why a probe's fit does not stand on the graded dt, or NULL when it does:
 * the graded dt's point is in the fit, or (a method not yet quite
 * asymptotic there: symplectic Euler on the chain, local slope 1.20
 * against 1.01) it is clean and its slope to the fit's first point is
 * within SW_MEASURE_GRADED_SLOPE of the order. */
static const char *off_graded_dt(const sw_bench_series *s, double scale, char *buf, size_t len)
{
    const sw_bench_point *p0 = &s->points[0], *f = p0;
    while (f < s->points + s->npoints - 1 && !f->in_fit)
        f++;
    double e0 = p0->error, slope = log(e0 / f->error) / log(p0->h / f->h);
    if (p0->in_fit)
        return NULL;
    if (!(e0 < SW_BENCH_CEILING * scale))
        snprintf(buf, len, "at the graded dt (%g) the error is %.2g, %s 1e-2 of the state even over one step: the "
                 "order is read only from a sweep that starts at the graded dt", p0->h, e0,
                 isnan(e0) ? "not below" : "above");
    else if (e0 < SW_BENCH_MARGIN * p0->floor)
        snprintf(buf, len, "at the graded dt (%g) the error (%.2g) is already at round-off: no order can be read "
                 "from a sweep that starts there", p0->h, e0);
    else if (fabs(slope - s->order) < SW_MEASURE_GRADED_SLOPE)
        return NULL;
    else
        snprintf(buf, len, "the error at the graded dt (%g: %.2g) is off the line of the finer steps (slope "
                 "%.2f to dt = %g, order %.2f below it): a method not the same at every dt has no order", p0->h,
                 e0, slope, f->h, s->order);
    return buf;
}

int sw_measure_order_on(const sw_integrator *m, const sw_measure_probe *pr, double *order, sw_bench_series *fit,
                        char *err, size_t errlen)
{
    double p[SW_MAX_PARAMS], h[SW_MEASURE_POINTS], e[SW_MEASURE_POINTS];
    long steps[SW_MEASURE_POINTS];
    static sw_bench_series own; /* large: kept off the stack when the caller has no use for it */
    sw_bench_series *s = fit ? fit : &own;
    *order = NAN;
    if (m->flags & SW_ADAPTIVE) {
        snprintf(err, errlen, "%s is adaptive: its tolerances, not dt, set its steps (stepwise bench reads its "
                 "order against them)", m->name);
        return SW_EINVAL;
    }
    const sw_scene *sc = pr ? pr->scene : spring_undamped(p);
    if (!sc) {
        snprintf(err, errlen, "no spring scene to measure on");
        return SW_EINVAL;
    }
    sweep w = { .pr = pr };
    double dt0 = pr ? pr->dt : SW_MEASURE_DT0;
    if (pr && pr->whole)
        *pr->whole = 0;
    if (sw_truth_init(&w.truth, sc, pr ? pr->p : p, err, errlen) != SW_OK)
        return SW_EINVAL;
    if (w.truth.source == SW_TRUTH_NONE) {
        snprintf(err, errlen, "no true state to measure against: %s", w.truth.why);
        sw_truth_free(&w.truth);
        return SW_EINVAL;
    }
    /* a probe's budget, and what a step costs of it */
    double step = pr ? sw_measure_step_work(&w.truth.sys, m) : 0;
    double budget = pr ? fmax(SW_MEASURE_FREE, SW_MEASURE_GRADED * (double)pr->graded_steps * step) : 0;
    if (pr) {
        /* the whole graded run where four points over it fit the budget
         * (a method that changes after some steps shows then), else its
         * first SW_MEASURE_PROBE_STEPS steps */
        long all = pr->graded_steps > 1 ? pr->graded_steps : 1;
        w.n = 15.0 * (double)all * step <= budget ? all : all < SW_MEASURE_PROBE_STEPS ? all : SW_MEASURE_PROBE_STEPS;
        w.T = (double)w.n * dt0;
    } else
        w.T = SW_MEASURE_T;
    if (pr) { /* the reference run behind the errors is the grader's work: within SW_MEASURE_REF_WORK */
        double solve, eval = sw_truth_eval_work(&w.truth.sys, &solve);
        w.truth.max_evals = (long)fmax(1, fmin(1e12, SW_MEASURE_REF_WORK / fmax(eval, 1)));
    }
    double scale = truth_scale(&w);
    int n = 0, echo = 1, rc = SW_OK;
    char why[SW_ERRLEN];
    /* what the first point costs (the rerun of the graded run to its end
     * included) */
    double spent = pr ? (double)(pr->graded_y ? (pr->graded_steps > w.n ? pr->graded_steps : w.n) : w.n) * step : 0;
    for (int k = 0; k < SW_MEASURE_POINTS && rc == SW_OK; k++) {
        if (pr && k > 0 && (spent += ldexp((double)w.n, k) * step) > budget)
            break; /* the sweep's budget: the order rule says what the points so far carry */
        h[k] = ldexp(dt0, -k);
        e[k] = run_error(&w, m, k, h[k], &steps[k], &echo, err, errlen);
        /* a probe's horizon: halved (to one step) until the graded dt's
         * error is below the ceiling, where an order can stand on it */
        while (k == 0 && pr && w.n > 1 && e[0] >= SW_BENCH_CEILING * scale) {
            w.n /= 2;
            w.T = (double)w.n * dt0;
            scale = truth_scale(&w);
            e[0] = run_error(&w, m, 0, h[0], &steps[0], &echo, err, errlen);
        }
        if (w.truth.failed) {
            snprintf(err, errlen, "no true state to measure against: %s", w.truth.why);
            rc = SW_EINVAL;
        } else if (e[k] < 0)
            rc = SW_EINVAL;
        else if (sw_plugin_last_failure(m, why, sizeof why) != SW_PF_NONE) {
            snprintf(err, errlen, "the run with dt = %g failed: the plugin %s", h[k], why);
            rc = SW_EINVAL;
        } else if (!echo) {
            snprintf(err, errlen, "the plugin's run at the graded dt did not repeat its graded run (the same "
                     "steps from the same state gave other numbers): a method that changes between runs has no "
                     "measured order");
            rc = SW_EINVAL;
        }
        if (rc != SW_OK)
            break;
        n = k + 1;
        *order = sw_bench_order_rule(h, e, steps, n, scale, SW_BENCH_CEILING, s);
        /* settled, or down at round-off where finer steps only cost */
        if ((!isnan(*order) && s->nfit >= SW_MEASURE_SETTLED) ||
            e[k] < SW_BENCH_MARGIN * sw_bench_roundoff(scale, steps[k]))
            break;
    }
    sw_truth_free(&w.truth);
    if (pr && pr->span)
        *pr->span = w.n;
    if (rc != SW_OK) {
        *order = NAN;
        return rc;
    }
    if (pr && pr->whole) /* the sweep spans the graded run, and its first point repeated it */
        *pr->whole = pr->graded_y && echo && w.n >= pr->graded_steps;
    const char *off = !isnan(*order) && pr ? off_graded_dt(s, scale, why, sizeof why) : NULL;
    if (isnan(*order) || off) {
        *order = NAN;
        snprintf(err, errlen, "no order: %s (dt %g to %g)", off ? off : sw_bench_no_order_text(s), h[0],
                 h[n - 1]);
        return SW_EINVAL;
    }
    return SW_OK;
}

int sw_measure_order(const sw_integrator *m, double *order, sw_bench_series *fit, char *err, size_t errlen)
{
    return sw_measure_order_on(m, NULL, order, fit, err, errlen);
}

int sw_measure_stability_as_plugin(const sw_integrator *m, double *omega_dt, int *kind, char *err,
                                   size_t errlen)
{
    sw_integrator as_plugin = *m;
    as_plugin.flags &= ~SW_SYMPLECTIC;
    return sw_measure_stability(&as_plugin, omega_dt, kind, err, errlen);
}

/* Lighter than `stability`'s defaults (a figure for feedback, from a
 * plugin that costs a round trip per step): 20 periods per probe,
 * bisection to 0.1%. */
static void light_config(sw_stability_config *cfg)
{
    sw_stability_config_default(cfg);
    cfg->periods = 20;
    cfg->rel_tol = 1e-3;
}

/* A failure of m's in its last run, as an error: 0 none, else 1 with err
 * filled, and *limit (when not NULL) 1 where it was a CPU limit. */
static int plugin_failed(const sw_integrator *m, int *limit, char *err, size_t errlen)
{
    char why[SW_ERRLEN];
    sw_plugin_fault f = sw_plugin_last_failure(m, why, sizeof why);
    if (limit)
        *limit = f == SW_PF_LIMIT;
    if (f == SW_PF_NONE)
        return 0;
    snprintf(err, errlen, "the plugin %s", why);
    return 1;
}

int sw_measure_stability(const sw_integrator *m, double *omega_dt, int *kind, char *err,
                         size_t errlen)
{
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = spring_undamped(p);
    if (!sc) {
        snprintf(err, errlen, "no spring scene to measure on");
        return SW_EINVAL;
    }
    sw_stability_config cfg;
    light_config(&cfg);
    sw_stability_result res;
    int rc = sw_stability_find(sc, p, m, &cfg, &res, err, errlen);
    if (rc != SW_OK)
        return rc;
    if (plugin_failed(m, NULL, err, errlen))
        return SW_EINVAL;
    /* a step that refused (returned non-zero) above some step size is no
     * instability: its limit would be where it refuses (student pass) */
    if (res.fail.verdict == SW_PROBE_BLOWN && sw_sim_refused(res.fail.reason)) {
        snprintf(err, errlen, "%.300s (at omega*dt = %.4g on the undamped spring): a step that refuses is not "
                 "one that grows", res.fail.reason, res.fail.dt * res.stiff);
        return SW_EINVAL;
    }
    if (!res.measured) {
        snprintf(err, errlen, "%s", res.why[0] ? res.why : "growth cannot be measured here");
        return SW_EINVAL;
    }
    *kind = (int)res.kind;
    *omega_dt = res.dt * res.stiff; /* the undamped spring's only mode: |λ| = ω = √(k/m) */
    return SW_OK;
}

/* One probe of m at step dt over cfg's horizon, its steps added to out's:
 * 1 held (stable or decayed), 0 did not, -1 m failed (err filled,
 * out->budget 1 where it was its CPU time). */
static int holds(const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                 const sw_stability_config *cfg, sw_stability_match *out, char *err, size_t errlen)
{
    sw_stability_probe pr;
    if (sw_stability_probe_run(sc, p, m, dt, cfg, &pr, err, errlen) != SW_OK)
        return -1;
    out->steps += pr.steps;
    if (plugin_failed(m, &out->budget, err, errlen))
        return -1;
    return pr.verdict == SW_PROBE_STABLE || pr.verdict == SW_PROBE_DECAYED;
}

int sw_measure_stability_match(const sw_integrator *m, const sw_integrator *ref, double rel,
                               sw_stability_match *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    out->limit = out->inside = out->outside = NAN;
    out->held_inside = out->held_outside = -1;
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = spring_undamped(p);
    if (!sc) {
        snprintf(err, errlen, "no spring scene to measure on");
        return SW_EINVAL;
    }
    /* the method's limit, measured as a plugin is (its flags but
     * SW_SYMPLECTIC: sw_measure_stability_as_plugin) */
    sw_integrator as_plugin = *ref;
    as_plugin.flags &= ~SW_SYMPLECTIC;
    sw_stability_config cfg;
    light_config(&cfg);
    sw_stability_result res;
    int rc = sw_stability_find(sc, p, &as_plugin, &cfg, &res, err, errlen);
    if (rc != SW_OK)
        return rc;
    if (!res.measured) {
        snprintf(err, errlen, "%s", res.why[0] ? res.why : "growth cannot be measured here");
        return SW_EINVAL;
    }
    out->kind = (int)res.kind;
    double w = res.stiff;
    out->limit = res.kind == SW_STAB_NONE ? 0.0 : res.kind == SW_STAB_UNBOUNDED ? INFINITY : res.dt * w;
    /* m's probes over the horizon that set the method's limit: a limit
     * within rel of it holds at (1 - rel) of it and not at (1 + rel);
     * none, as the method's, fails at its smallest step; unbounded holds
     * at its largest */
    cfg.horizon = res.horizon;
    double in = res.kind == SW_STAB_LIMIT ? res.dt * (1 - rel) : res.kind == SW_STAB_UNBOUNDED ? res.dt : NAN;
    double outside = res.kind == SW_STAB_LIMIT ? res.dt * (1 + rel) : res.kind == SW_STAB_NONE ? res.dt : NAN;
    if (!isnan(in)) {
        out->inside = in * w;
        out->held_inside = holds(sc, p, m, in, &cfg, out, err, errlen);
        if (out->held_inside < 0)
            return SW_EINVAL;
    }
    if (!isnan(outside) && out->held_inside != 0) {
        out->outside = outside * w;
        out->held_outside = holds(sc, p, m, outside, &cfg, out, err, errlen);
        if (out->held_outside < 0)
            return SW_EINVAL;
    }
    out->match = out->held_inside != 0 && out->held_outside != 1;
    return SW_OK;
}

int sw_measure_pace_holds(double graded_cpu, long graded_steps, double spent, long steps)
{
    /* spent/steps <= slack * graded_cpu/graded_steps, without a division */
    return graded_steps > 0 && steps > 0 && graded_cpu >= 0 &&
           spent * (double)graded_steps <= SW_MEASURE_PACE_SLACK * graded_cpu * (double)steps;
}
