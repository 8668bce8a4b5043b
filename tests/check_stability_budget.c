/* Issue 38: `stability --all` and `stability SCENE --set P=END` for every
 * scene and every parameter at both ends of its range return within their
 * budget. `stability bounce --set drag=0.5` never returned: its theory's
 * reference crawled through ever smaller bounces (resting contact now
 * ends them, tests/check_rest.c). Counted in work, never a clock: the
 * work each sw_stability_find reports (its probes' evaluations and its
 * theory's reference run, in SW_WORK_REPORT's units: state components ×
 * evaluations), summed over the methods the command runs, is at most
 * SW_WORK_REPORT wherever the command runs at all (`stability SCENE`
 * refuses before any run when the estimate is over the budget; --all does
 * so for a measured scene, and runs a theory-only one's reference). The reference is counted
 * once per method though the methods share it: an upper bound. At the
 * quick tier (SW_TEST_QUICK) one end per scene, in turn over its
 * parameters; at the full tier every scene's defaults and every end.
 * At the quick tier each scene runs half the fixed-step methods in turn,
 * under valgrind (SW_TEST_MEMCHECK, set by .ci/run) a quarter: every
 * method still runs on some scene and every scene with some methods (the
 * whole set took 18 s of make test's CPU, and 12 of CI's 47 minutes
 * under memcheck); the full tier runs them all. A subset's work is at
 * most the whole's, so the bound tested is the same. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "measure/measure.h"
#include "measure/stability.h"
#include "sim/truth.h"
#include "stepwise/stepwise.h"

static double worst; /* the largest share of the budget seen */

/* One method in `share` a scene: 4 under valgrind, 2 at the quick tier, all at the full. */
static int method_share(void)
{
    return getenv("SW_TEST_MEMCHECK") ? 4 : getenv("SW_TEST_QUICK") ? 2 : 1;
}

static void within_budget(const sw_scene *sc, const double *p, const char *what, int all, int turn)
{
    const sw_integrator *methods[32];
    int n = 0, fixed = 0, share = method_share();
    for (int i = 0; i < sw_integrator_count() && n < 32; i++)
        if (!(sw_integrator_at(i)->flags & SW_ADAPTIVE) && fixed++ % share == turn % share)
            methods[n++] = sw_integrator_at(i);
    char err[SW_ERRLEN], why[SW_ERRLEN];
    sw_system sys;
    if (sw_system_build(&sys, sc, p, err, sizeof err) != SW_OK)
        return; /* refused with its reason before anything runs */
    sw_system_free(&sys);
    sw_stability_config c;
    sw_stability_config_default(&c);
    double cost = sw_stability_cost_sum(sc, p, methods, n, &c, NULL);
    /* refused up front, "over the budget": `stability SCENE` whenever the
     * estimate is over it, --all for a measured scene (a theory-only one
     * runs its reference) */
    if ((!all || sw_stability_measurable(sc, p, why, sizeof why)) && !(cost <= SW_WORK_REPORT))
        return;
    double total = 0;
    for (int i = 0; i < n; i++) {
        sw_stability_result r;
        if (sw_stability_find(sc, p, methods[i], &c, &r, err, sizeof err) != SW_OK)
            continue; /* the method cannot step this scene: a row saying so */
        ck_assert_msg(r.work >= 0 && isfinite(r.work), "%s %s: work %g", what, methods[i]->name, r.work);
        total += r.work;
    }
    if (getenv("SW_BUDGET_PRINT"))
        fprintf(stderr, "%-32s work %.3g (estimate %.3g)\n", what, total, cost);
    worst = fmax(worst, total / SW_WORK_REPORT);
    ck_assert_msg(total <= SW_WORK_REPORT, "%s: work %.3g over the budget %.0e (estimated %.3g)", what, total,
                  SW_WORK_REPORT, cost);
}

START_TEST(every_scene_every_end)
{
    int quick = getenv("SW_TEST_QUICK") != NULL, runs = 0;
    worst = 0;
    for (int i = 0; i < sw_scene_count(); i++) {
        const sw_scene *sc = sw_scene_at(i);
        double p[SW_MAX_PARAMS];
        char what[160];
        sw_scene_fill(sc, NULL, p);
        if (!quick) { /* --all: the defaults */
            within_budget(sc, p, sc->name, 1, i);
            runs++;
        }
        for (int k = 0; k < sc->nparams; k++)
            for (int end = 0; end < 2; end++) {
                if (quick && (2 * k + end) % (2 * sc->nparams) != i % (2 * sc->nparams))
                    continue;
                sw_scene_fill(sc, NULL, p);
                p[k] = end ? sc->params[k].max : sc->params[k].min;
                snprintf(what, sizeof what, "%s %s=%g", sc->name, sc->params[k].name, p[k]);
                within_budget(sc, p, what, 0, i);
                runs++;
            }
    }
    ck_assert_int_ge(runs, quick ? sw_scene_count() : 3 * sw_scene_count());
}
END_TEST

/* The grader's budget spent on the test spring counts against the
 * plugin only where it went much slower a step than its graded runs
 * (red team 4: compared with the pace --cpu allowed, a plugin fast on
 * its 20 graded steps and slow only on the spring kept the point). */
START_TEST(pace_against_the_graded_runs)
{
    /* honest and slow everywhere: 200 graded steps in 2 s of CPU with its
     * build, the spring's 38 s budget gone in 3 000 steps (a smaller system) */
    ck_assert(sw_measure_pace_holds(2.3, 200, 38, 3000));
    /* red team 4's: 20 graded steps in 0.3 s (its build, mostly), 38 s gone
     * in 300 steps of the spring, 8.4 times slower a step */
    ck_assert(!sw_measure_pace_holds(0.3, 20, 38, 300));
    /* at the slack's edge: 4 times slower a step holds, more does not */
    ck_assert(sw_measure_pace_holds(1.0, 100, 4.0, 100));
    ck_assert(!sw_measure_pace_holds(1.0, 100, 4.01, 100));
    /* no steps, or no graded run: never held */
    ck_assert(!sw_measure_pace_holds(1.0, 0, 38, 100));
    ck_assert(!sw_measure_pace_holds(1.0, 100, 38, 0));
}
END_TEST

Suite *make_stability_budget_suite(void);
Suite *make_stability_budget_suite(void)
{
    Suite *s = suite_create("stability_budget");
    TCase *tc = tcase_create("budget");
    tcase_set_timeout(tc, 3600);
    tcase_add_test(tc, every_scene_every_end);
    tcase_add_test(tc, pace_against_the_graded_runs);
    suite_add_tcase(s, tc);
    return s;
}
