/* The sim: one running simulation, as every front end advances it. Its
 * contract: steps are deterministic (two sims agree bit for bit), a method
 * change keeps state and time, dt stays in its limits, runs land exactly on
 * their end time, counters count, reset really resets, a blow-up stops
 * the sim with its step and time, and the drift it keeps between steps is
 * the one a fresh computation gives after every kind of change. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "sim/history.h"

static void sim_with(sw_sim *s, const char *scene, const char *method, double dt)
{
    char err[SW_ERRLEN];
    const sw_integrator *m = sw_integrator_find(method);
    ck_assert_ptr_nonnull(m);
    ck_assert_msg(sw_sim_init(s, sw_scene_find(scene), NULL, m, dt, err, sizeof err) == SW_OK, "%s", err);
}

/* Two sims of the same settings are the same run, bit for bit. */
/* An embedder's scene without a view (issue 39: it was called unchecked):
 * the sim starts and steps, its runaway limit taken from the state, and
 * gives the same numbers as the scene with its view. */
START_TEST(scene_without_view)
{
    sw_scene bare = *sw_scene_find("spring");
    bare.view = NULL;
    char err[SW_ERRLEN];
    sw_sim a, b;
    ck_assert_msg(sw_sim_init(&a, &bare, NULL, sw_integrator_find("rk4"), 0.01, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_sim_init(&b, sw_scene_find("spring"), NULL, sw_integrator_find("rk4"), 0.01, err, sizeof err) ==
                      SW_OK, "%s", err);
    for (int i = 0; i < 100; i++) {
        ck_assert_int_eq(sw_sim_step(&a), 0);
        ck_assert_int_eq(sw_sim_step(&b), 0);
    }
    ck_assert_mem_eq(a.sys.y, b.sys.y, (size_t)a.sys.ode->dim * sizeof(double));
    sw_sim_free(&a);
    sw_sim_free(&b);
}
END_TEST

START_TEST(deterministic)
{
    sw_sim a, b;
    sim_with(&a, "chain", "rk4", 0.01);
    sim_with(&b, "chain", "rk4", 0.01);
    for (int i = 0; i < 200; i++) {
        sw_sim_step(&a);
        sw_sim_step(&b);
    }
    ck_assert_int_eq(a.steps, 200);
    ck_assert_int_eq(memcmp(a.sys.y, b.sys.y, (size_t)a.sys.ode->dim * sizeof *a.sys.y), 0);
    ck_assert_double_eq(a.t, b.t);
    sw_sim_free(&a);
    sw_sim_free(&b);
}
END_TEST

/* rk4 costs four evaluations a step; run_until lands on t exactly, with a
 * shortened last step (0.25 / 0.1 is 2.5 steps). */
START_TEST(counters_and_landing)
{
    sw_sim s;
    sim_with(&s, "spring", "rk4", 0.1);
    ck_assert_int_eq(sw_sim_run_until(&s, 0.25), 0);
    ck_assert_double_eq(s.t, 0.25);
    ck_assert_int_eq(s.steps, 3);
    ck_assert_int_eq(sw_sim_evals(&s), 12);
    sw_sim_free(&s);
}
END_TEST

/* Changing the method keeps state and time; refusing one changes nothing. */
START_TEST(method_change_keeps_state)
{
    sw_sim s;
    char err[SW_ERRLEN];
    sim_with(&s, "spring", "euler", 0.01);
    sw_sim_run_until(&s, 0.5);
    double x = s.sys.y[0], t = s.t;
    ck_assert_int_eq(sw_sim_set_method(&s, sw_integrator_find("verlet"), err, sizeof err), SW_OK);
    ck_assert_str_eq(s.method->name, "verlet");
    ck_assert_double_eq(s.sys.y[0], x);
    ck_assert_double_eq(s.t, t);
    sw_sim_free(&s);

    sim_with(&s, "vortex", "euler", 0.05);
    ck_assert_int_eq(sw_sim_set_method(&s, sw_integrator_find("verlet"), err, sizeof err), SW_EINVAL);
    ck_assert_str_eq(s.method->name, "euler");
    ck_assert_ptr_nonnull(strstr(err, "masses"));
    sw_sim_free(&s);
}
END_TEST

/* dt outside [SW_DT_MIN, SW_DT_MAX] (or NaN) is refused and dt kept. */
START_TEST(dt_limits)
{
    sw_sim s;
    char err[SW_ERRLEN];
    sim_with(&s, "spring", "rk4", 0.01);
    ck_assert_int_eq(sw_sim_set_dt(&s, SW_DT_MIN / 2, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_sim_set_dt(&s, SW_DT_MAX * 2, err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_sim_set_dt(&s, NAN, err, sizeof err), SW_EINVAL);
    ck_assert_double_eq(s.dt, 0.01);
    ck_assert_int_eq(sw_sim_set_dt(&s, 0.02, err, sizeof err), SW_OK);
    ck_assert_double_eq(s.dt, 0.02);
    sw_sim_free(&s);
}
END_TEST

/* Reset returns the initial state at t = 0 with the counters cleared. */
START_TEST(reset_resets)
{
    sw_sim s;
    char err[SW_ERRLEN];
    sim_with(&s, "orbit", "verlet", 0.01);
    double y0[8];
    memcpy(y0, s.sys.y, (size_t)s.sys.ode->dim * sizeof *y0);
    sw_sim_run_until(&s, 1.0);
    ck_assert_int_ne(memcmp(y0, s.sys.y, (size_t)s.sys.ode->dim * sizeof *y0), 0);
    ck_assert_int_eq(sw_sim_reset(&s, err, sizeof err), SW_OK);
    ck_assert_double_eq(s.t, 0.0);
    ck_assert_int_eq(s.steps, 0);
    ck_assert_int_eq(sw_sim_evals(&s), 0);
    ck_assert_int_eq(memcmp(y0, s.sys.y, (size_t)s.sys.ode->dim * sizeof *y0), 0);
    sw_sim_free(&s);
}
END_TEST

/* Energy drift is 0 at the start and small for a symplectic method over a
 * couple of orbits (|drift| under 1 %, a bound that explicit Euler at the
 * same step breaks by spiralling outwards). */
START_TEST(energy_drift)
{
    sw_sim s;
    sim_with(&s, "orbit", "verlet", 0.01);
    ck_assert_double_eq(sw_sim_energy_drift(&s), 0.0);
    sw_sim_run_until(&s, 10.0);
    ck_assert_double_lt(fabs(sw_sim_energy_drift(&s)), 1.0);
    sw_sim_free(&s);
    sim_with(&s, "orbit", "euler", 0.01);
    sw_sim_run_until(&s, 10.0);
    ck_assert_double_gt(fabs(sw_sim_energy_drift(&s)), 1.0);
    sw_sim_free(&s);
}
END_TEST

/* Euler far beyond its stability limit blows up: the sim stops, says at
 * which step and time, and refuses further steps (returning 1). */
START_TEST(blow_up_stops)
{
    sw_sim s;
    sim_with(&s, "stiff-spring", "euler", 0.5);
    ck_assert_int_eq(sw_sim_run_until(&s, 1000.0), 1);
    ck_assert(s.blown);
    ck_assert_int_gt(s.blow_step, 0);
    ck_assert_int_le(s.blow_step, s.steps);
    ck_assert(s.blow_time > 0 && s.blow_time < 1000.0);
    ck_assert(s.blow_reason[0] != '\0');
    long steps = s.steps;
    ck_assert_int_eq(sw_sim_step(&s), 1);
    ck_assert_int_eq(s.steps, steps);
    sw_sim_free(&s);
}
END_TEST

/* rk45 steps adaptively, never past a stop time, and counts its steps. */
START_TEST(adaptive_counts)
{
    sw_sim s;
    long acc, rej;
    sim_with(&s, "orbit", "rk45", 0.1);
    ck_assert_int_eq(sw_sim_step_until(&s, 0.05), 0);
    ck_assert_double_le(s.t, 0.05);
    ck_assert_int_eq(sw_sim_run_until(&s, 2.0), 0);
    ck_assert_double_eq(s.t, 2.0);
    sw_sim_step_counts(&s, &acc, &rej);
    ck_assert_int_eq(acc, s.steps);
    ck_assert_int_ge(rej, 0);
    sw_sim_free(&s);
    sim_with(&s, "orbit", "rk4", 0.1);
    sw_sim_run_until(&s, 1.0);
    sw_sim_step_counts(&s, &acc, &rej);
    ck_assert_int_eq(acc, 0);
    ck_assert_int_eq(rej, 0);
    sw_sim_free(&s);
}
END_TEST

/* The scene's drift worked out now, past the sim's cache. */
static double fresh_drift(const sw_sim *s)
{
    return s->sys.scene->drift(&s->sys, s->sys.y);
}

/* Bit for bit, NaN included: the cache must return what was computed. */
static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* After a change the sim's drift is the fresh one; when the change moved
 * the drift (moved = 1) the value read before it (which filled the cache)
 * must differ from the fresh one, or a missed invalidation would go unseen. */
static void drift_after(const sw_sim *s, double before, double before_e, int moved, const char *what)
{
    double fresh = fresh_drift(s), got = sw_sim_drift(s);
    ck_assert_msg(same_bits(got, fresh), "%s on %s: the sim says %.17g, a fresh computation %.17g", what,
                  s->sys.scene->name, got, fresh);
    if (moved)
        ck_assert_msg(!same_bits(before, fresh), "%s on %s did not move the drift (%.17g): the test would "
                      "not see a stale value", what, s->sys.scene->name, fresh);
    /* the energy is kept the same way (and its bound with it) */
    const sw_scene *sc = s->sys.scene;
    double fresh_e = sc->energy ? sc->energy(&s->sys, s->sys.y) : NAN, got_e = sw_sim_energy(s);
    ck_assert_msg(same_bits(got_e, fresh_e), "%s on %s: the sim's energy %.17g, a fresh one %.17g", what, sc->name,
                  got_e, fresh_e);
    if (moved && sc->energy)
        ck_assert_msg(!same_bits(before_e, fresh_e), "%s on %s did not move the energy", what, sc->name);
}

/* The drift a sim reports is worked out once per state and kept: after
 * each kind of change (a step, a run, a new dt, method, tolerances or
 * events mode, set_state, a rewind, a reset) it is bit for bit the scene's
 * drift of the state now (and the energy, kept the same way). Each check
 * reads the drift just before the change,
 * so the cache is full, and the changes that move the state are chosen so
 * that the drift moves too: a missed invalidation shows as a mismatch. */
START_TEST(drift_cache_follows_every_change)
{
    static const struct { const char *scene, *method; double dt; } runs[] = {
        { "vortex", "euler", 0.05 },  /* flow: radius drift from each point's seed */
        { "river", "euler", 0.05 },   /* flow: stream-function drift */
        { "orbit", "euler", 0.01 },   /* one body: |L - L0| from the parameters */
        { "galaxy", "euler", 0.01 },  /* N bodies: |L - L0| from the system's extra data */
        { "orbit", "rk45", 0.1 },     /* adaptive: a step is one accepted step */
    };
    char err[SW_ERRLEN];
    for (size_t r = 0; r < sizeof runs / sizeof runs[0]; r++) {
        sw_sim s;
        sw_history h;
        sim_with(&s, runs[r].scene, runs[r].method, runs[r].dt);
        ck_assert(s.sys.scene->drift != NULL);
        sw_history_init(&h, &s);
        ck_assert_int_gt(h.cap, 0);
        sw_history_push(&h, &s);
        int dim = s.sys.ode->dim;
        double *y0 = malloc((size_t)dim * sizeof *y0);
        ck_assert_ptr_nonnull(y0);
        memcpy(y0, s.sys.y, (size_t)dim * sizeof *y0);

        double before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        drift_after(&s, before, before_e, 0, "the start");
        for (int k = 0; k < 5; k++) {
            before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
            ck_assert_int_eq(sw_sim_step(&s), 0);
            sw_history_push(&h, &s);
            drift_after(&s, before, before_e, 1, "a step");
        }
        const double t_back = s.t;
        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        ck_assert_int_eq(sw_sim_run_until(&s, s.t + 20 * runs[r].dt), 0);
        sw_history_push(&h, &s);
        drift_after(&s, before, before_e, 1, "a run");

        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        ck_assert_int_eq(sw_sim_set_dt(&s, runs[r].dt / 2, err, sizeof err), SW_OK);
        drift_after(&s, before, before_e, 0, "set_dt");
        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        ck_assert_int_eq(sw_sim_step(&s), 0);
        sw_history_push(&h, &s);
        drift_after(&s, before, before_e, 1, "a step at the new dt");

        /* the rewind before the change of method: a history is its
         * method's (the app clears it on a change) */
        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        ck_assert_int_eq(sw_history_back_to(&h, &s, t_back), 1);
        ck_assert_double_eq(s.t, t_back);
        drift_after(&s, before, before_e, 1, "a rewind");

        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        ck_assert_int_eq(sw_sim_set_method(&s, sw_integrator_find("rk4"), err, sizeof err), SW_OK);
        drift_after(&s, before, before_e, 0, "set_method");
        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        sw_sim_set_tolerances(&s, 1e-8, 1e-10);
        drift_after(&s, before, before_e, 0, "set_tolerances");
        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        ck_assert_int_eq(sw_sim_set_events(&s, SW_EVENTS_LOCATE, err, sizeof err), SW_OK);
        drift_after(&s, before, before_e, 0, "set_events");

        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        sw_sim_set_state(&s, y0);
        drift_after(&s, before, before_e, 1, "set_state");
        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        ck_assert_int_eq(sw_sim_step(&s), 0);
        drift_after(&s, before, before_e, 1, "a step from the set state");

        before = sw_sim_drift(&s), before_e = sw_sim_energy(&s);
        ck_assert_int_eq(sw_sim_reset(&s, err, sizeof err), SW_OK);
        drift_after(&s, before, before_e, 1, "reset");

        free(y0);
        sw_history_free(&h);
        sw_sim_free(&s);
    }
}
END_TEST

/* The drift is kept, not recomputed on every read: a state written behind
 * the sim's back (what a mutator that forgot to invalidate would leave)
 * still reads the old drift, so drift_cache_follows_every_change above
 * would catch a missed invalidation; sw_sim_state_changed, the call the
 * header asks of such writers, brings the fresh value back. */
START_TEST(drift_cache_is_stale_until_told)
{
    sw_sim s;
    sim_with(&s, "vortex", "euler", 0.05);
    double start = sw_sim_drift(&s);
    ck_assert_double_eq(start, 0.0); /* the seeds themselves: on their circles */
    s.sys.y[0] *= 1.5;               /* one point off its circle, the sim not told */
    ck_assert_double_gt(fresh_drift(&s), 0.0);
    ck_assert_msg(same_bits(sw_sim_drift(&s), start), "the drift was recomputed, not kept: %.17g",
                  sw_sim_drift(&s));
    sw_sim_state_changed(&s);
    ck_assert(same_bits(sw_sim_drift(&s), fresh_drift(&s)));
    sw_sim_free(&s);
}
END_TEST

Suite *make_sim_suite(void);
Suite *make_sim_suite(void)
{
    Suite *s = suite_create("sim");
    TCase *tc = tcase_create("sim");
    tcase_add_test(tc, deterministic);
    tcase_add_test(tc, scene_without_view);
    tcase_add_test(tc, counters_and_landing);
    tcase_add_test(tc, method_change_keeps_state);
    tcase_add_test(tc, dt_limits);
    tcase_add_test(tc, reset_resets);
    tcase_add_test(tc, energy_drift);
    tcase_add_test(tc, blow_up_stops);
    tcase_add_test(tc, adaptive_counts);
    tcase_add_test(tc, drift_cache_follows_every_change);
    tcase_add_test(tc, drift_cache_is_stale_until_told);
    suite_add_tcase(s, tc);
    return s;
}
