/* The growth watch (src/sim/watch.c) on made-up series of M, the energy of
 * the motion as a fraction of its start, where the right verdict is known by
 * construction: bounded oscillation, decay into rounding noise, energy that
 * sank and came back, slow steady growth, a thousandfold jump and NaN. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "sim/watch.h"
#include "stepwise/stepwise.h"

/* Feed M(t) at steps of 0.01 over [0, T) into a watch with 1-s windows. */
static sw_watch_verdict feed(double raised, double T, double (*m)(double t), double *when)
{
    sw_watch w;
    sw_watch_init(&w, 1.0, raised);
    for (long k = 0; k * 0.01 < T; k++) {
        double t = k * 0.01;
        if (sw_watch_add(&w, t, m(t)) != SW_WATCH_STEADY) {
            *when = t;
            return w.verdict;
        }
    }
    *when = T;
    return sw_watch_finish(&w);
}

/* a symplectic method near its limit: energy swinging between 0.2 and 1.8 */
static double swinging(double t) { return 1 + 0.8 * sin(40 * t); }
/* damped to rounding: e^-t down to 1e-15, then noise of that size */
static double damped(double t) { return exp(-3 * t) + 1e-15 * (1 + sin(1e3 * t)); }
/* sank to a twentieth, then pumped back up to 0.9 (a limit cycle below
 * the start, raised from its low all the same) */
static double rebound(double t) { return t < 5 ? exp(-0.6 * t) : fmin(0.9, 0.05 * exp(0.5 * (t - 5))); }
/* grows 1% a second, steadily: never near any level within 19 s */
static double creeping(double t) { return exp(0.01 * t) * (1 + 0.01 * sin(30 * t)); }
static double jump(double t) { return t < 3 ? 1 : 2000; }
static double not_a_number(double t) { return t < 3 ? 1 : NAN; }

START_TEST(test_verdicts)
{
    double when;
    ck_assert_int_eq(feed(3, 20, swinging, &when), SW_WATCH_STEADY);
    ck_assert_int_eq(feed(3, 20, damped, &when), SW_WATCH_STEADY);
    ck_assert_int_eq(feed(3, 20, rebound, &when), SW_WATCH_RAISED);
    /* 3x the low of 0.05 (the window over t in [4, 5], mean ~0.07) is passed
     * within the window that ends at t = 8 */
    ck_assert_double_le(when, 9.0);
    /* a symplectic method's factor of 30 is not reached by 0.9/0.05 */
    ck_assert_int_eq(feed(30, 20, rebound, &when), SW_WATCH_STEADY);
    ck_assert_int_eq(feed(3, 20, creeping, &when), SW_WATCH_TREND);
    ck_assert_int_eq(feed(3, 20, jump, &when), SW_WATCH_BOUND);
    ck_assert_double_lt(when, 3.02);
    ck_assert_int_eq(feed(3, 20, not_a_number, &when), SW_WATCH_BOUND);
}
END_TEST

/* like symplectic Euler from rest at 99.8% of its limit (a = 0.998: M up to
 * 1/(1 - a) = 500, averaging 1/(1 - a²) ≈ 250), the same in every window */
static double symplectic_swing(double t) { return 250 + 240 * sin(40 * t); }

/* an orbit's M with a coarse perihelion pass once a second: 1, and at each
 * pass a spike past 2 (E > 0 for a step), back to 1 */
static double perihelion_spike(double t)
{
    double phase = t - floor(t);
    return fabs(phase - 0.5) < 0.005 ? 2.1 : 1.0;
}

/* A symplectic method's level is relative to its first window: its bounded
 * swing averages far above 30 near its limit and is no growth; a fixed level
 * called it raised. A bound orbit escapes at any sample with M >= 2. */
