/* The water scene's CFL limit, measured by bisection and from the theory. */
#include "water_cfl.h"

#include <check.h>
#include <math.h>

#include "sim/truth.h"
#include "stepwise/stepwise.h"

static void column(sw_sim *s, const char *method, double dt)
{
    const sw_scene *sc = sw_scene_find("water");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    ck_assert(sw_scene_set(sc, p, "n=100", err, sizeof err) == SW_OK);
    ck_assert(sw_scene_set(sc, p, "shape=2", err, sizeof err) == SW_OK);
    ck_assert_msg(sw_sim_init(s, sc, p, sw_integrator_find(method), dt, err, sizeof err) == SW_OK, "%s", err);
}

/* Whether the column blows up within 1 s at step dt. */
static int column_blows(const char *method, double dt)
{
    sw_sim s;
    column(&s, method, dt);
    int n = s.sys.n, blown = 0;
    while (!blown && s.t < 1.0) {
        blown = sw_sim_step(&s) != 0 || s.blown;
        for (int i = 0; i < n && !blown; i++)
            blown = !(hypot(s.sys.y[2 * n + 2 * i], s.sys.y[2 * n + 2 * i + 1]) < 5.0);
    }
    sw_sim_free(&s);
    return blown;
}

void water_cfl(const char *method, double *theory, double *measured)
{
    sw_sim s;
    column(&s, method, 0.001);
    sw_spectrum sp;
    ck_assert_int_eq(sw_truth_spectrum(&s.sys, 0.0, s.sys.y, &sp), 0);
    sw_sim_free(&s);
    int unbounded;
    *theory = sw_truth_limit(sw_integrator_find(method), &sp, SW_DT_MAX, &unbounded);
    double lo = *theory / 8, hi = *theory * 8;
    ck_assert(!column_blows(method, lo) && column_blows(method, hi));
    while (hi / lo > 1.01) {
        double mid = sqrt(lo * hi);
        if (column_blows(method, mid))
            hi = mid;
        else
            lo = mid;
    }
    *measured = lo;
}

double water_cfl_ratio(const char *method)
{
    double theory, measured;
    water_cfl(method, &theory, &measured);
    return measured / theory;
}
