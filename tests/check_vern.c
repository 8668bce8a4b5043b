/* vern8 and vern9 (Verner's efficient 8(7) and 9(8) pairs) against
 * theory: their observed orders with fixed steps on the orbit (Kepler's
 * equation gives the exact state) and vern8's floor there, and adaptive
 * runs at rtol = atol = 1e-13 on the orbit at e = 0.5 against the exact
 * state and dop853's evaluations. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "stepwise/sim.h"
#include "engine/stepper.h"

static double max_diff(int n, const double *a, const double *b)
{
    double m = 0;
    for (int i = 0; i < n; i++)
        m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

/* The scene's settings "k=v,k=v" into p, one at a time. */
static void set_all(const sw_scene *sc, double *p, const char *set)
{
    char buf[128], err[SW_ERRLEN];
    snprintf(buf, sizeof buf, "%s", set);
    for (char *w = strtok(buf, ","); w; w = strtok(NULL, ","))
        ck_assert_msg(sw_scene_set(sc, p, w, err, sizeof err) == SW_OK, "%s: %s", w, err);
}

/* method on a scene at settings `set` to T; fixed > 0: that many steps
 * of T/fixed (tolerances so loose that every trial is accepted), else
 * adaptive at rtol = atol = tol. State into out; evaluations returned. */
static long run(const char *method, const char *scene, const char *set, double T, long fixed, double tol,
                double *out, int *dim)
{
    sw_sim s;
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find(scene);
    double p[SW_MAX_PARAMS];
    sw_scene_defaults(sc, p);
    set_all(sc, p, set);
    ck_assert_int_eq(sw_sim_init(&s, sc, p, sw_integrator_find(method), fixed ? T / (double)fixed : T, err, sizeof err),
                     SW_OK);
    sw_stepper *st = s.stepper;
    if (fixed) {
        double h = T / (double)fixed, t = 0;
        st->rtol = st->atol = 1e300;
        st->h_next = h;
        for (long i = 0; i < fixed; i++)
            ck_assert_int_eq(sw_stepper_step(st, s.sys.ode, &t, s.sys.y, h), SW_OK);
        ck_assert_int_eq(st->rejected, 0);
    } else {
        st->rtol = st->atol = tol;
        ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
    }
    *dim = s.sys.ode->dim;
    memcpy(out, s.sys.y, (size_t)*dim * sizeof *out);
    long evals = s.sys.ode->evals;
    sw_sim_free(&s);
    return evals;
}

static void exact(const char *scene, const char *set, double T, double *ref)
{
    const sw_scene *sc = sw_scene_find(scene);
    sw_system sys;
    char err[SW_ERRLEN];
    double p[SW_MAX_PARAMS];
    sw_scene_defaults(sc, p);
    set_all(sc, p, set);
    ck_assert_int_eq(sw_system_build(&sys, sc, p, err, sizeof err), SW_OK);
    ck_assert_int_eq(sc->exact(&sys, T, ref), 0);
    sw_system_free(&sys);
}

/* The least-squares slope of log error against log h: method with
 * counts[0..2] fixed steps over one period of the orbit at settings set
 * (1 + evals evaluations a step: the first k1, then each step's), its
 * errors into errs. */