START_TEST(test_relative_and_escape)
{
    sw_watch w;
    sw_watch_verdict v = SW_WATCH_STEADY;
    for (int relative = 0; relative < 2; relative++) {
        sw_watch_init(&w, 1.0, 30);
        w.relative = relative;
        v = SW_WATCH_STEADY;
        for (long k = 0; k * 0.001 < 20 && v == SW_WATCH_STEADY; k++)
            v = sw_watch_add(&w, k * 0.001, symplectic_swing(k * 0.001));
        if (v == SW_WATCH_STEADY)
            v = sw_watch_finish(&w);
        ck_assert_int_eq(v, relative ? SW_WATCH_STEADY : SW_WATCH_RAISED);
    }
    double when;
    /* as every window shows the same spike, only the escape rule sees it */
    ck_assert_int_eq(feed(2, 20, perihelion_spike, &when), SW_WATCH_STEADY);
    sw_watch_init(&w, 1.0, 2);
    w.rebound = 0;
    w.escape = 2;
    v = SW_WATCH_STEADY;
    for (long k = 0; k * 0.01 < 20 && v == SW_WATCH_STEADY; k++)
        v = sw_watch_add(&w, k * 0.01, perihelion_spike(k * 0.01));
    ck_assert_int_eq(v, SW_WATCH_RAISED);
}
END_TEST

/* A bound orbit's M is 1 + (E - E0)/|E0|, not a fraction of the start: it
 * gets the escape level (M = 2 is E = 0) and no rebound test; a spring's M
 * is a fraction of its swing energy and gets both. */
START_TEST(test_start)
{
    char err[SW_ERRLEN];
    sw_sim s;
    sw_watch w;
    ck_assert_int_eq(sw_sim_init(&s, sw_scene_find("orbit"), NULL, sw_integrator_find("rk4"), 0.01, err, sizeof err),
                     SW_OK);
    sw_watch_start(&w, 1.0, &s);
    ck_assert_double_eq(w.raised, 2.0);
    ck_assert_double_eq(w.rebound, 0.0);
    ck_assert_double_eq(w.escape, 2.0);
    ck_assert_int_eq(w.relative, 0);
    sw_sim_free(&s);
    ck_assert_int_eq(sw_sim_init(&s, sw_scene_find("spring"), NULL, sw_integrator_find("verlet"), 0.01, err,
                                 sizeof err), SW_OK);
    sw_watch_start(&w, 1.0, &s);
    ck_assert_double_eq(w.raised, 30.0);
    ck_assert_double_eq(w.rebound, 30.0);
    ck_assert_int_eq(w.relative, 1); /* verlet is symplectic */
    ck_assert_double_eq(w.escape, 0.0);
    sw_sim_free(&s);
}
END_TEST

/* What the watch can judge, as the stability lab can measure: a flow with
 * a closed form (on |y|²), an energy with a floor or a well; not a river
 * (no energy, no closed form: its particles drift away from the origin),
 * not a projectile (its energy falls forever), not contact or births. */
START_TEST(test_judges)
{
    static const struct { const char *scene; int judged; } cases[] = {
        { "vortex", 1 }, { "river", 0 }, { "gyre", 0 }, { "projectile", 0 }, { "bounce", 0 },
        { "fireworks", 0 }, { "spring", 1 }, { "stiff-spring", 1 }, { "chain", 1 }, { "orbit", 1 },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char err[SW_ERRLEN], why[SW_ERRLEN] = "";
        sw_sim s;
        const sw_scene *sc = sw_scene_find(cases[i].scene);
        ck_assert_int_eq(sw_sim_init(&s, sc, NULL, sw_integrator_find("rk4"), sc->dt, err, sizeof err), SW_OK);
        int j = sw_watch_judges(&s, why, sizeof why);
        ck_assert_msg(j == cases[i].judged, "%s: judged %d (%s)", cases[i].scene, j, why);
        if (!j)
            ck_assert_ptr_nonnull(strstr(why, cases[i].scene));
        sw_sim_free(&s);
    }
}
END_TEST

Suite *make_watch_suite(void);
Suite *make_watch_suite(void)
{
    Suite *s = suite_create("watch");
    TCase *tc = tcase_create("verdicts");
    tcase_add_test(tc, test_verdicts);
    tcase_add_test(tc, test_start);
    tcase_add_test(tc, test_relative_and_escape);
    tcase_add_test(tc, test_judges);
    suite_add_tcase(s, tc);
    return s;
}
