/* The sim: one running simulation, as every front end advances it. Its
 * contract: steps are deterministic (two sims agree bit for bit), a method
 * change keeps state and time, dt stays in its limits, runs land exactly on
 * their end time, counters count, reset really resets, and a blow-up stops
 * the sim with its step and time. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "stepwise/stepwise.h"

static void sim_with(sw_sim *s, const char *scene, const char *method, double dt)
{
    char err[SW_ERRLEN];
    const sw_integrator *m = sw_integrator_find(method);
    ck_assert_ptr_nonnull(m);
    ck_assert_msg(sw_sim_init(s, sw_scene_find(scene), NULL, m, dt, err, sizeof err) == SW_OK, "%s", err);
}

/* Two sims of the same settings are the same run, bit for bit. */
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

Suite *make_sim_suite(void);
Suite *make_sim_suite(void)
{
    Suite *s = suite_create("sim");
    TCase *tc = tcase_create("sim");
    tcase_add_test(tc, deterministic);
    tcase_add_test(tc, counters_and_landing);
    tcase_add_test(tc, method_change_keeps_state);
    tcase_add_test(tc, dt_limits);
    tcase_add_test(tc, reset_resets);
    tcase_add_test(tc, energy_drift);
    tcase_add_test(tc, blow_up_stops);
    tcase_add_test(tc, adaptive_counts);
    suite_add_tcase(s, tc);
    return s;
}