static double orbit_order(const char *method, const char *set, int evals, const long counts[3], double errs[3])
{
    double ref[4], y[4], sx = 0, sy = 0, sxx = 0, sxy = 0, T = 2 * M_PI;
    int dim;
    exact("orbit", set, T, ref);
    for (int j = 0; j < 3; j++) {
        ck_assert_int_eq(run(method, "orbit", set, T, counts[j], 0, y, &dim), 1 + evals * counts[j]);
        errs[j] = max_diff(4, y, ref);
        double lx = log(T / (double)counts[j]), ly = log(errs[j]);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    }
    return (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
}

/* vern8: at 15, 22 and 33 steps the errors are 1e-8 .. 1.4e-11, far above
 * round-off, and the slope is the order: theory 8, +-0.6 for the drift of
 * the error constant over the range (the local slopes there are 11.2 and
 * 5.8: measured 8.39). Then at 163 steps the error falls below 1e-13:
 * with the coefficients rounded one by one the order conditions were
 * 1.3e-13 from true and fixed steps stalled at 1.2e-13 .. 8.7e-13 from 49
 * steps on (bench/vern_gen.py prints both residuals: 1.3e-13 and 4e-15;
 * now 9.8e-15 at 163 steps). */
START_TEST(vern8_order_orbit)
{
    double errs[3], ref[4], y[4];
    int dim;
    const long counts[] = { 15, 22, 33 };
    double order = orbit_order("vern8", "e=0.1", 13, counts, errs);
    ck_assert_msg(errs[0] < 1e-7 && errs[2] > 1e-12, "errors %g .. %g out of the asymptotic range", errs[0], errs[2]);
    ck_assert_msg(fabs(order - 8.0) <= 0.6, "orbit: observed order %.3f (errors %g %g %g)", order, errs[0], errs[1],
                  errs[2]);
    exact("orbit", "e=0.1", 2 * M_PI, ref);
    run("vern8", "orbit", "e=0.1", 2 * M_PI, 163, 0, y, &dim);
    ck_assert_msg(max_diff(4, y, ref) < 1e-13, "163 steps: error %g (stalled above round-off?)", max_diff(4, y, ref));
}
END_TEST

/* vern9, on the orbit at e = 0.5 (at e = 0.1 its error falls like h^10.3
 * down to round-off: the h^9 term is small there): at 45, 67 and 101
 * steps the errors are 3.3e-8 .. 1.6e-11, and the slope is 9.46 (local
 * slopes 9.4 and 9.5; from 100 steps on the error nears round-off,
 * 2e-14). Theory 9, +-0.6. */
START_TEST(vern9_order_orbit)
{
    double errs[3];
    const long counts[] = { 45, 67, 101 };
    double order = orbit_order("vern9", "e=0.5", 16, counts, errs);
    ck_assert_msg(errs[0] < 1e-7 && errs[2] > 1e-12, "errors %g .. %g out of the asymptotic range", errs[0], errs[2]);
    ck_assert_msg(fabs(order - 9.0) <= 0.6, "orbit: observed order %.3f (errors %g %g %g)", order, errs[0], errs[1],
                  errs[2]);
}
END_TEST

/* Adaptive at rtol = atol = 1e-13 on the orbit at e = 0.5, one period:
 * each pair's error is within 10 tolerances of the exact state (measured:
 * vern8 2.1e-13, vern9 2.9e-13), and its evaluations within 1.25 of
 * dop853's run the same way (vern8 1016, vern9 1026, dop853 1022). With its coefficients rounded one by one vern8's error was
 * 2.3e-12 here (1029 evaluations). */
START_TEST(vern_tight_orbit)
{
    double ref[4], y[4];
    int dim;
    exact("orbit", "e=0.5", 2 * M_PI, ref);
    long ed = run("dop853", "orbit", "e=0.5", 2 * M_PI, 0, 1e-13, y, &dim);
    for (int k = 0; k < 2; k++) {
        const char *m = k ? "vern9" : "vern8";
        long ev = run(m, "orbit", "e=0.5", 2 * M_PI, 0, 1e-13, y, &dim);
        double d = max_diff(4, y, ref);
        ck_assert_msg(d < 1e-12, "%s at 1e-13: error %g", m, d);
        ck_assert_msg(ev < 1.25 * (double)ed, "%s: %ld evaluations, dop853 %ld", m, ev, ed);
    }
}
END_TEST

/* Both are listed, adaptive, explicit: order 8, 13 evaluations a step;
 * order 9, 16. */
START_TEST(vern_listed)
{
    const sw_integrator *m = sw_integrator_find("vern8"), *n = sw_integrator_find("vern9");
    ck_assert_ptr_nonnull(m);
    ck_assert_ptr_nonnull(n);
    ck_assert_int_eq(m->order, 8);
    ck_assert_int_eq(m->evals, 13);
    ck_assert_uint_eq(m->flags, SW_EXPLICIT | SW_ADAPTIVE);
    ck_assert_int_eq(n->order, 9);
    ck_assert_int_eq(n->evals, 16);
    ck_assert_uint_eq(n->flags, SW_EXPLICIT | SW_ADAPTIVE);
}
END_TEST

Suite *make_vern_suite(void);
Suite *make_vern_suite(void)
{
    Suite *s = suite_create("vern");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, vern8_order_orbit);
    tcase_add_test(tc, vern9_order_orbit);
    tcase_add_test(tc, vern_tight_orbit);
    tcase_add_test(tc, vern_listed);
    suite_add_tcase(s, tc);
    return s;
}
