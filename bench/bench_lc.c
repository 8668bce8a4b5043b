/* The orbit's engines on the same equations (issue 41): GSL's rk8pd
 * stepping Levi-Civita's regularised Kepler problem, landed on the report
 * time by the very code that lands dop853-lc (sw_lc_run_until), so that
 * dop853-lc is measured against GSL on its own equations and the
 * difference left is the engines'. GSL calls the five-line right-hand side
 * its user writes; it steps through gsl_odeiv2_evolve_apply, one step of at
 * most what the landing allows, as a method of stepwise's table would. */
#include <math.h>
#include <string.h>

#include "bench_common.h"
#include "engine/regularise.h"
#include "stepwise/sim.h"

#ifdef SW_HAVE_GSL
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

static long lc_evals;

/* w = [u1, u2, u1', u2', h, t]; f = dw/ds for one body alone about its
 * centre: the oscillator u'' = (h/2)·u and the clock t' = |u|² (the
 * arithmetic of regularise.c's lc_deriv without a perturbation). */
static int gsl_lc_deriv(double s, const double w[], double f[], void *params)
{
    (void)s, (void)params;
    lc_evals++;
    f[0] = w[2];
    f[1] = w[3];
    f[2] = 0.5 * w[4] * w[0];
    f[3] = 0.5 * w[4] * w[1];
    f[4] = 0.0;
    f[5] = w[0] * w[0] + w[1] * w[1];
    return GSL_SUCCESS;
}

static gsl_odeiv2_driver *lc_driver;

/* One step of GSL's evolve of at most h_max, its proposal kept in h_next. */
static int gsl_lc_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    (void)ode;
    double h = s->h_next > 0 ? s->h_next : h_max;
    if (!s->have_cache) /* a step from a state set from outside (the landing's retries) */
        gsl_odeiv2_evolve_reset(lc_driver->e);
    s->have_cache = 1;
    int rc = gsl_odeiv2_evolve_apply(lc_driver->e, lc_driver->c, lc_driver->s, lc_driver->sys, t, *t + h_max, &h, y);
    s->h_next = h;
    return rc == GSL_SUCCESS ? SW_OK : SW_EDIVERGED;
}

static const sw_integrator gsl_rk8pd_lc = { .name = "rk8pd-lc", .flags = SW_EXPLICIT | SW_ADAPTIVE,
                                            .step = gsl_lc_step };

int bench_lc_run(const sw_integrator *m, sw_ode *ode, const double *y0, double T, double tol, double *y,
                 double *seconds, long *evals)
{
    char err[SW_ERRLEN];
    sw_lc lc;
    sw_stepper st;
    double w[SW_LC_DIM];
    gsl_odeiv2_system sys = { gsl_lc_deriv, NULL, SW_LC_DIM, NULL };
    if (sw_lc_init_central(&lc, ode, err, sizeof err) != SW_OK || sw_lc_from(&lc, 0.0, y0, w) != SW_OK ||
        sw_stepper_init(&st, m ? m : &gsl_rk8pd_lc, &lc.ode, err, sizeof err) != SW_OK)
        return -1;
    st.rtol = st.atol = tol;
    lc_driver = m ? NULL : gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, tol, tol);
    if (!m && !lc_driver) {
        sw_stepper_free(&st);
        return -1;
    }
    lc_evals = 0;
    double t0 = thread_seconds();
    int rc = sw_lc_run_until(&lc, &st, w, T, y);
    *seconds = thread_seconds() - t0;
    *evals = m ? lc.ode.evals : lc_evals;
    if (lc_driver)
        gsl_odeiv2_driver_free(lc_driver);
    sw_stepper_free(&st);
    return rc == SW_OK ? 0 : -1;
}
#endif

/* For counting instructions (callgrind): `runs` runs to the orbit's report
 * time at rtol = atol = tol of dop853-lc through the sim ("dop853-lc") or
 * of GSL's rk8pd on the same equations ("rk8pd-lc"), or the sim's set-up
 * that each run makes alone ("setup"); 0, or 1. */
int bench_lc_probe(const char *who, double tol, long runs)
{
    const sw_scene *sc = sw_scene_find("orbit");
    double p[SW_MAX_PARAMS], y[4], sec;
    char err[SW_ERRLEN];
    long ev;
    int ok = sc != NULL;
    if (!ok)
        return 1;
    sw_scene_defaults(sc, p);
    ok = sw_scene_set(sc, p, "e=0.9", err, sizeof err) == SW_OK;
    for (long r = 0; ok && r < runs; r++) {
        sw_sim s;
        ok = sw_sim_init(&s, sc, p, sw_integrator_find("dop853-lc"), sc->duration, err, sizeof err) == SW_OK;
        if (!ok)
            break;
        sw_sim_set_tolerances(&s, tol, tol);
        if (strcmp(who, "dop853-lc") == 0)
            ok = !sw_sim_run_until(&s, sc->duration);
#ifdef SW_HAVE_GSL
        else if (strcmp(who, "rk8pd-lc") == 0)
            ok = bench_lc_run(NULL, s.sys.ode, s.sys.y, sc->duration, tol, y, &sec, &ev) == 0;
#endif
        else
            ok = strcmp(who, "setup") == 0; /* the sim's set-up alone, to subtract */
        sw_sim_free(&s);
    }
    (void)y, (void)sec, (void)ev;
    return ok ? 0 : 1;
}
