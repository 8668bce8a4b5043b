/* The stability search (src/lab/stability.c) against closed forms: on the
 * undamped spring ω = √(k/m), and the limits of ω·Δt on x'' = -ω²x are
 * verlet 2 and rk4 2√2 (|R(iy)|² = 1 - y⁶/72 + y⁸/576 = 1 at y = 2√2);
 * euler, midpoint and heun grow at every step (|R(iy)|² = 1 + y², 1 + y⁴/4);
 * backward Euler never does. On the damped spring, explicit Euler is stable
 * while |1 + hλ| <= 1 for λ = -γ ± iω_d, i.e. h <= 2γ/(γ² + ω_d²) = c/k. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/sim.h"
#include "lab/stability.h"

static const sw_scene *spring(double *p, double k, double m, double c)
{
    char err[SW_ERRLEN], set[64];
    const sw_scene *sc = sw_scene_find("spring");
    sw_scene_defaults(sc, p);
    snprintf(set, sizeof set, "k=%.17g", k);
    ck_assert_int_eq(sw_scene_set(sc, p, set, err, sizeof err), SW_OK);
    snprintf(set, sizeof set, "m=%.17g", m);
    ck_assert_int_eq(sw_scene_set(sc, p, set, err, sizeof err), SW_OK);
    snprintf(set, sizeof set, "c=%.17g", c);
    ck_assert_int_eq(sw_scene_set(sc, p, set, err, sizeof err), SW_OK);
    return sc;
}

static sw_stability_result find(const sw_scene *sc, const double *p, const char *name)
{
    sw_stability_config c;
    sw_stability_result res;
    char err[SW_ERRLEN];
    sw_stability_config_default(&c);
    const sw_integrator *m = sw_integrator_find(name);
    ck_assert_ptr_nonnull(m);
    ck_assert_msg(sw_stability_find(sc, p, m, &c, &res, err, sizeof err) == SW_OK, "%s: %s", name, err);
    return res;
}

/* A found limit is within 1% of the theory (the tolerance; the
 * bisection itself brackets it to 0.01%), both ends of the bracket too. */
static void assert_limit(const sw_stability_result *r, double theory)
{
    ck_assert_int_eq(r->kind, SW_STAB_LIMIT);
    ck_assert_msg(fabs(r->dt / theory - 1) < 0.01, "%s: stable up to %.6g, theory %.6g",
                  r->method->name, r->dt, theory);
    ck_assert_double_gt(r->dt_unstable, r->dt);
    ck_assert_double_lt(r->dt_unstable / r->dt - 1, 2e-4);
}

START_TEST(test_verlet_and_rk4_limits)
{
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = spring(p, 1, 1, 0);
    sw_stability_result v = find(sc, p, "verlet"), r = find(sc, p, "rk4");
    assert_limit(&v, 2.0);
    assert_limit(&r, 2.0 * sqrt(2.0));
    ck_assert_double_eq_tol(v.stiff, 1.0, 1e-12);
    /* the theory column agrees with the closed forms too (bisected to 1e-9) */
    ck_assert_msg(fabs(v.theory / 2.0 - 1) < 1e-6, "verlet theory %.9g", v.theory);
    ck_assert_msg(fabs(r.theory / (2.0 * sqrt(2.0)) - 1) < 1e-6, "rk4 theory %.9g", r.theory);
    ck_assert(v.agree && r.agree);
}
END_TEST

/* The same limits scale as 1/ω: k = 9, m = 1 gives ω = 3. */
START_TEST(test_limits_scale_with_omega)
{
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = spring(p, 9, 1, 0);
    sw_stability_result v = find(sc, p, "verlet"), r = find(sc, p, "rk4");
    assert_limit(&v, 2.0 / 3.0);
    assert_limit(&r, 2.0 * sqrt(2.0) / 3.0);
}
END_TEST

