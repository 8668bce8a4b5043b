/* The scene catalog: exact solutions against tight rk45 runs or closed-form
 * identities, the growth laws the lessons quote, parameter range checks,
 * and every scene running 10^4 steps at its defaults without allocating. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "stepwise/sim.h"
#include "sim/truth.h"
#include "alloc_count.h"

#define PI 3.14159265358979323846

/* A built system's parameter by name (tests never rely on the order). */
static double param(const sw_system *sys, const char *name)
{
    int i = sw_scene_param_index(sys->scene, name);
    ck_assert_msg(i >= 0, "scene %s has no parameter %s", sys->scene->name, name);
    return sys->p[i];
}

static void sim_with3(sw_sim *s, const char *scene, const char *method, double dt, const char *set1,
                      const char *set2, const char *set3)
{
    const sw_scene *sc = sw_scene_find(scene);
    ck_assert_ptr_nonnull(sc);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    const char *sets[3] = { set1, set2, set3 };
    for (int i = 0; i < 3; i++)
        if (sets[i])
            ck_assert_msg(sw_scene_set(sc, p, sets[i], err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_sim_init(s, sc, p, sw_integrator_find(method), dt, err, sizeof err) == SW_OK, "%s", err);
}

static void sim_with(sw_sim *s, const char *scene, const char *method, double dt, const char *set1,
                     const char *set2)
{
    sim_with3(s, scene, method, dt, set1, set2, NULL);
}

/* Largest |exact - rk45| over a run to t_end, relative to the state's size
 * (at least 1), with rk45 at rtol 1e-11. The bound 1e-7 is what such a run
 * reaches on these smooth problems (~1e-8 at the fast periapsis of an
 * e = 0.9 orbit); a wrong closed form misses by O(1). */
static double exact_vs_rk45(const char *scene, const char *set1, const char *set2, double t_end)
{
    sw_sim s;
    sim_with(&s, scene, "rk45", 0.1, set1, set2);
    sw_sim_set_tolerances(&s, 1e-11, 1e-13);
    double worst = 0, ex[64];
    ck_assert_int_le(s.sys.ode->dim, 64);
    for (int k = 1; k <= 10; k++) {
        ck_assert_int_eq(sw_sim_run_until(&s, t_end * k / 10), 0);
        double e = sw_sim_exact_error(&s, ex), scale = 1;
        ck_assert_msg(isfinite(e), "%s has no exact solution here", scene);
        for (int i = 0; i < s.sys.ode->dim; i++)
            scale = fmax(scale, fabs(ex[i]));
        worst = fmax(worst, e / scale);
    }
    sw_sim_free(&s);
    return worst;
}

START_TEST(exact_solutions_match_rk45)
{
    struct { const char *scene, *s1, *s2; double t; } cases[] = {
        { "vortex", "n=20", "omega=1.7", 10 },
        { "projectile", NULL, NULL, 2 },
        { "projectile", "drag=0", NULL, 2 },
        { "projectile", "drag=3", "vy=-4", 3 },
        { "spring", "c=0.5", NULL, 10 },               /* under-damped */
        { "spring", "c=6.324555320336759", NULL, 10 }, /* critical: c = 2√(km) */
        { "spring", "c=20", NULL, 10 },                /* over-damped */
        { "spring", "c=0", "stretch=-0.4", 10 },       /* undamped, compressed */
        { "orbit", NULL, NULL, 2 * PI },
        { "orbit", "e=0.9", "mu=4", PI },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double e = exact_vs_rk45(cases[i].scene, cases[i].s1, cases[i].s2, cases[i].t);
        ck_assert_msg(e < 1e-7, "%s %s %s: exact and rk45 differ by %g", cases[i].scene,
                      cases[i].s1 ? cases[i].s1 : "", cases[i].s2 ? cases[i].s2 : "", e);
    }
}
END_TEST

/* The spring's closed form satisfies m u'' + c u' + k u = 0 in each regime:
 * checked with central differences of the exact position (h = 1e-4, so the
 * residual is O(h²) ≈ 1e-7 relative to the terms). */
START_TEST(spring_exact_satisfies_ode)
{
    const char *cs[] = { "c=1", "c=6.324555320336759", "c=15" };
    for (int i = 0; i < 3; i++) {
        sw_sim s;
        sim_with(&s, "spring", "rk4", 0.01, cs[i], NULL);
        const sw_scene *sc = s.sys.scene;
        double k = param(&s.sys, "k"), m = param(&s.sys, "m"), c = param(&s.sys, "c"), h = 1e-4;
        for (double t = 0.3; t < 5; t += 0.7) {
            double a[4], b[4], z[4];
            sc->exact(&s.sys, t - h, a);
            sc->exact(&s.sys, t, z);
            sc->exact(&s.sys, t + h, b);
            double u = z[0] - 1.0, du = (b[0] - a[0]) / (2 * h), ddu = (b[0] - 2 * z[0] + a[0]) / (h * h);
            ck_assert_double_eq_tol(du, z[2], 1e-6);
            ck_assert_msg(fabs(m * ddu + c * du + k * u) < 1e-5, "%s at t=%g: residual %g", cs[i], t,
                          m * ddu + c * du + k * u);
        }
        sw_sim_free(&s);
    }
}
END_TEST

/* Euler on x' = ω(-y, x): each step multiplies every radius by √(1+(ωΔt)²). */
START_TEST(vortex_euler_spiral)
{
    sw_sim s;
    sim_with(&s, "vortex", "euler", 0.1, "omega=2", "n=30");
    double g = sqrt(1 + 0.2 * 0.2);
    for (int step = 0; step < 50; step++) {
        double r0 = hypot(s.sys.y[10], s.sys.y[11]);
        sw_sim_step(&s);
        double r1 = hypot(s.sys.y[10], s.sys.y[11]);
        ck_assert_msg(fabs(r1 / r0 / g - 1) < 1e-12, "step %d: growth %.17g, expected %.17g", step, r1 / r0, g);
    }
    sw_sim_free(&s);
}
END_TEST

/* Orbit: E(0) = ½ μ(1+e)/(1-e) - μ/(1-e) = -μ/2 for every e and μ. */
START_TEST(orbit_energy)
{
    const char *es[] = { "e=0", "e=0.5", "e=0.95" }, *mus[] = { "mu=1", "mu=0.3", "mu=40" };
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            sw_sim s;
            sim_with(&s, "orbit", "verlet", 0.01, es[i], mus[j]);
            double mu = param(&s.sys, "mu");
            ck_assert_double_eq_tol(sw_sim_energy(&s), -mu / 2, 1e-15 * fmax(1, mu) * 4);
            sw_sim_free(&s);
        }
}
END_TEST

