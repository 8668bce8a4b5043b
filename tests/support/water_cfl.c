/* The water scene's CFL limit, measured by bisection and from the theory. */
#include "water_cfl.h"

#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sim/truth.h"
#include "stepwise/stepwise.h"

/* A column of 100 particles at rest, with sets ("NAME=VALUE ...", or NULL) on top. */
static void column(sw_sim *s, const char *sets, const char *method, double dt)
{
    const sw_scene *sc = sw_scene_find("water");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN], buf[128];
    sw_scene_defaults(sc, p);
    snprintf(buf, sizeof buf, "n=100 shape=2 %s", sets ? sets : "");
    for (char *tok = strtok(buf, " "); tok; tok = strtok(NULL, " "))
        ck_assert_msg(sw_scene_set(sc, p, tok, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_sim_init(s, sc, p, sw_integrator_find(method), dt, err, sizeof err) == SW_OK, "%s", err);
}

/* Whether the column blows up within `horizon` seconds at step dt. */
static int column_blows(const char *sets, const char *method, double dt, double horizon)
{
    sw_sim s;
    column(&s, sets, method, dt);
    int n = s.sys.n, blown = 0;
    while (!blown && s.t < horizon) {
        blown = sw_sim_step(&s) != 0 || s.blown;
        for (int i = 0; i < n && !blown; i++)
            blown = !(hypot(s.sys.y[2 * n + 2 * i], s.sys.y[2 * n + 2 * i + 1]) < 5.0);
    }
    sw_sim_free(&s);
    return blown;
}

double water_cfl_theory(const char *sets, const char *method)
{
    sw_sim s;
    column(&s, sets, method, 0.001);
    sw_spectrum sp;
    ck_assert_int_eq(sw_truth_spectrum(&s.sys, 0.0, s.sys.y, &sp), 0);
    sw_sim_free(&s);
    int unbounded;
    return sw_truth_limit(sw_integrator_find(method), &sp, SW_DT_MAX, &unbounded);
}

void water_cfl_at(const char *sets, const char *method, double horizon, double *theory, double *measured)
{
    *theory = water_cfl_theory(sets, method);
    ck_assert_msg(*theory > 0, "%s has no limit in theory on the column", method);
    double lo = *theory / 8, hi = *theory * 8;
    ck_assert(!column_blows(sets, method, lo, horizon));
    while (!column_blows(sets, method, hi, horizon)) { /* Euler's boil reaches the blow-up speed late */
        lo = hi;
        hi *= 2;
        ck_assert_msg(hi < 256 * *theory, "%s: no blow-up within %g s up to %g s steps", method, horizon, hi);
    }
    while (hi / lo > 1.01) {
        double mid = sqrt(lo * hi);
        if (column_blows(sets, method, mid, horizon))
            hi = mid;
        else
            lo = mid;
    }
    *measured = lo;
}

void water_cfl(const char *method, double *theory, double *measured)
{
    water_cfl_at(NULL, method, 1.0, theory, measured);
}

double water_cfl_ratio(const char *method)
{
    double theory, measured;
    water_cfl(method, &theory, &measured);
    return measured / theory;
}