START_TEST(test_none_and_unbounded)
{
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = spring(p, 1, 1, 0);
    static const char *const none[] = { "euler", "midpoint", "heun" };
    for (int i = 0; i < 3; i++) {
        sw_stability_result r = find(sc, p, none[i]);
        ck_assert_msg(r.kind == SW_STAB_NONE, "%s: kind %d at %g", none[i], r.kind, r.dt);
        ck_assert_double_eq_tol(r.dt, 0.01, 1e-15); /* the smallest step probed: ω·Δt = 0.01 */
        ck_assert_int_eq(r.fail.verdict, SW_PROBE_TREND);
    }
    sw_stability_result r = find(sc, p, "implicit-euler");
    ck_assert_int_eq(r.kind, SW_STAB_UNBOUNDED);
    ck_assert_double_ge(r.dt * r.stiff, 1000 * (1 - 1e-9));
    ck_assert(r.theory_unbounded && r.agree);
}
END_TEST

/* Damped (k = 10, m = 1, c = 0.5): euler's limit is c/k = 0.05. */
START_TEST(test_damped_euler_limit)
{
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = spring(p, 10, 1, 0.5);
    sw_stability_result r = find(sc, p, "euler");
    assert_limit(&r, 0.5 / 10.0);
}
END_TEST

/* Single probes on either side of verlet's limit, and what they report. */
START_TEST(test_probe)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = spring(p, 1, 1, 0);
    sw_stability_config c;
    sw_stability_probe pr;
    sw_stability_config_default(&c);
    const sw_integrator *m = sw_integrator_find("verlet");
    ck_assert_int_eq(sw_stability_probe_run(sc, p, m, 1.9, &c, &pr, err, sizeof err), SW_OK);
    ck_assert_int_eq(pr.verdict, SW_PROBE_STABLE);
    ck_assert_int_ge(pr.steps, c.min_steps);
    /* started at rest, verlet's energy never exceeds its start below the limit */
    ck_assert_double_le(pr.m_max, 1 + 1e-12);
    ck_assert_int_eq(sw_stability_probe_run(sc, p, m, 2.1, &c, &pr, err, sizeof err), SW_OK);
    ck_assert_int_ne(pr.verdict, SW_PROBE_STABLE);
    ck_assert_int_ne(pr.verdict, SW_PROBE_DECAYED);
}
END_TEST

START_TEST(test_refusals)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_stability_config c;
    sw_stability_result r;
    sw_stability_config_default(&c);
    const sw_scene *sc = spring(p, 1, 1, 0);
    ck_assert_int_eq(sw_stability_find(sc, p, sw_integrator_find("rk45"), &c, &r, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "rk45"));
    ck_assert_int_eq(sw_stability_find(sw_scene_find("vortex"), NULL, sw_integrator_find("verlet"), &c, &r,
                                       err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "masses"));
    ck_assert(!sw_stability_measurable(sw_scene_find("bounce"), NULL, err, sizeof err));
    ck_assert(!sw_stability_measurable(sw_scene_find("fireworks"), NULL, err, sizeof err));
    ck_assert(!sw_stability_measurable(sw_scene_find("river"), NULL, err, sizeof err));
    ck_assert(!sw_stability_measurable(sw_scene_find("projectile"), NULL, err, sizeof err));
    ck_assert_ptr_nonnull(strstr(err, "no floor"));
    ck_assert(sw_stability_measurable(sw_scene_find("vortex"), NULL, err, sizeof err));
    ck_assert(sw_stability_measurable(sw_scene_find("orbit"), NULL, err, sizeof err));
    /* the gyre: theory only, from its points' Jacobians */
    ck_assert_int_eq(sw_stability_find(sw_scene_find("gyre"), NULL, sw_integrator_find("rk4"), &c, &r, err,
                                       sizeof err), SW_OK);
    ck_assert(!r.measured && r.theory > 0);
}
END_TEST

Suite *make_stability_suite(void);
Suite *make_stability_suite(void)
{
    Suite *s = suite_create("stability");
    TCase *tc = tcase_create("limits");
    tcase_set_timeout(tc, 60); /* each search: ~20 probes of a one-particle sim, well under a second */
    tcase_add_test(tc, test_verlet_and_rk4_limits);
    tcase_add_test(tc, test_limits_scale_with_omega);
    tcase_add_test(tc, test_none_and_unbounded);
    tcase_add_test(tc, test_damped_euler_limit);
    tcase_add_test(tc, test_probe);
    tcase_add_test(tc, test_refusals);
    suite_add_tcase(s, tc);
    return s;
}
