/* Measured order and stability limit of a method on the undamped spring.
 * The order is a least-squares slope over four halvings of dt, so one
 * unlucky error (a cancellation at the report time) cannot decide it. */
#include "measure/measure.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "plugin/plugin.h"
#include "measure/stability.h"
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

int sw_measure_order(const sw_integrator *m, double *order, char *err, size_t errlen)
{
    double p[SW_MAX_PARAMS], xs[4], ys[4], exact[4];
    const sw_scene *sc = spring_undamped(p);
    if (!sc) {
        snprintf(err, errlen, "no spring scene to measure on");
        return SW_EINVAL;
    }
    int n = 0;
    for (int k = 0; k < 4; k++) {
        double dt = 0.02 / (double)(1 << k);
        sw_sim s;
        char msg[SW_ERRLEN];
        if (sw_sim_init(&s, sc, p, m, dt, msg, sizeof msg) != SW_OK) {
            snprintf(err, errlen, "%s", msg);
            return SW_EINVAL;
        }
        int blown = sw_sim_run_until(&s, SW_MEASURE_T);
        if (blown) {
            sw_plugin_failed(&s);
            snprintf(err, errlen, "the run with dt = %g stopped at step %ld: %s", dt, s.blow_step,
                     s.blow_reason);
            sw_sim_free(&s);
            return SW_EINVAL;
        }
        double e = 0;
        if (sc->exact(&s.sys, s.t, exact) == 0)
            for (int i = 0; i < s.sys.ode->dim; i++)
                e = fmax(e, fabs(s.sys.y[i] - exact[i]));
        sw_sim_free(&s);
        if (e > 1e-11) {
            xs[n] = log(dt);
            ys[n] = log(e);
            n++;
        }
    }
    if (n < 2) {
        snprintf(err, errlen, "the errors are at round-off for every dt: the order cannot be "
                 "measured on this problem");
        return SW_EINVAL;
    }
    double mx = 0, my = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < n; i++) {
        mx += xs[i] / n;
        my += ys[i] / n;
    }
    for (int i = 0; i < n; i++) {
        sxx += (xs[i] - mx) * (xs[i] - mx);
        sxy += (xs[i] - mx) * (ys[i] - my);
    }
    *order = sxy / sxx;
    return SW_OK;
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
