/* Measured order and stability limit of a method on the undamped spring.
 * The order is read by the order rule every printed order passes
 * (sw_bench_order_rule): only from points above round-off, below 1e-2 of
 * the state, whose local slopes agree; else no order and why. */
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

/* The largest error against the exact solution over the sample times to
 * SW_MEASURE_T (one time can sit where a term cancels: symplectic Euler's
 * first-order one read 1.45 at t = 2 alone). NaN when the run blew up. */
static double run_error(const sw_scene *sc, const double *p, const sw_integrator *m, double dt, long *steps,
                        char *err, size_t errlen)
{
    sw_sim s;
    double scratch[2 * SW_MEASURE_DIM];
    if (sw_sim_init(&s, sc, p, m, dt, err, errlen) != SW_OK)
        return -1;
    if (s.sys.ode->dim > SW_MEASURE_DIM) {
        snprintf(err, errlen, "the measuring spring's state has %d numbers, over %d", s.sys.ode->dim,
                 SW_MEASURE_DIM);
        sw_sim_free(&s);
        return -1;
    }
    double e = 0;
    for (int j = sw_truth_first_sample(SW_MEASURE_T, dt); j <= SW_TRUTH_SAMPLES && !s.blown; j++) {
        sw_sim_run_until(&s, sw_truth_sample_time(SW_MEASURE_T, j));
        if (!s.blown)
            e = fmax(e, sw_sim_exact_error(&s, scratch));
    }
    if (s.blown) {
        sw_plugin_failed(&s);
        e = NAN;
    }
    *steps = s.steps;
    sw_sim_free(&s);
    return e;
}

/* The state's size over the samples: max(1, max |exact|). */
static double exact_scale(const sw_scene *sc, const double *p)
{
    sw_system sys;
    char err[SW_ERRLEN];
    double y[SW_MEASURE_DIM], scale = 1;
    if (sw_system_build(&sys, sc, p, err, sizeof err) != SW_OK)
        return scale;
    for (int j = 1; j <= SW_TRUTH_SAMPLES && sys.ode->dim <= SW_MEASURE_DIM; j++)
        if (sc->exact(&sys, sw_truth_sample_time(SW_MEASURE_T, j), y) == 0)
            for (int i = 0; i < sys.ode->dim; i++)
                scale = fmax(scale, fabs(y[i]));
    sw_system_free(&sys);
    return scale;
}

int sw_measure_order(const sw_integrator *m, double *order, sw_bench_series *fit, char *err, size_t errlen)
{
    double p[SW_MAX_PARAMS], h[SW_MEASURE_POINTS], e[SW_MEASURE_POINTS];
    long steps[SW_MEASURE_POINTS];
    static sw_bench_series own; /* large: kept off the stack when the caller has no use for it */
    sw_bench_series *s = fit ? fit : &own;
    const sw_scene *sc = spring_undamped(p);
    if (!sc) {
        snprintf(err, errlen, "no spring scene to measure on");
        return SW_EINVAL;
    }
    if (m->flags & SW_ADAPTIVE) {
        snprintf(err, errlen, "%s is adaptive: its tolerances, not dt, set its steps (stepwise bench reads its "
                 "order against them)", m->name);
        return SW_EINVAL;
    }
    double scale = exact_scale(sc, p);
    *order = NAN;
    int n = 0;
    for (int k = 0; k < SW_MEASURE_POINTS; k++) {
        h[k] = ldexp(SW_MEASURE_DT0, -k);
        char why[SW_ERRLEN];
        e[k] = run_error(sc, p, m, h[k], &steps[k], err, errlen);
        if (e[k] < 0)
            return SW_EINVAL;
        if (sw_plugin_last_failure(m, why, sizeof why) != SW_PF_NONE) {
            snprintf(err, errlen, "the run with dt = %g failed: the plugin %s", h[k], why);
            return SW_EINVAL;
        }
        n = k + 1;
        *order = sw_bench_order_rule(h, e, steps, n, scale, SW_BENCH_CEILING, s);
        /* settled, or down at round-off where finer steps only cost */
        if ((!isnan(*order) && s->nfit >= SW_MEASURE_SETTLED) ||
            e[k] < SW_BENCH_MARGIN * sw_bench_roundoff(scale, steps[k]))
            break;
    }
    if (isnan(*order)) {
        snprintf(err, errlen, "no order: %s (dt %g to %g)", sw_bench_no_order_text(s), h[0], h[n - 1]);
        return SW_EINVAL;
    }
    return SW_OK;
}

int sw_measure_stability_as_plugin(const sw_integrator *m, double *omega_dt, int *kind, char *err,
                                   size_t errlen)
{
    sw_integrator as_plugin = *m;
    as_plugin.flags &= ~SW_SYMPLECTIC;
    return sw_measure_stability(&as_plugin, omega_dt, kind, err, errlen);
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
    /* Lighter than `stability`'s defaults (a figure for feedback, from a
     * plugin that costs a round trip per step): 20 periods per probe,
     * bisection to 0.1%. */
    sw_stability_config cfg;
    sw_stability_config_default(&cfg);
    cfg.periods = 20;
    cfg.rel_tol = 1e-3;
    sw_stability_result res;
    int rc = sw_stability_find(sc, p, m, &cfg, &res, err, errlen);
    if (rc != SW_OK)
        return rc;
    char why[SW_ERRLEN];
    if (sw_plugin_last_failure(m, why, sizeof why) != SW_PF_NONE) {
        snprintf(err, errlen, "the plugin %s", why);
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