/* Over one period the exact orbit returns to its start (Kepler's third law:
 * T = 2π/√μ for semi-major axis 1). */
START_TEST(orbit_period)
{
    sw_sim s;
    sim_with(&s, "orbit", "verlet", 0.01, "e=0.6", "mu=2.5");
    double y0[4], y1[4], T = 2 * PI / sqrt(2.5);
    s.sys.scene->exact(&s.sys, 0, y0);
    s.sys.scene->exact(&s.sys, T, y1);
    for (int i = 0; i < 4; i++)
        ck_assert_double_eq_tol(y0[i], y1[i], 1e-12);
    ck_assert_double_eq_tol(y0[0], s.sys.y[0], 1e-15);
    ck_assert_double_eq_tol(y0[3], s.sys.y[3], 1e-14);
    sw_sim_free(&s);
}
END_TEST

/* River: exact paths keep the stream function; RK4 at a small step keeps it
 * to 1e-8, Euler at the same step visibly does not. */
START_TEST(river_stream_function)
{
    sw_sim a, b;
    sim_with(&a, "river", "rk4", 0.01, "n=40", NULL);
    sim_with(&b, "river", "euler", 0.01, "n=40", NULL);
    sw_sim_run_until(&a, 3.0);
    sw_sim_run_until(&b, 3.0);
    ck_assert_msg(sw_sim_drift(&a) < 1e-8, "rk4 drift %g", sw_sim_drift(&a));
    ck_assert_msg(sw_sim_drift(&b) > 100 * sw_sim_drift(&a), "euler drift %g", sw_sim_drift(&b));
    sw_sim_free(&a);
    sw_sim_free(&b);
}
END_TEST

/* The double gyre is incompressible: ∂u/∂x + ∂v/∂y = 0 (central differences). */
START_TEST(gyre_divergence_free)
{
    sw_sim s;
    sim_with(&s, "gyre", "rk4", 0.1, "n=4", NULL);
    double h = 1e-5;
    for (double t = 0; t < 10; t += 1.3)
        for (double x = 0.1; x < 2; x += 0.37)
            for (double y = 0.1; y < 1; y += 0.23) {
                double pts[8] = { x + h, y, x - h, y, x, y + h, x, y - h }, v[8];
                s.sys.flow.field(s.sys.p, t, 4, pts, v);
                double div = (v[0] - v[2]) / (2 * h) + (v[5] - v[7]) / (2 * h);
                ck_assert_msg(fabs(div) < 1e-6, "div %g at (%g, %g, t=%g)", div, x, y, t);
            }
    sw_sim_free(&s);
}
END_TEST

