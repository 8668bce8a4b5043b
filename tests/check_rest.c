/* Issue 38: a ball at rest on the floor is a resting contact. Bouncing
 * with restitution e < 1, its hops shrink geometrically and their sum of
 * flight times is finite; stepped, each step then met a new contact, and
 * the located reference crawled, a contact every step (`stability bounce
 * --set drag=0.5` never returned). A ball that would leave the floor too
 * slowly to rise 1 mm (v² < 2g·1e-3) now rests on it: y = 0 and v = 0
 * exactly, in the stepped sim, with events located and in the reference.
 * The expected values are computed here: the time the ball comes to rest
 * from the geometric series of its hops. (Explicit Euler is left out: its
 * flights gain about g·Δt of landing speed each, so at e = 0.6, Δt = 0.01
 * its hops settle near 1.5·g·Δt ≈ 0.15 m/s, just above resting: the
 * method's energy gain, lesson 2's subject, keeps the ball hopping.) */
#include <check.h>
#include <math.h>
#include <string.h>

#include "sim/truth.h"
#include "stepwise/stepwise.h"

static void one_ball(double *p, const char *drag, const char *e)
{
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find("bounce");
    sw_scene_defaults(sc, p);
    ck_assert_int_eq(sw_scene_set(sc, p, "n=1", err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_scene_set(sc, p, drag, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_scene_set(sc, p, e, err, sizeof err), SW_OK);
}

/* The time the one ball (seed: height y0, vertical speed v0) comes to
 * rest without drag: first landing, then hops 2v/g each launched at e
 * times the landing speed while v² >= 2g·1e-3. */
static double rest_time(double y0, double v0, double g, double e)
{
    double t = (v0 + sqrt(v0 * v0 + 2 * g * y0)) / g, v = e * sqrt(v0 * v0 + 2 * g * y0);
    while (v * v >= 2 * g * 1e-3) {
        t += 2 * v / g;
        v *= e;
    }
    return t;
}

START_TEST(ball_comes_to_rest)
{
    double p[SW_MAX_PARAMS];
    one_ball(p, "drag=0", "e=0.6");
    const sw_scene *sc = sw_scene_find("bounce");
    static const char *const methods[] = { "verlet", "rk4", "midpoint" };
    static const sw_events_mode modes[] = { SW_EVENTS_STEP, SW_EVENTS_LOCATE };
    sw_system sys;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_system_build(&sys, sc, p, err, sizeof err), SW_OK);
    double y0 = sys.y[1], v0 = sys.y[3], g = p[1];
    sw_system_free(&sys);
    double t_rest = rest_time(y0, v0, g, 0.6);
    ck_assert(t_rest < 5.0); /* it rests well within the run below */
    for (size_t i = 0; i < 3; i++)
        for (size_t j = 0; j < 2; j++) {
            sw_sim s;
            ck_assert_int_eq(sw_sim_init(&s, sc, p, sw_integrator_find(methods[i]), 0.01, err, sizeof err), SW_OK);
            ck_assert_int_eq(sw_sim_set_events(&s, modes[j], err, sizeof err), SW_OK);
            sw_sim_run_until(&s, 10.0);
            long located = sw_sim_events_located(&s);
            /* at rest: on the floor, not moving, exactly */
            ck_assert_msg(s.sys.y[1] == 0 && s.sys.y[3] == 0, "%s (%s): y %g, v %g at t = 10", methods[i],
                          j ? "located" : "stepped", s.sys.y[1], s.sys.y[3]);
            sw_sim_run_until(&s, 20.0);
            ck_assert_msg(s.sys.y[1] == 0 && s.sys.y[3] == 0, "%s: left the floor", methods[i]);
            /* resting, the floor is no event: only the walls' hits are located */
            if (j)
                ck_assert_msg(sw_sim_events_located(&s) - located <= 10, "%s: %ld contacts located while resting",
                              methods[i], sw_sim_events_located(&s) - located);
            sw_sim_free(&s);
        }
    /* the closed form rests there too, from the time the series gives */
    ck_assert_int_eq(sw_system_build(&sys, sc, p, err, sizeof err), SW_OK);
    double y[4];
    ck_assert_int_eq(sc->exact(&sys, t_rest + 1e-9, y), 0);
    ck_assert(y[1] == 0 && y[3] == 0);
    ck_assert_int_eq(sc->exact(&sys, t_rest - 1e-3, y), 0);
    ck_assert(y[1] > 0 || y[3] != 0);
    sw_system_free(&sys);
}
END_TEST

/* The reference with drag (no closed form) reaches t = 1257, the horizon
 * stability's theory asks of it (100 periods of the drag's 0.5/s), without
 * crawling: the balls rest, and a resting ball meets no contact. */
START_TEST(reference_rests)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find("bounce");
    sw_scene_defaults(sc, p);
    ck_assert_int_eq(sw_scene_set(sc, p, "drag=0.5", err, sizeof err), SW_OK);
    sw_truth tr;
    ck_assert_int_eq(sw_truth_init(&tr, sc, p, err, sizeof err), SW_OK);
    ck_assert_int_eq(tr.source, SW_TRUTH_REFERENCE);
    tr.frame = 1257.0 / 15;
    const double *y = sw_truth_at(&tr, 1257.0);
    ck_assert_msg(y != NULL, "the reference stopped: %s", tr.why);
    for (int i = 0; i < tr.sys.n; i++)
        ck_assert_msg(y[2 * i + 1] == 0 && y[2 * tr.sys.n + 2 * i + 1] == 0, "ball %d not at rest", i);
    sw_truth_free(&tr);
}
END_TEST

Suite *make_rest_suite(void);
Suite *make_rest_suite(void)
{
    Suite *s = suite_create("rest");
    TCase *tc = tcase_create("rest");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, ball_comes_to_rest);
    tcase_add_test(tc, reference_rests);
    suite_add_tcase(s, tc);
    return s;
}