/* Bounce: the event-driven exact solution conserves energy when e = 1, and
 * contact inside a step limits even rk4 to first order: its error falls
 * about 4x (not 256x) when Δt is quartered. */
START_TEST(bounce_breaks_order)
{
    sw_sim s;
    sim_with(&s, "bounce", "rk4", 0.01, "e=1", "n=3");
    double y[12];
    double e0 = sw_sim_energy(&s);
    for (double t = 0.5; t < 6; t += 0.5) {
        s.sys.scene->exact(&s.sys, t, y);
        ck_assert_double_eq_tol(s.sys.scene->energy(&s.sys, y), e0, 1e-9 * fabs(e0));
    }
    sw_sim_free(&s);
    double err[2];
    for (int k = 0; k < 2; k++) {
        sim_with(&s, "bounce", "rk4", k ? 0.0025 : 0.01, "n=3", NULL);
        sw_sim_run_until(&s, 3.0);
        err[k] = sw_sim_exact_error(&s, y);
        sw_sim_free(&s);
    }
    double order = log(err[0] / err[1]) / log(4.0);
    ck_assert_msg(order > 0.5 && order < 1.6, "rk4 on bounce: observed order %g (errors %g, %g)", order, err[0], err[1]);
}
END_TEST

/* A chain's stiffest mode at rest is 2√(k/m) sin(nπ/(2(n+1))): the truth
 * module's spectrum of the straight chain must give it (QR on the 28x28
 * Jacobian, to 1e-9). It sets Verlet's limit ω_max Δt = 2: bisect Δt between
 * runs of the plucked chain that stay finite for 4000 steps and runs the sim
 * flags as blown up, and compare, 1%. (Energy is no criterion here: near the
 * limit Verlet's energy error for the top mode grows like 1/(1 - (ωΔt/2)²)
 * while the run stays bounded.) */
START_TEST(chain_limit_matches_formula)
{
    sw_sim s;
    sim_with(&s, "chain", "verlet", 0.01, "n=7", "k=50");
    sw_sim_free(&s);
    sim_with3(&s, "chain", "verlet", 0.01, "n=7", "k=50", "pluck=0");
    sw_spectrum sp;
    ck_assert_int_eq(sw_truth_spectrum(&s.sys, 0.0, s.sys.y, &sp), 0);
    double w = sp.largest;
    sw_sim_free(&s);
    double n = 7, expect = 2 * sqrt(50.0) * sin(n * PI / (2 * (n + 1)));
    ck_assert_msg(fabs(w / expect - 1) < 1e-9, "chain at rest: stiffest |L| %.15g, formula %.15g", w, expect);
    double lo = 1.5 / w, hi = 2.5 / w;
    for (int it = 0; it < 20; it++) {
        double mid = 0.5 * (lo + hi);
        sim_with(&s, "chain", "verlet", mid, "n=7", "k=50");
        int bad = 0;
        for (int step = 0; step < 4000 && !bad; step++)
            bad = sw_sim_step(&s);
        sw_sim_free(&s);
        if (bad)
            hi = mid;
        else
            lo = mid;
    }
    ck_assert_msg(fabs(lo * w / 2 - 1) < 0.01, "verlet limit on chain: w dt = %g, expected 2", lo * w);
}
END_TEST

START_TEST(parameter_ranges)
{
    const sw_scene *sc = sw_scene_find("spring");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    ck_assert_int_eq(sw_scene_set(sc, p, "k=-1", err, sizeof err), SW_EINVAL);
    ck_assert_msg(strstr(err, "[0.001, 1e+07]") && strstr(err, "'k'"), "message: %s", err);
    ck_assert_int_eq(sw_scene_set(sc, p, "stiffness=3", err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "k, m, c, rest, stretch, g"));
    ck_assert_int_eq(sw_scene_set(sc, p, "k=nan", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_scene_set(sc, p, "k=", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_scene_set(sc, p, "=3", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_scene_set(sc, p, "k=1e400", err, sizeof err), SW_EINVAL);
    ck_assert_int_eq(sw_scene_set(sc, p, "k=25", err, sizeof err), SW_OK);
    ck_assert_double_eq(p[0], 25);
    const sw_scene *ch = sw_scene_find("chain");
    sw_scene_defaults(ch, p);
    ck_assert_int_eq(sw_scene_set(ch, p, "n=2.5", err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "whole number"));
    sw_sim s;
    sw_scene_defaults(sc, p);
    p[sw_scene_param_index(sc, "stretch")] = -2.0; /* below -rest: the mass would start behind the anchor */
    ck_assert_int_eq(sw_sim_init(&s, sc, p, sw_integrator_find("rk4"), 0.01, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "rest + stretch"));
}
END_TEST

/* Every scene, at its defaults, runs 10^4 steps finite and allocation-free. */
START_TEST(defaults_run_clean)
{
    for (int i = 0; i < sw_scene_count(); i++) {
        const sw_scene *sc = sw_scene_at(i);
        sw_sim s;
        char err[SW_ERRLEN];
        ck_assert_msg(sw_integrator_find(sc->integrator), "%s: default integrator %s", sc->name, sc->integrator);
        ck_assert_msg(sw_sim_init(&s, sc, NULL, sw_integrator_find(sc->integrator), sc->dt, err, sizeof err) == SW_OK,
                      "%s: %s", sc->name, err);
        long before = sw_test_allocations();
        for (int step = 0; step < 10000; step++)
            sw_sim_step(&s);
        ck_assert_msg(sw_test_allocations() == before, "%s allocated while stepping", sc->name);
        ck_assert_msg(!s.blown, "%s blew up at its defaults: %s (step %ld)", sc->name, s.blow_reason, s.blow_step);
        sw_view v = sc->view(&s.sys);
        ck_assert(v.xmax > v.xmin && v.ymax > v.ymin);
        ck_assert(sc->summary && *sc->summary && sc->teaches && *sc->teaches && sc->duration > 0);
        sw_sim_free(&s);
    }
}
END_TEST

/* Fireworks: the same seed gives the same show, another seed another. */
START_TEST(fireworks_seeded)
{
    sw_sim a, b, c;
    sim_with(&a, "fireworks", "symplectic-euler", 0.02, "seed=5", NULL);
    sim_with(&b, "fireworks", "symplectic-euler", 0.02, "seed=5", NULL);
    sim_with(&c, "fireworks", "symplectic-euler", 0.02, "seed=6", NULL);
    for (int i = 0; i < 150; i++) {
        sw_sim_step(&a);
        sw_sim_step(&b);
        sw_sim_step(&c);
    }
    ck_assert_int_eq(memcmp(a.sys.y, b.sys.y, (size_t)a.sys.ode->dim * sizeof(double)), 0);
    ck_assert_int_ne(memcmp(a.sys.y, c.sys.y, (size_t)a.sys.ode->dim * sizeof(double)), 0);
    int alive = 0;
    for (int i = 0; i < a.sys.n; i++)
        alive += sw_sim_alive(&a, i);
    ck_assert_int_gt(alive, 0); /* at t = 3 some bursts are lit */
    ck_assert_int_lt(alive, a.sys.n);
    sw_sim_free(&a);
    sw_sim_free(&b);
    sw_sim_free(&c);
}
END_TEST

/* A million particles: the scenes that take a count take up to 1e6, and
 * refuse one more with a message that names the limit in full (1000001
 * printed as %g would read 1e+06, the limit itself). Building at the cap
 * is left to the benchmark (bench_engine --memory): hundreds of MiB. */
START_TEST(million_particles_cap)
{
    const char *names[] = { "chain", "vortex", "river", "gyre" };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        const sw_scene *sc = sw_scene_find(names[i]);
        double p[SW_MAX_PARAMS];
        char err[SW_ERRLEN], want[SW_ERRLEN];
        ck_assert_ptr_nonnull(sc);
        sw_scene_defaults(sc, p);
        ck_assert_msg(sw_scene_set(sc, p, "n=1000000", err, sizeof err) == SW_OK, "%s: %s", names[i], err);
        ck_assert_int_eq(sw_scene_set(sc, p, "n=1000001", err, sizeof err), SW_EINVAL);
        snprintf(want, sizeof want, "%s: parameter 'n' = 1000001 is outside its range [1, 1000000]", names[i]);
        ck_assert_str_eq(err, want);
        ck_assert_ptr_null(strchr(err, '\n'));
    }
}
END_TEST

Suite *make_scenes_suite(void);
Suite *make_scenes_suite(void)
{
    Suite *s = suite_create("scenes");
    TCase *tc = tcase_create("catalog");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, exact_solutions_match_rk45);
    tcase_add_test(tc, spring_exact_satisfies_ode);
    tcase_add_test(tc, vortex_euler_spiral);
    tcase_add_test(tc, orbit_energy);
    tcase_add_test(tc, orbit_period);
    tcase_add_test(tc, river_stream_function);
    tcase_add_test(tc, gyre_divergence_free);
    tcase_add_test(tc, bounce_breaks_order);
    tcase_add_test(tc, chain_limit_matches_formula);
    tcase_add_test(tc, parameter_ranges);
    tcase_add_test(tc, defaults_run_clean);
    tcase_add_test(tc, fireworks_seeded);
    tcase_add_test(tc, million_particles_cap);
    suite_add_tcase(s, tc);
    return s;
}
